// ports/web/api/api_tokai1994.cpp — the C API of the tokai1994 panels (§3, reptile leather):
// the two-stage Voronoi division step by step (figs. 4-7, 10), one scale's Bezier
// cross-section and its relief (§3.2, figs. 12-15, Table 1), the leather maps and the
// bump-mapped patch under a movable light (§4-5, figs. 16-18).
// State: the pattern of the last sk_tokai1994_pattern call (with its intermediate steps), the
// current cross-section, the maps of the last sk_tokai1994_maps call.
#include <cmath>
#include <cstdio>
#include <vector>

#include "api_common.hpp"
#include "shitsukan/geom/bezier_patch.hpp"
#include "shitsukan/geom/bezier_patch_mesh.hpp"
#include "shitsukan/image/colormap.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/relief.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/render/leather_mesh.hpp"

using namespace shitsukan;

namespace {

ScaleParams g_params;
ScalePattern g_pattern;
ScaleDivision g_steps;
bool g_have_pattern = false;
BezierChain g_section = table1_section(Table1Section::convex);
LeatherMaps g_maps;
bool g_have_maps = false;

Status need_pattern() {
    if (!g_have_pattern)
        return Status::error(StatusCode::invalid_argument,
                             "no scale pattern yet: call sk_tokai1994_pattern (generate_scale_pattern) first");
    return Status::success();
}

const Rgb8 kInk{30, 30, 30}, kFaint{185, 185, 185}, kAccent{200, 40, 30}, kPaper{255, 255, 255};

// Pattern units [0, W] x [0, H] (y up) -> pixels with a margin.
struct Frame {
    float margin, scale, size;
    Vec2 operator()(Vec2d p) const {
        return Vec2{margin + float(p.x) * scale, size - margin - float(p.y) * scale};
    }
    Vec2 operator()(Vec2 p) const { return (*this)(Vec2d{double(p.x), double(p.y)}); }
};

void draw_subdivision(RasterCanvas& c, const PlanarSubdivision& s, const Frame& f, Rgb8 color, float width) {
    for (const PlanarSubdivision::Edge& e : s.edges)
        c.line(f(s.vertices[std::size_t(e.v0)]), f(s.vertices[std::size_t(e.v1)]), color, width);
}

void draw_pattern(RasterCanvas& c, const ScalePattern& p, const Frame& f, Rgb8 color, float width) {
    std::vector<Vec2> pts;
    for (int i = 0; i < p.polygon_count(); ++i) {
        int n = 0;
        const Vec2* poly = p.polygon(i, &n);
        pts.clear();
        for (int k = 0; k < n; ++k) pts.push_back(f(poly[k]));
        c.polygon_outline(pts.data(), n, color, width);
    }
}

void draw_seeds(RasterCanvas& c, const SeedLayout& s, const Frame& f, float marker) {
    for (std::size_t i = 0; i < s.moved.size(); ++i) {
        const Vec2d o = s.original[i], m = s.moved[i];
        if (o.x < -0.05 || o.x > 1.05 || o.y < -0.05 || o.y > 1.05) continue;
        c.line(f(o), f(m), kAccent, 1.0f);
        c.marker(f(o), MarkerShape::circle, marker, kInk);
        c.marker(f(m), MarkerShape::dot, marker * 0.8f, kAccent);
    }
}

// The polygon of the pattern whose centroid is nearest the region's centre ("one scale").
int middle_scale() {
    int best = 0;
    float best_d = 1e30f;
    const Vec2 c{0.5f * g_pattern.width, 0.5f * g_pattern.height};
    for (int i = 0; i < g_pattern.polygon_count(); ++i) {
        const Vec2 d = g_pattern.centroids[std::size_t(i)] - c;
        if (dot(d, d) < best_d) best_d = dot(d, d), best = i;
    }
    return best;
}

}  // namespace

