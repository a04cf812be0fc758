#include "shitsukan/leather/maps.hpp"

#include <algorithm>
#include <cmath>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/leather/scale_labels.hpp"
#include "shitsukan/leather/tileable.hpp"

namespace shitsukan {

namespace {

// The largest height the relief can reach: |z| <= the section's largest |control point z|
// (a Bezier curve lies in its control polygon's hull), times S / edge_r · height_scale
// (relief.hpp step 3), S the largest scale size. Past kMaxReliefHeight the heights (and the
// 16-bit encoding's unit) would overflow a float: fuzz_maps found edge_r = 3.5e-43 giving
// infinite heights, and NaN with height_scale = 0, under an ok Status.
Status check_height_range(const ScalePattern& pattern, const BezierChain& section,
                          const ReliefOptions& options) {
    double z = 0.0, size = 0.0;
    for (int k = 0; k < section.count; ++k)
        for (const Vec2& p : section.segments[k].p) z = std::fabs(p.y) > z ? std::fabs(p.y) : z;
    for (int i = 0; i < pattern.polygon_count(); ++i) {
        int n = 0;
        const Vec2* poly = pattern.polygon(i, &n);
        const double s = double(scale_size(poly, n));
        size = s > size ? s : size;
    }
    // (both factors: the relief forms z·S / edge_r first, so an overflow there is NaN after
    // a height_scale of 0)
    const double unscaled = z * size / double(options.edge_r);
    const double top = unscaled * double(options.height_scale);
    if (!(unscaled <= double(kMaxReliefHeight) && top <= double(kMaxReliefHeight)))
        return Status::error(StatusCode::out_of_range,
                             "leather maps: heights could reach %g (section |z| %g x scale size "
                             "%g / edge_r %g x height_scale %g), past %g: raise edge_r or lower "
                             "height_scale",
                             top, z, size, double(options.edge_r), double(options.height_scale),
                             double(kMaxReliefHeight));
    return Status::success();
}

// The public boundary: sizes, labels, the pattern's plain data (a caller may fill it by hand),
// the section and the options.
Status check_leather_map_inputs(const ScalePattern& pattern, const int* labels, int width,
                                int height, const BezierChain& section,
                                const ReliefOptions& options) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        return Status::error(StatusCode::invalid_argument,
                             "leather maps: size must be 1..16384 a side (got %d x %d)", width,
                             height);
    if (labels == nullptr)
        return Status::error(StatusCode::invalid_argument, "leather maps: labels is null");
    int polygons = pattern.polygon_count();
    if (polygons < 1 || int(pattern.centroids.size()) != polygons)
        return Status::error(StatusCode::invalid_argument,
                             "leather maps: the pattern has %d polygons and %d centroids", polygons,
                             int(pattern.centroids.size()));
    // The pattern is plain data a caller may fill by hand: check the offsets before
    // pattern.polygon() reads through them, and the coordinates before they reach the relief.
    if (pattern.polygon_offsets.front() != 0 ||
        std::size_t(pattern.polygon_offsets.back()) != pattern.vertices.size())
        return Status::error(StatusCode::invalid_argument,
                             "leather maps: polygon_offsets must run from 0 to the vertex count "
                             "%d (got %d .. %d)",
                             int(pattern.vertices.size()), pattern.polygon_offsets.front(),
                             pattern.polygon_offsets.back());
    for (std::size_t v = 0; v < pattern.vertices.size(); ++v)
        if (!is_finite(pattern.vertices[v]))
            return Status::error(StatusCode::invalid_argument,
                                 "leather maps: vertex %d of the pattern is not finite", int(v));
    for (int i = 0; i < polygons; ++i)
        if (!is_finite(pattern.centroids[std::size_t(i)]))
            return Status::error(StatusCode::invalid_argument,
                                 "leather maps: the centroid of polygon %d is not finite", i);
    if (!(pattern.width > 0) || !(pattern.height > 0))
        return Status::error(StatusCode::invalid_argument,
                             "leather maps: pattern size must be > 0 (got %g x %g)",
                             double(pattern.width), double(pattern.height));
    SHITSUKAN_TRY(validate_section(section));
    SHITSUKAN_TRY(validate_relief_options(options));
    for (int i = 0; i < polygons; ++i) {
        // Offsets that go backwards give n < 3 here too, before anything reads through them.
        std::size_t k = std::size_t(i);
        int n = pattern.polygon_offsets[k + 1] - pattern.polygon_offsets[k];
        if (n < 3)
            return Status::error(StatusCode::invalid_argument,
                                 "leather maps: polygon %d has %d vertices (need >= 3)", i, n);
    }
    SHITSUKAN_TRY(check_height_range(pattern, section, options));
    std::size_t count = std::size_t(width) * std::size_t(height);
    for (std::size_t k = 0; k < count; ++k)
        if (labels[k] < -1 || labels[k] >= polygons)
            return Status::error(StatusCode::invalid_argument,
                                 "leather maps: label %d at pixel (%d, %d) is not a polygon id "
                                 "(-1..%d)",
                                 labels[k], int(k % std::size_t(width)),
                                 int(k / std::size_t(width)), polygons - 1);
    return Status::success();
}

// Once per scale: its height unit S (relief.hpp step 3) and the angular index of its vertices
// around m (O(log n) edge search; polygons that are not star-shaped use the full scan).
struct ScaleTables {
    std::vector<float> sizes;
    std::vector<float> angles;
    std::vector<char> indexed;
};

void prepare_scale_tables(const ScalePattern& pattern, ScaleTables& t) {
    const int polygons = pattern.polygon_count();
    t.sizes.assign(std::size_t(polygons), 0.0f);
    t.angles.assign(pattern.vertices.size(), 0.0f);
    t.indexed.assign(std::size_t(polygons), 0);
    for (int i = 0; i < polygons; ++i) {
        int n;
        const Vec2* poly = pattern.polygon(i, &n);
        t.sizes[std::size_t(i)] = scale_size(poly, n);
        float* a = t.angles.data() + pattern.polygon_offsets[std::size_t(i)];
        t.indexed[std::size_t(i)] = make_angular_index(poly, n, pattern.centroids[std::size_t(i)], a);
    }
}

// tokai1994 §3.2 for one pixel row j: every pixel's height and normal from its scale's
// cross-section along the ray from the centroid m through the pixel to the edge point p
// ("computed for each polygon edge and for every polygon of §3.1").
void relief_row(const ScalePattern& pattern, const int* labels, const ScaleTables& t,
                const BezierChain& section, const ReliefOptions& options, int j, LeatherMaps* out) {
    const int width = out->width;
    const float sx = pattern.width / float(width), sy = pattern.height / float(out->height);
    for (int i = 0; i < width; ++i) {
        std::size_t k = std::size_t(j) * std::size_t(width) + std::size_t(i);
        int id = labels[k];
        if (id < 0) continue;  // no polygon: groove floor
        int n;
        const Vec2* poly = pattern.polygon(id, &n);
        Vec2 x{(float(i) + 0.5f) * sx, (float(j) + 0.5f) * sy};
        ReliefSample s;
        Vec2 m = pattern.centroids[std::size_t(id)];
        EdgeHit hit =
            t.indexed[std::size_t(id)]
                ? scale_edge_point_indexed(
                      poly, n, m, x, t.angles.data() + pattern.polygon_offsets[std::size_t(id)])
                : scale_edge_point(poly, n, m, x);
        float mp = length(hit.p - m);
        float rho = mp > 0.0f ? length(x - m) / mp : 0.0f;
        relief_along_ray(rho, m, hit, t.sizes[std::size_t(id)], section, options, &s);
        out->heights[k] = s.height;
        out->normals[k] = s.normal;
        if (s.height > out->max_height) out->max_height = s.height;
    }
}

}  // namespace

