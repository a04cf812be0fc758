// small-device: yes (trilinear interpolation eq. (6); no allocation)
#include "shitsukan/solid/turbulence.hpp"

#include <cstring>

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
typedef int Int4 __attribute__((vector_size(16)));

inline Float4 splat(float v) { return Float4{v, v, v, v}; }
#else
typedef float Float4;  // without the extension: one lane, the loops below run four times
inline Float4 splat(float v) { return v; }
#endif

// The eight nodes of one cell, each in all four lanes: loaded once per cell of the row.
struct CellCorners4 {
    Float4 d[8];
};
inline void load_corners4(const float* base, std::size_t side, std::size_t plane,
                          CellCorners4* c) {
    const float v[8] = {base[0],     base[1],         base[side],         base[side + 1],
                        base[plane], base[plane + 1], base[plane + side], base[plane + side + 1]};
    for (int k = 0; k < 8; ++k) c->d[k] = splat(v[k]);
}

#if defined(__GNUC__) || defined(__clang__)

// detail::lerp on four fractions at once, with the same operation order.
inline Float4 lerp4(Float4 a, Float4 b, Float4 t) { return (splat(1.0f) - t) * a + t * b; }

// trilinear_corners for four samples of one cell (the same eight nodes, four x fractions).
inline void trilinear_corners4(const CellCorners4& c, const float* fx, Float4 ty, Float4 tz,
                               float* out) {
    Float4 t;
    std::memcpy(&t, fx, sizeof t);
    const Float4 edge_y0z0 = lerp4(c.d[0], c.d[1], t), edge_y1z0 = lerp4(c.d[2], c.d[3], t);
    const Float4 edge_y0z1 = lerp4(c.d[4], c.d[5], t), edge_y1z1 = lerp4(c.d[6], c.d[7], t);
    const Float4 face_z0 = lerp4(edge_y0z0, edge_y1z0, ty);
    const Float4 face_z1 = lerp4(edge_y0z1, edge_y1z1, ty);
    const Float4 r = lerp4(face_z0, face_z1, tz);
    std::memcpy(out, &r, sizeof r);
}

// The four coordinates start + float(i + l)·step, l = 0..3 (the single call's expression).
inline Float4 row_coordinates4(float start, float step, int i) {
    const Float4 index = {float(i), float(i + 1), float(i + 2), float(i + 3)};
    return splat(start) + index * splat(step);
}

// split_lattice_coordinate on four samples: the same comparisons and conversions lane by lane
// (masks instead of branches), so the same cells and fractions.
void split_row4(float start, float step, int i, int cells, int* cell, float* fraction) {
    const Float4 x = row_coordinates4(start, step, i);
    const Float4 hi = splat(float(cells));
    Int4 bits = (Int4)x & (x > splat(0.0f));  // !(t > 0) (NaN too) -> +0
    Float4 t = (Float4)bits;
    const Int4 over = t > hi;
    t = (Float4)((bits & ~over) | ((Int4)hi & over));
    Int4 c = __builtin_convertvector(t, Int4);
    c += c >= Int4{cells, cells, cells, cells};  // the last node belongs to the last cell
    const Float4 f = t - __builtin_convertvector(c, Float4);
    std::memcpy(cell, &c, sizeof c);
    std::memcpy(fraction, &f, sizeof f);
}