// §3.1: the whole two-stage division with the perturbation (generate_scale_pattern), kept
// with its steps. d is given as a multiple of D (fig. 7: d = 1.0 D); p is fig. 10's
// perturbation. Text: counts and the perturbation report.
SK_API int sk_tokai1994_pattern(float D, float d_over_D, float a, float p, unsigned seed) {
    ScaleParams prm;
    prm.D = D;
    prm.d = d_over_D * D;
    prm.a = a;
    prm.perturbation.p = p;
    prm.seed = seed;
    ScalePattern pattern;
    ScaleDivision steps;
    Status s = check_scale_params(prm);
    if (s) s = generate_scale_pattern(prm, pattern, &steps, skweb::progress());
    if (!s) return skweb::finish(s);
    g_params = prm;
    g_pattern = std::move(pattern);
    g_steps = std::move(steps);
    g_have_pattern = true;
    g_have_maps = false;
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "{\"scales\":%d,\"stage1\":%d,\"stage2_seeds\":%d,\"columns\":%d,\"edges\":%d,\"shrunk\":%d,"
                  "\"requested_rms\":%.6g,\"realised_rms\":%.6g}",
                  g_pattern.polygon_count(), g_steps.stage1.face_count(), int(g_steps.stage2_seeds.moved.size()),
                  int(g_steps.columns.x.size()), g_steps.perturbation.edges, g_steps.perturbation.shrunk,
                  g_steps.perturbation.requested_rms, g_steps.perturbation.realised_rms);
    skweb::text() = buf;
    return skweb::finish(s);
}

// One step of §3.1 drawn from the kept pattern, size x size: 0 stage-1 seeds on the lattice
// and moved along y, with their Voronoi division (fig. 4); 1 the stage-1 polygons, edges bent
// (fig. 5); 2 the stage-2 seeds moved along x and the stage-2 cells in the stage-1 polygons
// (fig. 6); 3 the final pattern (fig. 7); 4 the perturbation alone: the straight cells (grey)
// under the bent ones (fig. 10's p).
SK_API int sk_tokai1994_step(int step, int size) {
    Status s = need_pattern();
    if (s && (step < 0 || step > 4))
        s = Status::error(StatusCode::invalid_argument, "step must be in 0..4 (got %d)", step);
    if (s && (size < 64 || size > 2048))
        s = Status::error(StatusCode::invalid_argument, "size must be in 64..2048 (got %d)", size);
    if (!s) return skweb::finish(s);
    RgbImage img(size, size, kPaper);
    RasterCanvas c(img.view());
    const float margin = float(size) / 24.0f;
    const Frame f{margin, (float(size) - 2.0f * margin) / g_pattern.width, float(size)};
    const float marker = float(size) / 90.0f;
    switch (step) {
        case 0:
            draw_subdivision(c, g_steps.stage1, f, kFaint, 1.0f);
            draw_seeds(c, g_steps.stage1_seeds, f, marker);
            break;
        case 1: draw_pattern(c, g_steps.stage1_pattern, f, kInk, 1.3f); break;
        case 2:
            draw_subdivision(c, g_steps.cells, f, kFaint, 1.0f);
            draw_subdivision(c, g_steps.stage1, f, kInk, 1.3f);
            draw_seeds(c, g_steps.stage2_seeds, f, marker * 0.8f);
            break;
        case 3: draw_pattern(c, g_pattern, f, kInk, 1.2f); break;
        default:
            draw_subdivision(c, g_steps.cells, f, kFaint, 1.0f);
            draw_pattern(c, g_pattern, f, kInk, 1.2f);
            break;
    }
    c.rect_outline(f(Vec2{0.0f, g_pattern.height}), Vec2{g_pattern.width * f.scale, g_pattern.height * f.scale},
                   kInk, 1.5f);
    skweb::set_picture(img);
    return skweb::finish(s);
}

// Table 1's cross-sections (0 convex fig. 13, 1 concave fig. 14, 2 two segments fig. 15).
SK_API int sk_tokai1994_section_load(int which) {
    if (which < 0 || which > 2)
        return skweb::finish(Status::error(StatusCode::invalid_argument, "section must be 0, 1 or 2 (got %d)", which));
    g_section = table1_section(static_cast<Table1Section>(which));
    g_have_maps = false;
    return skweb::finish(Status::success());
}

// The current section: floats = its control points (r, z), 4 per segment.
SK_API int sk_tokai1994_section_points() {
    std::vector<float>& f = skweb::floats();
    f.clear();
    for (int k = 0; k < g_section.count; ++k)
        for (const Vec2& p : g_section.segments[k].p) {
            f.push_back(p.x);
            f.push_back(p.y);
        }
    skweb::set_float_columns(2);
    return skweb::finish(Status::success());
}

// Moves control point `index` (0..3) of segment `segment` to (r, z); a joint between two
// segments moves in both. Kept only when validate_section accepts the result (its message
// otherwise, the section unchanged).
SK_API int sk_tokai1994_section_move(int segment, int index, float r, float z) {
    if (segment < 0 || segment >= g_section.count || index < 0 || index > 3)
        return skweb::finish(Status::error(StatusCode::invalid_argument,
                                           "control point %d of segment %d does not exist (%d segments)", index,
                                           segment, g_section.count));
    BezierChain next = g_section;
    next.segments[segment].p[index] = Vec2{r, z};
    if (index == 3 && segment + 1 < next.count) next.segments[segment + 1].p[0] = Vec2{r, z};
    if (index == 0 && segment > 0) next.segments[segment - 1].p[3] = Vec2{r, z};
    Status s = validate_section(next);
    if (s) {
        g_section = next;
        g_have_maps = false;
    }
    return skweb::finish(s);
}

