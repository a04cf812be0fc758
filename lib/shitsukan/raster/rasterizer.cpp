// small-device: yes (no allocation, no exceptions)
//
// The scanline rasterizer. Per triangle:
//   1. fetch its three corners and take them to clip space; skip degenerate ones,
//   2. clip in homogeneous space when an outcode asks for it (clip.hpp),
//   3. divide by w and snap to 1/256 pixel,
//   4. decide the facing once for the triangle and cull; then per triangle of the
//      (fan-triangulated) polygon, if it touches the band, fetch the remaining vertex
//      attributes (world position, normals, uv, colour) and walk the scanlines of the band:
//      per row, the span between the left and right edge
//      follows from exact integer arithmetic (top-left rule), per pixel the depth is tested
//      before the shader is called (early z), and attributes are interpolated
//      perspective-correctly.
// Every per-pixel value is a function of the pixel and the triangle only (nothing is
// stepped incrementally from the top of the triangle or of the band), so any band of rows
// gives the same bits as the full frame.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>

#include "shitsukan/raster/clip.hpp"
#include "shitsukan/raster/rasterizer.hpp"

// bin_triangle is flattened (speed: it runs for every triangle of a frame); snapped_area2 (four
// call sites) and next_in_band are kept out of line (flash; and the band's walk over its
// binned-away triangles stays in registers).
#if defined(__GNUC__) || defined(__clang__)
#define SHITSUKAN_RASTER_FLATTEN __attribute__((flatten))
#define SHITSUKAN_RASTER_NOINLINE __attribute__((noinline))
#define SHITSUKAN_RASTER_INLINE inline __attribute__((always_inline))
#else
#define SHITSUKAN_RASTER_FLATTEN
#define SHITSUKAN_RASTER_NOINLINE
#define SHITSUKAN_RASTER_INLINE inline
#endif

namespace shitsukan {

namespace {

using i64 = std::int64_t;

constexpr int kSubpixelBits = 8;  // chosen here: 1/256 pixel vertex positions
constexpr i64 kSubpixel = i64(1) << kSubpixelBits;
constexpr i64 kHalfPixel = kSubpixel / 2;  // pixel centres are at integer + 1/2

// The attributes of one original mesh vertex, in the form the fragment needs them.
struct VertexData {
    Vec3 object_position, world_position, normal, object_normal, color;
    Vec2 uv;
};

// The original triangle. Its clip-space corners are computed for every triangle; the rest
// (world positions, normals, uv, colours) only when a part of it survives culling and lies
// in the band (prepare), since most triangles of a band render do not.
struct SourceTriangle {
    VertexData v[3];
    VertexData dq, dr;  // v[1] - v[0] and v[2] - v[0], attribute by attribute
    const std::uint32_t* corner_index = nullptr;  // the three mesh indices
    int index = 0;
    bool flat = false;  // the mesh has no normals
    bool ready = false;
};

struct MeshContext {
    const MeshView* mesh;
    const Mat4* model;
    const Mat4* normal_matrix;
};

// A sub-triangle corner after the divide: fixed-point screen position, depth, 1/w and the
// barycentric coordinates in the original triangle.
struct ScreenVertex {  // no default member values: arrays of these are not zeroed
    std::int32_t x, y;  // pixels · 256, |x|, |y| < kMaxFixed = 2^28 (differences fit 32 bits)
    float z;           // depth in [0, 1]
    float inv_w;       // 1 / w_clip, for perspective-correct interpolation
    Vec3 bary;
};

struct DrawContext {
    MeshContext mesh;
    const FrameBand* band;
    FragmentShader shader;
    void* user;
    CullMode cull;
    long fragments = 0;
    Fragment f;  // one per draw call, not per triangle (raster_triangle sets what it reads)
};

// q = floor(a / b), r = a - q·b in [0, b), for b > 0: shift and subtract on 32-bit words
// (Armv7-M divides 32 bits in hardware; libgcc's 64-bit __aeabi_ldivmod is 700 bytes and
// slow). Runs once per edge per band, never per row.
SHITSUKAN_RASTER_INLINE void floor_divmod(i64 a, i64 b, i64* q, i64* r) {
    const bool negative = a < 0;
    std::uint64_t n = negative ? 0u - std::uint64_t(a) : std::uint64_t(a);
    const std::uint64_t d = std::uint64_t(b);
    std::uint64_t quotient = 0, rest = 0;
    if ((n >> 32) == 0 && (d >> 32) == 0) {
        quotient = std::uint32_t(n) / std::uint32_t(d);
        rest = std::uint32_t(n) - std::uint32_t(quotient) * std::uint32_t(d);
    } else {
        for (int bit = 63; bit >= 0; --bit) {
            rest = (rest << 1) | ((n >> bit) & 1u);
            if (rest >= d) {
                rest -= d;
                quotient |= std::uint64_t(1) << bit;
            }
        }
    }
    i64 fq = i64(quotient), fr = i64(rest);
    if (negative) {  // -(quotient·d + rest) = -(quotient + 1)·d + (d - rest)
        fq = -fq;
        fr = -fr;
        if (fr < 0) {
            fq -= 1;
            fr += b;
        }
    }
    *q = fq;
    *r = fr;
}

// The first row (or column) whose centre lies at or past the snapped coordinate v:
// ceil((v - 128) / 256), exact for negative v too (an arithmetic shift, no division), in 32
// bits (|v| < kMaxFixed = 2^28).
inline int first_centre_from(std::int32_t v) {
    return -((std::int32_t(kHalfPixel) - v) >> kSubpixelBits);
}

// a·b for |a|, |b| < 2^31 (differences of snapped coordinates, which stay below 2^29): one
// 32 x 32 -> 64-bit multiply (SMULL on a Cortex-M4F) instead of a 64 x 64-bit one. Exact.
inline i64 wide_product(i64 a, i64 b) { return i64(std::int32_t(a)) * std::int32_t(b); }

// The first pixel column whose centre lies at or right of the edge e0 -> e1, on consecutive
// scanlines (e0.y <= yc < e1.y). Exact: x_edge = e0.x + dx·(yc - e0.y)/dy is compared as a
// fraction, so a centre exactly on an edge is decided the same way by both triangles sharing
// it. Used as the start of a span (left edge: centre on the edge is inside) and as its
// exclusive end (right edge: centre on the edge is outside): that is the top-left rule for
// non-horizontal edges. The column is ceil(N / D) with N = x_edge·dy - 128·dy and D = 256·dy
// (centre 256·x + 128 >= x_edge <=> x >= N / D); from one row to the next N grows by
// 256·dx, so the walk keeps the quotient and remainder and adds that step's quotient and
// remainder: two divisions when the walk starts, none per row, the same columns exactly.
// The column and the step's quotient fit 32 bits (|x_edge| and |dx| stay below 2^29 / 256 and
// 2^29); the remainders, up to 256·dy, need 64.
struct EdgeWalk {  // no default member values: three per piece, zeroing them cost a memset
    std::int32_t column;  // ceil(N / D) on the current row
    std::int32_t step_q;  // 256·dx = step_q·D + step_r, 0 <= step_r < D
    i64 slack;            // column·D - N, in [0, D)
    i64 d;                // D = 256·dy
    i64 step_r;

