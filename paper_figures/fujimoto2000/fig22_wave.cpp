// fujimoto2000 fig. 22 and Table 3: wave, 1200 x 600. (x) control mesh, (y) the conventional
// surface coloured per parameter interval, (z) conventional B-spline surface; (a-1..4) with
// the fully-connected IST N = 5 (fig. 6a), (b-1..4) with the connected IST of fig. 6b:
// 1 = WR surface (spiky), 2/3/4 = superposed with delta 0.25 / 0.50 / 0.75. K = 3, Hermite
// interpolation of the samples, displacement along per-point directions and Gaussian jitter
// of the samples (§5). The two ISTs distribute the heights differently (§5).
// Example: none of its own; examples/31_superposed_mountains.cpp teaches the superposed surface.
#include <algorithm>
#include <cmath>
#include <map>

#include "driver/figure.hpp"
#include "fujimoto2000/wr_figure_common.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/core/detmath.hpp"

namespace shitsukan::fujimoto2000 {
namespace {

using figures::FigureContext;
using figures::fmt;

constexpr int kLevels = 3;                           // K, given
constexpr float kDeltas[3] = {0.25f, 0.50f, 0.75f};  // given

// Chosen: 6 x 10 control points (3 x 7 spans) on [-3.5, 3.5] x [-2, 2]; a swell along x, the
// crest (the middle rows) pushed up and forward (direction (0, 1, crest) normalised, up
// elsewhere); heights 0.1..1.05; deep blue troughs, white crests; transparency (§5 gives the
// wave's control points one) 0.30 in the troughs to 0.05 in the foam of the crest.
// Why 3 x 7 spans (measured): the IST acts on u and v alike (a direct product, the same N and
// K on both), so its small intervals are as wide as they are long when the spans are; with the
// former 7 x 5 spans of about 1 x 0.8 world units, every step-1 small interval held one bump,
// repeating along both axes (relief correlation one step-1 interval on: 0.40-0.62 along u
// and v in row (a)): a plaid. Spans 2.3 x 0.57 units long make the small intervals long
// along the crest, so the relief runs as crests along x, as a wave's does (crest_anisotropy
// 0.76 -> 0.99; notes). The paper prints neither the mesh nor its spans.
constexpr float kMeshLengthX = 7.0f, kMeshLengthZ = 4.0f;  // the mesh's extent along x and z
WrControlMesh wave_mesh(float delta) {
    const int cols = 6, rows = 10;
    WrControlMesh m = make_control_mesh(cols, rows);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            WrControlPoint& p = m.at(c, r);
            const float x = -0.5f * kMeshLengthX + kMeshLengthX * float(c) / float(cols - 1);
            const float z = 0.5f * kMeshLengthZ - kMeshLengthZ * float(r) / float(rows - 1);
            // The former 10 x 8 mesh's crest, on the same (x, z) (its columns c' = 9 c / 5,
            // rows r' = 7 r / 9).
            const float rr = float(r) * 7.0f / float(rows - 1),
                        cc = float(c) * 9.0f / float(cols - 1);
            const float crest =
                det_expf(-(rr - 3.5f) * (rr - 3.5f) / 0.8f) * (0.7f + 0.3f * det_sin(1.3f * cc));
            p.position = {x, 0.3f * det_sin(0.9f * x + 0.5f * z), z};
            p.height = 0.1f + 0.9f * crest + 0.05f * hash_uniform(22, 0, c, r);
            p.direction = normalize(Vec3{0.0f, 1.0f, crest});
            p.color = lerp(Vec3{0.05f, 0.22f, 0.42f}, Vec3{0.95f, 0.97f, 1.0f},
                           clamp(1.5f * crest, 0.0f, 1.0f));
            p.transparency = 0.05f + 0.25f * (1.0f - clamp(1.5f * crest, 0.0f, 1.0f));
            p.delta = delta;
        }
    return m;
}

const Shot kShot{{0.0f, 2.2f, 6.6f}, {0.0f, 0.35f, 0.0f}, {0, 1, 0}, 29.0f};
// Table 3: 1200 x 600 per panel (each panel rendered on its own); the composite is an overview
// of 300 x 150 cells (each full panel shrunk 4x).
constexpr int kPanelW = 1200, kPanelH = 600;
constexpr int kCellW = 300, kCellH = 150;

// What the superposed panels must not be: a plaid of round bumps. Measured on the relief
// r = eq. (20)'s height - the plain height, along 16 rows (in u) and 16 columns (in v), each
// sampled at 3/2 of the step-K small intervals, with the parameter steps converted to world
// lengths along x (len_u) and z (len_v): J_x = mean (dr/dx)^2, J_z = mean (dr/dz)^2 and
// crest_anisotropy = (J_z - J_x) / (J_z + J_x): 0 for bumps alike along x and z (a plaid),
// towards 1 for crests running along x (the relief changes across them, along z).
struct ReliefShape {
    double anisotropy = 0;          // crest_anisotropy
    double repetition[2] = {0, 0};  // along u, v: correlation with the relief one span on
};
// A parameter located once: its spline basis and its sample weights for k = 1..K (the
// same bits as locating it per point, hierarchical_sampling.hpp).
struct Located {
    WrBasisAt basis;
    std::vector<SampleWeights> weights;
};
Located locate(const WrSurface& surface, const HierarchicalSampling& hs, int axis, float x) {
    Located l;
    l.basis = axis == 0 ? surface.basis_u(x) : surface.basis_v(x);
    for (int k = 1; k <= hs.levels(); ++k)
        l.weights.push_back(axis == 0 ? hs.weights_u(k, x) : hs.weights_v(k, x));
    return l;
}

ReliefShape relief_shape(const WrSurface& surface, const HierarchicalSampling& hs, float len_u,
                         float len_v) {
    auto relief = [&](const Located& lu, const Located& lv, float u, float v) {
        return double(superposed_sampled(surface, hs, lu.basis, lv.basis, lu.weights.data(),
                                         lv.weights.data(), u, v, 0.0f)
                          .attributes.height) -
               double(surface.attributes(lu.basis, lv.basis).height);
    };
    ReliefShape out;
    double j[2] = {0, 0};
    for (int axis = 0; axis < 2; ++axis) {
        const WrAxis& a = axis == 0 ? surface.axis_u() : surface.axis_v();
        long n = a.base_intervals;
        for (int k = 0; k < hs.levels(); ++k) n *= a.division;
        n = n * 3 / 2;
        const long lag = n / (long(a.base_intervals) * a.division);
        const double step = double(axis == 0 ? len_u : len_v) / double(n);
        std::vector<Located> along_at(static_cast<std::size_t>(n));
        for (long i = 0; i < n; ++i)
            along_at[std::size_t(i)] = locate(surface, hs, axis, (float(i) + 0.5f) / float(n));
        long count = 0;
        double c = 0, c0 = 0, c1 = 0;
        for (int p = 0; p < 16; ++p) {
            const float across = (float(p) + 0.5f) / 16.0f;
            const Located across_at = locate(surface, hs, 1 - axis, across);
            std::vector<double> r(std::size_t(n), 0.0);
            double mean = 0;
            for (long i = 0; i < n; ++i) {
                const float along = (float(i) + 0.5f) / float(n);
                const Located& la = along_at[std::size_t(i)];
                r[std::size_t(i)] = axis == 0 ? relief(la, across_at, along, across)
                                              : relief(across_at, la, across, along);
                mean += r[std::size_t(i)];
                if (i > 0) {
                    const double d = r[std::size_t(i)] - r[std::size_t(i - 1)];
                    j[axis] += d * d / (step * step), ++count;
                }
            }
            mean /= double(n);
            for (long i = 0; i + lag < n; ++i) {
                const double x = r[std::size_t(i)] - mean, y = r[std::size_t(i + lag)] - mean;
                c += x * y, c0 += x * x, c1 += y * y;
            }
        }
        j[axis] /= double(count);
        out.repetition[axis] = c0 > 0 && c1 > 0 ? c / std::sqrt(c0 * c1) : 0.0;
    }
    out.anisotropy = j[0] + j[1] > 0 ? (j[1] - j[0]) / (j[1] + j[0]) : 0.0;
    return out;
}

// One panel: kind 'x' mesh, 'y' spans, 'z' plain, or IST row ('a' fully, 'b' fig6b) with
// column 1 (WR) .. 4 (delta 0.75).
Status draw_panel(bool quick, char row, int col, RgbView view, StageTimes* t) {
    const int w = view.width, h = view.height;
    const float delta = col >= 2 ? kDeltas[col - 2] : 0.5f;
    WrControlMesh mesh = wave_mesh(delta);
    WrSurface surface;
    SHITSUKAN_TRY(make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface));
    const int levels = quick ? 2 : kLevels;  // quick: 5^2 instead of 5^3 small intervals
    AxisPair axes;
    SHITSUKAN_TRY(make_axes(surface, row == 'b' ? IstKind::connected : IstKind::fully_connected,
                            "fig6b", 5, levels, &axes));
    SHITSUKAN_TRY(surface.set_axes(axes.u.axis(), axes.v.axis()));
    Shading shading;
    shading.background = Rgb8{232, 236, 240};
    const Camera camera = shot_camera(kShot, w, h);
    if (row == 'x') {
        draw_control_mesh(view, camera, mesh, surface, true, shading.background);
        return Status::success();
    }
    // Grid: step 2, 2 vertices per interval (chosen: cells of about 7.5 px along x, where the
    // crests change little, and 1.8 px along z at 1200 x 600; step 3 would take ~25x the
    // vertices for detail of about one pixel, and the paper's own figure is printed far
    // smaller).
    WrTessellationOptions o;
    o.grid_level = quick ? 1 : 2;
    o.subdivisions = quick ? 1 : 2;
    o.levels = levels;
    HierarchicalSampling hs;
    auto t0 = Clock::now();
    if (row == 'y' || row == 'z') {
        o.form = WrSurfaceForm::plain;
    } else if (col == 1) {
        o.form = WrSurfaceForm::wr;
    } else {
        HierarchicalOptions ho;
        ho.levels = levels;
        ho.interpolation = SampleInterpolation::hermite;
        ho.jitter_height = 0.15f;
        ho.jitter_color = 0.04f;
        ho.jitter_transparency = 0.04f;
        ho.seed = 22;
        SHITSUKAN_TRY(sample_hierarchy(surface, ho, hs));
        o.form = WrSurfaceForm::superposed;
    }
    WrMesh wm;
    SHITSUKAN_TRY(
        evaluate_wr_grid(surface, o.form == WrSurfaceForm::superposed ? &hs : nullptr, o, wm));
    t->sampling = seconds_since(t0);
    t0 = Clock::now();
    polygonise_wr_grid(surface, &wm);
    t->polygonisation = seconds_since(t0);
    if (row == 'y') color_by_source_span(&wm, surface, 0);
    t0 = Clock::now();
    if (row == 'y')
        SHITSUKAN_TRY(render_opaque(camera, wm.mesh, view, shading));
    else
        SHITSUKAN_TRY(render_transparent(camera, wm, view, shading, nullptr, &t->seen));
    t->rendering = seconds_since(t0);
    t->triangles = wm.mesh.triangle_count();
    t->mean_offset = mean_offset(surface, wm);
    t->grid_level = o.grid_level;
    t->levels = levels;
    t->quick = quick;
    if (o.form == WrSurfaceForm::superposed) {
        const ReliefShape rs = relief_shape(surface, hs, kMeshLengthX, kMeshLengthZ);
        t->relief_anisotropy = rs.anisotropy;
        t->relief_repetition[0] = rs.repetition[0];
        t->relief_repetition[1] = rs.repetition[1];
    }
    return Status::success();
}