// z(r) of the current section at n values of r over its range (section_at_r, the §3.2
// inversion of eq. (2)). Floats: (r, z) pairs.
SK_API int sk_tokai1994_section_curve(int n) {
    if (n < 2 || n > 4096)
        return skweb::finish(Status::error(StatusCode::invalid_argument, "samples must be in 2..4096 (got %d)", n));
    const float r0 = section_r_first(g_section), r1 = section_r_last(g_section);
    std::vector<float>& f = skweb::floats();
    f.clear();
    for (int i = 0; i < n; ++i) {
        const SectionSample q = section_at_r(g_section, r0 + (r1 - r0) * float(i) / float(n - 1));
        f.push_back(q.r);
        f.push_back(q.z);
    }
    skweb::set_float_columns(2);
    return skweb::finish(Status::success());
}

// §3.2 fig. 12: the relief of one scale (the pattern's polygon nearest the centre) from the
// current section, size x size over the scale's bounding box: left, the height (grey, white
// highest); right, the normal of eq. (4) lit from the direction (lx, ly, lz) (n·l, drawn
// only). Floats: the heights (NaN outside the scale). Text: S and the vertex count.
SK_API int sk_tokai1994_scale_relief(int size, float height_scale, float lx, float ly, float lz) {
    Status s = need_pattern();
    ReliefOptions opt;
    opt.height_scale = height_scale;
    if (s) s = validate_relief_options(opt);
    if (s) s = validate_section(g_section);
    if (s && (size < 16 || size > 1024))
        s = Status::error(StatusCode::invalid_argument, "size must be in 16..1024 (got %d)", size);
    const Vec3 light = normalize(Vec3{lx, ly, lz});
    if (s && !(std::isfinite(light.x) && std::isfinite(light.y) && std::isfinite(light.z)))
        s = Status::error(StatusCode::invalid_argument, "the light direction must be finite and non-zero");
    if (!s) return skweb::finish(s);
    const int id = middle_scale();
    int n = 0;
    const Vec2* poly = g_pattern.polygon(id, &n);
    const Vec2 m = g_pattern.centroids[std::size_t(id)];
    Vec2 lo = poly[0], hi = poly[0];
    for (int k = 1; k < n; ++k) {
        lo = Vec2{std::fmin(lo.x, poly[k].x), std::fmin(lo.y, poly[k].y)};
        hi = Vec2{std::fmax(hi.x, poly[k].x), std::fmax(hi.y, poly[k].y)};
    }
    const float span = std::fmax(hi.x - lo.x, hi.y - lo.y) * 1.08f;
    const Vec2 c0{0.5f * (lo.x + hi.x) - 0.5f * span, 0.5f * (lo.y + hi.y) - 0.5f * span};
    const float S = scale_size(poly, n);
    std::vector<float>& h = skweb::floats();
    h.assign(std::size_t(size) * std::size_t(size), NAN);
    RgbImage img(2 * size + 8, size, kPaper);
    float top = 0.0f;
    std::vector<ReliefSample> samples(std::size_t(size) * std::size_t(size));
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const Vec2 x{c0.x + span * (float(i) + 0.5f) / float(size), c0.y + span * (1.0f - (float(j) + 0.5f) / float(size))};
            if (!scale_edge_point(poly, n, m, x).inside) continue;
            ReliefSample& r = samples[std::size_t(j) * std::size_t(size) + std::size_t(i)];
            scale_relief(poly, n, m, x, g_section, opt, &r);
            h[std::size_t(j) * std::size_t(size) + std::size_t(i)] = r.height;
            top = std::fmax(top, r.height);
        }
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const std::size_t k = std::size_t(j) * std::size_t(size) + std::size_t(i);
            if (std::isnan(h[k])) continue;
            img.view().at(i, j) = colormap(ColorMap::gray, top > 0.0f ? h[k] / top : 0.0f);
            const float lit = std::fmax(0.0f, dot(samples[k].normal, light));
            img.view().at(size + 8 + i, j) = colormap(ColorMap::gray, 0.15f + 0.85f * lit);
        }
    skweb::set_picture(img);
    skweb::set_float_columns(size);
    char buf[160];
    std::snprintf(buf, sizeof buf, "{\"scale\":%d,\"vertices\":%d,\"S\":%.6g,\"max_height\":%.6g}", id, n, double(S),
                  double(top));
    skweb::text() = buf;
    return skweb::finish(s);
}