    // The walk on to the next row: N += step, ceil moves by step_q, and by one more when the
    // slack runs out. Inline (a call per row and edge cost as much as the step).
    void next_row() {
        column += step_q;
        slack -= step_r;
        if (slack < 0) {
            slack += d;
            column += 1;
        }
    }
    // The walk's start on row y (e0.y <= y·256 + 128 < e1.y), out of line.
    SHITSUKAN_RASTER_NOINLINE void start(const ScreenVertex& e0, const ScreenVertex& e1, int y) {
        const i64 dy = e1.y - e0.y, yc = i64(y) * kSubpixel + kHalfPixel;
        d = kSubpixel * dy;
        const i64 n = wide_product(e0.x, dy) + wide_product(e1.x - e0.x, yc - e0.y) -
                      kHalfPixel * dy;
        i64 q, r, sq;
        floor_divmod(n, d, &q, &r);
        column = std::int32_t(r == 0 ? q : q + 1);
        slack = r == 0 ? 0 : d - r;
        floor_divmod(kSubpixel * (e1.x - e0.x), d, &sq, &step_r);
        step_q = std::int32_t(sq);
    }
};

inline Vec3d to_double(Vec3 v) { return {double(v.x), double(v.y), double(v.z)}; }

// Smallest w_clip divided by: 1/w stays finite (FLT_MIN = 2^-126, so 1/w <= 2^126).
constexpr float kMinClipW = std::numeric_limits<float>::min();
// Largest |fixed-point coordinate| accepted (chosen here: 2^28, i.e. 2^20 pixels). Inside the
// guard band a coordinate is at most 4.5·kMaxFrameSize pixels (< 2^17), so this only refuses
// values that went wrong; it keeps every product of the edge tests below 2^60.
constexpr float kMaxFixed = 268435456.0f;

// v·256 rounded half away from zero. false (and nothing stored) for NaN or a value beyond
// kMaxFixed: converting those to an integer would be undefined behaviour.
inline bool to_fixed(float v, std::int32_t* out) {
    float s = v * float(kSubpixel);
    if (!(s > -kMaxFixed && s < kMaxFixed)) return false;
    // |s ± 0.5| < 2^28 + 1: through int32 the same truncation is one FPU conversion (an int64
    // one is libgcc's __aeabi_f2lz, by way of software double: about 100 instructions on a
    // Cortex-M4F, six per triangle).
    *out = std::int32_t(s < 0.0f ? s - 0.5f : s + 0.5f);
    return true;
}

// One square root and one division per vector: this runs twice per fragment. A vector whose
// squared length leaves the normal floats (a model scaled by 1e22 has a normal matrix of
// 1e-22, whose products square to denormals and lose their digits) is first divided by its
// largest component, so that the result still has unit length; zero, NaN and inf give the
// fallback (normalize: false, nothing stored).
inline bool normalize(Vec3 v, Vec3* unit) {
    float l2 = v.x * v.x + v.y * v.y + v.z * v.z;
    if (l2 >= std::numeric_limits<float>::min() && l2 < 3.0e38f) {
        *unit = v * (1.0f / std::sqrt(l2));
        return true;
    }
    if (!(l2 >= 0.0f)) return false;  // NaN
    const float ax = std::fabs(v.x), ay = std::fabs(v.y), az = std::fabs(v.z);
    const float m = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
    if (!(m > 0.0f) || !(m <= std::numeric_limits<float>::max())) return false;
    v = v / m;  // largest component +-1: the squared length lies in [1, 3]
    *unit = v * (1.0f / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z));
    return true;
}
inline Vec3 normalize_or(Vec3 v, Vec3 fallback) {
    Vec3 unit;
    return normalize(v, &unit) ? unit : fallback;
}

// M·(p, 1) without the divide (inline: three of these per triangle).
inline Vec4 transform_homogeneous(const Mat4& m, Vec3 p) {
    return {m.m[0][0] * p.x + m.m[0][1] * p.y + m.m[0][2] * p.z + m.m[0][3],
            m.m[1][0] * p.x + m.m[1][1] * p.y + m.m[1][2] * p.z + m.m[1][3],
            m.m[2][0] * p.x + m.m[2][1] * p.y + m.m[2][2] * p.z + m.m[2][3],
            m.m[3][0] * p.x + m.m[3][1] * p.y + m.m[3][2] * p.z + m.m[3][3]};
}

// transform_point and transform_vector of core/vec, inline (same operations, same bits).
inline Vec3 model_point(const Mat4& m, Vec3 p) {
    Vec4 r = transform_homogeneous(m, p);
    if (r.w != 0.0f && r.w != 1.0f) return {r.x / r.w, r.y / r.w, r.z / r.w};
    return {r.x, r.y, r.z};
}
inline Vec3 model_vector(const Mat4& m, Vec3 v) {
    return {m.m[0][0] * v.x + m.m[0][1] * v.y + m.m[0][2] * v.z,
            m.m[1][0] * v.x + m.m[1][1] * v.y + m.m[1][2] * v.z,
            m.m[2][0] * v.x + m.m[2][1] * v.y + m.m[2][2] * v.z};
}

bool plane_direction(Vec3 e1, Vec3 e2, Vec3* direction);

// The plane's unit normals, object and world, for the vertices whose own normal cannot serve
// (needs_plane[k]: 0 no; 1 for the world normal; 2 for both normals).
void plane_normals(const MeshContext& mc, const int needs_plane[3], SourceTriangle* t) {
    // The direction is nonzero and finite (place_in_world checked it), normalized in float.
    Vec3 direction{0.0f, 0.0f, 1.0f};
    (void)plane_direction(t->v[1].object_position - t->v[0].object_position,
                          t->v[2].object_position - t->v[0].object_position, &direction);
    const Vec3 object_n = normalize_or(direction, Vec3{0.0f, 0.0f, 1.0f});
    const Vec3 world_n = normalize_or(model_vector(*mc.normal_matrix, object_n), object_n);
    for (int k = 0; k < 3; ++k) {
        // 2: the plane's normals (normalising M·object_n again would give world_n).
        if (needs_plane[k] == 2) t->v[k].object_normal = object_n;
        if (needs_plane[k] != 0) t->v[k].normal = world_n;
    }
}

// The differences v[1] - v[0] and v[2] - v[0] that interpolate() reads, attribute by attribute.
void attribute_differences(SourceTriangle* t) {
    for (int k = 0; k < 2; ++k) {
        VertexData& d = k == 0 ? t->dq : t->dr;
        const VertexData& q = t->v[k + 1];
        const VertexData& p = t->v[0];
        d.object_position = q.object_position - p.object_position;
        d.world_position = q.world_position - p.world_position;
        d.normal = q.normal - p.normal;
        d.object_normal = q.object_normal - p.object_normal;
        d.color = q.color - p.color;
        d.uv = q.uv - p.uv;
    }
}

// A vertex's normals: the mesh's, normalised, in object space and (by the normal matrix) in
// world space. Returns which of them the triangle's plane must supply (0 none, 1 the world
// normal, 2 both).
inline int vertex_normals(const MeshContext& mc, std::uint32_t i, Vec3* object_normal,
                          Vec3* normal) {
    const MeshView& mesh = *mc.mesh;
    if (!(mesh.normals && normalize(mesh.normals[i], object_normal))) return 2;
    return normalize(model_vector(*mc.normal_matrix, *object_normal), normal) ? 0 : 1;
}

// The per-vertex attributes of the original triangle: world position, world and object
// normals (the plane's when the mesh has none), uv and colour. The plane's unit normal is
// made only when a vertex needs it (a mesh without normals, or a normal that cannot be
// normalised): a mesh with normals skips its exact cross product.
void prepare(const MeshContext& mc, SourceTriangle* t) {
    const MeshView& mesh = *mc.mesh;
    int needs_plane[3];  // 0: no; 1: for the world normal; 2: for both normals
    for (int k = 0; k < 3; ++k) {
        std::uint32_t i = t->corner_index[k];
        VertexData& v = t->v[k];
        // v.world_position: set by fetch_corners (step 1), the same model_point.
        v.uv = mesh.uvs ? mesh.uvs[i] : Vec2{0, 0};
        v.color = mesh.colors ? mesh.colors[i] : Vec3{1, 1, 1};
        needs_plane[k] = vertex_normals(mc, i, &v.object_normal, &v.normal);
    }
    if (needs_plane[0] + needs_plane[1] + needs_plane[2] > 0) plane_normals(mc, needs_plane, t);
    attribute_differences(t);
    t->flat = mesh.normals == nullptr;
    t->ready = true;
}

// Fills the fragment's surface point from the perspective-correct barycentrics b.
void interpolate(const SourceTriangle& t, Vec3 b, Fragment* f) {
    // a = p·b0 + q·b1 + r·b2 = p + (q - p)·b1 + (r - p)·b2 (b0 + b1 + b2 = 1): one product
    // fewer per component, with the differences made once per triangle (prepare).
    const VertexData& p = t.v[0];
    const VertexData& dq = t.dq;
    const VertexData& dr = t.dr;
    f->object_position = p.object_position + dq.object_position * b.y + dr.object_position * b.z;
    f->world_position = p.world_position + dq.world_position * b.y + dr.world_position * b.z;
    if (t.flat) {  // no vertex normals: the plane's normal, the same over the triangle
        f->normal = p.normal;
        f->object_normal = p.object_normal;
    } else {
        if (!normalize(p.normal + dq.normal * b.y + dr.normal * b.z, &f->normal))
            f->normal = p.normal;
        if (!normalize(p.object_normal + dq.object_normal * b.y + dr.object_normal * b.z,
                       &f->object_normal))
            f->object_normal = p.object_normal;
    }
    f->uv = p.uv + dq.uv * b.y + dr.uv * b.z;
    f->color = p.color + dq.color * b.y + dr.color * b.z;
}

// float(n) for |n| < 2^62, rounded as the conversion rounds, through the FPU's int32
// conversion only (libgcc's __aeabi_l2f would cost 576 bytes of flash on a Cortex-M4F): the top
// 30 bits with a sticky bit for the rest round to 24 bits as n does (core/gaussian.cpp's way).
inline float to_float_via_int32(i64 n) {
    const bool negative = n < 0;
    std::uint64_t u = negative ? 0u - std::uint64_t(n) : std::uint64_t(n);
    int shift = 0;
    while ((u >> shift) >= (std::uint64_t(1) << 30)) ++shift;  // once per piece and band
    std::uint32_t top = std::uint32_t(u >> shift);
    if (shift > 0 && (u & ((std::uint64_t(1) << shift) - 1u)) != 0) top |= 1u;
    const std::uint32_t scale_bits = std::uint32_t(127 + shift) << 23;  // 2^shift, exact
    float scale;
    std::memcpy(&scale, &scale_bits, sizeof scale);
    const float f = float(std::int32_t(top)) * scale;
    return negative ? -f : f;
}

// Twice the signed area of a snapped triangle, in (1/256 pixel)^2. Screen y points down, so
// a counter-clockwise (front) triangle of the world has a negative area here.
SHITSUKAN_RASTER_NOINLINE i64 snapped_area2(const ScreenVertex& a, const ScreenVertex& b,
                                             const ScreenVertex& c) {
    return wide_product(b.x - a.x, c.y - a.y) - wide_product(c.x - a.x, b.y - a.y);
}

// The orientation of the original triangle in homogeneous clip space: det of the rows
// (x, y, w) of its three corners, in double (only clipped triangles get here; double keeps the
// two-float products exact, so the sign holds for slivers whose float determinant would round
// to zero or flip). A piece of the clipped polygon has corners
// B·C (B: their barycentrics, det B > 0 since clipping keeps the order), so its own
// determinant is det B · det C, and with all its w > 0 its screen orientation is the sign of
// det C: one answer for every piece, whatever snapping does to a sliver. Positive = counter-
// clockwise in NDC (y up) = front.
inline double clip_orientation(const ClipSpaceVertex corners[3]) {
    double x0 = corners[0].clip.x, y0 = corners[0].clip.y, w0 = corners[0].clip.w;
    double x1 = corners[1].clip.x, y1 = corners[1].clip.y, w1 = corners[1].clip.w;
    double x2 = corners[2].clip.x, y2 = corners[2].clip.y, w2 = corners[2].clip.w;
    return x0 * (y1 * w2 - y2 * w1) - y0 * (x1 * w2 - x2 * w1) + w0 * (x1 * y2 - x2 * y1);
}

// The corners sorted by y: v0 top, v1 middle, v2 bottom.
SHITSUKAN_RASTER_INLINE void sort_by_y(const ScreenVertex& a, const ScreenVertex& b,
                                       const ScreenVertex& c, const ScreenVertex** v0,
                                       const ScreenVertex** v1, const ScreenVertex** v2) {
    const ScreenVertex* top = &a;
    const ScreenVertex* middle = &b;
    const ScreenVertex* bottom = &c;
    if (middle->y < top->y) std::swap(top, middle);
    if (bottom->y < middle->y) std::swap(middle, bottom);
    if (middle->y < top->y) std::swap(top, middle);
    *v0 = top;
    *v1 = middle;
    *v2 = bottom;
}

// Rasterizes one sub-triangle into the band, with the facing decided for its whole source
// triangle; area2 is its snapped_area2 (the caller has it). Returns true when it touches the
// band's rows.
bool raster_triangle(DrawContext& ctx, SourceTriangle& src, const ScreenVertex& a,
                     const ScreenVertex& b, const ScreenVertex& c, i64 area2, bool front,
                     bool original) {
    const FrameBand& band = *ctx.band;
    if (area2 == 0) return false;  // covers no pixel centre

    const ScreenVertex *v0, *v1, *v2;  // top, middle, bottom
    sort_by_y(a, b, c, &v0, &v1, &v2);

    // Rows whose centre lies in [v0.y, v2.y): the top vertex row is in, the bottom one is
    // out (the top-left rule for horizontal edges), intersected with the band.
    int row_begin = first_centre_from(v0->y);
    int row_end = first_centre_from(v2->y);
    const int band_begin = band.y0, band_end = band.y0 + band.color.height;  // validate_band
    if (row_begin < band_begin) row_begin = band_begin;
    if (row_end > band_end) row_end = band_end;
    if (row_begin >= row_end) return false;
    if (!src.ready) prepare(ctx.mesh, &src);

    // Is the middle vertex right of the long edge v0 -> v2? Then the long edge is the left.
    bool middle_right = wide_product(v1->x - v0->x, v2->y - v0->y) -
                            wide_product(v2->x - v0->x, v1->y - v0->y) >
                        0;

    // Barycentrics around corner a (1/256 pixel units): lambda_b = (p - a) x (c - a) / area,
    // lambda_c = (b - a) x (p - a) / area; float division (differences < 2^29, via int32).
    auto per_area = [f = to_float_via_int32(area2)](i64 d) { return float(std::int32_t(d)) / f; };
    float lb_dx = per_area(c.y - a.y), lb_dy = per_area(a.x - c.x);
    float lc_dx = per_area(a.y - b.y), lc_dy = per_area(b.x - a.x);
    float dz_b = b.z - a.z, dz_c = c.z - a.z;
    // original: the caller knows a, b, c are the source triangle's corners (not clipped).
    const bool unclipped = original || (a.bary == Vec3{1, 0, 0} && b.bary == Vec3{0, 1, 0} &&
                                        c.bary == Vec3{0, 0, 1});

    Fragment& f = ctx.f;
    f.triangle = src.index;
    f.front_facing = front;
    const int width = band.frame_width;
    // Rows [y_begin, y_mid) lie above the middle vertex (short edge v0 -> v1), rows [y_mid,
    // y_end) below it (v1 -> v2): a centre y·256 + 128 < v1.y <=> y < ceil((v1.y - 128) / 256).
    const int y_begin = row_begin, y_end = row_end;
    const int mid = first_centre_from(v1->y);
    const int y_mid = mid < row_begin ? row_begin : (mid > row_end ? row_end : mid);
    EdgeWalk long_edge, short_edge;
    long_edge.start(*v0, *v2, y_begin);
    if (y_mid > y_begin)
        short_edge.start(*v0, *v1, y_begin);
    else
        short_edge.start(*v1, *v2, y_begin);
    for (int y = y_begin; y < y_end; ++y) {
        if (y == y_mid && y != y_begin) short_edge.start(*v1, *v2, y);
        const int x_long = long_edge.column, x_short = short_edge.column;
        long_edge.next_row();
        short_edge.next_row();
        int x_begin = middle_right ? x_long : x_short;
        int x_end = middle_right ? x_short : x_long;
        if (x_begin < 0) x_begin = 0;
        if (x_end > width) x_end = width;
        if (x_begin >= x_end) continue;

        int band_row = y - band.y0;
        Rgb8* color_row = band.color.row(band_row);
        float* depth_row = band.depth.row(band_row);
        // |yc - a.y| and |256·x + 128 - a.x| stay below 2^29 (coordinates below kMaxFixed =
        // 2^28): in int32 (the latter stepped by 256 per pixel), converted by the FPU (an int64
        // one is libgcc's __aeabi_l2f per pixel on a Cortex-M4F): the same integers and floats.
        float ry = float(std::int32_t(i64(y) * kSubpixel + kHalfPixel - a.y));
        float lb_row = ry * lb_dy, lc_row = ry * lc_dy;
        f.y = y;
        std::int32_t rx_fixed = std::int32_t(i64(x_begin) * kSubpixel + kHalfPixel - a.x);
        for (int x = x_begin; x < x_end; ++x, rx_fixed += std::int32_t(kSubpixel)) {
            float rx = float(rx_fixed);
            float lb = lb_row + rx * lb_dx;  // screen-space (affine) barycentrics
            float lc = lc_row + rx * lc_dx;
            float la = 1.0f - lb - lc;
            // Depth z_ndc is affine in screen space: interpolate it linearly.
            float z = a.z + lb * dz_b + lc * dz_c;
            if (!(z < depth_row[x]) || z > 1.0f) continue;  // early z (and the far plane)
            // Perspective-correct: interpolate bary / w linearly, divide by the 1 / w sum.
            float qa = la * a.inv_w, qb = lb * b.inv_w, qc = lc * c.inv_w;
            float inv_sum = 1.0f / (qa + qb + qc);
            // An unclipped triangle's corners are the original ones, bary (1,0,0), (0,1,0),
            // (0,0,1): the general sum below then reduces exactly (same bits) to (qa, qb, qc).
            Vec3 bary = unclipped ? Vec3{qa, qb, qc} * inv_sum
                                  : (a.bary * qa + b.bary * qb + c.bary * qc) * inv_sum;
            interpolate(src, bary, &f);
            f.x = int(x);
            f.depth = z < 0.0f ? 0.0f : z;
            color_row[x] = ctx.shader(f, ctx.user);
            depth_row[x] = f.depth;
            ++ctx.fragments;
        }
    }
    return true;
}

inline bool finite_clip(Vec4 p) {
    return is_finite(p.x) && is_finite(p.y) && is_finite(p.z) && is_finite(p.w);
}

// The divide and the viewport mapping, as clip_to_screen (camera.cpp) does it, keeping 1/w.
// false when the corner cannot be mapped: w below kMinClipW (at or behind the eye: only a
// vertex on the eye plane or a custom projection gets here) or a screen position out of
// range.
bool to_screen(const Camera& camera, const ClipSpaceVertex& v, ScreenVertex* r) {
    if (!(v.clip.w >= kMinClipW)) return false;
    float inv_w = 1.0f / v.clip.w;
    float nx = v.clip.x * inv_w, ny = v.clip.y * inv_w, nz = v.clip.z * inv_w;
    if (!to_fixed((nx * 0.5f + 0.5f) * float(camera.width), &r->x) ||
        !to_fixed((0.5f - ny * 0.5f) * float(camera.height), &r->y))
        return false;
    r->z = nz * 0.5f + 0.5f;
    r->inv_w = inv_w;
    r->bary = v.bary;
    return true;
}

// a·b = hi + lo exactly (Dekker's product with Veltkamp's split, float only: not every FPU
// has a fused multiply-add), for |a|, |b| in {0} U [2^-50, 2^60] (no overflow in the
// split, no underflow in lo).
inline float two_product(float a, float b, float* lo) {
    auto split = [](float v, float* high) {
        const float c = 4097.0f * v;  // 2^12 + 1
        *high = c - (c - v);
        return v - *high;  // the low half
    };
    float ah, bh;
    const float al = split(a, &ah), bl = split(b, &bh);
    const float hi = a * b;
    *lo = ((ah * bh - hi) + ah * bl + al * bh) + al * bl;
    return hi;
}

// u·v - w·z, exactly zero when it is zero, else its float to within about an ulp: both
// products exact as hi + lo, their difference summed from the exact two-sum of the his.
inline float cross_component(float u, float v, float w, float z, bool* zero) {
    float lo1, lo2;
    const float hi1 = two_product(u, v, &lo1), hi2 = two_product(w, z, &lo2);
    *zero = hi1 == hi2 && lo1 == lo2;  // the rounded products agree iff the exact ones do
    const float d = hi1 - hi2, bv = d - hi1;
    const float e = (hi1 - (d - bv)) + (-hi2 - bv);  // d + e = hi1 - hi2 exactly
    return d + (e + (lo1 - lo2));
}

inline bool in_exact_product_range(float v) {
    const float a = std::fabs(v);
    return a == 0.0f || (a >= 0x1p-50f && a <= 0x1p60f);
}

// The plane's direction (p1 - p0) x (p2 - p0), and whether it is zero (degenerate), with
// every product exact: in float as hi + lo pairs when the edges' components allow it (the
// common case), else in double, where products of two floats are exact (a huge or tiny
// mesh; scaled by a power of two into float range there). Exact products keep a sliver's
// normal from cancelling and make "nonzero" a reliable test. (Was always double: about
// 1,000 instructions per triangle and band in software on a Cortex-M4F.) false: zero (or not
// finite), nothing stored.
bool plane_direction(Vec3 e1, Vec3 e2, Vec3* direction) {
    if (in_exact_product_range(e1.x) && in_exact_product_range(e1.y) &&
        in_exact_product_range(e1.z) && in_exact_product_range(e2.x) &&
        in_exact_product_range(e2.y) && in_exact_product_range(e2.z)) {
        bool zx, zy, zz;
        const Vec3 d{cross_component(e1.y, e2.z, e1.z, e2.y, &zx),
                     cross_component(e1.z, e2.x, e1.x, e2.z, &zy),
                     cross_component(e1.x, e2.y, e1.y, e2.x, &zz)};
        if (zx && zy && zz) return false;
        *direction = d;
        return true;
    }
    const Vec3d c = cross(to_double(e1), to_double(e2));
    const double ax = std::fabs(c.x), ay = std::fabs(c.y), az = std::fabs(c.z);
    const double m = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
    if (!(m > 0.0 && is_finite(m))) return false;
    // c·2^-e with m = f·2^e, f in [0.5, 1) (frexp's e), the power of two built from m's
    // exponent bits: m is a normal double (products of floats lie in [2^-298, 2^256]), and
    // frexp/ldexp/scalbn would be about 480 bytes of flash on a microcontroller.
    std::uint64_t bits;
    std::memcpy(&bits, &m, sizeof bits);
    const int e = int((bits >> 52) & 0x7ffu) - 1022;
    const std::uint64_t scale_bits = std::uint64_t(1023 - e) << 52;
    double scale;
    std::memcpy(&scale, &scale_bits, sizeof scale);
    *direction = to_float(c * scale);  // largest in [0.5, 1)
    return true;
}

// is_finite of every component of a and b, as one test: 0·v is 0 for a finite v and NaN for
// inf or NaN, and a sum of zeros is 0 (inline, no call per vector: it runs for every triangle
// of every band).
inline bool all_finite(Vec3 a, Vec3 b) {
    return (a.x * 0.0f + a.y * 0.0f + a.z * 0.0f) + (b.x * 0.0f + b.y * 0.0f + b.z * 0.0f) == 0.0f;
}

// Whether plane_direction finds the plane nonzero, mostly without its exact products:
// rounding is monotonic, so when the rounded products of a component, u·v and w·z, differ
// (neither NaN), the exact ones differ too and that component is nonzero. Only a triangle
// whose rounded products all agree (degenerate, or nearly) takes the exact test.
inline bool plane_is_nonzero(Vec3 e1, Vec3 e2) {
    auto differ = [](float a, float b) { return a < b || a > b; };
    if (all_finite(e1, e2) &&
        (differ(e1.y * e2.z, e1.z * e2.y) || differ(e1.z * e2.x, e1.x * e2.z) ||
         differ(e1.x * e2.y, e1.y * e2.x)))
        return true;
    Vec3 unused;
    return plane_direction(e1, e2, &unused);
}

// Whether a triangle whose object and world positions are in src has a plane and a place in
// the world. A projective model can send a corner to w ~ 0: world positions (and the
// differences the fragments interpolate) overflow to inf and NaN (fuzz_raster finding). Such a
// triangle has no place in the world: rejected like a degenerate one (false).
inline bool in_world(const SourceTriangle& src) {
    const Vec3 e1 = src.v[1].object_position - src.v[0].object_position;
    const Vec3 e2 = src.v[2].object_position - src.v[0].object_position;
    const bool has_plane = plane_is_nonzero(e1, e2);
    const Vec3 w0 = src.v[0].world_position;
    return has_plane && all_finite(w0, w0) &&
           all_finite(src.v[1].world_position - w0, src.v[2].world_position - w0);
}

// The rest of step 1 once the object positions are in src: the world positions, then the plane
// test (in_world). The world positions are kept for prepare(), which would otherwise compute
// them again.
bool place_in_world(const Mat4& model, SourceTriangle* src) {
    for (int k = 0; k < 3; ++k)
        src->v[k].world_position = model_point(model, src->v[k].object_position);
    return in_world(*src);
}

// ---- 1. Fetch the three corners, into clip space ----
// false for a degenerate triangle (zero area, NaN/inf corner). The plane normal stays in
// double (once per triangle): products of two floats are exact there, so the cross product of
// a sliver is rounded once instead of cancelling, no finite mesh overflows or underflows it,
// and cross2 > 0 is a reliable degeneracy test.
bool fetch_corners(const MeshView& mesh, const Mat4& model, const Mat4& mvp, int t,
                   SourceTriangle* src, ClipSpaceVertex corners[3]) {
    src->index = t;
    src->corner_index = mesh.indices + 3 * std::size_t(t);  // no int overflow
    bool finite = true;
    for (int k = 0; k < 3; ++k) {
        Vec3 p = mesh.positions[src->corner_index[k]];
        finite = finite && is_finite(p);
        src->v[k].object_position = p;
        corners[k].clip = transform_homogeneous(mvp, p);
        corners[k].bary = Vec3{k == 0 ? 1.0f : 0.0f, k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f};
    }
    const bool placed = place_in_world(model, src);
    return finite && placed;
}

enum class Projected { drawable, outside, rejected };

// ---- 2. Clip in homogeneous space (most triangles need not: outcodes tell) ----
// ---- 3. Divide and snap each corner of the (clipped) polygon ----
Projected clip_and_snap(const Camera& camera, const ClipSpaceVertex corners[3],
                        ScreenVertex s[kMaxClipVertices], int* count, bool* clipped,
                        RasterStats* local) {
    *clipped = false;  // went through clip_triangle (near plane or guard band)
    unsigned c0 = clip_outcode(corners[0].clip), c1 = clip_outcode(corners[1].clip),
             c2 = clip_outcode(corners[2].clip);
    if (c0 & c1 & c2 & kOutsideBits) return Projected::outside;  // beyond one side of the view
    // The fast path needs every corner strictly in front of the eye (w >= kMinClipW), not
    // only inside the clip planes: a corner with w == 0 (at the eye) has outcode 0 when
    // x = y = 0, and dividing by it would give NaN.
    bool fast = ((c0 | c1 | c2) & kClipPlaneBits) == 0;
    for (int k = 0; k < 3 && fast; ++k)
        fast = finite_clip(corners[k].clip) && corners[k].clip.w >= kMinClipW;
    bool usable = true;
    if (fast) {
        for (int k = 0; k < 3; ++k) usable = to_screen(camera, corners[k], &s[k]) && usable;
        *count = 3;
    } else {
        ClipPolygon poly;
        ClipResult clip = clip_triangle(corners, &poly);
        if (clip.not_finite) return Projected::rejected;
        if (clip.outside) return Projected::outside;
        if (clip.clipped_near) ++local->triangles_clipped;
        *clipped = true;
        // After near clipping w > 0 for the cameras this library makes; a corner on the eye
        // plane (w == 0, e.g. through a projective model matrix) or a custom projection can
        // still give w <= 0: such a triangle cannot be drawn (its plane passes through the
        // eye, or it wraps around behind it).
        for (int k = 0; k < poly.count; ++k) usable = to_screen(camera, poly.v[k], &s[k]) && usable;
        *count = poly.count;
    }
    return usable ? Projected::drawable : Projected::rejected;
}

// ---- 4. Decide the facing once for the whole triangle ----
// Unclipped: the sign of the snapped area, so that the snapped triangles of a closed mesh
// still pair up exactly (as many front as back ones over every pixel). Clipped: the
// clip-space orientation, which all pieces share (a sliver's snapped area may flip sign),
// or failing that (edge-on) the whole polygon's snapped area. false: it covers nothing.
bool decide_facing(bool clipped, const ClipSpaceVertex corners[3], const ScreenVertex* s, int count,
                   bool* front) {
    if (!clipped) {
        i64 area2 = snapped_area2(s[0], s[1], s[2]);
        *front = area2 < 0;
        return area2 != 0;
    }
    double orientation = clip_orientation(corners);
    if (orientation == 0.0) {
        i64 area2 = 0;
        for (int k = 1; k + 1 < count; ++k) area2 += snapped_area2(s[0], s[k], s[k + 1]);
        if (area2 == 0) return false;
        orientation = area2 < 0 ? 1.0 : -1.0;
    }
    *front = orientation > 0.0;
    return true;
}

void add_stats(const RasterStats& local, long fragments, RasterStats* stats) {
    if (!stats) return;
    stats->triangles_in += local.triangles_in;
    stats->triangles_drawn += local.triangles_drawn;
    stats->triangles_clipped += local.triangles_clipped;
    stats->triangles_rejected += local.triangles_rejected;
    stats->fragments_shaded += fragments;
}


// ---- Binning: which rows a triangle can touch, decided once per frame ----
// Steps 1-4 for the common case only (every corner in front of the eye and inside the guard
// band: no clipping), from the same clip-space corners, the same divide and the same snapping
// as draw_mesh, so the rows are those raster_triangle would walk. A triangle that needs
// clipping keeps every row (the band pass decides); one that cannot be drawn (outside one
// side of the view, a corner that cannot be mapped, zero snapped area, culled) gets none.
// Flattened (its helpers inlined into it, in this function only): it runs for every triangle of
// the frame, and the calls cost as much as the arithmetic (bin_mesh alone was 870 instructions
// per triangle of the 48 x 24 UV sphere on a Cortex-M4F).
TriangleRows rows_of(const Camera& camera, CullMode cull, i64 area2, std::int32_t y0,
                     std::int32_t y1, std::int32_t y2);

SHITSUKAN_RASTER_FLATTEN
TriangleRows bin_triangle(const Camera& camera, const MeshView& mesh, const Mat4& mvp,
                          CullMode cull, int t, ClipSpaceVertex corners[3]) {
    const TriangleRows all{0, std::uint16_t(camera.height)}, none{0, 0};
    const std::uint32_t* index = mesh.indices + 3 * std::size_t(t);
    unsigned outcodes = 0, outside = kOutsideBits;
    for (int k = 0; k < 3; ++k) {
        const Vec3 p = mesh.positions[index[k]];
        if (!is_finite(p)) return none;  // fetch_corners rejects it
        corners[k].clip = transform_homogeneous(mvp, p);
        corners[k].bary = Vec3{0, 0, 0};
        const unsigned c = clip_outcode(corners[k].clip);
        outcodes |= c;
        outside &= c;
    }
    if (outside != 0) return none;  // beyond one side of the view
    if ((outcodes & kClipPlaneBits) != 0) return all;
    ScreenVertex s[3];  // no default member values: not zeroed
    for (int k = 0; k < 3; ++k) {
        if (!finite_clip(corners[k].clip) || !(corners[k].clip.w >= kMinClipW)) return all;
        if (!to_screen(camera, corners[k], &s[k])) return none;  // rejected
    }
    return rows_of(camera, cull, snapped_area2(s[0], s[1], s[2]), s[0].y, s[1].y, s[2].y);
}

// The rows of a triangle drawn without clipping, from its snapped area (twice, signed) and
// the rows of its corners (none: zero area or culled).
TriangleRows rows_of(const Camera& camera, CullMode cull, i64 area2, std::int32_t y0,
                     std::int32_t y1, std::int32_t y2) {
    const TriangleRows none{0, 0};
    const bool front = area2 < 0;
    if (area2 == 0 || (cull == CullMode::back && !front) || (cull == CullMode::front && front))
        return none;
    const std::int32_t top = y0 < y1 ? (y0 < y2 ? y0 : y2) : (y1 < y2 ? y1 : y2);
    const std::int32_t bottom = y0 > y1 ? (y0 > y2 ? y0 : y2) : (y1 > y2 ? y1 : y2);
    int begin = first_centre_from(top), end = first_centre_from(bottom);
    if (begin < 0) begin = 0;
    if (end > camera.height) end = camera.height;
    if (begin >= end) return none;
    return TriangleRows{std::uint16_t(begin), std::uint16_t(end)};
}

// A binned-away triangle (end 0) keeps in begin the number of binned-away triangles from it
// on (at most 65,535), so that a band's walk steps over a run of them at once: the triangles
// of a mesh that face away come in long runs (the 48 x 24 UV sphere's 1,342 in 27).
void count_empty_runs(TriangleRows* rows, int n) {
    unsigned run = 0;
    for (int t = n - 1; t >= 0; --t) {
        run = rows[t].end == 0 ? (run < 65535u ? run + 1u : 65535u) : 0u;
        if (rows[t].end == 0) rows[t].begin = std::uint16_t(run);
    }
}

// ---- Binning with the vertices kept: each vertex transformed, divided and snapped once ----
constexpr std::int32_t kUnmapped = std::numeric_limits<std::int32_t>::min();  // never snapped
constexpr std::uint8_t kNormalsNotMade = 0xff;  // BinnedVertex::normals: no triangle needs them

// A vertex's clip-space outcode and, when a triangle of it could take the fast path there
// (finite, inside the guard band and the near plane, w >= kMinClipW, mappable), its screen
// position: the values clip_and_snap's to_screen gives. Else x = kUnmapped.
SHITSUKAN_RASTER_FLATTEN
void bin_vertex(const Camera& camera, const Mat4& mvp, Vec3 p, BinnedVertex* v) {
    v->x = kUnmapped;
    v->outcode = 0;
    v->normals = kNormalsNotMade;
    if (!is_finite(p)) return;
    const ClipSpaceVertex c{transform_homogeneous(mvp, p), Vec3{0, 0, 0}};
    const unsigned outcode = clip_outcode(c.clip);
    static_assert((kClipPlaneBits | kOutsideBits) <= 0xffffu,
                  "BinnedVertex::outcode (16 bits) holds every outcode bit");
    v->outcode = std::uint16_t(outcode);  // kClipPlaneBits | kOutsideBits: 11 bits
    ScreenVertex screen;  // no default member values: not zeroed
    if ((outcode & kClipPlaneBits) != 0 || !finite_clip(c.clip) || !(c.clip.w >= kMinClipW) ||
        !to_screen(camera, c, &screen))
        return;
    v->x = screen.x;
    v->y = screen.y;
    v->z = screen.z;
    v->inv_w = screen.inv_w;
}

// The world position and normals of a vertex that a drawable triangle uses (normals: which of
// them the plane supplies), the values prepare() and place_in_world() make for each corner.
void bin_vertex_attributes(const MeshContext& mc, std::uint32_t i, BinnedVertex* v) {
    const Vec3 w = model_point(*mc.model, mc.mesh->positions[i]);
    v->world_position = w;
    const float bound = 0x1p126f;  // |a - b| <= 2^127 < FLT_MAX for two such values
    v->near_world = std::fabs(w.x) <= bound && std::fabs(w.y) <= bound && std::fabs(w.z) <= bound;
    v->normals = std::uint8_t(vertex_normals(mc, i, &v->object_normal, &v->normal));
}

// The screen corner of a kept vertex. Its barycentrics are not set: raster_triangle reads them
// only for a piece of a clipped triangle.
inline void kept_corner(const BinnedVertex& v, ScreenVertex* s) {
    s->x = v.x;
    s->y = v.y;
    s->z = v.z;
    s->inv_w = v.inv_w;
}

// bin_triangle from the kept vertices (a vertex left unmapped: bin_triangle itself).
// A triangle drawn from its kept vertices marks them: their attributes are made (bin_mesh).
TriangleRows bin_kept_triangle(const Camera& camera, const MeshView& mesh, const Mat4& mvp,
                               CullMode cull, int t, BinnedVertex* vertices,
                               ClipSpaceVertex corners[3]) {
    const std::uint32_t* index = mesh.indices + 3 * std::size_t(t);
    BinnedVertex &a = vertices[index[0]], &b = vertices[index[1]], &c = vertices[index[2]];
    if (a.x == kUnmapped || b.x == kUnmapped || c.x == kUnmapped)
        return bin_triangle(camera, mesh, mvp, cull, t, corners);
    if ((a.outcode & b.outcode & c.outcode & kOutsideBits) != 0) return TriangleRows{0, 0};
    // snapped_area2 of the kept corners, in the same 64-bit integers
    const i64 area2 = wide_product(b.x - a.x, c.y - a.y) - wide_product(c.x - a.x, b.y - a.y);
    const TriangleRows rows = rows_of(camera, cull, area2, a.y, b.y, c.y);
    if (rows.end != 0) a.normals = b.normals = c.normals = 0;
    return rows;
}

// q - p and r - p of one attribute, into the differences, and p into the first vertex.
template <class V>
inline void differences(V p, V q, V r, V* first, V* dq, V* dr) {
    *first = p;
    *dq = q - p;
    *dr = r - p;
}

// prepare() from the kept vertices: their world positions (already in src) and normals, the
// plane's where a vertex asks for it. Without the plane the differences are made straight from
// the kept vertices and the mesh's arrays (the same subtractions as attribute_differences).
// p0, e1, e2: the first object position and the edges from it (draw_kept_triangle made them).
void prepare_kept(const MeshContext& mc, const BinnedVertex* const kept[3], Vec3 p0, Vec3 e1,
                  Vec3 e2, SourceTriangle* t) {
    const MeshView& mesh = *mc.mesh;
    const std::uint32_t* i = t->corner_index;
    t->flat = mesh.normals == nullptr;
    t->ready = true;
    VertexData& p = t->v[0];
    if (mesh.uvs)
        differences(mesh.uvs[i[0]], mesh.uvs[i[1]], mesh.uvs[i[2]], &p.uv, &t->dq.uv, &t->dr.uv);
    else
        differences(Vec2{0, 0}, Vec2{0, 0}, Vec2{0, 0}, &p.uv, &t->dq.uv, &t->dr.uv);
    const Vec3 white{1, 1, 1};
    if (mesh.colors)
        differences(mesh.colors[i[0]], mesh.colors[i[1]], mesh.colors[i[2]], &p.color,
                    &t->dq.color, &t->dr.color);
    else
        differences(white, white, white, &p.color, &t->dq.color, &t->dr.color);
    p.object_position = p0;
    t->dq.object_position = e1;
    t->dr.object_position = e2;
    differences(kept[0]->world_position, kept[1]->world_position, kept[2]->world_position,
                &p.world_position, &t->dq.world_position, &t->dr.world_position);
    const int needs_plane[3] = {kept[0]->normals, kept[1]->normals, kept[2]->normals};
    if (needs_plane[0] + needs_plane[1] + needs_plane[2] == 0) {
        differences(kept[0]->normal, kept[1]->normal, kept[2]->normal, &p.normal, &t->dq.normal,
                    &t->dr.normal);
        differences(kept[0]->object_normal, kept[1]->object_normal, kept[2]->object_normal,
                    &p.object_normal, &t->dq.object_normal, &t->dr.object_normal);
        return;
    }
    for (int k = 0; k < 3; ++k) {
        t->v[k].object_position = mesh.positions[i[k]];  // plane_normals' edges, as prepare's
        t->v[k].object_normal = kept[k]->object_normal;
        t->v[k].normal = kept[k]->normal;
    }
    plane_normals(mc, needs_plane, t);
    differences(t->v[0].normal, t->v[1].normal, t->v[2].normal, &p.normal, &t->dq.normal,
                &t->dr.normal);
    differences(t->v[0].object_normal, t->v[1].object_normal, t->v[2].object_normal,
                &p.object_normal, &t->dq.object_normal, &t->dr.object_normal);
}

// Steps 1-5 for a handed triangle whose three vertices bin_mesh kept: the object positions and
// the kept world positions, the plane test (in_world), the kept screen positions and normals
// instead of transforming, testing, dividing and normalising the corners again. false: a vertex
// was not kept (the general path then draws the triangle).
bool draw_kept_triangle(DrawContext& ctx, SourceTriangle* src, const BinnedVertex* vertices,
                        int t, RasterStats* local) {
    const CullMode cull = ctx.cull;
    const MeshView& mesh = *ctx.mesh.mesh;
    const std::uint32_t* index = mesh.indices + 3 * std::size_t(t);
    const BinnedVertex* const kept[3] = {&vertices[index[0]], &vertices[index[1]],
                                         &vertices[index[2]]};
    const BinnedVertex &a = *kept[0], &b = *kept[1], &c = *kept[2];
    if (a.x == kUnmapped || b.x == kUnmapped || c.x == kUnmapped ||
        a.normals == kNormalsNotMade || b.normals == kNormalsNotMade ||
        c.normals == kNormalsNotMade)
        return false;
    src->index = t;
    src->corner_index = index;
    const Vec3 p0 = mesh.positions[index[0]];
    const Vec3 e1 = mesh.positions[index[1]] - p0, e2 = mesh.positions[index[2]] - p0;
    // in_world: with every world position within +-2^126 their differences are finite, and
    // only the plane is left to test.
    bool placed;
    if (a.near_world && b.near_world && c.near_world) {
        placed = plane_is_nonzero(e1, e2);
    } else {
        for (int k = 0; k < 3; ++k) {
            src->v[k].object_position = mesh.positions[index[k]];
            src->v[k].world_position = kept[k]->world_position;
        }
        placed = in_world(*src);
    }
    if (!placed) {
        ++local->triangles_rejected;
        return true;
    }
    if ((a.outcode & b.outcode & c.outcode & kOutsideBits) != 0) return true;
    ScreenVertex s[3];  // no default member values: not zeroed
    for (int k = 0; k < 3; ++k) kept_corner(*kept[k], &s[k]);
    const i64 area2 = snapped_area2(s[0], s[1], s[2]);  // decide_facing, unclipped
    const bool front = area2 < 0;
    if (area2 == 0 || (cull == CullMode::back && !front) || (cull == CullMode::front && front))
        return true;
    // Its rows meet the band (bin_mesh's rows_of gave them): raster_triangle would prepare it.
    prepare_kept(ctx.mesh, kept, p0, e1, e2, src);
    if (raster_triangle(ctx, *src, s[0], s[1], s[2], area2, front, true))
        ++local->triangles_drawn;
    return true;
}

// binned: the mesh's indices were checked by bin_mesh, and each triangle handed to the band is
// checked again before it is read (in_range_indices): every index of the mesh once per band
// was 190 instructions per triangle of the frame on a Cortex-M4F.
Status check_draw_inputs(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                         const DrawOptions& options, FragmentShader shader, bool binned,
                         Mat4* normal_matrix) {
    if (shader == nullptr)
        return Status::error(StatusCode::invalid_argument, "draw_mesh: the shader is null");
    SHITSUKAN_TRY(validate_camera(camera));
    SHITSUKAN_TRY(validate_band(camera, band));
    SHITSUKAN_TRY(binned ? validate_mesh_arrays(mesh) : validate_mesh(mesh));
    return validate_model(options.model, *normal_matrix);
}

// The first triangle from t on whose rows meet the band [band_begin, band_end) (n when none):
// a loop of its own, so that the walk over a band's binned-away
// triangles (most of the mesh) keeps its few values in registers (22 instructions per
// triangle and band on a Cortex-M4F inside draw_mesh_rows' loop). A run of binned-away
// triangles is stepped over at once (count_empty_runs).
SHITSUKAN_RASTER_NOINLINE int next_in_band(const TriangleRows* rows, int t, int n, int band_begin,
                                           int band_end) {
    while (t < n) {
        const TriangleRows r = rows[t];
        if (r.end == 0) {  // binned away from every band (most of a mesh: culled)
            t += r.begin > 1 ? int(r.begin) : 1;
            continue;
        }
        if (r.end > band_begin && r.begin < band_end && r.begin < r.end) return t;
        ++t;
    }
    return n;
}

inline bool in_range_indices(const MeshView& mesh, int t) {
    const std::uint32_t* index = mesh.indices + 3 * std::size_t(t);
    const std::uint32_t n = std::uint32_t(mesh.vertex_count);
    return index[0] < n && index[1] < n && index[2] < n;
}

// Steps 1-5 for triangle t of the mesh.
void draw_triangle(DrawContext& ctx, SourceTriangle* src, const Camera& camera, const Mat4& mvp,
                   int t, RasterStats* local) {
    const MeshView& mesh = *ctx.mesh.mesh;
    ClipSpaceVertex corners[3];
    if (!fetch_corners(mesh, *ctx.mesh.model, mvp, t, src, corners)) {
        ++local->triangles_rejected;
        return;
    }
    ScreenVertex s[kMaxClipVertices];
    int count = 0;
    bool clipped = false, front = false;
    Projected projected = clip_and_snap(camera, corners, s, &count, &clipped, local);
    if (projected == Projected::rejected) ++local->triangles_rejected;
    if (projected != Projected::drawable) return;
    if (!decide_facing(clipped, corners, s, count, &front)) return;
    const CullMode cull = ctx.cull;
    if ((cull == CullMode::back && !front) || (cull == CullMode::front && front)) return;
    // ---- 5. Walk each piece of the fan ----
    bool drawn = false;
    for (int k = 1; k + 1 < count; ++k)
        drawn = raster_triangle(ctx, *src, s[0], s[k], s[k + 1],
                                snapped_area2(s[0], s[k], s[k + 1]), front, !clipped) ||
                drawn;
    if (drawn) ++local->triangles_drawn;
}

// draw_mesh (kBinned false: every triangle) and draw_binned_mesh (the triangles whose rows meet
// the band; with the vertices bin_mesh kept when vertices is not null). A template, so that
// draw_mesh's code carries none of the binned paths.
template <bool kBinned>
Status draw_mesh_rows(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                      const DrawOptions& options, const TriangleRows* rows,
                      const BinnedVertex* vertices, FragmentShader shader, void* user,
                      RasterStats* stats) {
    // ---- Check everything before drawing anything ----
    Mat4 normal_matrix;
    SHITSUKAN_TRY(check_draw_inputs(camera, band, mesh, options, shader, kBinned, &normal_matrix));

    const Mat4 mvp = camera.projection * (camera.view * options.model);
    DrawContext ctx{{&mesh, &options.model, &normal_matrix}, &band, shader, user, options.cull,
                    0, Fragment{}};
    RasterStats local;
    const int band_begin = band.y0, band_end = band.y0 + band.color.height;
    SourceTriangle src;  // one, reused: fetch_corners and prepare write what is read

    const int n = mesh.triangle_count;
    for (int t = kBinned ? next_in_band(rows, 0, n, band_begin, band_end) : 0; t < n;
         t = kBinned ? next_in_band(rows, t + 1, n, band_begin, band_end) : t + 1) {
        if constexpr (kBinned) {
            if (!in_range_indices(mesh, t))
                return Status::error(StatusCode::invalid_argument,
                                     "draw_binned_mesh: triangle %d: index out of range", t);
        }
        ++local.triangles_in;
        src.ready = false;
        if constexpr (kBinned) {
            if (vertices != nullptr && draw_kept_triangle(ctx, &src, vertices, t, &local))
                continue;
        }
        draw_triangle(ctx, &src, camera, mvp, t, &local);
    }
    add_stats(local, ctx.fragments, stats);
    return Status::success();
}

}  // namespace