// Renders every panel: those of Table 3 at 1200 x 600 each (saved as fig22_<panel>.png when
// `save_prefix` is given), the mesh and span panels at cell size; the composite shows them all
// shrunk into 300 x 150 cells.
Status build_fig22(bool quick, RgbImage* img, std::map<std::string, StageTimes>* times,
                   const std::string& save_prefix) {
    const int s = quick ? 4 : 1;  // quick: a quarter of every size
    const int pw = kPanelW / s, ph = kPanelH / s, cw = kCellW / s, ch = kCellH / s;
    *img = RgbImage(4 * cw, 3 * ch, Rgb8{255, 255, 255});
    struct P {
        char row;
        int col;
        int gx, gy;
        const char* label;
        const char* file;  // per-panel file (Table 3 panels)
    };
    const P panels[] = {{'x', 0, 0, 0, "(x)", nullptr}, {'y', 0, 1, 0, "(y)", nullptr},
                        {'z', 0, 2, 0, "(z)", "_z"},    {'a', 1, 0, 1, "(a-1)", "_a1"},
                        {'a', 2, 1, 1, "(a-2)", "_a2"}, {'a', 3, 2, 1, "(a-3)", "_a3"},
                        {'a', 4, 3, 1, "(a-4)", "_a4"}, {'b', 1, 0, 2, "(b-1)", "_b1"},
                        {'b', 2, 1, 2, "(b-2)", "_b2"}, {'b', 3, 2, 2, "(b-3)", "_b3"},
                        {'b', 4, 3, 2, "(b-4)", "_b4"}};
    for (const P& p : panels) {
        RgbView cell = img->view().subview(p.gx * cw, p.gy * ch, cw, ch);
        StageTimes t;
        if (p.file) {
            RgbImage full(pw, ph);
            SHITSUKAN_TRY(draw_panel(quick, p.row, p.col, full.view(), &t));
            if (!save_prefix.empty())
                SHITSUKAN_TRY(write_png((save_prefix + p.file + ".png").c_str(), full.view()));
            downsample_into(full.view(), cell);
            (*times)[p.label] = t;
        } else {
            SHITSUKAN_TRY(draw_panel(quick, p.row, p.col, cell, &t));
        }
        if (!quick) label_panel(cell, p.label, Rgb8{20, 20, 20});
    }
    // The free cell: what the rows are.
    RgbView legend = img->view().subview(3 * cw, 0, cw, ch);
    if (!quick) {
        RasterCanvas c(legend);
        c.text({12, 12}, "fig. 22 wave", Rgb8{0, 0, 0}, 2);
        c.text({12, 44}, "(a) fully-connected N=5", Rgb8{0, 0, 0}, 1);
        c.text({12, 62}, "(b) connected IST fig. 6b", Rgb8{0, 0, 0}, 1);
        c.text({12, 80}, "1 WR, 2/3/4 delta .25/.50/.75", Rgb8{0, 0, 0}, 1);
        c.text({12, 98}, "K = 3, Hermite, jitter", Rgb8{0, 0, 0}, 1);
        c.text({12, 116}, "panels: fig22_*.png 1200x600", Rgb8{0, 0, 0}, 1);
    }
    return Status::success();
}

}  // namespace