// §3.2 for the whole pattern: the height and normal maps (make_leather_maps) at size x size
// from the current section. Picture: the normal map (encode_normal_rgb, top row = +y).
// Floats: the heights, row 0 = y = 0 (the maps' own order).
SK_API int sk_tokai1994_maps(int size) {
    Status s = need_pattern();
    if (s && (size < 16 || size > 4096))
        s = Status::error(StatusCode::invalid_argument, "size must be in 16..4096 (got %d)", size);
    if (!s) return skweb::finish(s);
    LeatherMaps maps;
    s = make_leather_maps(g_pattern, size, size, g_section, ReliefOptions{}, maps, skweb::progress());
    if (!s) return skweb::finish(s);
    g_maps = std::move(maps);
    g_have_maps = true;
    std::vector<std::uint8_t> rgb(std::size_t(size) * std::size_t(size) * 3u);
    encode_normal_rgb(g_maps, rgb.data());
    RgbImage img(size, size);
    for (std::size_t i = 0, n = std::size_t(size) * std::size_t(size); i < n; ++i)
        img.data()[i] = Rgb8{rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]};
    skweb::set_picture(img);
    skweb::floats().assign(g_maps.heights.data(), g_maps.heights.data() + std::size_t(size) * std::size_t(size));
    skweb::set_float_columns(size);
    return skweb::finish(s);
}

// §4-5 figs. 16-18: a bicubic Bezier patch (eq. (5)) bump-mapped with the maps of the last
// sk_tokai1994_maps call, lit by Blinn 1977 from a key light the user moves (azimuth and
// elevation in radians, distance 6 around the patch; the fill light of
// tokai1994_scene_lights stays), drawn by draw_leather_mesh at size x size.
// Chosen here: the patch is a gentle arch along u (heights 0, 0.35, 0.35, 0 across), 2 x 2
// units, one pattern repeat across it, so the light rakes across the scales as it moves.
SK_API int sk_tokai1994_patch(float azimuth, float elevation, int size) {
    Status s = g_have_maps ? Status::success()
                           : Status::error(StatusCode::invalid_argument,
                                           "no leather maps for this pattern and section: call sk_tokai1994_maps first");
    if (s && (size < 16 || size > 2048))
        s = Status::error(StatusCode::invalid_argument, "size must be in 16..2048 (got %d)", size);
    if (s && !(std::isfinite(azimuth) && std::isfinite(elevation)))
        s = Status::error(StatusCode::invalid_argument, "the light's azimuth and elevation must be finite");
    if (!s) return skweb::finish(s);
    BezierPatch patch;
    const float arch[4] = {0.0f, 0.35f, 0.35f, 0.0f};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            patch.p[i][j] = Vec3{-1.0f + 2.0f * float(i) / 3.0f, arch[i], 1.0f - 2.0f * float(j) / 3.0f};
    s = validate_patch(patch);
    TriangleMesh mesh;
    PatchStripOptions opt;
    opt.segments_u = opt.segments_v = 32;
    opt.texture_scale = 0.5f;  // texture units per world unit: one pattern across the 2-unit patch
    if (s) s = tessellate_patch_strip(&patch, 1, opt, mesh);
    TextureTangents tangents;
    if (s) s = compute_texture_tangents(mesh.view(), tangents);
    Camera cam;
    if (s) s = make_perspective_camera(Vec3{0.0f, 2.6f, 2.4f}, Vec3{0.0f, 0.1f, 0.0f}, Vec3{0, 1, 0}, 40.0f, size, size,
                                       0.05f, 100.0f, cam);
    if (!s) return skweb::finish(s);
    LeatherShading shading;
    shading.lights[0].position = Vec3{6.0f * std::cos(elevation) * std::sin(azimuth), 6.0f * std::sin(elevation),
                                      6.0f * std::cos(elevation) * std::cos(azimuth)};
    RgbImage img(size, size);
    FloatImage depth(size, size);
    const FrameBand band = full_frame_band(img.view(), depth.view());
    clear_band(band, Rgb8{24, 26, 32});
    DrawOptions draw;
    draw.cull = CullMode::none;
    s = draw_leather_mesh(cam, band, mesh.view(), draw, g_maps, tangents, shading);
    if (!s) return skweb::finish(s);
    skweb::set_picture(img);
    return skweb::finish(s);
}
