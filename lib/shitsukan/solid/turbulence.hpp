// shitsukan/solid/turbulence.hpp — the 3D turbulence function D(P): trilinear interpolation
// of the lattice, okada1987 eq. (6) (okada1989 §3-4).
//
// Manual
//   FractalLattice store;                                          // lattice_store.hpp
//   Status s = store.build(FractalParams{});
//   if (!s) return s;
//   LatticeView lattice = store.view();
//   Vec3 p{10.3f, 40.0f, 31.7f};
//   float d = turbulence(lattice, Vec3{10.3f, 40.0f, 31.7f});      // Type I view, clamped
//   s = turbulence_checked(lattice, p, d);                         // out_of_range outside
//   const float corner_values[8] = {0, 1, 0, 1, 0, 1, 0, 1};
//   float fx = 0.5f, fy = 0.25f, fz = 0.75f;
//   float d8 = trilinear_corners(corner_values, fx, fy, fz);       // eq. (6) on one cell
//   float row[512];                                                // same bits as 512 calls
//   turbulence_row(lattice, Vec3{0.5f, 40.0f, 31.7f}, 0.125f, 512, row);  // 512 samples along x
//   const Vec3 points[2] = {p, Vec3{1.0f, 2.0f, 3.0f}};
//   float values[2];
//   turbulence_points(lattice, points, 2, values);                 // n points at once
//   return s;
//   #include "shitsukan/solid/lattice_store.hpp"
//
// Coordinates are lattice coordinates: node (i, j, k) sits at P = (i, j, k), the lattice
// fills [0, 2^R]^3 (R = 6: [0, 64]^3). Objects are mapped into it by the caller (the
// figures use (32 + 30x, 32 - 30z, 32 + 30y) for objects inside [-1, 1]^3, y up, so the
// texture's z is the object's up axis: object_to_lattice in solid/object_mapping.hpp).
// Outside the lattice: turbulence() clamps each coordinate to [0, 2^R] (the boundary
// values continue outwards, constant along the normal); NaN coordinates are treated as 0.
// turbulence_checked() refuses such points with out_of_range / invalid_argument instead.
// Corner order everywhere: index i + 2j + 4k for the corner at offset (i, j, k).
// small-device: yes (no allocation)
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#endif

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"