SHITSUKAN_FIGURE(
    fig22_wave, "fujimoto2000", "fig22",
    "Wave (1200 x 600): mesh, spans, plain; (a) fully-connected N = 5, (b) fig. 6b IST; "
    "1 WR, 2-4 superposed delta 0.25/0.50/0.75") {
    ctx.given("image size", "1200 x 600 per panel", "Table 3");
    ctx.chosen("composite",
               "an overview: 11 panels shrunk into 300 x 150 cells; the panels of "
               "Table 3 are written at full size as fig22_z.png, fig22_a1.png .. "
               "fig22_b4.png",
               "Table 3 times each panel at 1200 x 600");
    ctx.given("K", "3", "fig. 22 caption");
    ctx.given("sample interpolation", "Hermite", "fig. 22 caption");
    ctx.given("deltas", "0.25, 0.50, 0.75", "fig. 22 caption");
    ctx.given("ISTs", "(a) fully-connected N = 5 (fig. 6a), (b) fig. 6b", "fig. 22 caption");
    ctx.chosen("control mesh",
               "6 x 10 (3 x 7 spans, each about 2.3 x 0.57 units), swell along x, crest rows "
               "pushed up and forward, heights 0.1..1.05",
               "not printed; spans long along the crest so that the IST's small intervals, "
               "alike on u and v, run as crests rather than a plaid of bumps");
    ctx.chosen("jitter", "height x(1 + 0.15 g), colour + 0.04 g, transparency + 0.04 g",
               "§5 gives no deviation");
    ctx.given("transparency per control point", "yes, sampled and superposed like the heights",
              "§5 (figs. 22, 23)");
    ctx.chosen("transparency values", "0.30 in the troughs .. 0.05 in the crest's foam",
               "not printed; clear water, opaque foam");
    ctx.chosen("transparency rendering",
               "back-to-front sort of triangles + Z-buffer + blend (as fig. 23), Lambert shading",
               "the paper does not say how it blended");
    ctx.chosen("adaptive sampling", "grid: step 2, 2 vertices per interval",
               "cells of about 7.5 x 1.8 px on a 1200 x 600 panel (step 2)");
    RgbImage img;
    std::map<std::string, StageTimes> times;
    SHITSUKAN_TRY(build_fig22(ctx.quick(), &img, &times, ctx.path("")));
    for (const auto& kv : times) record_stage_times("fig22" + kv.first, kv.second);
    const double plain = times["(z)"].mean_offset;
    ctx.note(
        fmt("Total height kept (eq. 18): mean displacement from the base surface relative "
            "to (z): (a-2) %.1f %%, (a-3) %.1f %%, (a-4) %.1f %%; (b-2) %.1f %%, (b-3) "
            "%.1f %%, (b-4) %.1f %% (jitter included).",
            100 * times["(a-2)"].mean_offset / plain, 100 * times["(a-3)"].mean_offset / plain,
            100 * times["(a-4)"].mean_offset / plain, 100 * times["(b-2)"].mean_offset / plain,
            100 * times["(b-3)"].mean_offset / plain, 100 * times["(b-4)"].mean_offset / plain));
    std::string seen =
        "Transparency, measured (coverage of the frame; mean share of the colour "
        "that is the background seen through the water; share from the wave's "
        "own layers behind its front one):";
    for (const char* label : {"(z)", "(a-3)", "(b-3)"}) {
        const TransparencySeen& v = times[label].seen;
        seen +=
            fmt(" %s %.1f %%, %.2f, %.2f;", label, 100.0 * v.coverage, v.background, v.see_through);
        if (v.background + v.see_through < 0.1)
            return Status::error(StatusCode::not_supported,
                                 "fig22 %s: the water shows nothing through it (§5 gives it a "
                                 "transparency)",
                                 label);
    }
    ctx.note(seen);
    std::string crests =
        "Crests, measured (crest_anisotropy in the source: 0 = a plaid of round "
        "bumps, towards 1 = crests along x):";
    for (const char* label : {"(a-2)", "(a-3)", "(a-4)", "(b-2)", "(b-3)", "(b-4)"})
        crests += fmt(" %s %.2f (repetition u %.2f, v %.2f)", label, times[label].relief_anisotropy,
                      times[label].relief_repetition[0], times[label].relief_repetition[1]);
    ctx.note(crests + ".");
    // The wave's relief runs as crests along x (the check holds the full run).
    for (const char* label : {"(a-2)", "(a-3)", "(a-4)", "(b-2)", "(b-3)", "(b-4)"})
        if (!ctx.quick() && times[label].relief_anisotropy < 0.9)
            return Status::error(StatusCode::not_supported,
                                 "fig22 %s: crest anisotropy %.2f: the relief is a plaid of "
                                 "bumps, not crests along x",
                                 label, times[label].relief_anisotropy);
    ctx.note(
        fmt("Per-panel images (%d x %d): fig22_z.png, fig22_a1.png .. fig22_a4.png, "
            "fig22_b1.png .. fig22_b4.png; this image is the overview.",
            ctx.quick() ? kPanelW / 4 : kPanelW, ctx.quick() ? kPanelH / 4 : kPanelH));
    return ctx.save_png(img.view());
}

