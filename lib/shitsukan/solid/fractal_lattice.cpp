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
    int h;                   // half spacing of this level: parents are h away
    float amplitude;         // L_r^(n), eq. (2)
    NoiseSource noise;
    Pcg32* rng;                // only for NoiseSource::sequential
    std::uint64_t hash_start;  // of (seed, kLatticeStream), computed once
};

// The nodes of one pattern are taken in runs along x, of at most kRun nodes of one row (chosen
// here: 33, a whole row of the R = 6 lattice; 33 · 28 bytes of stack): first the run's numbers
// g, then each node from its parents.
constexpr int kRun = 33;

// One run: the nodes first, first + step, ... (count of them) from their 2·OddCount parents
// (index offsets from the parent rule of fractal_node.hpp) and g[], eq. (1), (3) or (4).
template <int OddCount>
void compute_run(const LevelStep& s, const std::int64_t* offset, float* first, int count,
                 const float* g) {
    const int step = 2 * s.h;
    for (int c = 0; c < count; ++c) {
        float* node = first + std::int64_t(c) * step;
        float parents[2 * OddCount];
        for (int k = 0; k < 2 * OddCount; ++k) parents[k] = node[offset[k]];
        *node = node_from_parents(OddCount, parents, g[c] * s.amplitude);
    }
}

// One pattern of one step (the nodes whose odd axes are `mask`): the parent rule resolved into
// index offsets once per pattern, not once per node. With NoiseSource::sequential the rows are
// scanned z, y, x upwards, drawing g from the generator in that order. With NoiseSource::hash
// no node of a step depends on another of the same step (its parents are older), so the order
// is free: runs of x, then y, then z upwards. The node's number is node_gaussian_from(start,
// x, y, z), whose hash adds x, then y, then z (core/hash.hpp): the x parts are computed once per
// run, the (x, y) parts once per row of the run, so one hash_add per node; the run's numbers
// then come four at a time (gaussians_from_bits_float), the same bits as one by one.
template <int OddCount>
void compute_pattern(const LevelStep& s, int mask) {
    std::int64_t offset[2 * OddCount];
    for (int k = 0; k < 2 * OddCount; ++k) {
        const ParentStep p = parent_step(mask, k);
        offset[k] = p.sign * s.stride[p.axis] * s.h;
    }
    const int h = s.h, step = 2 * h, side = int(s.side);
    const int x_start = (mask & 1) ? h : 0, y_start = (mask & 2) ? h : 0,
              z_start = (mask & 4) ? h : 0;
    const int columns = (side - 1 - x_start) / step + 1;  // nodes per row
    float g[kRun];
    if (s.noise == NoiseSource::sequential) {
        for (int z = z_start; z < side; z += step)
            for (int y = y_start; y < side; y += step)
                for (int c0 = 0; c0 < columns; c0 += kRun) {
                    const int count = columns - c0 < kRun ? columns - c0 : kRun;
                    for (int c = 0; c < count; ++c) g[c] = s.rng->gaussian();
                    compute_run<OddCount>(s, offset, s.v + (z * s.side + y) * s.side + x_start +
                                                         std::int64_t(c0) * step,
                                          count, g);
                }
        return;
    }
    std::uint64_t hash_x[kRun], hash_xy[kRun], bits[kRun];
    for (int c0 = 0; c0 < columns; c0 += kRun) {
        const int count = columns - c0 < kRun ? columns - c0 : kRun;
        const int x0 = x_start + c0 * step;
        for (int c = 0; c < count; ++c)
            hash_x[c] = hash_add(s.hash_start, std::uint32_t(x0 + c * step));
        for (int y = y_start; y < side; y += step) {
            for (int c = 0; c < count; ++c) hash_xy[c] = hash_add(hash_x[c], std::uint32_t(y));
            for (int z = z_start; z < side; z += step) {
                for (int c = 0; c < count; ++c) bits[c] = hash_add(hash_xy[c], std::uint32_t(z));
                gaussians_from_bits_float(bits, count, g);
                compute_run<OddCount>(s, offset, s.v + (z * s.side + y) * s.side + x0, count, g);
            }
        }
    }
}

// One step of okada1987 §2.2: every new node with `OddCount` odd axes, pattern by pattern
// (odd axes as a bit mask x = 1, y = 2, z = 4, in increasing order): step (1), eq. (1), the
// edge midpoints (1 odd axis); step (2), eq. (3), the face centres from step (1)'s edge
// midpoints (2); step (3), eq. (4), the cube centres from step (2)'s face centres (3).
template <int OddCount>
void compute_new_nodes(const LevelStep& s) {
    for (int mask = 1; mask < 8; ++mask)
        if ((mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) == OddCount)
            compute_pattern<OddCount>(s, mask);
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
        const LevelStep s{buffer, side, {1, side, side * side}, 1 << (R - n),
                          level_amplitude(n, params.beta), params.noise, &rng,
                          hash_start(params.seed, kLatticeStream)};
        compute_new_nodes<1>(s);  // step (1), eq. (1): the 12 edge midpoints of every cell
        compute_new_nodes<2>(s);  // step (2), eq. (3): the face centres
        compute_new_nodes<3>(s);  // step (3), eq. (4): the cube centres
    }
    out.values = buffer;
    out.R = R;
    out.side = int(side);
    return Status::success();
}

}  // namespace shitsukan
