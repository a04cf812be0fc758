// small-device: yes (trilinear interpolation eq. (6); no allocation)
#include "shitsukan/solid/turbulence.hpp"

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

Status check_lattice_point(Vec3 p, int R) {
    if (!is_finite(p))
        return Status::error(StatusCode::invalid_argument,
                             "turbulence: point (%g, %g, %g) is not finite", double(p.x),
                             double(p.y), double(p.z));
    if (!inside_lattice(p, R))
        return Status::error(StatusCode::out_of_range,
                             "turbulence: point (%g, %g, %g) is outside the lattice [0, %d]^3",
                             double(p.x), double(p.y), double(p.z), 1 << R);
    return Status::success();
}

Status turbulence_checked(const LatticeView& lattice, Vec3 p, float* out) {
    if (lattice.values == nullptr || out == nullptr)
        return Status::error(StatusCode::invalid_argument,
                             "turbulence: lattice and out must not be null");
    SHITSUKAN_TRY(check_lattice_point(p, lattice.R));
    *out = turbulence(lattice, p);
    return Status::success();
}

}  // namespace shitsukan
