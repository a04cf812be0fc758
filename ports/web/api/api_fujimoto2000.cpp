// ports/web/api/api_fujimoto2000.cpp — the C API of the fujimoto2000 panel (§2, the Iterated
// Shuffle Transformation): the digit diagrams of figs. 3-9 for any N, K, B, kind and ends
// (drawn by the figures' own paper_figures/fujimoto2000/ist_diagram.cpp), a point u followed
// forward and back by the procedure (div / in-shf / ex-shf, ist_procedure.hpp) beside the
// scale reverse formulas (eqs. 7, 12 on the digits, eqs. 9, 10, 14 on u: ist_digits.hpp,
// ist_formula.hpp), the IST's table (ist_table.hpp) and Table 1's ratio measured live.
// State: the axis of the last successful sk_fujimoto2000_axis call.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "api_common.hpp"
#include "fujimoto2000/ist_diagram.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/wrinkly/ist.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

IstAxis g_axis;
bool g_have_axis = false;

// The kinds the panel offers: the unit-IST (§2.2.1), the fully-connected IST (fig. 6a, fig. 8)
// and the connected ISTs of figs. 6b, 7a, 7b (no external shuffle), 7c by their library names.
const char* const kShuffleNames[] = {nullptr, "fully", "fig6b", "fig7a", "none", "fig7c"};
constexpr int kKinds = 6;

// Chosen here: a diagram draws at most this many sub-intervals on its deepest axis (B N^K);
// beyond it the boxes are thinner than a pixel at the widest picture and say nothing.
constexpr std::uint64_t kMaxDiagramPieces = 20000;

Status need_axis() {
    if (!g_have_axis)
        return Status::error(StatusCode::invalid_argument,
                             "no IST yet: call sk_fujimoto2000_axis (ist_*_axis) first");
    return Status::success();
}

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string digits_text(const IstDigits& a) {
    char buf[96];
    return ist_digits_format(a, 0, buf, int(sizeof buf));
}

}  // namespace

// Selects the IST: kind 0 unit (ist_unit_axis), 1 fully-connected (ist_fully_connected_axis),
// 2..5 connected with the external shuffle of fig. 6b, 7a, 7b (none), 7c (ist_shuffle_named,
// ist_connected_axis); ends 0 cyclic, 1 translation (fig. 9). The library judges N, K, B and
// the pairing; the text gives N^K and the shuffle table (group: offset, slot).
SK_API int sk_fujimoto2000_axis(int kind, int n, int k, int b, int ends) {
    if (kind < 0 || kind >= kKinds)
        return skweb::finish(Status::error(StatusCode::invalid_argument,
                                           "kind must be 0 (unit) .. 5 (got %d)", kind));
    if (ends < 0 || ends > 1)
        return skweb::finish(Status::error(StatusCode::invalid_argument,
                                           "ends must be 0 (cyclic) or 1 (translation) (got %d)", ends));
    const IstEnds e = ends ? IstEnds::translation : IstEnds::cyclic;
    IstAxis axis;
    Status s;
    if (kind == 0) {
        s = ist_unit_axis(n, k, b, axis);
        if (s && e == IstEnds::translation) axis.ends = e;  // a unit-IST never leaves its base
    } else if (kind == 1) {
        s = ist_fully_connected_axis(n, k, b, e, axis);
    } else {
        IstShuffle shuffle;
        s = ist_shuffle_named(kShuffleNames[kind], n, shuffle);
        if (s) s = ist_connected_axis(shuffle, k, b, e, axis);
    }
    if (!s) return skweb::finish(s);
    g_axis = axis;
    g_have_axis = true;
    std::string& t = skweb::text();
    t = "{\"N\":" + std::to_string(axis.n) + ",\"K\":" + std::to_string(axis.iterations) +
        ",\"B\":" + std::to_string(axis.base_intervals) +
        ",\"sub_intervals\":" + std::to_string(ist_sub_interval_count(axis)) + ",\"shuffle\":[";
    if (axis.kind != IstKind::unit)
        for (int g = 0; g < axis.shuffle.n; ++g)
            t += std::string(g ? "," : "") + "[" + std::to_string(int(axis.shuffle.offset[g])) + "," +
                 std::to_string(int(axis.shuffle.slot[g])) + "]";
    t += "]}";
    return skweb::finish(Status::success());
}