// The same for four samples strictly inside (0, cells), where no clamp applies (as in
// turbulence()'s inside path): the integer part and the rest.
void split_row4_inside(float start, float step, int i, int* cell, float* fraction) {
    const Float4 x = row_coordinates4(start, step, i);
    const Int4 c = __builtin_convertvector(x, Int4);
    const Float4 f = x - __builtin_convertvector(c, Float4);
    std::memcpy(cell, &c, sizeof c);
    std::memcpy(fraction, &f, sizeof f);
}
#else
void trilinear_corners4(const CellCorners4& c, const float* fx, float fy, float fz, float* out) {
    for (int k = 0; k < 4; ++k) out[k] = trilinear_corners(c.d, fx[k], fy, fz);
}
void split_row4(float start, float step, int i, int cells, int* cell, float* fraction) {
    for (int k = 0; k < 4; ++k)
        split_lattice_coordinate(start + float(i + k) * step, cells, &cell[k], &fraction[k]);
}
void split_row4_inside(float start, float step, int i, int* cell, float* fraction) {
    for (int k = 0; k < 4; ++k) {
        const float x = start + float(i + k) * step;
        cell[k] = int(x);
        fraction[k] = x - float(cell[k]);
    }
}
#endif

// Is every coordinate start + float(i)·step, i in [0, n), strictly inside (0, cells)? The
// coordinates are monotone in i (a product and a sum of floats round monotonically), so the
// two ends decide.
bool row_inside(float start, float step, int n, int cells) {
    const float first = start, last = start + float(n - 1) * step, top = float(cells);
    return first > 0.0f && first < top && last > 0.0f && last < top;
}

}  // namespace

void turbulence_row(const LatticeView& lattice, Vec3 start, float step_x, int n, float* out) {
    SHITSUKAN_REQUIRE_BUILT(lattice.values != nullptr && lattice.side >= 2,
                            "build_fractal_lattice()", "turbulence_row() on an empty LatticeView");
    const int cells = lattice.side - 1;
    int iy, iz;
    float fy, fz;
    split_lattice_coordinate(start.y, cells, &iy, &fy);
    split_lattice_coordinate(start.z, cells, &iz, &fz);
    const std::size_t side = std::size_t(lattice.side), plane = side * side;
    const float* row = lattice.values + (std::size_t(iz) * side + std::size_t(iy)) * side;
    const bool inside = n > 0 && row_inside(start.x, step_x, n, cells);
    const Float4 ty = splat(fy), tz = splat(fz);
    constexpr int kChunk = 64;  // samples split at once (stack: 512 bytes)
    int cell[kChunk];
    float fx[kChunk];
    CellCorners4 corners;
    int corners_of = -1;  // the cell whose nodes `corners` holds
    for (int i0 = 0; i0 < n; i0 += kChunk) {
        const int m = n - i0 < kChunk ? n - i0 : kChunk;
        int k0 = 0;
        for (; k0 + 4 <= m; k0 += 4) {
            if (inside)
                split_row4_inside(start.x, step_x, i0 + k0, cell + k0, fx + k0);
            else
                split_row4(start.x, step_x, i0 + k0, cells, cell + k0, fx + k0);
        }
        for (; k0 < m; ++k0)
            split_lattice_coordinate(start.x + float(i0 + k0) * step_x, cells, &cell[k0], &fx[k0]);
        // Four samples at a time: in one cell (the usual case when the step is below a
        // quarter of a cell) they share its eight nodes, loaded once per cell, and go through
        // eq. (6) as one vector; otherwise, and for the last few, one by one.
        auto single = [&](int l) {
            out[i0 + l] = detail::cell_trilinear(lattice, cell[l], iy, iz, fx[l], fy, fz);
        };
        int k = 0;
        for (; k + 4 <= m; k += 4) {
            if (cell[k] == cell[k + 1] && cell[k + 2] == cell[k + 3] && cell[k] == cell[k + 3]) {
                if (cell[k] != corners_of) {
                    load_corners4(row + std::size_t(cell[k]), side, plane, &corners);
                    corners_of = cell[k];
                }
                trilinear_corners4(corners, fx + k, ty, tz, out + i0 + k);
            } else {
                for (int l = k; l < k + 4; ++l) single(l);
            }
        }
        for (; k < m; ++k) single(k);
    }
}

void turbulence_points(const LatticeView& lattice, const Vec3* points, std::size_t n, float* out) {
    for (std::size_t i = 0; i < n; ++i) out[i] = turbulence(lattice, points[i]);
}

}  // namespace shitsukan
