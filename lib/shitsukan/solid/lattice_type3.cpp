// small-device: yes (Type III lattice: hash-addressed nodes, O(R) state, no allocation)
#include "shitsukan/solid/lattice_type3.hpp"

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/solid/fractal_node.hpp"
#include "shitsukan/solid/turbulence.hpp"

namespace shitsukan {
namespace {
constexpr int grid_index(int a, int b, int c) { return a + 3 * b + 9 * c; }

// The 19 new nodes of a 27-node block in the order subdivide makes them (the 12 edge
// midpoints, the 6 face centres, the centre; each group in c, b, a order), with their
// parents' grid positions in parent_step's order: worked out at compile time, so subdivide
// reads and computes exactly what walking the 27 positions and testing each would. Bytes, not
// ints: every entry is below 27, and the plan is 209 bytes of flash instead of 836.
struct BlockStep {
    std::uint8_t index, odd_count, a, b, c;
    std::uint8_t parents[6];
};
struct BlockPlan {
    BlockStep steps[19];
};
constexpr BlockPlan make_block_plan() {
    BlockPlan plan{};
    int s = 0;
    for (int odd_count = 1; odd_count <= 3; ++odd_count)
        for (int c = 0; c <= 2; ++c)
            for (int b = 0; b <= 2; ++b)
                for (int a = 0; a <= 2; ++a) {
                    const int odd_axes = (a == 1) | ((b == 1) << 1) | ((c == 1) << 2);
                    if ((a == 1) + (b == 1) + (c == 1) != odd_count) continue;
                    BlockStep& step = plan.steps[s++];
                    step.index = std::uint8_t(grid_index(a, b, c));
                    step.odd_count = std::uint8_t(odd_count);
                    step.a = std::uint8_t(a), step.b = std::uint8_t(b), step.c = std::uint8_t(c);
                    for (int k = 0; k < 2 * odd_count; ++k) {
                        const ParentStep p = parent_step(odd_axes, k);
                        step.parents[k] = std::uint8_t(grid_index(a + (p.axis == 0 ? p.sign : 0),
                                                                  b + (p.axis == 1 ? p.sign : 0),
                                                                  c + (p.axis == 2 ? p.sign : 0)));
                    }
                }
    return plan;
}
constexpr BlockPlan kBlockPlan = make_block_plan();
}  // namespace

Status TypeIIILattice::check_params(const FractalParams& params) const {
    SHITSUKAN_TRY(validate_fractal_params(params, kTypeIIIMaxDepth));
    if (params.noise != NoiseSource::hash)
        return Status::error(StatusCode::not_supported,
                             "Type III lattice: needs NoiseSource::hash (a sequential stream "
                             "depends on the order of queries)");
    return Status::success();
}

Status TypeIIILattice::init(const FractalParams& params) {
    SHITSUKAN_TRY(check_params(params));
    // eq. (2)
    for (int n = 1; n <= params.R; ++n) amplitude_[n] = level_amplitude(n, params.beta);
    start(params);
    return Status::success();
}

Status TypeIIILattice::init(const FractalParams& params, const LevelAmplitudes& amplitudes) {
    SHITSUKAN_TRY(check_params(params));
    if (!(amplitudes.beta == params.beta))
        return Status::error(StatusCode::invalid_argument,
                             "Type III lattice: the amplitudes are for beta %g, the parameters' "
                             "beta is %g",
                             double(amplitudes.beta), double(params.beta));
    // A table filled by level_amplitudes: L^(1) = 1, then non-increasing and >= 0 (eq. (2)
    // with beta >= 0). Float compares only, so checking it links no double arithmetic.
    for (int n = 1; n <= params.R; ++n) {
        const float v = amplitudes.v[n];
        if (n == 1 ? !(v == 1.0f) : !(v >= 0.0f && v <= amplitudes.v[n - 1]))
            return Status::error(StatusCode::invalid_argument,
                                 "Type III lattice: the amplitudes are not eq. (2)'s (level %d is "
                                 "%g): fill them with level_amplitudes(beta)",
                                 n, double(v));
    }
    for (int n = 1; n <= params.R; ++n) amplitude_[n] = amplitudes.v[n];  // only once valid
    start(params);
    return Status::success();
}

void TypeIIILattice::start(const FractalParams& params) {
    R_ = params.R;
    built_ = true;
    hash_start_ = hash_start(params.seed, kLatticeStream);
    for (int i = 0; i < 8; ++i) corners0_[i] = params.corners[i];
    cached_depth_ = 0;
    subdivisions_ = 0;
    last_cell_[0] = last_cell_[1] = last_cell_[2] = -1;
    for (Block& b : row_cache_) b.x0 = b.y0 = b.z0 = -1;
}

// One recursion level on one cell (okada1987 §2.2 steps (1)-(3)): the cell of level n-1 with
// lower corner (x0, y0, z0) and the given corners becomes the 27-node block of level n.
void TypeIIILattice::subdivide(int n, const float corners[8], std::int32_t x0, std::int32_t y0,
                               std::int32_t z0) {
    Block& block = blocks_[n];
    float* grid = block.v;
    const std::int32_t h = std::int32_t(1) << (R_ - n);
    const float amplitude = amplitude_[n];
    auto g = [&](int a, int b, int c) {
        return node_gaussian_from(hash_start_, x0 + a * h, y0 + b * h, z0 + c * h) * amplitude;
    };
    // The parent's corners sit at the even grid positions.
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                grid[grid_index(2 * i, 2 * j, 2 * k)] = corners[i + 2 * j + 4 * k];
    // Steps (1)-(3), eqs. (1), (3), (4): the 12 edge midpoints, the 6 face centres, the
    // centre. A grid position is an odd multiple of h on the axes where its index is 1; its
    // parents (the parent rule of fractal_node.hpp) are one grid step away along those axes
    // (kBlockPlan lists them).
    for (const BlockStep& step : kBlockPlan.steps) {
        float parents[6];
        for (int k = 0; k < 2 * step.odd_count; ++k) parents[k] = grid[step.parents[k]];
        grid[step.index] = node_from_parents(step.odd_count, parents, g(step.a, step.b, step.c));
    }
    block.x0 = x0, block.y0 = y0, block.z0 = z0;
    ++subdivisions_;
}

// The 8 corners of the sub-cell (ox, oy, oz) in {0, 1}^3 of a block.
static void block_corners(const float* grid, int ox, int oy, int oz, float out[8]) {
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                out[i + 2 * j + 4 * k] = grid[grid_index(ox + i, oy + j, oz + k)];
}

const float* TypeIIILattice::unit_cell_corners(std::int32_t ix, std::int32_t iy, std::int32_t iz) {
    if (no_reuse_) cached_depth_ = 0;  // okada1989 §3-3: a fresh list for every point
    if (!no_reuse_ && ix == last_cell_[0] && iy == last_cell_[1] && iz == last_cell_[2])
        return cell_;
    if (R_ == 0) {
        for (int i = 0; i < 8; ++i) cell_[i] = corners0_[i];
    } else {
        // The finest block (edge 2) holding the unit cell: first look in the row cache.
        const std::int32_t fx0 = ix & ~1, fy0 = iy & ~1, fz0 = iz & ~1;
        Block* slot = nullptr;
        if (kTypeIIIRowCache > 0 && !no_reuse_) {
            std::uint32_t key = (std::uint32_t(fx0 >> 1) * 73856093u) ^
                                (std::uint32_t(fy0 >> 1) * 19349663u) ^
                                (std::uint32_t(fz0 >> 1) * 83492791u);
            slot = &row_cache_[key & std::uint32_t(kTypeIIIRowCache - 1)];
            if (slot->x0 == fx0 && slot->y0 == fy0 && slot->z0 == fz0) {
                block_corners(slot->v, ix - fx0, iy - fy0, iz - fz0, cell_);
                last_cell_[0] = ix, last_cell_[1] = iy, last_cell_[2] = iz;
                return cell_;
            }
        }
        float corners[8];
        for (int n = 1; n <= R_; ++n) {
            // The cell of level n-1 holding the query: edge 2^(R-n+1).
            const std::int32_t edge = std::int32_t(1) << (R_ - n + 1);
            const std::int32_t x0 = ix & ~(edge - 1), y0 = iy & ~(edge - 1), z0 = iz & ~(edge - 1);
            const Block& b = blocks_[n];
            if (n <= cached_depth_ && b.x0 == x0 && b.y0 == y0 && b.z0 == z0) continue;
            // Cache miss: take the cell's corners from the block of level n-1 and subdivide.
            if (n == 1) {
                for (int i = 0; i < 8; ++i) corners[i] = corners0_[i];
            } else {
                const Block& up = blocks_[n - 1];
                block_corners(up.v, (x0 - up.x0) / edge, (y0 - up.y0) / edge, (z0 - up.z0) / edge,
                              corners);
            }
            subdivide(n, corners, x0, y0, z0);
            cached_depth_ = n;
        }
        const Block& last = blocks_[R_];
        block_corners(last.v, ix - last.x0, iy - last.y0, iz - last.z0, cell_);
        if (slot != nullptr) *slot = last;
    }
    last_cell_[0] = ix, last_cell_[1] = iy, last_cell_[2] = iz;
    return cell_;
}

float TypeIIILattice::node_value(std::int32_t x, std::int32_t y, std::int32_t z) {
    SHITSUKAN_REQUIRE_BUILT(built_, "TypeIIILattice::init()", "a TypeIIILattice");
    const std::int32_t last = std::int32_t(1) << R_;
    SHITSUKAN_ASSERT(x >= 0 && y >= 0 && z >= 0 && x <= last && y <= last && z <= last);
    // The unit cell whose lower corner is the node (the last node uses the last cell).
    const std::int32_t ix = x < last ? x : last - 1, iy = y < last ? y : last - 1,
                       iz = z < last ? z : last - 1;
    const float* corner = unit_cell_corners(ix, iy, iz);
    return corner[(x - ix) + 2 * (y - iy) + 4 * (z - iz)];
}

Status TypeIIILattice::node_value_checked(std::int32_t x, std::int32_t y, std::int32_t z,
                                          float& out) {
    if (!built_)
        return Status::error(StatusCode::invalid_argument, "Type III lattice: not initialised");
    const std::int32_t last = std::int32_t(1) << R_;
    if (x < 0 || y < 0 || z < 0 || x > last || y > last || z > last)
        return Status::error(StatusCode::out_of_range,
                             "Type III lattice: node (%d, %d, %d) is outside [0, %d]^3", int(x),
                             int(y), int(z), int(last));
    out = node_value(x, y, z);
    return Status::success();
}

float TypeIIILattice::turbulence(Vec3 p) {
    SHITSUKAN_REQUIRE_BUILT(built_, "TypeIIILattice::init()", "a TypeIIILattice");
    const int cells = 1 << R_;
    int ix, iy, iz;
    float fx, fy, fz;
    split_lattice_coordinate(p.x, cells, &ix, &fx);
    split_lattice_coordinate(p.y, cells, &iy, &fy);
    split_lattice_coordinate(p.z, cells, &iz, &fz);
    return trilinear_corners(unit_cell_corners(ix, iy, iz), fx, fy, fz);  // eq. (6)
}

Status TypeIIILattice::turbulence_checked(Vec3 p, float& out) {
    if (!built_)
        return Status::error(StatusCode::invalid_argument, "Type III lattice: not initialised");
    SHITSUKAN_TRY(check_lattice_point(p, R_));
    out = turbulence(p);
    return Status::success();
}

}  // namespace shitsukan