// The digit diagram of figs. 3-9 for the current IST: u* (the divisions unshuffled), u^0 ..
// u^K, with the intermediate axes u^{k.5} (div + in-shf before ex-shf) when half_axes; the
// sub-interval holding u followed from axis to axis. Base intervals numbered from first_label;
// window_bases > 0 shows that many base intervals around the one holding u (figs. 6-8 show 5
// of a long axis), 0 all. width: the picture's width in pixels (400 .. 4000).
SK_API int sk_fujimoto2000_diagram(int half_axes, double u, int first_label, int window_bases, int width) {
    Status s = need_axis();
    if (s && (width < 400 || width > 4000))
        s = Status::error(StatusCode::invalid_argument, "width must be in 400..4000 px (got %d)", width);
    if (s && !(u >= 0.0 && u <= 1.0))
        s = Status::error(StatusCode::out_of_range, "u must be in [0, 1] (got %g)", u);
    const std::uint64_t pieces = s ? ist_sub_interval_count(g_axis) * std::uint64_t(g_axis.base_intervals) : 0;
    if (s && pieces > kMaxDiagramPieces)
        s = Status::error(StatusCode::too_large,
                          "the diagram would draw B N^K = %llu sub-intervals on u^K (at most %llu: "
                          "lower N, K or B)",
                          static_cast<unsigned long long>(pieces),
                          static_cast<unsigned long long>(kMaxDiagramPieces));
    if (!s) return skweb::finish(s);
    IstDiagram d;
    d.ist.axis = g_axis;
    d.first_label = first_label;
    const int B = g_axis.base_intervals, K = g_axis.iterations;
    d.unit_labels = g_axis.kind == IstKind::unit && B == 1;
    if (window_bases > 0 && window_bases < B) {
        const int holder = std::min(B - 1, int(u * B));
        int lo = std::max(0, holder - window_bases / 2);
        lo = std::min(lo, B - window_bases);
        d.window0 = double(lo) / B;
        d.window1 = double(lo + window_bases) / B;
    }
    d.rows.push_back(diagram_row(d.ist, "u*", K, DiagramStage{0, false}));
    char name[16];
    for (int k = 0; k <= K; ++k) {
        std::snprintf(name, sizeof name, "u^%d", k);
        DiagramRow row = diagram_row(d.ist, name, k, DiagramStage{k, false});
        if (k < K) row.tick_depth = k + 1;
        d.rows.push_back(row);
        if (half_axes && k < K && g_axis.kind != IstKind::unit) {
            std::snprintf(name, sizeof name, "u^%d.5", k);
            d.rows.push_back(diagram_row(d.ist, name, k + 1, DiagramStage{k, true}));
        }
    }
    d.follow = [u](const DiagramPiece& p) { return p.start0 <= u && (u < p.end0 || (u == 1.0 && p.end0 == 1.0)); };
    DiagramLayout layout;
    layout.top = 40;
    layout.left = 70;
    layout.row_height = 40;
    layout.gap = 34;
    layout.width = float(width) - layout.left - 16.0f;
    RgbImage image(width, int(diagram_height(d, layout)), Rgb8{255, 255, 255});
    RasterCanvas canvas(image.view());
    draw_ist_diagram(canvas, d, layout);
    skweb::set_picture(image);
    return skweb::finish(Status::success());
}

