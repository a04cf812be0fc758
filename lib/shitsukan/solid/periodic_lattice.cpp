// Host side: the periodic fractal lattice (periodic_lattice.hpp).
#include "shitsukan/solid/periodic_lattice.hpp"

#include <cmath>
#include <limits>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/solid/fractal_node.hpp"
#include "shitsukan/solid/turbulence.hpp"

namespace shitsukan {
namespace {

// One step of level n: every node on the spacing-h grid whose coordinates / h are odd on
// exactly `odd_count` axes, pattern by pattern and z, y, x upwards (fractal_lattice.hpp's
// order), gets eq. (1), (3) or (4) from its parents with g of its wrapped coordinates.
void periodic_step(float* v, int R, int n, int odd_count, float amplitude, std::uint64_t start) {
    const std::int64_t N = std::int64_t(1) << R, side = N + 1;
    const std::int64_t stride[3] = {1, side, side * side};
    const int h = 1 << (R - n);
    const std::int32_t mask_n = std::int32_t(N - 1);
    for (int mask = 1; mask < 8; ++mask) {
        if ((mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) != odd_count) continue;
        const int x0 = (mask & 1) ? h : 0, y0 = (mask & 2) ? h : 0, z0 = (mask & 4) ? h : 0;
        for (std::int64_t z = z0; z < side; z += 2 * h)
            for (std::int64_t y = y0; y < side; y += 2 * h)
                for (std::int64_t x = x0; x < side; x += 2 * h) {
                    const std::int64_t i = (z * side + y) * side + x;
                    const float g = node_gaussian_from(start, std::int32_t(x) & mask_n,
                                                       std::int32_t(y) & mask_n,
                                                       std::int32_t(z) & mask_n) *
                                    amplitude;
                    // eqs. (1), (3), (4) through the one parent rule (fractal_node.hpp)
                    float parents[6];
                    for (int k = 0; k < 2 * odd_count; ++k) {
                        const ParentStep ps = parent_step(mask, k);
                        parents[k] = v[i + ps.sign * stride[ps.axis] * h];
                    }
                    v[i] = node_from_parents(odd_count, parents, g);
                }
    }
}

}  // namespace

Status PeriodicLattice::build(const FractalParams& params, std::uint64_t budget_bytes) {
    values_.clear();
    SHITSUKAN_TRY(validate_fractal_params(params, kTypeIMaxDepth));
    if (params.noise != NoiseSource::hash)
        return Status::error(StatusCode::invalid_argument,
                             "periodic lattice: noise must be NoiseSource::hash (a sequential "
                             "stream gives the two faces different numbers)");
    for (int c = 1; c < 8; ++c)
        if (!(params.corners[c] == params.corners[0]))
            return Status::error(StatusCode::invalid_argument,
                                 "periodic lattice: the eight corners must be equal (corner %d "
                                 "is %g, corner 0 is %g)",
                                 c, double(params.corners[c]), double(params.corners[0]));
    if (lattice_bytes(params.R) > budget_bytes)
        return Status::error(StatusCode::too_large,
                             "periodic lattice: R = %d needs %llu bytes, over the budget of %llu",
                             params.R, static_cast<unsigned long long>(lattice_bytes(params.R)),
                             static_cast<unsigned long long>(budget_bytes));
    const int R = params.R;
    const std::int64_t side = lattice_side(R);
    values_.assign(std::size_t(side * side * side), std::numeric_limits<float>::quiet_NaN());
    const std::int64_t last = side - 1;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                values_[std::size_t(((k * last) * side + j * last) * side + i * last)] =
                    params.corners[0];
    const std::uint64_t start = hash_start(params.seed, kLatticeStream);
    for (int n = 1; n <= R; ++n) {
        const float amplitude = level_amplitude(n, params.beta);  // eq. (2)
        for (int step = 1; step <= 3; ++step)
            periodic_step(values_.data(), R, n, step, amplitude, start);
    }
    view_.values = values_.data();
    view_.R = R;
    view_.side = int(side);
    return Status::success();
}

LatticeView PeriodicLattice::view() const {
    SHITSUKAN_REQUIRE_BUILT(!values_.empty(), "PeriodicLattice::build()",
                            "PeriodicLattice::view()");
    return view_;
}

Vec3 wrap_lattice_point(Vec3 p, int R) {
    const float n = float(std::int64_t(1) << R);
    auto wrap = [n](float t) {
        if (!(t == t) || std::isinf(t)) return 0.0f;
        float w = t - n * std::floor(t / n);
        return w >= n ? 0.0f : (w < 0.0f ? 0.0f : w);
    };
    return Vec3{wrap(p.x), wrap(p.y), wrap(p.z)};
}

float periodic_turbulence(const LatticeView& lattice, Vec3 p) {
    return turbulence(lattice, wrap_lattice_point(p, lattice.R));
}

float tileable_layer_period(float period, int R) {
    const float n = float(std::int64_t(1) << R);
    float layers = std::round(n / (period > 0.0f ? period : n));
    if (layers < 1.0f) layers = 1.0f;
    return n / layers;
}

}  // namespace shitsukan
