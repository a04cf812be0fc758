// shitsukan/solid/lattice_type3.hpp — okada1989 §3-3 Type III: the fractal lattice with no
// table at all. Each node's g comes from the coordinate hash of the node, so a node can be
// recomputed on demand and always gets the same number; only the ancestry of the current
// query is kept (O(R) memory, no allocation).
//
// Manual
//   FractalParams p;  p.R = 20;                     // 1,048,577 points a side, never stored
//   TypeIIILattice lattice;                          // 10,888 bytes, fixed capacity
//                                                    // (3,328 without the row cache below);
//                                                    // all zero until init(): .bss if static
//   Status s = lattice.init(p);                      // hash noise only (see below)
//   if (!s) return s;
//   constexpr LevelAmplitudes amps = level_amplitudes(FractalParams{}.beta);  // at build time:
//   s = lattice.init(p, amps);        // eq. (2) computed by the compiler, the same values
//   if (!s) return s;
//   float v = lattice.node_value(7, 1 << 19, 3);     // one node, 0 <= x, y, z <= 2^R
//   float d = lattice.turbulence(Vec3{3.5f, 8.25f, 1.0f});   // eq. (6), clamped like Type I
//
// How: to reach the unit cell holding a query, descend from the initial cube: at level n
// the cell of level n-1 holding the query is subdivided once with eqs. (1)-(4) into a block
// of 3x3x3 nodes (its 8 corners, 12 edge midpoints, 6 face centres and centre: every node
// inside a cell depends only on that cell's 8 corners), and the sub-cell holding the query
// is the cell of level n. The block of every level is cached; the next query restarts from
// the deepest cached block that still holds it (and skips the descent when it falls in the
// same unit cell), so neighbouring queries (a scanline, a raster slice) recompute only the
// last level or two. A small direct-mapped cache of finest-level blocks (kTypeIIIRowCache
// = 64 blocks, 7.7 KB; define SHITSUKAN_TYPE3_ROW_CACHE=0 to leave it out) keeps the blocks
// of the previous raster row, so the next row reuses them without any descent: a block's
// values depend only on its coordinates, never on the path that computed it.
// Ranges: 0 <= R <= kTypeIIIMaxDepth (24: float coordinates still resolve single cells).
// NoiseSource::sequential is refused (not_supported): an order-dependent stream is exactly
// what Type III cannot use.
// Agreement: with NoiseSource::hash, Types I, II and III return the same float at every
// node (the same rules in fractal_node.hpp, summed in the same order).
// small-device: yes (no allocation; state is this object)
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/solid/fractal_params.hpp"

namespace shitsukan {

#ifndef SHITSUKAN_TYPE3_ROW_CACHE
#define SHITSUKAN_TYPE3_ROW_CACHE 64
#endif
constexpr int kTypeIIIRowCache = SHITSUKAN_TYPE3_ROW_CACHE;  // 0 or a power of two
static_assert((kTypeIIIRowCache & (kTypeIIIRowCache - 1)) == 0, "row cache: a power of two");

class TypeIIILattice {
public:
    Status init(const FractalParams& params);
    // The same with eq. (2)'s amplitudes computed before (level_amplitudes(params.beta), at
    // compile time: no double arithmetic linked); refused (invalid_argument) when they are
    // for another beta.
    Status init(const FractalParams& params, const LevelAmplitudes& amplitudes);

    int depth() const { return R_; }
    std::int64_t side() const { return lattice_side(R_); }

    // The value of node (x, y, z); coordinates must lie in [0, 2^R] (SHITSUKAN_ASSERT).
    float node_value(std::int32_t x, std::int32_t y, std::int32_t z);
    Status node_value_checked(std::int32_t x, std::int32_t y, std::int32_t z, float& out);

    // D(P), eq. (6), at P in lattice coordinates; clamped outside [0, 2^R]^3.
    float turbulence(Vec3 p);
    Status turbulence_checked(Vec3 p, float& out);

    // true (default): keep the ancestry blocks and the row cache between queries (this
    // library's Type III). false: okada1989's own Type III (§3-3: the list is cleared for
    // every new point), every query descends all R levels from the initial cube; the values
    // are the same, only the time differs.
    void set_reuse(bool reuse) { no_reuse_ = !reuse; }
    bool reuse() const { return !no_reuse_; }

    // Teaching/bench counters: how many cell subdivisions (19 new nodes each) were computed.
    long subdivisions() const { return subdivisions_; }
    // Bytes that hold the ancestry for depth R (one 27-node block per level), and the object.
    std::size_t ancestry_bytes() const { return std::size_t(R_) * sizeof(Block); }
    static constexpr std::size_t object_bytes() { return sizeof(TypeIIILattice); }

private:
    // The 27 nodes of one subdivided cell of level n-1: node (a, b, c), a, b, c in 0..2, is at
    // (x0 + a·h, y0 + b·h, z0 + c·h) with h = 2^(R-n); index a + 3b + 9c.
    struct Block {
        std::int32_t x0 = 0, y0 = 0, z0 = 0;  // valid once init() has run (see below)
        float v[27] = {};
    };

    Status check_params(const FractalParams& params) const;
    void start(const FractalParams& params);  // after the amplitudes are set
    const float* unit_cell_corners(std::int32_t ix, std::int32_t iy, std::int32_t iz);
    void subdivide(int n, const float corners[8], std::int32_t x0, std::int32_t y0,
                   std::int32_t z0);

    // Every member starts at zero, so a static TypeIIILattice is .bss (no flash for its
    // initial value); init() marks the caches empty (coordinates -1).
    bool built_ = false;
    int R_ = 0;
    std::uint64_t hash_start_ = 0;
    int cached_depth_ = 0;  // blocks_[1..cached_depth_] hold the ancestry of the last query
    bool no_reuse_ = false;
    long subdivisions_ = 0;
    std::int32_t last_cell_[3] = {};  // unit cell of the last query
    float corners0_[8] = {};          // the eight initial corner values
    float cell_[8] = {};              // corners of the last query's unit cell
    float amplitude_[kTypeIIIMaxDepth + 1] = {};
    Block blocks_[kTypeIIIMaxDepth + 1];
    Block row_cache_[kTypeIIIRowCache > 0 ? kTypeIIIRowCache : 1];
};

}  // namespace shitsukan