// A point u of u^0 followed through the current IST, both ways, both methods.
// Floats: rows of 4 (k, position after div + in-shf of iteration k, position after ex-shf of
// iteration k, base interval then) for k = 1..K, from ist_procedure_start,
// ist_divide_and_shuffle_internally, ist_shuffle_externally; row 0 is (0, u, u, base of u).
// Text: the procedure's result and the formula's (ist_procedure_forward, ist_forward_double),
// the sub-interval alpha^0 holding u with its offset (eq. 9, ist_locate), alpha^K by the
// iterations one at a time (ist_digits_forward_by_steps) and by the scale reverse formula
// (eq. 7 unit, eq. 12 fully connected: ist_scale_reverse_*), and the way back
// (ist_procedure_inverse, ist_inverse_double).
SK_API int sk_fujimoto2000_follow(double u) {
    Status s = need_axis();
    if (s && !(u >= 0.0 && u <= 1.0))
        s = Status::error(StatusCode::out_of_range, "u must be in [0, 1] (got %g)", u);
    if (!s) return skweb::finish(s);
    const IstAxis& a = g_axis;
    std::vector<float>& out = skweb::floats();
    IstPoint p;
    ist_procedure_start(a, nullptr, u, &p);
    out = {0.0f, float(p.u), float(p.u), float(p.base)};
    for (int k = 1; k <= a.iterations; ++k) {
        ist_divide_and_shuffle_internally(a, nullptr, &p);
        const double half = p.u;
        ist_shuffle_externally(a, nullptr, &p);
        out.insert(out.end(), {float(k), float(half), float(p.u), float(p.base)});
    }
    skweb::set_float_columns(4);
    const double v_proc = ist_procedure_forward(a, u), v_form = ist_forward_double(a, u);
    IstLocation loc;
    ist_locate(a, u, &loc);
    IstDigits steps, formula, back;
    ist_digits_forward_by_steps(a, loc.alpha, &steps);
    std::string formula_name = "none (a general connected IST has no scale reverse formula: "
                               "the iterations one by one)";
    if (a.kind == IstKind::unit) {
        ist_scale_reverse_unit(loc.alpha, &formula);
        formula_name = "eq. (7) alpha^K_i = alpha^0_{K-i+1}";
    } else if (a.kind == IstKind::fully_connected) {
        ist_scale_reverse_fully_connected(a.n, loc.alpha, &formula);
        formula_name = "eq. (12) alpha^K_0 = alpha^0_0 + sum(alpha^0_j - M), alpha^K_i = N-1-alpha^0_{K-i+1}";
        if (a.ends == IstEnds::translation)
            formula_name += " (a translation axis skips moves past its ends: the iterations decide there)";
    } else {
        formula = steps;
    }
    ist_digits_inverse(a, steps, &back);
    std::string& t = skweb::text();
    t = "{\"u\":" + number(u) + ",\"v_procedure\":" + number(v_proc) + ",\"v_formula\":" + number(v_form) +
        ",\"agree\":" + (v_proc == v_form ? "true" : "false") +
        ",\"back_procedure\":" + number(ist_procedure_inverse(a, v_proc)) +
        ",\"back_formula\":" + number(ist_inverse_double(a, v_form)) +
        ",\"alpha0\":" + skweb::json_string(digits_text(loc.alpha).c_str()) +
        ",\"offset\":" + number(loc.offset) +
        ",\"alphaK_steps\":" + skweb::json_string(digits_text(steps).c_str()) +
        ",\"alphaK_formula\":" + skweb::json_string(digits_text(formula).c_str()) +
        ",\"formula\":" + skweb::json_string(formula_name.c_str()) +
        ",\"alpha0_back\":" + skweb::json_string(digits_text(back).c_str()) + "}";
    return skweb::finish(Status::success());
}

// The IST's table (figs. 3, 6: alpha^0 -> alpha^K, one pair a line), as ist_table writes it,
// base intervals numbered from first_label; refused (too_large) beyond max_lines pairs.
SK_API int sk_fujimoto2000_table(int first_label, int max_lines) {
    Status s = need_axis();
    if (s && max_lines < 1)
        s = Status::error(StatusCode::invalid_argument, "max_lines must be >= 1 (got %d)", max_lines);
    if (!s) return skweb::finish(s);
    IstTableOptions o;
    o.first = first_label;
    o.max_lines = std::uint64_t(max_lines);
    std::string& t = skweb::text();
    t.clear();
    auto line = [](const char* text, void* user) {
        std::string& out = *static_cast<std::string*>(user);
        out += text;
        out += '\n';
    };
    s = ist_table(g_axis, o, line, &t);
    if (!s) t.clear();
    return skweb::finish(s);
}