SHITSUKAN_FIGURE_AFTER(
    table03_times, "fujimoto2000", "table03",
    "Execution times of fig. 22 (1200 x 600): paper (Origin2000, min:sec) vs. this library",
    "fig22") {
    const std::vector<PaperTimes> rows = {{"(z)", {"4:23", "0:52", "1:27", "6:42"}},
                                          {"(a-1)", {"4:50", "0:52", "161:24", "167:06"}},
                                          {"(a-2)", {"10:43", "0:53", "1:32", "13:08"}},
                                          {"(a-3)", {"10:42", "0:52", "2:46", "14:20"}},
                                          {"(a-4)", {"10:43", "0:52", "6:46", "18:21"}},
                                          {"(b-1)", {"4:53", "0:52", "74:53", "80:38"}},
                                          {"(b-2)", {"10:47", "0:52", "1:28", "13:07"}},
                                          {"(b-3)", {"10:48", "0:52", "2:07", "13:47"}},
                                          {"(b-4)", {"10:47", "0:52", "4:09", "15:48"}}};
    std::map<std::string, StageTimes> times;
    StageTimes probe;
    if (!find_stage_times("fig22(z)", &probe) || probe.quick != ctx.quick()) {
        RgbImage img;
        SHITSUKAN_TRY(build_fig22(ctx.quick(), &img, &times, ""));
    }
    ctx.given("paper times", "Table 3 (Origin2000, R10000 250 MHz)", "Table 3");
    ctx.chosen("stage mapping",
               "sam. = hierarchical sampling + surface points, pol. = normals + "
               "triangles, ren. = Z-buffer",
               "the paper's stages");
    return ctx.save_markdown(
        "# Table 3: execution times of fig. 22 (1200 x 600 per panel)\n\n" +
        stage_table("fig22", rows, times) +
        (ctx.quick() ? "\n(quick run: small images, not comparable)\n" : "") +
        "\nPaper: Origin2000, min:sec, each panel rendered on its own at 1200 x 600. Ours: "
        "seconds for the same panel at 1200 x 600 (fig22_<panel>.png).\n");
}

}  // namespace shitsukan::fujimoto2000
