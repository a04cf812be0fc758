// small-device: yes (no allocation, no exceptions)
#include "shitsukan/raster/wireframe.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <cmath>

#include "shitsukan/raster/clip.hpp"

namespace shitsukan {

namespace {

bool less_position(Vec3 p, Vec3 q) {
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    return p.z < q.z;
}

// Parametric (Liang-Barsky) clipping of the segment p0 -> p1 against the planes of clip.hpp.
// Each parameter is computed from the segment's own ends, so the result depends only on it.
bool clip_segment(Vec4* p0, Vec4* p1) {
    float t0 = 0.0f, t1 = 1.0f;
    for (int plane = 0; plane < 5; ++plane) {
        float d0 = detail::clip_plane_value(plane, *p0), d1 = detail::clip_plane_value(plane, *p1);
        if (d0 < 0.0f && d1 < 0.0f) return false;
        if (d0 < 0.0f) t0 = std::max(t0, d0 / (d0 - d1));
        else if (d1 < 0.0f) t1 = std::min(t1, d0 / (d0 - d1));
    }
    if (t0 > t1) return false;
    Vec4 a = *p0, b = *p1;
    if (t0 > 0.0f) *p0 = a + (b - a) * t0;
    if (t1 < 1.0f) *p1 = a + (b - a) * t1;
    return true;
}

struct LineContext {
    const Camera* camera;
    const FrameBand* band;
    const WireOptions* options;
    long pixels = 0;
};

void plot(LineContext& ctx, long x, long y, float depth) {
    const FrameBand& band = *ctx.band;
    if (x < 0 || x >= band.frame_width || y < band.y0 || y >= band.y0 + band.color.height) return;
    int row = int(y - band.y0);
    if (ctx.options->depth_test) {
        float stored = band.depth.row(row)[x];
        if (is_finite(stored)) {
            float d_line = view_distance(*ctx.camera, depth);
            float d_surface = view_distance(*ctx.camera, stored);
            if (d_line > d_surface * (1.0f + ctx.options->depth_tolerance)) return;  // hidden
        }
    }
    band.color.row(row)[x] = ctx.options->color;
    ++ctx.pixels;
}

// One pixel per step of the major axis, at the pixel centres in [start, end) along it.
void draw_line(LineContext& ctx, Vec3 a, Vec3 b) {
    float dx = b.x - a.x, dy = b.y - a.y;
    bool x_major = std::fabs(dx) >= std::fabs(dy);
    float major_a = x_major ? a.x : a.y, major_b = x_major ? b.x : b.y;
    if (major_a == major_b) return;  // shorter than a pixel step: nothing is sampled
    float lo = std::min(major_a, major_b), hi = std::max(major_a, major_b);
    long first = long(std::ceil(lo - 0.5f)), end = long(std::ceil(hi - 0.5f));
    // Only the steps that can land in the band (plus one either side for rounding).
    const FrameBand& band = *ctx.band;
    long limit = x_major ? band.frame_width : band.frame_height;
    if (!x_major) {
        first = std::max(first, long(band.y0));
        end = std::min(end, long(band.y0 + band.color.height));
    } else if (dy != 0.0f) {
        float ta = (float(band.y0) - a.y) / dy;
        float tb = (float(band.y0 + band.color.height) - a.y) / dy;
        float xa = a.x + dx * std::min(ta, tb), xb = a.x + dx * std::max(ta, tb);
        float xlo = std::min(xa, xb), xhi = std::max(xa, xb);
        // Clamped before the conversion (a nearly horizontal line gives huge or inf values;
        // NaN fails both tests): the limits only need to lie outside [0, kMaxFrameSize].
        if (xlo > -1e6f) first = std::max(first, long(std::floor(std::min(xlo, 1e6f))) - 1);
        if (xhi < 1e6f) end = std::min(end, long(std::ceil(std::max(xhi, -1e6f))) + 2);
    }
    first = std::max(first, 0L);
    end = std::min(end, limit);
    for (long i = first; i < end; ++i) {
        float centre = float(i) + 0.5f;
        float t = (centre - major_a) / (major_b - major_a);
        float minor = x_major ? a.y + t * dy : a.x + t * dx;
        float depth = a.z + t * (b.z - a.z);  // window depth is affine along a screen line
        long m = long(std::floor(minor));
        if (x_major) plot(ctx, i, m, depth);
        else plot(ctx, m, i, depth);
    }
}

}  // namespace

float view_distance(const Camera& camera, float depth) {
    float z_ndc = 2.0f * depth - 1.0f;
    float a = camera.projection.m[2][2], b = camera.projection.m[2][3];
    if (camera.orthographic) return (b - z_ndc) / a;  // z_ndc = a·z_eye + b, distance -z_eye
    return b / (z_ndc + a);                             // z_ndc = -a - b / z_eye
}

Status collect_edges(const MeshView& mesh, WireEdge* edges, int capacity, int& count) {
    count = 0;
    // The room is checked first, from the counts alone, in 64 bits (3·triangle_count can
    // exceed INT_MAX): validate_mesh reads every index, so it must not run on a count the
    // arrays cannot back.
    if (mesh.triangle_count < 0 || capacity < 0)
        return Status::error(StatusCode::invalid_argument,
                             "collect_edges: %d triangles, room for %d edges; counts must be "
                             ">= 0", mesh.triangle_count, capacity);
    const std::int64_t needed = 3 * std::int64_t(mesh.triangle_count);
    if ((edges == nullptr && needed > 0) || std::int64_t(capacity) < needed)
        return Status::error(StatusCode::buffer_too_small,
                             "collect_edges: room for %d edges, %d triangles need %lld",
                             edges ? capacity : 0, mesh.triangle_count,
                             static_cast<long long>(needed));
    SHITSUKAN_TRY(validate_mesh(mesh));
    // Every triangle side, its lower end (by position) first.
    int n = 0;
    for (int t = 0; t < mesh.triangle_count; ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t* corner = mesh.indices + 3 * std::size_t(t);
            std::uint32_t i = corner[k], j = corner[(k + 1) % 3];
            Vec3 p = mesh.positions[i], q = mesh.positions[j];
            if (!is_finite(p) || !is_finite(q) || p == q) continue;
            edges[n++] = less_position(p, q) ? WireEdge{i, j} : WireEdge{j, i};
        }
    // Sort by (lower end, upper end) and keep the first of each run of equal positions.
    const Vec3* pos = mesh.positions;
    std::sort(edges, edges + n, [pos](const WireEdge& e, const WireEdge& f) {
        if (pos[e.a] != pos[f.a]) return less_position(pos[e.a], pos[f.a]);
        return less_position(pos[e.b], pos[f.b]);
    });
    int unique = 0;
    for (int i = 0; i < n; ++i) {
        if (unique > 0 && pos[edges[unique - 1].a] == pos[edges[i].a] &&
            pos[edges[unique - 1].b] == pos[edges[i].b])
            continue;
        edges[unique++] = edges[i];
    }
    count = unique;
    return Status::success();
}

Status draw_edges(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                  const WireEdge* edges, int count, const WireOptions& options,
                  long* pixels_written) {
    SHITSUKAN_TRY(validate_camera(camera));
    SHITSUKAN_TRY(validate_band(camera, band));
    if (count < 0 || (count > 0 && (edges == nullptr || mesh.positions == nullptr)))
        return Status::error(StatusCode::invalid_argument,
                             "draw_edges: %d edges given without edge or position arrays", count);
    for (int i = 0; i < count; ++i)
        if (edges[i].a >= std::uint32_t(mesh.vertex_count) ||
            edges[i].b >= std::uint32_t(mesh.vertex_count))
            return Status::error(StatusCode::invalid_argument,
                                 "draw_edges: edge %d (%u, %u) is out of range for %d vertices",
                                 i, unsigned(edges[i].a), unsigned(edges[i].b), mesh.vertex_count);
    Mat4 normal_matrix;
    SHITSUKAN_TRY(validate_model(options.model, normal_matrix));
    if (!(options.depth_tolerance >= 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "draw_edges: depth_tolerance must be >= 0 (got %g)",
                             double(options.depth_tolerance));

    const Mat4 mvp = camera.projection * (camera.view * options.model);
    LineContext ctx{&camera, &band, &options, 0};
    for (int i = 0; i < count; ++i) {
        Vec3 p = mesh.positions[edges[i].a], q = mesh.positions[edges[i].b];
        if (!is_finite(p) || !is_finite(q)) continue;
        Vec4 a = mvp * Vec4{p.x, p.y, p.z, 1.0f};
        Vec4 b = mvp * Vec4{q.x, q.y, q.z, 1.0f};
        // w >= FLT_MIN keeps 1/w finite; after the guard band the ends lie within a few
        // screens, so the bound below only refuses values that went wrong (NaN included),
        // and every float -> integer conversion in draw_line stays in range.
        const float min_w = std::numeric_limits<float>::min(), max_screen = 1.0e7f;
        if (!clip_segment(&a, &b) || !(a.w >= min_w) || !(b.w >= min_w)) continue;
        Vec3 sa = clip_to_screen(camera, a), sb = clip_to_screen(camera, b);
        if (!(std::fabs(sa.x) < max_screen && std::fabs(sa.y) < max_screen &&
              std::fabs(sb.x) < max_screen && std::fabs(sb.y) < max_screen))
            continue;
        draw_line(ctx, sa, sb);
    }
    if (pixels_written) *pixels_written += ctx.pixels;
    return Status::success();
}

}  // namespace shitsukan