// Table 1's measure on the current IST: microseconds per coordinate of the step-by-step
// procedure (ist_procedure_forward, the implementation the paper timed as ref. 13) and of the
// scale reverse formula (ist_forward, eq. 14), on `coordinates` values of Pcg32(2000, 1) as
// paper_figures/fujimoto2000/table01_ist_speed.cpp draws them, timed in turns in chunks of
// 1000. Text: both times, their ratio (live: it varies with the machine's load, never hashed),
// and the largest |procedure - formula| over the coordinates (the same transformation).
SK_API int sk_fujimoto2000_ratio(int coordinates) {
    Status s = need_axis();
    if (s && (coordinates < 1000 || coordinates > 2000000))
        s = Status::error(StatusCode::invalid_argument, "coordinates must be in 1000..2000000 (got %d)",
                          coordinates);
    if (!s) return skweb::finish(s);
    Pcg32 rng(2000u, 1u);
    std::vector<float> u(static_cast<std::size_t>(coordinates));
    for (float& x : u) x = rng.uniform();
    std::vector<double> vp(u.size());
    std::vector<float> vf(u.size());
    double t_proc = 0.0, t_form = 0.0;
    const int chunk = 1000;
    shitsukan::Progress progress = skweb::progress();
    for (int c0 = 0; c0 < coordinates; c0 += chunk) {
        const int c1 = std::min(coordinates, c0 + chunk);
        double t0 = skweb::now_ms();
        for (int i = c0; i < c1; ++i) vp[std::size_t(i)] = ist_procedure_forward(g_axis, double(u[std::size_t(i)]));
        t_proc += skweb::now_ms() - t0;
        t0 = skweb::now_ms();
        for (int i = c0; i < c1; ++i) vf[std::size_t(i)] = ist_forward(g_axis, u[std::size_t(i)]);
        t_form += skweb::now_ms() - t0;
        progress.report(float(c1) / float(coordinates));
    }
    double worst = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) worst = std::max(worst, std::fabs(vp[i] - double(vf[i])));
    const double us = 1000.0 / double(coordinates);
    std::string& t = skweb::text();
    t = "{\"coordinates\":" + std::to_string(coordinates) + ",\"procedure_us\":" + number(t_proc * us) +
        ",\"formula_us\":" + number(t_form * us) + ",\"ratio\":" + number(t_form > 0 ? t_proc / t_form : 0.0) +
        ",\"max_difference\":" + number(worst) + "}";
    return skweb::finish(Status::success());
}