Status make_leather_maps(const ScalePattern& pattern, const int* labels, int width, int height,
                         const BezierChain& section, const ReliefOptions& options,
                         LeatherMaps& out, Progress progress) {
    SHITSUKAN_TRY(check_leather_map_inputs(pattern, labels, width, height, section, options));
    const std::size_t count = std::size_t(width) * std::size_t(height);
    // heights (4 B) and normals (12 B) a pixel, and the per-scale tables
    SHITSUKAN_TRY(check_memory_budget(
        budget_add(budget_mul(count, 16), budget_mul(pattern.vertices.size(), 4)),
        "leather maps (heights and normals)"));
    out.width = width;
    out.height = height;
    out.pattern_width = pattern.width;
    out.pattern_height = pattern.height;
    out.heights.assign(count, 0.0f);
    out.normals.assign(count, Vec3{0, 0, 1});
    out.max_height = 0.0f;
    ScaleTables tables;
    prepare_scale_tables(pattern, tables);
    const int block = std::max(1, height / 100);  // chosen: about 100 reports per map
    for (int j = 0; j < height; ++j) {
        relief_row(pattern, labels, tables, section, options, j, &out);
        if ((j + 1) % block == 0 || j + 1 == height) progress.report(float(j + 1) / float(height));
    }
    return Status::success();
}

