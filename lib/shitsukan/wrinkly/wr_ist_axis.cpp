#include "shitsukan/wrinkly/wr_ist_axis.hpp"

#include "shitsukan/core/assert.hpp"
#include "shitsukan/wrinkly/ist_formula.hpp"

namespace shitsukan {

Status make_wr_ist_axis(const IstAxis& ist, int max_level, WrIstAxis& out) {
    if (max_level < 0 || max_level > kMaxWrLevel)
        return Status::error(StatusCode::invalid_argument, "max level K must be in 0..%d (got %d)",
                             kMaxWrLevel, max_level);
    SHITSUKAN_TRY(ist_validate(ist));
    out.steps_.clear();
    for (int k = 0; k <= max_level; ++k) {
        IstAxis a;
        SHITSUKAN_TRY(ist_with_iterations(ist, k, a));
        out.steps_.push_back(a);
    }
    return Status::success();
}

float WrIstAxis::inverse(const void* self, float s, int k) {
    const WrIstAxis& a = *static_cast<const WrIstAxis*>(self);
    SHITSUKAN_ASSERT(k >= 0 && k <= a.max_level());
    const IstAxis& ist = a.steps_[std::size_t(k)];
    const double b = double(ist.base_intervals);
    // WrAxis works in base-interval units [0, B]; the IST formulas in [0, 1].
    return float(ist_inverse_double(ist, double(s) / b) * b);
}

WrAxis WrIstAxis::axis() const {
    WrAxis w;
    SHITSUKAN_ASSERT(!steps_.empty());
    w.base_intervals = steps_[0].base_intervals;
    w.division = steps_[0].n;
    w.max_level = max_level();
    w.inverse = &WrIstAxis::inverse;
    w.context = this;
    return w;
}

}  // namespace shitsukan