// ---- WR surfaces (§3, §4: eqs. 15, 16, 19, 20; figs. 14-18) ----
namespace {

// Chosen here (the panel's own meshes, in the spirit of figs. 14/17 and 15/18): a 4 x 4 Bezier
// patch (IST-Bezier, unit-IST N = 3) or an 11 x 11 uniform cubic B-spline (IST-B-spline,
// fully-connected IST N = 3, translation ends: 8 spans = 8 base intervals) over [-1.2, 1.2]^2
// in the x-z plane; heights h_i = 0.05 + 0.9 hash_uniform(seed, 15, c, r) (0.45 of that for the
// B-spline's denser points), coloured green (low) to pale (high).
struct WrScene {
    WrControlMesh mesh;
    WrSurface surface;
    WrIstAxis u, v;
};
WrScene g_wr;
bool g_have_wr = false;
int g_wr_figure = -1;
unsigned g_wr_seed = 0;
float g_wr_delta = 0.0f;
WrMesh g_wr_mesh;     // the last tessellation, redrawn while only the view turns
int g_mesh_form = -1, g_mesh_k = -1;
float g_mesh_jitter = -1.0f;  // the jitter g_wr_mesh was sampled with (0 unless superposed)

Status make_scene(int figure, unsigned seed, float delta, WrScene* out) {
    const int n = figure == 0 ? 4 : 11;
    const float hmax = figure == 0 ? 0.95f : 0.5f;
    out->mesh = make_control_mesh(n, n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            WrControlPoint& p = out->mesh.at(c, r);
            p.position = {-1.2f + 2.4f * float(c) / float(n - 1), 0.0f, 1.2f - 2.4f * float(r) / float(n - 1)};
            p.height = 0.05f + (hmax - 0.05f) * hash_uniform(seed, 15, c, r, 0);
            const float t = p.height / hmax;
            p.color = Vec3{0.50f + 0.38f * t, 0.58f + 0.26f * t, 0.34f + 0.44f * t};
            p.delta = delta;
        }
    Status s = make_wr_surface(out->mesh, figure == 0 ? SurfaceBasis::bezier : SurfaceBasis::bspline, 3,
                               out->surface);
    IstAxis iu, iv;
    if (s && figure == 0) s = ist_unit_axis(3, 1, out->surface.spans_u(), iu);
    if (s && figure == 0) s = ist_unit_axis(3, 1, out->surface.spans_v(), iv);
    if (s && figure == 1) s = ist_fully_connected_axis(3, 1, out->surface.spans_u(), IstEnds::translation, iu);
    if (s && figure == 1) s = ist_fully_connected_axis(3, 1, out->surface.spans_v(), IstEnds::translation, iv);
    if (s) s = make_wr_ist_axis(iu, kMaxWrLevel, out->u);
    if (s) s = make_wr_ist_axis(iv, kMaxWrLevel, out->v);
    if (s) s = out->surface.set_axes(out->u.axis(), out->v.axis());
    return s;
}

// g_wr tessellated into g_wr_mesh: form 0 conventional (grid level 2), 1 WR (eq. 15) to K,
// 2 superposed (eq. 20) to max(K, 1) with §4.2's Hermite sampling and §5's Gaussian jitter on
// the height samples, x(1 + jitter g), g drawn from the heights' seed (sample_hierarchy judges
// the jitter). On failure g_wr_mesh is marked stale.
Status tessellate_wr(int figure, int form, int K, float jitter, unsigned seed) {
    g_mesh_form = -1;
    WrTessellationOptions o;
    HierarchicalSampling hs;
    o.progress = skweb::progress();
    o.levels = K;
    o.grid_level = K;
    o.subdivisions = figure == 0 ? 8 : 2;  // chosen here: about 3^K x 8 cells along an axis
    if (form == 0) {
        o.form = WrSurfaceForm::plain;
        o.grid_level = 2;
    } else if (form == 1) {
        o.form = WrSurfaceForm::wr;
    } else {
        HierarchicalOptions ho;
        ho.levels = std::max(K, 1);
        ho.interpolation = SampleInterpolation::hermite;
        ho.jitter_height = jitter;
        ho.seed = seed;
        SHITSUKAN_TRY(sample_hierarchy(g_wr.surface, ho, hs));
        o.form = WrSurfaceForm::superposed;
        o.levels = ho.levels;
        o.grid_level = ho.levels;
    }
    SHITSUKAN_TRY(tessellate_wr_surface(g_wr.surface, form == 2 ? &hs : nullptr, o, g_wr_mesh));
    g_mesh_form = form, g_mesh_k = K, g_mesh_jitter = jitter;
    return Status::success();
}

}  // namespace