Status bin_mesh(const Camera& camera, const MeshView& mesh, const DrawOptions& options,
                TriangleRows* rows, int capacity, BinnedVertex* vertices, int vertex_capacity) {
    SHITSUKAN_TRY(validate_camera(camera));
    SHITSUKAN_TRY(validate_mesh(mesh));
    Mat4 normal_matrix;
    SHITSUKAN_TRY(validate_model(options.model, normal_matrix));
    if (rows == nullptr || capacity < mesh.triangle_count)
        return Status::error(StatusCode::invalid_argument,
                             "bin_mesh: room for %d triangles' rows, the mesh has %d",
                             rows == nullptr ? 0 : capacity, mesh.triangle_count);
    if (vertices != nullptr && vertex_capacity < mesh.vertex_count)
        return Status::error(StatusCode::invalid_argument,
                             "bin_mesh: room for %d vertices, the mesh has %d", vertex_capacity,
                             mesh.vertex_count);
    const Mat4 mvp = camera.projection * (camera.view * options.model);
    ClipSpaceVertex corners[3];  // scratch, not zeroed per triangle
    if (vertices == nullptr) {
        for (int t = 0; t < mesh.triangle_count; ++t)
            rows[t] = bin_triangle(camera, mesh, mvp, options.cull, t, corners);
        count_empty_runs(rows, mesh.triangle_count);
        return Status::success();
    }
    for (int i = 0; i < mesh.vertex_count; ++i)
        bin_vertex(camera, mvp, mesh.positions[i], &vertices[i]);
    for (int t = 0; t < mesh.triangle_count; ++t)
        rows[t] = bin_kept_triangle(camera, mesh, mvp, options.cull, t, vertices, corners);
    const MeshContext mc{&mesh, &options.model, &normal_matrix};
    for (int i = 0; i < mesh.vertex_count; ++i)
        if (vertices[i].normals != kNormalsNotMade)
            bin_vertex_attributes(mc, std::uint32_t(i), &vertices[i]);
    count_empty_runs(rows, mesh.triangle_count);
    return Status::success();
}

