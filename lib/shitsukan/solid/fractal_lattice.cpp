// small-device: yes (Type I lattice into a caller buffer; no allocation, no exceptions)
#include "shitsukan/solid/fractal_lattice.hpp"

#include <cmath>
#include <limits>

#include "shitsukan/core/prng.hpp"
#include "shitsukan/solid/fractal_node.hpp"

namespace shitsukan {
namespace {

// One level's context: where the array is, how far parents are, where g comes from.
struct LevelStep {
    float* v;
    std::int64_t side;
    std::int64_t stride[3];  // index distance of one lattice step along x, y, z
    int R;
    int h;                   // half spacing of this level: parents are h away
    float amplitude;         // L_r^(n), eq. (2)
    const FractalParams* params;
    Pcg32* rng;              // only for NoiseSource::sequential

    std::int64_t index(int x, int y, int z) const { return (z * side + y) * side + x; }
    std::uint64_t hash_start;  // of (seed, kLatticeStream), computed once
    float g(int x, int y, int z) const {
        float gauss = params->noise == NoiseSource::hash ? node_gaussian_from(hash_start, x, y, z)
                                                         : rng->gaussian();
        return gauss * amplitude;
    }
};

// Visits the nodes of this level that are odd multiples of h on exactly `odd_count` axes:
// pattern by pattern (odd axes as a bit mask x = 1, y = 2, z = 4, in increasing order), each
// scanning z, y, x upwards. An odd axis runs h, 3h, 5h, ...; an even one 0, 2h, 4h, ...
template <class F>
void for_each_new_node(const LevelStep& s, int odd_count, F&& visit) {
    const int h = s.h, step = 2 * h, side = int(s.side);
    for (int mask = 1; mask < 8; ++mask) {
        if ((mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) != odd_count) continue;
        const int x_start = (mask & 1) ? h : 0, y_start = (mask & 2) ? h : 0,
                  z_start = (mask & 4) ? h : 0;
        for (int z = z_start; z < side; z += step)
            for (int y = y_start; y < side; y += step)
                for (int x = x_start; x < side; x += step) visit(x, y, z, mask);
    }
}

// One step of okada1987 §2.2: every new node with `odd_count` odd axes from its parents (the
// parent rule of fractal_node.hpp): step (1), eq. (1), the edge midpoints (1 odd axis); step
// (2), eq. (3), the face centres from step (1)'s edge midpoints (2); step (3), eq. (4), the
// cube centres from step (2)'s face centres (3).
void compute_new_nodes(const LevelStep& s, int odd_count) {
    for_each_new_node(s, odd_count, [&](int x, int y, int z, int mask) {
        const std::int64_t i = s.index(x, y, z);
        float parents[6];
        for (int k = 0; k < 2 * odd_count; ++k) {
            const ParentStep p = parent_step(mask, k);
            parents[k] = s.v[i + p.sign * s.stride[p.axis] * s.h];
        }
        s.v[i] = node_from_parents(odd_count, parents, s.g(x, y, z));
    });
}

}  // namespace

Status build_fractal_lattice(const FractalParams& params, float* buffer, std::size_t buffer_bytes,
                             LatticeView& out, int levels) {
    SHITSUKAN_TRY(validate_fractal_params(params, kTypeIMaxDepth));
    if (buffer == nullptr)
        return Status::error(StatusCode::invalid_argument,
                             "build_fractal_lattice: buffer must not be null");
    const std::uint64_t needed = lattice_bytes(params.R);
    if (std::uint64_t(buffer_bytes) < needed)
        return Status::error(StatusCode::buffer_too_small,
                             "build_fractal_lattice: R = %d needs %llu bytes (%lld^3 floats), "
                             "the buffer has %llu",
                             params.R, static_cast<unsigned long long>(needed),
                             static_cast<long long>(lattice_side(params.R)),
                             static_cast<unsigned long long>(buffer_bytes));
    if (levels < 0 || levels > params.R) levels = params.R;

    const int R = params.R;
    const std::int64_t side = lattice_side(R);
    const std::int64_t count = side * side * side;
    const float unset = std::numeric_limits<float>::quiet_NaN();
    for (std::int64_t i = 0; i < count; ++i) buffer[i] = unset;

    // The eight initial values at the cube's corners (okada1987 §2.2).
    const std::int64_t last = side - 1;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                buffer[((k * last) * side + j * last) * side + i * last] =
                    params.corners[i + 2 * j + 4 * k];

    Pcg32 rng(params.seed, kLatticeStream);
    for (int n = 1; n <= levels; ++n) {
        LevelStep s{buffer, side, {1, side, side * side}, R, 1 << (R - n),
                    level_amplitude(n, params.beta), &params, &rng,
                    hash_start(params.seed, kLatticeStream)};
        compute_new_nodes(s, 1);  // step (1), eq. (1): the 12 edge midpoints of every cell
        compute_new_nodes(s, 2);  // step (2), eq. (3): the face centres
        compute_new_nodes(s, 3);  // step (3), eq. (4): the cube centres
    }
    out.values = buffer;
    out.R = R;
    out.side = int(side);
    return Status::success();
}

}  // namespace shitsukan