// A WR surface tessellated by the library (tessellate_wr_surface) and drawn by its rasterizer
// (draw_mesh, Z-buffer, two-sided Lambert on the vertex colours), turned by yaw and pitch.
// figure 0: IST-Bezier (unit-IST, figs. 14, 17), 1: IST-B-spline (fully-connected, figs. 15, 18).
// form 0: the conventional surface P + H N; 1: the WR surface of eq. (15) with F^K; 2: the
// superposed WR surface of eq. (20) to K with the ratio delta (eq. 19) and the hierarchical
// Hermite sampling of §4.2, the height samples jittered by §5's Gaussian x(1 + jitter g) (fig.
// 17's 0.5, fig. 18's 0.12; 0 = none; g from seed, the heights' seed; forms 0 and 1 ignore it).
// The tessellation is kept while only yaw and pitch change (the mouse turns the view); a new
// figure, seed, delta, form, K or (superposed) jitter makes a new one. Text: vertices,
// triangles, grid, levels used, milliseconds.
SK_API int sk_fujimoto2000_wr(int figure, int form, float delta, int K, unsigned seed, float jitter, float yaw,
                              float pitch, int size) {
    Status s = Status::success();
    if (figure < 0 || figure > 1)
        s = Status::error(StatusCode::invalid_argument, "figure must be 0 (IST-Bezier) or 1 (IST-B-spline) (got %d)", figure);
    if (s && (form < 0 || form > 2))
        s = Status::error(StatusCode::invalid_argument, "form must be 0 (conventional), 1 (WR) or 2 (superposed) (got %d)", form);
    if (s && (size < 64 || size > 1024))
        s = Status::error(StatusCode::invalid_argument, "size must be in 64..1024 px (got %d)", size);
    if (s && (K < 0 || K > 5))  // chosen here: K = 5 on the B-spline is 1945^2 vertices' worth of work
        s = Status::error(StatusCode::out_of_range, "K must be in 0..5 in the browser (got %d)", K);
    if (s && !(delta > 0.0f && delta < 1.0f))
        s = Status::error(StatusCode::out_of_range, "delta must be in (0, 1) (eq. 19) (got %g)", double(delta));
    if (!s) return skweb::finish(s);
    const double t0 = skweb::now_ms();
    if (!g_have_wr || figure != g_wr_figure || seed != g_wr_seed || delta != g_wr_delta) {
        g_have_wr = false;
        g_mesh_form = -1;
        s = make_scene(figure, seed, delta, &g_wr);
        if (!s) return skweb::finish(s);
        g_have_wr = true;
        g_wr_figure = figure, g_wr_seed = seed, g_wr_delta = delta;
    }
    const float jitter_used = form == 2 ? jitter : 0.0f;  // only the superposed form samples
    if (form != g_mesh_form || K != g_mesh_k || !(jitter_used == g_mesh_jitter)) {
        s = tessellate_wr(figure, form, K, jitter_used, seed);
        if (!s) return skweb::finish(s);
    }
    const WrMesh& m = g_wr_mesh;
    const double t1 = skweb::now_ms();
    Camera cam;
    s = make_perspective_camera(Vec3{3.6f, 3.2f, 3.6f}, Vec3{0, 0.2f, 0}, Vec3{0, 1, 0}, 36.0f, size, size, 0.05f,
                                100.0f, cam);
    if (!s) return skweb::finish(s);
    RgbImage img(size, size);
    FloatImage depth(size, size);
    FrameBand band = full_frame_band(img.view(), depth.view());
    clear_band(band, Rgb8{255, 255, 255});
    const Vec3 light = normalize(Vec3{-0.6f, 0.55f, 0.35f});  // the figures' light (wr_figure_common.hpp)
    auto shader = [&](const Fragment& f) {
        const float lambert = std::fabs(dot(f.normal, light));  // two-sided: spikes flip
        return to_rgb8(f.color * (0.28f + 0.72f * lambert));
    };
    DrawOptions opt;
    opt.cull = CullMode::none;
    opt.model = Mat4::rotate_x(pitch) * Mat4::rotate_y(yaw);
    s = draw_mesh(cam, band, m.mesh.view(), opt, shader);
    if (!s) return skweb::finish(s);
    skweb::set_picture(img);
    skweb::text() = "{\"vertices\":" + std::to_string(m.mesh.positions.size()) +
                    ",\"triangles\":" + std::to_string(m.mesh.triangle_count()) +
                    ",\"grid\":[" + std::to_string(m.grid_u) + "," + std::to_string(m.grid_v) + "]" +
                    ",\"levels_used\":" + std::to_string(m.max_levels_used) +
                    ",\"tessellate_ms\":" + number(t1 - t0) + ",\"draw_ms\":" + number(skweb::now_ms() - t1) + "}";
    return skweb::finish(Status::success());
}
