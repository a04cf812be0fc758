// small-device: yes (wood original function and texture; no allocation)
#include "shitsukan/solid/wood.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>

#include "shitsukan/core/scalar.hpp"
#include "shitsukan/solid/pixel_shift.hpp"

namespace shitsukan {

namespace {
float axis_distance(Vec3 p, const WoodParams& w) {
    const float dx = p.x - w.x0, dy = p.y - w.y0;
    return std::sqrt(dx * dx + dy * dy);
}
}  // namespace

float wood_original(Vec3 p, const WoodParams& params) {
    // eq. (10). det_sinf_fast: float arithmetic only (det_sinf reduces and sums in double,
    // software on a single-precision FPU: most of a wood pixel's cost on a Cortex-M4F).
    return det_sinf_fast(params.k2 * axis_distance(p, params));
}

Status wood_radial_direction(Vec3 p, const WoodParams& params, Vec3& u) {
    const float r = axis_distance(p, params);
    if (!(r > 0.0f)) {
        u = Vec3{0.0f, 0.0f, 0.0f};
        return Status::error(StatusCode::degenerate,
                             "wood: (%g, %g, %g) lies on the axis (r = 0): no radial direction",
                             double(p.x), double(p.y), double(p.z));
    }
    u = Vec3{(p.x - params.x0) / r, (p.y - params.y0) / r, 0.0f};  // eq. (11)
    return Status::success();
}

float wood_texture(Vec3 p, float d, const WoodParams& params) {
    Vec3 u;
    (void)wood_radial_direction(p, params, u);   // u = 0 on the axis: P is not displaced
    return wood_original(pixel_shift(p, params.k, d, u), params);
}

Status validate_wood(const WoodParams& w) {
    if (!is_finite(w.x0) || !is_finite(w.y0))
        return Status::error(StatusCode::invalid_argument, "wood: axis (x0, y0) is not finite");
    if (!is_finite(w.k2) || !(w.k2 > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "wood: ring frequency k2 must be finite and > 0 (got %g)",
                             double(w.k2));
    if (!is_finite(w.k))
        return Status::error(StatusCode::invalid_argument, "wood: k is not finite");
    return Status::success();
}

}  // namespace shitsukan
