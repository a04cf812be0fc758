// small-device: yes (trilinear interpolation eq. (6); no allocation)
#include "shitsukan/solid/turbulence.hpp"

#include <cstring>
#include <limits>

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

float detail::turbulence_outside(LatticeView lattice, float x, float y, float z) {
    SHITSUKAN_REQUIRE_BUILT(lattice.values != nullptr && lattice.side >= 2,
                            "build_fractal_lattice()", "turbulence() on an empty LatticeView");
    return turbulence_clamped(lattice, Vec3{x, y, z});
}

Status turbulence_checked(const LatticeView& lattice, Vec3 p, float& out) {
    if (lattice.values == nullptr)
        return Status::error(StatusCode::invalid_argument,
                             "turbulence: lattice.values must not be null");
    SHITSUKAN_TRY(check_lattice_point(p, lattice.R));
    out = turbulence(lattice, p);
    return Status::success();
}

namespace {

#if defined(__GNUC__) || defined(__clang__)
// Four lanes of plain IEEE float arithmetic (GCC/Clang vector extension; on a target without
// SIMD the compiler splits it into scalar operations). No contraction: -ffp-contract=off.
typedef float Float4 __attribute__((vector_size(16)));

SHITSUKAN_TURBULENCE_INLINE Float4 splat(float v) { return Float4{v, v, v, v}; }
#else
typedef float Float4;  // without the extension: one lane, the loops below run four times
SHITSUKAN_TURBULENCE_INLINE Float4 splat(float v) { return v; }
#endif

// The eight nodes of one cell, each in all four lanes: loaded once per cell of the row.
struct CellCorners4 {
    Float4 d[8];
};
// The four lattice rows along x that hold a row's cells' nodes: (y0, z0), (y1, z0), (y0, z1),
// (y1, z1).
struct RowEdges {
    const float* r[4];
};
SHITSUKAN_TURBULENCE_INLINE void load_corners4(const RowEdges& e, std::size_t c,
                                               CellCorners4* out) {
    out->d[0] = splat(e.r[0][c]), out->d[1] = splat(e.r[0][c + 1]);
    out->d[2] = splat(e.r[1][c]), out->d[3] = splat(e.r[1][c + 1]);
    out->d[4] = splat(e.r[2][c]), out->d[5] = splat(e.r[2][c + 1]);
    out->d[6] = splat(e.r[3][c]), out->d[7] = splat(e.r[3][c + 1]);
}

#if defined(__GNUC__) || defined(__clang__)
// detail::lerp on four fractions at once, with the same operations: u = 1 - t, u·a + t·b.
SHITSUKAN_TURBULENCE_INLINE Float4 lerp4(Float4 a, Float4 b, Float4 t, Float4 u) {
    return u * a + t * b;
}

// trilinear_corners for four samples of one cell (the same eight nodes, four x fractions; the
// row's y and z fractions with their 1 - t computed once).
SHITSUKAN_TURBULENCE_INLINE Float4 trilinear_corners4(const CellCorners4& c, Float4 tx, Float4 ty,
                                                      Float4 uy, Float4 tz, Float4 uz) {
    const Float4 ux = splat(1.0f) - tx;
    const Float4 edge_y0z0 = lerp4(c.d[0], c.d[1], tx, ux);
    const Float4 edge_y1z0 = lerp4(c.d[2], c.d[3], tx, ux);
    const Float4 edge_y0z1 = lerp4(c.d[4], c.d[5], tx, ux);
    const Float4 edge_y1z1 = lerp4(c.d[6], c.d[7], tx, ux);
    const Float4 face_z0 = lerp4(edge_y0z0, edge_y1z0, ty, uy);
    const Float4 face_z1 = lerp4(edge_y0z1, edge_y1z1, ty, uy);
    return lerp4(face_z0, face_z1, tz, uz);
}
SHITSUKAN_TURBULENCE_INLINE float first_lane(Float4 v) { return v[0]; }
SHITSUKAN_TURBULENCE_INLINE float last_lane(Float4 v) { return v[3]; }
SHITSUKAN_TURBULENCE_INLINE void store4(float* out, Float4 v) { std::memcpy(out, &v, sizeof v); }
#else
SHITSUKAN_TURBULENCE_INLINE Float4 trilinear_corners4(const CellCorners4& c, Float4 tx, Float4 ty,
                                                      Float4, Float4 tz, Float4) {
    return trilinear_corners(c.d, tx, ty, tz);
}
SHITSUKAN_TURBULENCE_INLINE float first_lane(Float4 v) { return v; }
SHITSUKAN_TURBULENCE_INLINE float last_lane(Float4 v) { return v; }
SHITSUKAN_TURBULENCE_INLINE void store4(float* out, Float4 v) { *out = v; }
#endif
// Lanes per Float4: four with the vector extension, one without.
constexpr int kLanes = int(sizeof(Float4) / sizeof(float));

// float(i + l) for the lanes l = 0 .. kLanes - 1, exact while i + l < 2^24.
SHITSUKAN_TURBULENCE_INLINE Float4 lane_indices(int i) {
#if defined(__GNUC__) || defined(__clang__)
    return splat(float(i)) + Float4{0.0f, 1.0f, 2.0f, 3.0f};
#else
    return float(i);
#endif
}

// Four samples at a time: their coordinates start + float(i)·step (the single call's
// expression; float(i) formed by adding 4, exact while i < 2^24). When all four lie in one
// cell with x > 0 they go through eq. (6) as one vector with that cell's eight nodes, loaded
// and splatted once per cell: the same operations in the same order as single calls, so the
// same bits. x grows with i when step_x > 0: once a group has been found in cell c (first
// lane > c), every later group's first lane is too, so its last lane below c + 1 is the whole
// test. A group in no single cell is single calls. Returns the first sample not done (the
// last n % 4 are left to the caller). step_x > 0 and n <= 2^24.
SHITSUKAN_TURBULENCE_INLINE int row_in_groups(const LatticeView& lattice, Vec3 start,
                                              float step_x, int n, float* out) {
    const int cells = lattice.side - 1;
    int iy, iz;
    float fy, fz;
    split_lattice_coordinate(start.y, cells, &iy, &fy);
    split_lattice_coordinate(start.z, cells, &iz, &fz);
    const std::size_t side = std::size_t(lattice.side), plane = side * side;
    const float* row = lattice.values + (std::size_t(iz) * side + std::size_t(iy)) * side;
    const RowEdges edges{{row, row + side, row + plane, row + plane + side}};
    const Float4 ty = splat(fy), tz = splat(fz), x0 = splat(start.x), dx = splat(step_x);
    const Float4 uy = splat(1.0f - fy), uz = splat(1.0f - fz);
    const Float4 lanes = splat(float(kLanes));
    CellCorners4 corners{};
    float cell_high = std::numeric_limits<float>::quiet_NaN();  // no cell yet: x < NaN fails
    Float4 low = splat(0.0f), index = lane_indices(0);
    int i = 0;
    for (; i + kLanes <= n; i += kLanes, index += lanes) {
        const Float4 xs = x0 + index * dx;
        const float last = last_lane(xs);
        if (!(last < cell_high)) {
            const float first = first_lane(xs);
            const int c = first > 0.0f && first < float(cells) ? int(first) : -1;
            if (!(c >= 0 && last < float(c + 1))) {
                for (int l = 0; l < kLanes; ++l)
                    out[i + l] = turbulence(
                        lattice, Vec3{start.x + float(i + l) * step_x, start.y, start.z});
                continue;
            }
            load_corners4(edges, std::size_t(c), &corners);
            cell_high = float(c + 1);
            low = splat(float(c));
        }
        store4(out + i, trilinear_corners4(corners, xs - low, ty, uy, tz, uz));
    }
    return i;
}

// Not under clang-cl (_MSC_VER): its __builtin_cpu_supports needs compiler-rt at link time.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(_MSC_VER)
#define SHITSUKAN_ROW_AVX 1
// row_in_groups compiled for AVX: the same operations, VEX-encoded (three operands, so none of
// SSE's register copies: 12.4 instead of 15.7 instructions a sample on the bench's slice,
// callgrind), the same IEEE results. Taken when the processor has AVX (__builtin_cpu_supports,
// which also asks the OS).
__attribute__((target("avx"))) int row_in_groups_avx(const LatticeView& lattice, Vec3 start,
                                                     float step_x, int n, float* out) {
    return row_in_groups(lattice, start, step_x, n, out);
}
#endif

// D(P) along a row: the vector part (row_in_groups, for AVX when `avx`), then the last
// samples one by one.
void row(const LatticeView& lattice, Vec3 start, float step_x, int n, float* out, bool avx) {
    SHITSUKAN_REQUIRE_BUILT(lattice.values != nullptr && lattice.side >= 2,
                            "build_fractal_lattice()", "turbulence_row() on an empty LatticeView");
    int i = 0;
    if (step_x > 0.0f && n <= (1 << 24)) {
#ifdef SHITSUKAN_ROW_AVX
        if (avx)
            i = row_in_groups_avx(lattice, start, step_x, n, out);
        else
#endif
            i = row_in_groups(lattice, start, step_x, n, out);
    }
    (void)avx;
    for (; i < n; ++i)
        out[i] = turbulence(lattice, Vec3{start.x + float(i) * step_x, start.y, start.z});
}
}  // namespace

void turbulence_row(const LatticeView& lattice, Vec3 start, float step_x, int n, float* out) {
#ifdef SHITSUKAN_ROW_AVX
    row(lattice, start, step_x, n, out, __builtin_cpu_supports("avx"));
#else
    row(lattice, start, step_x, n, out, false);
#endif
}

void detail::turbulence_row_baseline(const LatticeView& lattice, Vec3 start, float step_x, int n,
                                     float* out) {
    row(lattice, start, step_x, n, out, false);
}

void turbulence_points(const LatticeView& lattice, const Vec3* points, std::size_t n, float* out) {
    for (std::size_t i = 0; i < n; ++i) out[i] = turbulence(lattice, points[i]);
}

}  // namespace shitsukan