namespace shitsukan {

// turbulence() is forced inline: g++ -O2 otherwise keeps the call (measured: 1.4x the cost of
// the lookup itself, tests/bench/bench_solid.cpp).
#if defined(__GNUC__) || defined(__clang__)
#define SHITSUKAN_TURBULENCE_INLINE inline __attribute__((always_inline))
#else
#define SHITSUKAN_TURBULENCE_INLINE inline
#endif

namespace detail {
// (1 - t)·a + t·b: t = 0 gives a and t = 1 gives b exactly (a + t·(b - a) would not).
SHITSUKAN_TURBULENCE_INLINE float lerp(float a, float b, float t) { return (1.0f - t) * a + t * b; }
}  // namespace detail

// okada1987 eq. (6): D_x = (1/V_0)·sum_i D_i·V_i, where V_i is the volume of the box that
// P_x cuts off diagonally opposite corner P_i (V_0 = 1 for a unit cell): corner (i, j, k)
// weighs wx[i]·wy[j]·wz[k], with wx = (1 - fx, fx) and so on. The sum is evaluated factored,
// one axis at a time: four lerps along x (the edges), two along y (the faces), one along z.
// Expanded, that is the same polynomial as eq. (6) (tests/test_solid_texture.cpp checks it
// against the literal sum); factored it needs 14 multiplications instead of 20, which is
// most of the cost of D(P). At a node the fractions are 0 or 1 and node values come back bit
// for bit.
SHITSUKAN_TURBULENCE_INLINE float trilinear_corners(const float d[8], float fx, float fy, float fz) {
    const float edge_y0z0 = detail::lerp(d[0], d[1], fx), edge_y1z0 = detail::lerp(d[2], d[3], fx);
    const float edge_y0z1 = detail::lerp(d[4], d[5], fx), edge_y1z1 = detail::lerp(d[6], d[7], fx);
    const float face_z0 = detail::lerp(edge_y0z0, edge_y1z0, fy);
    const float face_z1 = detail::lerp(edge_y0z1, edge_y1z1, fy);
    return detail::lerp(face_z0, face_z1, fz);
}

// Splits one coordinate into the unit cell [cell, cell + 1] holding it and the fraction
// within, clamping to [0, cells] (cells = 2^R). The last node belongs to the last cell.
// Written as selects (max, min, integer min), which compilers can emit without branches.
SHITSUKAN_TURBULENCE_INLINE void split_lattice_coordinate(float t, int cells, int* cell, float* fraction) {
    const float top = float(cells);
    t = t > 0.0f ? t : 0.0f;  // also catches NaN
    t = t < top ? t : top;
    const int c = int(t), last = cells > 0 ? cells - 1 : 0;
    *cell = c < last ? c : last;
    *fraction = t - float(*cell);
}

// True when p lies in [0, 2^R]^3 (and is not NaN).
inline bool inside_lattice(Vec3 p, int R) {
    const float hi = float(1 << R);
    return p.x >= 0.0f && p.y >= 0.0f && p.z >= 0.0f && p.x <= hi && p.y <= hi && p.z <= hi;
}

Status check_lattice_point(Vec3 p, int R);  // invalid_argument for NaN/inf, out_of_range outside

namespace detail {
// The eight nodes of cell (ix, iy, iz) in the order i + 2j + 4k (fig. 6), then eq. (6).
SHITSUKAN_TURBULENCE_INLINE float cell_trilinear(const LatticeView& lattice, int ix, int iy,
                                                 int iz, float fx, float fy, float fz) {
    const std::size_t side = std::size_t(lattice.side), plane = side * side;
    const float* base = lattice.values + (std::size_t(iz) * side + std::size_t(iy)) * side +
                        std::size_t(ix);
    const float d[8] = {base[0],     base[1],         base[side],         base[side + 1],
                        base[plane], base[plane + 1], base[plane + side], base[plane + side + 1]};
    return trilinear_corners(d, fx, fy, fz);
}
// D(P) for a point on the boundary or outside: each coordinate clamped to [0, 2^R].
inline float turbulence_clamped(const LatticeView& lattice, Vec3 p) {
    const int cells = lattice.side - 1;
    int ix, iy, iz;
    float fx, fy, fz;
    split_lattice_coordinate(p.x, cells, &ix, &fx);
    split_lattice_coordinate(p.y, cells, &iy, &fy);
    split_lattice_coordinate(p.z, cells, &iz, &fz);
    return cell_trilinear(lattice, ix, iy, iz, fx, fy, fz);
}
}  // namespace detail

namespace detail {
// t truncated towards zero, for any float: a NaN, an infinity or a value beyond the int range
// gives INT_MIN (int(t) would be undefined there). On x86 that is what cvttss2si does, one
// instruction; elsewhere two compares first.
SHITSUKAN_TURBULENCE_INLINE int truncate_or_min(float t) {
#if defined(__SSE__) || defined(_M_X64)
    return _mm_cvttss_si32(_mm_set_ss(t));
#else
    return t > -2147483648.0f && t < 2147483648.0f ? int(t) : std::numeric_limits<int>::min();
#endif
}
// The fraction of t in cell c = int(t), for t in (-1, cells): t - c, and +0 for t in (-1, 0]
// (int() truncates those to cell 0, where split_lattice_coordinate clamps t to +0).
// On x86 one maxss (f > 0 ? f : +0, the same select), which GCC would otherwise write as a
// compare and a branch per axis.
SHITSUKAN_TURBULENCE_INLINE float cell_fraction(float t, int c) {
    float f = t - float(c);
#if (defined(__GNUC__) || defined(__clang__)) && defined(__SSE_MATH__)
    __asm__("maxss %1, %0" : "+x"(f) : "x"(0.0f));
    return f;
#else
    return f > 0.0f ? f : 0.0f;
#endif
}
// D(P) at a point turbulence() does not take on its fast path (on the boundary, outside, NaN):
// the built check, then turbulence_clamped. Out of line, so that the fast path keeps its
// registers.
float turbulence_outside(LatticeView lattice, float x, float y, float z);
}  // namespace detail

// D(P) from a Type I array: the unit cell holding P, its eight nodes P_i (fig. 6) in the
// order i + 2j + 4k, then eq. (6). Inline: a renderer calls it once per pixel, and the call
// itself would cost as much as a fifth of the lookup. A point in (-1, 2^R)^3 (nearly every
// sample) needs no clamping beyond cell_fraction's: its cell and fraction are those
// split_lattice_coordinate gives there. One test decides it and the built check together:
// the OR of the three integer parts is below side - 1 = 2^R exactly when each is in
// [0, 2^R) (the OR of numbers below a power of two stays below it; a negative part, and NaN
// or infinity through truncate_or_min, has the sign bit, which the OR keeps), and never for an
// empty view (side 0) or one of another size where it would not be exact: the clamped path
// then makes the built check (tests/bench/bench_solid.cpp times it against the raw lookup).
SHITSUKAN_TURBULENCE_INLINE float turbulence(const LatticeView& lattice, Vec3 p) {
    const int ix = detail::truncate_or_min(p.x), iy = detail::truncate_or_min(p.y),
              iz = detail::truncate_or_min(p.z);
    if (!(std::int64_t(std::uint32_t(ix | iy | iz)) < std::int64_t(lattice.side) - 1))
        return detail::turbulence_outside(lattice, p.x, p.y, p.z);
    return detail::cell_trilinear(lattice, ix, iy, iz, detail::cell_fraction(p.x, ix),
                                  detail::cell_fraction(p.y, iy), detail::cell_fraction(p.z, iz));
}
Status turbulence_checked(const LatticeView& lattice, Vec3 p, float& out);

// D(P) along a row in x: out[i] = turbulence(lattice, Vec3{start.x + float(i) * step_x,
// start.y, start.z}) for i in [0, n), bit for bit (tests/test_solid_texture.cpp, whole
// slices). The cell and fractions along y and z are found once; four samples that fall in one
// cell share its eight nodes and are interpolated as one vector (the same operations in the
// same order as eq. (6) above, so the same bits). On x86-64 with GCC or Clang the vector loop
// is compiled twice, for SSE2 and for AVX, and the processor's choice is taken at run time
// (the same IEEE operations either way). A 512 x 512 slice at 1/8 cell per pixel: 12.4
// instructions per sample with AVX, 15.7 with SSE2, against 77 by single calls (callgrind;
// tests/bench/bench_solid.cpp times both).
void turbulence_row(const LatticeView& lattice, Vec3 start, float step_x, int n, float* out);
namespace detail {
// turbulence_row without the run-time choice: the baseline compilation (SSE2 on x86-64), which
// processors without AVX take; the tests compare it with turbulence_row and single calls.
void turbulence_row_baseline(const LatticeView& lattice, Vec3 start, float step_x, int n,
                             float* out);
}  // namespace detail

// D(P) at n points: out[i] = turbulence(lattice, points[i]), bit for bit; one check of the
// lattice for the batch.
void turbulence_points(const LatticeView& lattice, const Vec3* points, std::size_t n, float* out);

}  // namespace shitsukan