namespace {

// Bilinear weights for pixel-centre sampling, clamped at the borders.
struct Bilinear {
    int i0, i1, j0, j1;
    float fx, fy;
};

Bilinear bilinear(const LeatherMaps& maps, Vec2 q) {
    float u = q.x / maps.pattern_width * float(maps.width) - 0.5f;
    float v = q.y / maps.pattern_height * float(maps.height) - 0.5f;
    u = clamp(u, 0.0f, float(maps.width - 1));
    v = clamp(v, 0.0f, float(maps.height - 1));
    if (!is_finite(u)) u = 0.0f;
    if (!is_finite(v)) v = 0.0f;
    Bilinear b;
    b.i0 = int(u);
    b.j0 = int(v);
    b.i1 = b.i0 + 1 < maps.width ? b.i0 + 1 : b.i0;
    b.j1 = b.j0 + 1 < maps.height ? b.j0 + 1 : b.j0;
    b.fx = u - float(b.i0);
    b.fy = v - float(b.j0);
    return b;
}

}  // namespace

Vec3 normal_at(const LeatherMaps& maps, Vec2 q) {
    SHITSUKAN_ASSERT(maps.width > 0 && maps.height > 0);
    Bilinear b = bilinear(maps, q);
    Vec3 top = lerp(maps.at_normal(b.i0, b.j0), maps.at_normal(b.i1, b.j0), b.fx);
    Vec3 bottom = lerp(maps.at_normal(b.i0, b.j1), maps.at_normal(b.i1, b.j1), b.fx);
    Vec3 n = normalize(lerp(top, bottom, b.fy));
    return length_squared(n) > 0.0f ? n : Vec3{0, 0, 1};
}

float height_at(const LeatherMaps& maps, Vec2 q) {
    SHITSUKAN_ASSERT(maps.width > 0 && maps.height > 0);
    Bilinear b = bilinear(maps, q);
    float top = lerp(maps.at_height(b.i0, b.j0), maps.at_height(b.i1, b.j0), b.fx);
    float bottom = lerp(maps.at_height(b.i0, b.j1), maps.at_height(b.i1, b.j1), b.fx);
    return lerp(top, bottom, b.fy);
}

void encode_height16(const LeatherMaps& maps, std::uint16_t* out, float max_height) {
    float top = max_height > 0.0f ? max_height : maps.max_height;
    float scale = top > 0.0f ? 65535.0f / top : 0.0f;
    for (int j = 0; j < maps.height; ++j) {
        std::uint16_t* row = out + std::size_t(maps.height - 1 - j) * std::size_t(maps.width);
        for (int i = 0; i < maps.width; ++i) {
            // NaN (an infinite max_height times 0) must not reach the cast: that is UB.
            float v = maps.at_height(i, j) * scale;
            v = v >= 0.0f ? std::fmin(v, 65535.0f) : 0.0f;
            row[i] = std::uint16_t(v + 0.5f);
        }
    }
}

void encode_normal_rgb(const LeatherMaps& maps, std::uint8_t* out) {
    for (int j = 0; j < maps.height; ++j) {
        std::uint8_t* row = out + 3 * std::size_t(maps.height - 1 - j) * std::size_t(maps.width);
        for (int i = 0; i < maps.width; ++i) {
            Vec3 n = maps.at_normal(i, j);
            for (int c = 0; c < 3; ++c) {
                float v = clamp((n[c] + 1.0f) * 0.5f * 255.0f + 0.5f, 0.0f, 255.0f);
                row[3 * i + c] = std::uint8_t(v);
            }
        }
    }
}

