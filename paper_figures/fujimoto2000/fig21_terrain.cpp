// fujimoto2000 fig. 21 and Table 2: terrain, 800 x 800 per panel. (a) control mesh with the
// heights, (b) the conventional surface coloured per span (the captions of (a)(b) are lost in
// the OCR; read as fig. 22's (x)(y)), (c) conventional B-spline surface, (d) WR surface
// (spiky), (e)(f)(g) superposed IST-B-spline surfaces with three ratio functions delta: the
// roughness of the "mountain ranges" changes with delta (§5), with §5's Gaussian jitter on the
// sample values. As in the paper, the green part at the front right is not superposed: its
// control points carry a tiny delta (0.02), so W^0 = 0.98 and the sum is practically H itself.
// The product IST (u and v separately) gives every WR surface a plaid grain; a camera looking
// along one parameter turns it into curtains, so the view is diagonal, the light from above.
// Table 2 lists our time per stage beside the paper's Origin2000 minutes.
// Example: examples/31_superposed_mountains.cpp.
#include <algorithm>
#include <cmath>

#include "driver/figure.hpp"
#include "fujimoto2000/terrain_mesh.hpp"
#include "fujimoto2000/wr_figure_common.hpp"
#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"
#include "shitsukan/geom/obj.hpp"

namespace shitsukan::fujimoto2000 {
namespace {

using figures::FigureContext;
using figures::fmt;

// The three deltas of (e), (f), (g) (chosen: the paper does not print them); the green part's
// "not superposed" delta is kTerrainDeltaGreen (terrain_mesh.hpp, with the control mesh).
constexpr float kDeltas[3] = {0.35f, 0.55f, 0.75f};
// §5: "to add naturalness, Gaussian random numbers are given to the sample values" (chosen
// deviations: the paper gives none). Only the sampled panels (e)-(g) have samples.
constexpr float kJitterHeight = 0.12f, kJitterColor = 0.035f;

// The camera looks diagonally across the parameter grid (from +x +z, 45 degrees to both
// parameter directions, so neither the u nor the v stripes of the product IST line up with
// the view), from above; the light comes from above. Screen "right" is +x -z, "front" +x +z.
const Shot kShot{kTerrainEye, kTerrainTarget, {0, 1, 0}, kTerrainFovDegrees};
const Vec3 kLight = kTerrainLight;

struct Panel {
    char id;
    const char* name;
    const char* paper_sam;  // Table 2 (min:sec)
    const char* paper_pol;
    const char* paper_ren;
    const char* paper_total;
};
const Panel kPanels[5] = {{'c', "(c)", "1:06", "0:12", "0:35", "1:53"},
                          {'d', "(d)", "1:16", "0:12", "16:44", "18:12"},
                          {'e', "(e)", "1:49", "0:12", "2:02", "4:03"},
                          {'f', "(f)", "1:49", "0:12", "2:11", "4:12"},
                          {'g', "(g)", "1:49", "0:12", "2:24", "4:25"}};

// What the reader should see, measured on the vertex grid (the same grid for every panel):
// mean height (relative to the plain surface (c)), and the RMS departure from the plain
// surface in the mountains and in the green field.
struct TerrainMeasure {
    double mean_height = 0, mean_plain = 0, rms_mountains = 0, rms_green = 0;
};
TerrainMeasure measure_terrain(const WrSurface& surface, const WrMesh& wm) {
    TerrainMeasure m;
    double sum = 0, sum_plain = 0, sm = 0, sg = 0;
    long nm = 0, ng = 0, n = 0;
    for (std::size_t i = 0; i < wm.mesh.positions.size(); i += 7) {  // every 7th vertex
        const Vec2 uv = wm.mesh.uvs[i];
        const BasePoint b = surface.base_point(uv.x, uv.y);
        const float h = dot(wm.mesh.positions[i] - b.position, b.normal);
        const float hp = surface.attributes(uv.x, uv.y).height;
        const float d = h - hp;
        sum += h;
        sum_plain += hp;
        ++n;
        if (terrain_green_mask(b.position.x, b.position.z) > 0.99f) {
            sg += double(d) * d;
            ++ng;
        } else if (terrain_green_mask(b.position.x, b.position.z) == 0.0f) {
            sm += double(d) * d;
            ++nm;
        }
    }
    m.mean_height = sum / double(n);
    m.mean_plain = sum_plain / double(n);
    m.rms_mountains = nm ? std::sqrt(sm / double(nm)) : 0.0;
    m.rms_green = ng ? std::sqrt(sg / double(ng)) : 0.0;
    return m;
}

Status make_terrain_surface(float delta, WrControlMesh* mesh, WrSurface* surface, AxisPair* axes) {
    *mesh = terrain_control_mesh(delta);
    SHITSUKAN_TRY(make_wr_surface(*mesh, SurfaceBasis::bspline, 3, *surface));
    SHITSUKAN_TRY(make_axes(*surface, IstKind::fully_connected, "fully", 3, kMaxWrLevel, axes));
    return surface->set_axes(axes->u.axis(), axes->v.axis());
}

Status render_panel(bool quick, char panel, RgbImage* img, StageTimes* times, WrMesh* keep,
                    std::string* params, TerrainMeasure* measure = nullptr) {
    const int size = quick ? 160 : 800;
    const float delta = panel >= 'e' ? kDeltas[panel - 'e'] : 0.5f;
    WrControlMesh mesh;
    WrSurface surface;
    AxisPair axes;
    SHITSUKAN_TRY(make_terrain_surface(delta, &mesh, &surface, &axes));
    const float ppu = shot_pixels_per_unit(kShot, size);
    const AdaptiveLevels a = choose_adaptive_levels(surface, mesh, ppu, 1.5f, 0.5f, quick ? 2 : 4);
    WrTessellationOptions o;
    o.subdivisions = 1;
    o.grid_level = a.grid_level;
    HierarchicalSampling hs;
    times->quick = quick;
    times->grid_level = a.grid_level;
    auto t0 = Clock::now();
    if (panel == 'c' || panel == 'b') {
        o.form = WrSurfaceForm::plain;  // the paper polygonised (c) as finely as the WR surfaces
    } else if (panel == 'd') {
        o.form = WrSurfaceForm::wr;
        o.levels = a.grid_level;
        times->levels = o.levels;
    } else {
        HierarchicalOptions ho;
        ho.levels = std::max(1, a.sum_levels);
        ho.interpolation = SampleInterpolation::linear;
        ho.jitter_height = kJitterHeight;
        ho.jitter_color = kJitterColor;
        ho.seed = 21;
        SHITSUKAN_TRY(sample_hierarchy(surface, ho, hs));
        o.form = WrSurfaceForm::superposed;
        o.tail_tolerance = a.world_tolerance;
        times->levels = ho.levels;
    }
    WrMesh wm;
    SHITSUKAN_TRY(
        evaluate_wr_grid(surface, o.form == WrSurfaceForm::superposed ? &hs : nullptr, o, wm));
    times->sampling = seconds_since(t0);
    t0 = Clock::now();
    polygonise_wr_grid(surface, &wm);
    times->polygonisation = seconds_since(t0);
    if (panel == 'b') color_by_source_span(&wm, surface, 0);
    t0 = Clock::now();
    *img = RgbImage(size, size);
    Shading shading;
    shading.background = Rgb8{196, 216, 236};
    shading.light = kLight;
    shading.ambient = 0.32f;
    SHITSUKAN_TRY(render_opaque(shot_camera(kShot, size, size), wm.mesh, img->view(), shading));
    times->rendering = seconds_since(t0);
    times->triangles = wm.mesh.triangle_count();
    if (measure) *measure = measure_terrain(surface, wm);
    *params =
        fmt("grid level %d (%d x %d vertices), %s", a.grid_level, wm.grid_u, wm.grid_v,
            panel >= 'e' ? fmt("K = %d, delta = %.2f, linear sampling, Gaussian jitter "
                               "(height x(1 + %.2f g), colour + %.3f g), mean steps used %.2f",
                               times->levels, double(delta), double(kJitterHeight),
                               double(kJitterColor), wm.mean_levels_used)
                               .c_str()
                         : (panel == 'd' ? fmt("K = %d", o.levels).c_str() : "no IST"));
    if (keep) *keep = std::move(wm);
    return Status::success();
}

Status run_panel(FigureContext& ctx, char panel) {
    ctx.given("image size", "800 x 800", "Table 2");
    ctx.given("surface", "superposed IST-B-spline, n = 3", "§5");
    ctx.chosen("IST", "fully-connected, N = 3", "the paper does not name it for fig. 21");
    ctx.chosen("control mesh",
               "10 x 10 (7 x 7 spans), massif at the back, range to the left, green field front "
               "right (delta 0.02); colour per point from height band, hashed tint and a drift "
               "along x and z",
               "not printed");
    ctx.chosen("view", "diagonal camera from above (45 degrees to u and v), light from above",
               "a view along one parameter shows only the IST's stripes of the other");
    ctx.chosen("deltas (e)(f)(g)", "0.35, 0.55, 0.75", "not printed; small to large roughness");
    ctx.chosen("adaptive sampling", "grid cells <= 1.5 px, rest of the sum < 0.5 px, level cap 4",
               "keeps a full panel within seconds");
    if (panel >= 'e')
        ctx.chosen("jitter",
                   fmt("height x(1 + %.2f g), colour + %.3f g", double(kJitterHeight),
                       double(kJitterColor)),
                   "§5 applies Gaussian jitter to the sample values; it gives no deviation");
    RgbImage img;
    StageTimes t;
    WrMesh wm;
    std::string params;
    TerrainMeasure m;
    SHITSUKAN_TRY(render_panel(ctx.quick(), panel, &img, &t, &wm, &params, &m));
    if (panel >= 'd')
        ctx.note(
            fmt("Measured on every 7th vertex: mean height %.1f %% of the plain surface (c) "
                "(eq. 18: the total is set by H); RMS departure from (c) %.3f in the "
                "mountains, %.3f in the green field at the front right (not superposed).",
                100.0 * m.mean_height / m.mean_plain, m.rms_mountains, m.rms_green));
    if (panel != 'b') record_stage_times(fmt("fig21%c", panel), t);
    ctx.note(params +
             fmt("; %ld triangles; sampling %.2f s, polygonisation %.2f s, rendering %.2f s.",
                 t.triangles, t.sampling, t.polygonisation, t.rendering));
    if (panel == 'f' && !ctx.quick()) SHITSUKAN_TRY(write_obj(ctx.path(".obj").c_str(), wm.mesh));
    return ctx.save_png(img.view());
}

}  // namespace

SHITSUKAN_FIGURE(fig21a_panel, "fujimoto2000", "fig21a",
                 "Terrain: (a) control mesh with the heights h_i (sticks) and colours") {
    ctx.chosen("caption", "(a) control mesh with heights",
               "the captions of (a)(b) are lost in the OCR; read as fig. 22's (x)(y)");
    const int size = ctx.quick() ? 160 : 800;
    WrControlMesh mesh;
    WrSurface surface;
    AxisPair axes;
    SHITSUKAN_TRY(make_terrain_surface(0.5f, &mesh, &surface, &axes));
    RgbImage img(size, size);
    // Wider than the surface panels: the control polygon reaches beyond the B-spline surface.
    const Shot wide = zoom_shot(kShot, kShot.target + Vec3{0.3f, 0.0f, 0.3f}, 0.72f);
    draw_control_mesh(img.view(), shot_camera(wide, size, size), mesh, surface, true,
                      Rgb8{255, 255, 255});
    return ctx.save_png(img.view());
}
SHITSUKAN_FIGURE(fig21b_panel, "fujimoto2000", "fig21b",
                 "Terrain: (b) the conventional surface (c) coloured per parameter span") {
    return run_panel(ctx, 'b');
}
SHITSUKAN_FIGURE(fig21c_panel, "fujimoto2000", "fig21c",
                 "Terrain (800 x 800): (c) conventional B-spline surface") {
    return run_panel(ctx, 'c');
}
SHITSUKAN_FIGURE(fig21d_panel, "fujimoto2000", "fig21d", "Terrain: (d) WR surface (spiky)") {
    return run_panel(ctx, 'd');
}
SHITSUKAN_FIGURE(fig21e_panel, "fujimoto2000", "fig21e",
                 "Terrain: (e) superposed WR surface, delta = 0.35") {
    return run_panel(ctx, 'e');
}
SHITSUKAN_FIGURE(fig21f_panel, "fujimoto2000", "fig21f",
                 "Terrain: (f) superposed WR surface, delta = 0.55") {
    return run_panel(ctx, 'f');
}
SHITSUKAN_FIGURE(fig21g_panel, "fujimoto2000", "fig21g",
                 "Terrain: (g) superposed WR surface, delta = 0.75") {
    return run_panel(ctx, 'g');
}

SHITSUKAN_FIGURE_AFTER(
    table02_times, "fujimoto2000", "table02",
    "Execution times of fig. 21 (800 x 800): paper (Origin2000, min:sec) vs. this library",
    "fig21") {
    std::vector<std::string> names;
    std::vector<StageTimes> ours;
    std::vector<std::array<const char*, 4>> paper;
    for (const Panel& p : kPanels) {
        StageTimes t;
        if (!find_stage_times(fmt("fig21%c", p.id), &t) || t.quick != ctx.quick()) {
            RgbImage img;
            std::string params;
            SHITSUKAN_TRY(render_panel(ctx.quick(), p.id, &img, &t, nullptr, &params));
        }
        names.push_back(p.name);
        ours.push_back(t);
        paper.push_back({p.paper_sam, p.paper_pol, p.paper_ren, p.paper_total});
    }
    ctx.given("paper times", "Table 2 (Origin2000, R10000 250 MHz)", "Table 2");
    ctx.chosen("stage mapping",
               "sam. = hierarchical sampling + surface points, pol. = normals + "
               "triangles, ren. = Z-buffer rasterisation",
               "the paper's stages; ours are seconds on one shared core");
    const double ratio = ours[0].rendering > 0 ? ours[1].rendering / ours[0].rendering : 0.0;
    std::string md =
        "# Table 2: execution times of fig. 21 (800 x 800)\n\n" + stage_table(names, ours, paper) +
        (ctx.quick() ? "\n(quick run: small images, not comparable)\n" : "") +
        "\nPaper: Origin2000, min:sec. Ours: seconds. (d), the spiky WR surface, was "
        "the slowest to render in the paper (16:44 against 0:35 for (c), 29x: long "
        "thin polygons); here (d) takes " +
        fmt("%.1fx", ratio) +
        " the rendering time of (c) at the same triangle count (a Z-buffer scanline "
        "rasterizer pays per covered pixel, and the overlapping spikes are drawn over each "
        "other many times).\n";
    return ctx.save_markdown(md);
}

}  // namespace shitsukan::fujimoto2000
