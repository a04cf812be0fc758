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

float turbulence(const LatticeView& lattice, Vec3 p) {
    SHITSUKAN_ASSERT(lattice.values != nullptr && lattice.side >= 2);
    const int cells = lattice.side - 1;
    int ix, iy, iz;
    float fx, fy, fz;
    split_lattice_coordinate(p.x, cells, &ix, &fx);
    split_lattice_coordinate(p.y, cells, &iy, &fy);
    split_lattice_coordinate(p.z, cells, &iz, &fz);
    // The eight nodes P_i around P (fig. 6), in the order i + 2j + 4k.
    const std::size_t side = std::size_t(lattice.side), plane = side * side;
    const float* base = lattice.values + (std::size_t(iz) * side + std::size_t(iy)) * side +
                        std::size_t(ix);
    const float d[8] = {base[0],     base[1],         base[side],         base[side + 1],
                        base[plane], base[plane + 1], base[plane + side], base[plane + side + 1]};
    return trilinear_corners(d, fx, fy, fz);
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
