// small-device: yes (marble original function and texture; no allocation)
#include "shitsukan/solid/marble.hpp"

#include <cmath>

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/scalar.hpp"
#include "shitsukan/solid/pixel_shift.hpp"

namespace shitsukan {

float trapezoid_skirt(float z, const MarbleStripe& s) {
    const float d = std::fabs(z - s.c) - s.w * 0.5f;  // distance from the stripe's edge
    if (d <= 0.0f) return 1.0f;                       // inside the stripe: the flat top
    // the skirt: e^{-alpha·d}, in float arithmetic (det_expf_fast, <= 2 ulp): the double
    // det_exp cost ~2.5k instructions per stripe on a Cortex-M4F
    return det_expf_fast(-(s.alpha * d));
}

float marble_original(float z, const MarbleStripe* stripes, int count) {
    float g = 0.0f;
    for (int j = 0; j < count; ++j) g += trapezoid_skirt(z, stripes[j]);
    return g;
}

float marble_texture(Vec3 p, float d, const MarbleParams& params) {
    // okada1987 eq. (9) as pixel shift: only z moves, u = (0, 0, 1) (okada1989 eq. (9)).
    const Vec3 q = pixel_shift(p, params.k, d, Vec3{0.0f, 0.0f, 1.0f});
    return marble_original(q.z, params.stripes, params.count);
}

float marble_density(Vec3 p, float d, const MarbleParams& params) {
    const float g = marble_texture(p, d, params);
    return 1.0f - (g < 1.0f ? g : 1.0f);  // G' (chosen here, see solid_material.hpp)
}

Status validate_marble_stripe(const MarbleStripe& s) {
    if (!is_finite(s.c))
        return Status::error(StatusCode::invalid_argument, "marble stripe: centre c is not finite");
    if (!is_finite(s.w) || !(s.w > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "marble stripe: width w must be finite and > 0 (got %g)", double(s.w));
    if (!is_finite(s.alpha) || !(s.alpha > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "marble stripe: decay alpha must be finite and > 0 (got %g)",
                             double(s.alpha));
    return Status::success();
}

Status validate_marble(const MarbleParams& params) {
    if (params.stripes == nullptr || params.count < 1)
        return Status::error(StatusCode::invalid_argument,
                             "marble: needs at least one stripe (got %d)", params.count);
    if (!is_finite(params.k))
        return Status::error(StatusCode::invalid_argument, "marble: k is not finite");
    for (int j = 0; j < params.count; ++j) {
        Status s = validate_marble_stripe(params.stripes[j]);
        if (!s.ok())
            return Status::error(s.code(), "stripe %d: %s", j, s.message());
    }
    return Status::success();
}

}  // namespace shitsukan