Status make_relief_mesh(const LeatherMaps& maps, int step, float z_scale, TriangleMesh& out) {
    if (step < 1)
        return Status::error(StatusCode::invalid_argument,
                             "relief mesh: step must be >= 1 (got %d)", step);
    if (!is_finite(z_scale))
        return Status::error(StatusCode::invalid_argument, "relief mesh: z_scale is not finite");
    int nx = (maps.width - 1) / step + 1, ny = (maps.height - 1) / step + 1;
    if (nx < 2 || ny < 2)
        return Status::error(StatusCode::invalid_argument,
                             "relief mesh: %d x %d map with step %d gives fewer than 2x2 samples",
                             maps.width, maps.height, step);
    out = TriangleMesh{};
    const float sx = maps.pattern_width / float(maps.width);
    const float sy = maps.pattern_height / float(maps.height);
    for (int b = 0; b < ny; ++b) {
        for (int a = 0; a < nx; ++a) {
            int i = a * step, j = b * step;
            float x = (float(i) + 0.5f) * sx, y = (float(j) + 0.5f) * sy;
            Vec3 n = maps.at_normal(i, j);
            if (z_scale != 1.0f) n = normalize(Vec3{n.x * z_scale, n.y * z_scale, n.z});
            out.add_vertex({x, y, maps.at_height(i, j) * z_scale}, n,
                            {x / maps.pattern_width, y / maps.pattern_height});
        }
    }
    for (int b = 0; b + 1 < ny; ++b) {
        for (int a = 0; a + 1 < nx; ++a) {
            std::uint32_t v00 = std::uint32_t(b * nx + a), v10 = v00 + 1;
            std::uint32_t v01 = v00 + std::uint32_t(nx), v11 = v01 + 1;
            out.add_triangle(v00, v10, v11);  // counter-clockwise seen from +z
            out.add_triangle(v00, v11, v01);
        }
    }
    return Status::success();
}

namespace {
// The rows' share of the one-call form's progress: 0.1 .. 1.
struct RowProgress {
    Progress outer;
    static void show(float fraction, void* user) {
        const RowProgress* r = static_cast<const RowProgress*>(user);
        r->outer.report(0.1f + 0.9f * fraction);
    }
};
}  // namespace

Status make_leather_maps(const ScalePattern& pattern, int width, int height,
                         const BezierChain& section, const ReliefOptions& options,
                         LeatherMaps& out, Progress progress) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        return Status::error(StatusCode::invalid_argument,
                             "leather maps: size %d x %d outside 1..16384", width, height);
    // labels (4 B), heights (4 B) and normals (12 B) a pixel; a wrapped pattern's cover is at
    // most 9 times the pattern (8 B a vertex and a centroid)
    const std::uint64_t pixels = budget_mul(std::uint64_t(width), std::uint64_t(height));
    const bool wraps = pattern.wrap_x || pattern.wrap_y;
    const std::uint64_t cover_bytes =
        wraps ? budget_mul(9, budget_mul(8, pattern.vertices.size() + pattern.centroids.size()))
              : 0;
    SHITSUKAN_TRY(check_memory_budget(budget_add(budget_mul(pixels, 20), cover_bytes),
                                      "leather maps (labels, heights and normals)"));
    // a tileable (torus) pattern: its scales and their copies across the border (tileable.hpp)
    ScalePattern cover;
    const bool wrapped = pattern.wrap_x || pattern.wrap_y;
    if (wrapped) SHITSUKAN_TRY(torus_cover(pattern, cover));
    const ScalePattern& plain = wrapped ? cover : pattern;
    std::vector<std::int32_t> labels(std::size_t(width) * std::size_t(height));
    SHITSUKAN_TRY(rasterize_scale_labels(plain, width, height, labels.data()));
    static_assert(sizeof(std::int32_t) == sizeof(int), "labels are ints");
    progress.report(0.1f);
    RowProgress rows{progress};
    return make_leather_maps(plain, reinterpret_cast<const int*>(labels.data()), width, height,
                             section, options, out,
                             progress.fn ? Progress{RowProgress::show, &rows} : Progress{});
}

namespace {
// Folds x into [0, w] by mirrored repetition; *flip says whether this copy is mirrored.
float mirror(float x, float w, bool* flip) {
    float period = 2.0f * w;
    float m = std::fmod(x, period);
    if (m < 0.0f) m += period;
    *flip = m > w;
    return *flip ? period - m : m;
}
}  // namespace

Vec3 mirrored_normal_at(const LeatherMaps& maps, Vec2 t) {
    bool fx, fy;
    Vec2 q{mirror(t.x, maps.pattern_width, &fx), mirror(t.y, maps.pattern_height, &fy)};
    Vec3 n = normal_at(maps, q);
    if (fx) n.x = -n.x;
    if (fy) n.y = -n.y;
    return n;
}

float mirrored_height_at(const LeatherMaps& maps, Vec2 t) {
    bool fx, fy;
    return height_at(maps, {mirror(t.x, maps.pattern_width, &fx),
                            mirror(t.y, maps.pattern_height, &fy)});
}

}  // namespace shitsukan