Status bin_mesh(const Camera& camera, const MeshView& mesh, const DrawOptions& options,
                TriangleRows* rows, int capacity) {
    return bin_mesh(camera, mesh, options, rows, capacity, nullptr, 0);
}

Status draw_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                 const DrawOptions& options, FragmentShader shader, void* user,
                 RasterStats* stats) {
    return draw_mesh_rows<false>(camera, band, mesh, options, nullptr, nullptr, shader, user,
                                 stats);
}

Status draw_binned_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                        const DrawOptions& options, const TriangleRows* rows, int capacity,
                        FragmentShader shader, void* user, RasterStats* stats) {
    if (rows == nullptr || capacity < mesh.triangle_count)
        return Status::error(StatusCode::invalid_argument,
                             "draw_binned_mesh: rows for %d triangles, the mesh has %d (bin_mesh "
                             "fills them)",
                             rows == nullptr ? 0 : capacity, mesh.triangle_count);
    return draw_mesh_rows<true>(camera, band, mesh, options, rows, nullptr, shader, user, stats);
}

Status draw_binned_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                        const DrawOptions& options, const TriangleRows* rows, int capacity,
                        const BinnedVertex* vertices, int vertex_capacity, FragmentShader shader,
                        void* user, RasterStats* stats) {
    if (vertices == nullptr || vertex_capacity < mesh.vertex_count)
        return Status::error(StatusCode::invalid_argument,
                             "draw_binned_mesh: kept vertices for %d, the mesh has %d (bin_mesh "
                             "fills them)",
                             vertices == nullptr ? 0 : vertex_capacity, mesh.vertex_count);
    if (rows == nullptr || capacity < mesh.triangle_count)
        return draw_binned_mesh(camera, band, mesh, options, rows, capacity, shader, user, stats);
    return draw_mesh_rows<true>(camera, band, mesh, options, rows, vertices, shader, user, stats);
}

}  // namespace shitsukan
