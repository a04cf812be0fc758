// hirota1998 fig. 5 (the barks of camphor, Chinese tallow and pine) and Table 3 (the size of
// the regions bounded by cracks), from the same three runs.
// Example: examples/60_two_layer_bark.cpp.
#include <algorithm>
#include <cmath>
#include <string>

#include "hirota1998/bark_common.hpp"
#include "shitsukan/geom/obj.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"
#include "shitsukan/core/detmath.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;
using namespace shitsukan::figures::bark;

namespace {

const Species kSpecies[3] = {Species::camphor, Species::chinese_tallow, Species::pine};

// Table 3 (given): observed and simulated (mean, max) sizes, width x height in cm; -1 = "(>20)".
struct PaperRow {
    float observed_w, observed_h, mean_w, mean_h, max_w, max_h;
};
const PaperRow kPaper[3] = {{1.5f, -1, 1.58f, 11.6f, 2.06f, -1},
                            {1.5f, 3.0f, 1.70f, 3.02f, 2.08f, 3.96f},
                            {3.0f, 7.0f, 2.34f, 4.28f, 3.24f, 6.48f}};

std::string cm(float x) { return x < 0 ? std::string("(>20)") : fmt("%.2f", double(x)); }

// The 3D trunk at T with the crack map as its texture (theta = u / R), Lambert-lit, rendered at
// 3 x 3 samples per pixel and box-filtered (chosen here: 1-pixel cracks of the map would
// otherwise alias away on the trunk).
Status render_trunk(const SpeciesRun& s, const RgbImage& map, float px_per_cm, RgbView target) {
    const float T = s.params.T;
    TriangleMesh trunk;
    SHITSUKAN_TRY(make_trunk_mesh(s.bark, T, s.bark.net.W.data(), trunk));
    const float H = s.bark.H0 * (1.0f + axial_strain(s.params, T));
    const float R = s.bark.R0 + s.params.delta_r * T;
    const float C = s.bark.circumference * (1.0f + hoop_strain(s.params, T));
    const int ss = 3, w = target.width * ss, h = target.height * ss;
    // chosen here: a slightly raised front view that fits the trunk's height.
    const float dist = 0.62f * H / det_tan(0.5f * 30.0f * kPi / 180.0f) + R;
    Camera cam = perspective_camera({0.0f, 0.62f * H, dist}, {0.0f, 0.5f * H, 0.0f}, {0, 1, 0},
                                    30.0f, w, h, 1.0f, 4.0f * dist);
    RgbImage big(w, h);
    FloatImage depth(w, h);
    FrameBand band = full_frame_band(big.view(), depth.view());
    clear_band(band, Rgb8{236, 238, 240});
    const Light light = directional_light({-0.6f, 0.35f, 0.75f});
    Material m;
    m.ambient = 0.25f, m.diffuse = 0.85f;
    const ImageView<const Rgb8> tex = map.const_view();
    const int filled = std::max(1, int(C * px_per_cm));  // columns the map really covers
    auto shader = [&](const Fragment& f) {
        // uv is the unrolled position over (C, H): texel = uv times the map's scale.
        const int x = clamp(int(f.uv.x * C * px_per_cm), 0, filled - 1);
        const int y = clamp(int(float(tex.height) - f.uv.y * H * px_per_cm), 0, tex.height - 1);
        const Rgb8 c = tex.at(x, y);
        const Vec3 base{float(c.r) / 255.0f, float(c.g) / 255.0f, float(c.b) / 255.0f};
        return to_rgb8(shade_lambert(m, base, f.world_position, f.normal, &light, 1));
    };
    SHITSUKAN_TRY(draw_mesh(cam, band, trunk.view(), DrawOptions{}, shader));
    for (int y = 0; y < target.height; ++y)
        for (int x = 0; x < target.width; ++x) {
            int r = 0, g = 0, b = 0;
            for (int j = 0; j < ss; ++j)
                for (int i = 0; i < ss; ++i) {
                    const Rgb8 c = big.at(x * ss + i, y * ss + j);
                    r += c.r, g += c.g, b += c.b;
                }
            const int n = ss * ss;
            target.at(x, y) = Rgb8{std::uint8_t((r + n / 2) / n), std::uint8_t((g + n / 2) / n),
                                   std::uint8_t((b + n / 2) / n)};
        }
    return Status::success();
}

}  // namespace

namespace {

constexpr float kMapPxPerCm = 24.0f;  // chosen here: a 0.33 cm cell is 8 px

// fig05's layout: three columns of the trunk rendered (render_h) over one photograph view of
// its unrolled map (map_h; photograph_views.hpp), a title band (header) and two lines of text
// below (footer).
struct Fig05Layout {
    int col = 360, render_h = 480, header = 24, gap = 12, footer = 40, map_h = 0;
};

// Column i of fig05: the trunk with its crack map as texture, the map's window with Table 3's
// section marked, the species' numbers; and the run's SVG, CSV and OBJ files.
Status draw_species_column(FigureContext& ctx, const SpeciesRun& s, int i, const Fig05Layout& L,
                           RgbImage& out, RasterCanvas& page) {
    const float T = s.params.T, px_per_cm = kMapPxPerCm;
    const float C = s.bark.circumference * (1.0f + hoop_strain(s.params, T));
    const float H = s.bark.H0 * (1.0f + axial_strain(s.params, T));
    RgbImage map(int(std::ceil(C * px_per_cm)), int(std::ceil(H * px_per_cm)),
                 Rgb8{250, 250, 248});
    RasterCanvas mc(map.view());
    CrackMapStyle style;
    style.origin = {0.0f, float(map.height())};
    style.px_per_cm = px_per_cm;
    style.min_width_cm = 1.0f / px_per_cm;
    style.plate = kBarkPlate;
    style.crack = kCrack;
    // The trunk's texture shades the regions of the whole cylinder; the window below
    // shades those of Table 3's section (the end bands flat).
    style.regions = &s.whole;
    SHITSUKAN_TRY(draw_crack_map(mc, s.bark, T, s.bark.net.W.data(), style));
    RgbImage render(L.col, L.render_h);
    SHITSUKAN_TRY(render_trunk(s, map, px_per_cm, render.view()));
    style.regions = &s.regions;
    SHITSUKAN_TRY(draw_crack_map(mc, s.bark, T, s.bark.net.W.data(), style));
    for (int y = 0; y < L.render_h; ++y)
        for (int x = 0; x < L.col; ++x) out.at(i * L.col + x, L.header + y) = render.at(x, y);
    // The window: one of Table 3's photograph views (a third of the circumference: the
    // middle of the map), full height.
    const float view_cm = float(photograph_view_columns(s.params.N_R)) * s.bark.a_h *
                          (1.0f + hoop_strain(s.params, T));
    const int ww = std::min(int(std::lround(view_cm * px_per_cm)), map.width());
    const int x0 = (map.width() - ww) / 2;
    const int ox = i * L.col + (L.col - ww) / 2, oy = L.header + L.render_h + L.gap;
    for (int y = 0; y < map.height() && oy + y < out.height(); ++y)
        for (int x = 0; x < ww; ++x) out.at(ox + x, oy + y) = map.at(x0 + x, y);
    // Table 3's section: marks beside the window at its two ends (the bands outside it
    // are shaded flat, their regions not counted).
    const int end_rows = s.regions.label.empty() ? 0 : table3_section(ctx.quick()).end_rows;
    for (int e = 0; e < 2; ++e) {
        const float row = e == 0 ? float(end_rows) - 0.5f : float(s.params.N_H - end_rows) - 0.5f;
        const float y = float(oy + map.height()) -
                        row * s.params.species.L0 * (1.0f + axial_strain(s.params, T)) * px_per_cm;
        page.line({float(ox - 14), y}, {float(ox - 3), y}, Rgb8{200, 40, 30}, 2.0f);
        page.line({float(ox + ww + 2), y}, {float(ox + ww + 13), y}, Rgb8{200, 40, 30}, 2.0f);
    }
    page.text({float(i * L.col + 8), 6.0f}, fmt("(%d) %s", i + 1, s.params.species.name),
              Rgb8{20, 20, 20}, 2);
    page.text({float(i * L.col + 8), float(oy + map.height() + 6)},
              fmt("regions %.2f x %.2f cm (mean, section)", double(s.regions.mean_width),
                  double(s.regions.mean_height)),
              Rgb8{20, 20, 20}, 1);
    page.text({float(i * L.col + 8), float(oy + map.height() + 20)},
              fmt("%zu breaks, %zu regions", s.run.breaks.size(), s.regions.regions.size()),
              Rgb8{90, 90, 90}, 1);
    SHITSUKAN_TRY(write_crack_svg(s.bark, T, s.bark.net.W.data(),
                                  ctx.path(fmt("_%d.svg", i + 1)).c_str(), px_per_cm));
    SHITSUKAN_TRY(write_bark_csv(s.bark, T, s.bark.net.W.data(),
                                 ctx.path(fmt("_%d", i + 1)).c_str()));
    TriangleMesh trunk;
    SHITSUKAN_TRY(make_trunk_mesh(s.bark, T, s.bark.net.W.data(), trunk));
    return write_obj(ctx.path(fmt("_%d.obj", i + 1)).c_str(), trunk);
}

// The width of Fig. 4 over time: the cracks present at the first snapshot that has any
// (pine cracks late: its first break comes after 0.75 T), measured at that and every later
// snapshot.
std::string crack_widening(const SpeciesRun* const runs[3]) {
    std::string widen;
    for (int i = 0; i < 3; ++i) {
        const SpeciesRun& s = *runs[i];
        const float T = s.params.T;
        std::size_t first = 0;
        while (first + 1 < s.run.snapshots.size() && s.run.snapshots[first].break_count == 0)
            ++first;
        std::vector<std::uint32_t> early;
        for (const BreakEvent& e : s.run.breaks)
            if (e.t <= s.run.snapshots[first].t) early.push_back(e.spring);
        widen += fmt("%s%s (first crack at %.2f T; the %zu cracks of %.2f T):", i ? "; " : "",
                     s.params.species.name,
                     s.run.breaks.empty() ? 1.0 : double(s.run.breaks[0].t / T), early.size(),
                     double(s.run.snapshots[first].t / T));
        float last = 0;
        bool widening = true;
        for (std::size_t k = first; k < s.run.snapshots.size(); ++k) {
            const CrackSnapshot& snap = s.run.snapshots[k];
            const float w = mean_crack_width(s.bark, early.data(), int(early.size()), snap.t,
                                             snap.W.data());
            widen += fmt(" %.4f at %.2f T", double(w), double(snap.t / T));
            widening = widening && !early.empty() && w > last;
            last = w;
        }
        widen += widening ? ", widening" : ", not widening throughout";
    }
    return widen;
}

}  // namespace

SHITSUKAN_FIGURE(hirota_fig05, "hirota1998", "fig05",
                 "Bark patterns of camphor, Chinese tallow and pine (Table 2), grown to T") {
    const SpeciesRun* runs[3];
    for (int i = 0; i < 3; ++i) {
        ctx.progress("growing %s", species_name(kSpecies[i]));
        SHITSUKAN_TRY(species_run(kSpecies[i], ctx.quick(), &runs[i]));
    }
    record_parameters(ctx, runs[0]->params);
    ctx.chosen("crack map", fmt("%.0f px/cm; cracks are Fig. 4 ribbons (width l - l0), at least "
                                "1 px; intact springs in no intact triangle (a crack opened by "
                                "sliding) drawn 1 px",
                                double(kMapPxPerCm)),
               "cracks of 0.01-0.05 cm would vanish at this scale");
    ctx.chosen("plate shading", "each region's plates x0.88-1.12 (hash of the region)",
               "so the crack-bounded regions Table 3 measures can be seen");
    const CylinderParams& p0 = runs[0]->params;
    ctx.chosen("view", fmt("top: the trunk rendered with the rasterizer, the crack map as texture, "
                           "Lambert light from the upper left; bottom: one of Table 3's "
                           "photograph views (a third of the circumference, %.1f cm at T) of the "
                           "unrolled map, full height; red marks bound the section Table 3 "
                           "measures (the end bands, shaded flat, are left out)",
                           double(float(photograph_view_columns(p0.N_R)) * runs[0]->bark.a_h *
                                  (1.0f + hoop_strain(p0, p0.T)))),
               "the paper's photograph row cannot be reproduced");
    Fig05Layout L;
    const BarkCylinder& b0 = runs[0]->bark;
    const float Hmax = b0.H0 * (1.0f + axial_strain(runs[0]->params, runs[0]->params.T));
    L.map_h = int(std::ceil(Hmax * kMapPxPerCm));
    RgbImage out(3 * L.col, L.header + L.render_h + L.gap + L.map_h + L.footer,
                 Rgb8{250, 250, 248});
    RasterCanvas page(out.view());
    for (int i = 0; i < 3; ++i) SHITSUKAN_TRY(draw_species_column(ctx, *runs[i], i, L, out, page));
    const std::string widen = crack_widening(runs);
    ctx.note(fmt("What to see: camphor in long vertical strips, many reaching the full height "
                 "(Table 3 *1); Chinese tallow in small closed blocks (*2); pine in larger blocks "
                 "(*3). Mean width (cm, Fig. 4: l - l0) of the cracks present at each species' "
                 "first snapshot with cracks, measured then and at the later snapshots: %s. With "
                 "the set of cracks fixed every opening grows in proportion to t (the linear "
                 "solution is t W), so a drop between two snapshots is growth taken up by cracks "
                 "that opened in between (tallow's horizontal cracks, pine's late vertical ones). "
                 "Each species' crack network is also written as fig05_N.svg, the deformed trunk "
                 "as fig05_N.obj and the network as CSV (fig05_N_nodes/_springs/_triangles.csv) "
                 "for independent measurement.",
                 widen.c_str()));
    return ctx.save_png(out.view());
}

namespace {

// Table 3's statistics of one species over several seeds: each run measured in photograph
// views (photograph_views.hpp: Table 3's measure) and over its whole section (for comparison);
// the mean over the seeds of each run's value, and the runs' range.
struct SeedStats {
    enum { mean_w, mean_h, max_w, max_h, whole_mean_w, whole_mean_h, whole_max_w, whole_max_h,
           regions_per_view, full_share, p90_h, count };
    int runs = 0;
    float sum[count] = {}, lo[count], hi[count];
    SeedStats() { std::fill(lo, lo + count, 1e30f), std::fill(hi, hi + count, 0.0f); }
    void add(const PhotographViews& v, const RegionReport& r) {
        std::vector<float> h;  // the section's region heights: their 90th percentile
        for (const BarkRegion& g : r.regions) h.push_back(g.height);
        std::sort(h.begin(), h.end());
        const float p90 = h.empty() ? 0.0f : h[std::min(h.size() - 1, h.size() * 9 / 10)];
        const float x[count] = {v.mean_width,   v.mean_height,      v.max_width,
                                v.max_height,   r.mean_width,       r.mean_height,
                                r.max_width,    r.max_height,       v.regions_per_view,
                                v.full_height_share, p90};
        for (int k = 0; k < count; ++k)
            sum[k] += x[k], lo[k] = std::min(lo[k], x[k]), hi[k] = std::max(hi[k], x[k]);
        ++runs;
    }
    float avg(int k) const { return runs ? sum[k] / float(runs) : 0.0f; }
};

Status add_views(const BarkCylinder& bark, const RegionReport& rep, SeedStats* out) {
    PhotographViews v;
    SHITSUKAN_TRY(measure_photograph_views(bark, rep, photograph_view_columns(bark.params.N_R), v));
    out->add(v, rep);
    return Status::success();
}

// Seeds 2..n: the same run as species_run's, another seed (seed 1998 is the memoised run).
Status seed_stats(const SpeciesRun& base, bool quick, int seeds, SeedStats* out) {
    SHITSUKAN_TRY(add_views(base.bark, base.regions, out));
    for (int k = 1; k < seeds; ++k) {
        CylinderParams p = base.params;
        p.seed = std::uint32_t(k);
        BarkCylinder bark;
        SHITSUKAN_TRY(build_cylinder(p, bark));
        CrackRun run;
        SHITSUKAN_TRY(grow_and_crack(bark, CrackRunOptions{}, run));
        RegionReport rep;
        SHITSUKAN_TRY(measure_regions(bark, p.T, bark.net.W.data(), rep, table3_section(quick)));
        SHITSUKAN_TRY(add_views(bark, rep, out));
    }
    return Status::success();
}

// The §3.2 shear-lag estimate with this model's own constants: around (diagonals,
// hoop-dominated strain 0.75 e_theta + 0.25 e_z), along (vertical springs, e_z).
std::string spacing_estimates(const SpeciesRun& s) {
    const BarkSpring* diag = nullptr;
    const BarkSpring* vert = nullptr;
    for (const BarkSpring& sp : s.bark.net.springs)
        if (s.bark.spring_triangles[2 * std::size_t(&sp - s.bark.net.springs.data()) + 1] >= 0) {
            if (sp.family == 2 && !diag) diag = &sp;
            if (sp.family == 1 && !vert) vert = &sp;
        }
    const float k_sh = s.bark.net.k_anchor[std::size_t(s.bark.node(0, s.params.N_H / 2))];
    const float et = hoop_strain(s.params, s.params.T), ez = axial_strain(s.params, s.params.T);
    const float L_around = crack_spacing_estimate(s.bark.a_h, std::sqrt(diag->k / k_sh),
                                                  s.params.species.kappa2 - 1.0f,
                                                  0.75f * et + 0.25f * ez);
    const float L_along = crack_spacing_estimate(s.params.species.L0, std::sqrt(vert->k / k_sh),
                                                 s.params.species.kappa1 - 1.0f, ez);
    return fmt("%s x %s",
               std::isinf(L_around) ? "inf" : fmt("%.2f", double(L_around)).c_str(),
               std::isinf(L_along)
                   ? fmt("inf (kappa1 - 1 = %.3f > e_z = %.3f: none on an uncracked trunk; the "
                         "measured ones start where sigma and the stress at crack tips lower "
                         "the threshold)",
                         double(s.params.species.kappa1 - 1.0f), double(ez))
                         .c_str()
                   : fmt("%.2f", double(L_along)).c_str());
}

}  // namespace

namespace {

bool within(float ours, float paper, float tolerance) {
    return std::fabs(ours / paper - 1.0f) <= tolerance;
}

// Table 3's numbers over the seeds, one check per species and value: the means within 20 % of
// the paper's, the max within 30 % (camphor's max height "(>20)": the views' largest spans the
// section in every seed). `met` records what this model meets with Table 2 and the shared
// chosen values (enforced); the rest is printed "not met (reported)".
struct NumberCheck {
    int species, value;  // SeedStats::mean_w .. max_h
    bool met;
};
const NumberCheck kNumberChecks[] = {
    {0, SeedStats::mean_w, true},  {0, SeedStats::mean_h, true},  {0, SeedStats::max_w, true},
    {0, SeedStats::max_h, true},   {1, SeedStats::mean_w, false}, {1, SeedStats::mean_h, true},
    {1, SeedStats::max_w, true},   {1, SeedStats::max_h, false},  {2, SeedStats::mean_w, true},
    {2, SeedStats::mean_h, true},  {2, SeedStats::max_w, true},   {2, SeedStats::max_h, false}};

float paper_value(int species, int value) {
    const PaperRow& p = kPaper[species];
    return value == SeedStats::mean_w ? p.mean_w
           : value == SeedStats::mean_h ? p.mean_h
           : value == SeedStats::max_w  ? p.max_w
                                        : p.max_h;
}

// One line per NumberCheck; false when an enforced one fails.
bool number_checks(const SpeciesRun* const runs[3], const SeedStats stats[3], std::string* md) {
    const char* names[] = {"mean width", "mean height", "max width", "max height"};
    bool ok_all = true;
    for (const NumberCheck& k : kNumberChecks) {
        const SeedStats& st = stats[k.species];
        const float paper = paper_value(k.species, k.value), ours = st.avg(k.value);
        const bool is_max = k.value >= SeedStats::max_w;
        const bool spans = paper < 0;  // "(>20)": the largest region runs out of the picture
        const bool ok = spans ? st.lo[k.value] > 20.0f : within(ours, paper, is_max ? 0.3f : 0.2f);
        *md += fmt("- seeds: %s's %s %s: %.2f against %s%s: **%s**%s\n",
                   runs[k.species]->params.species.name, names[k.value],
                   spans ? "spans the section in every seed's views (> 20 cm)"
                         : (is_max ? "within 30 %" : "within 20 %"),
                   double(ours), cm(paper).c_str(),
                   spans ? "" : fmt(" (x%.2f)", double(ours / paper)).c_str(),
                   ok ? "pass" : (k.met ? "FAIL" : "not met"), k.met ? "" : " (reported)");
        ok_all = ok_all && (ok || !k.met);
    }
    return ok_all;
}

// The notes on what table03 reports and does not enforce: the widths' order and the max row.
void reported_notes(const SpeciesRun* const runs[3], const SeedStats stats[3], std::string* md) {
    const SeedStats &sc = stats[0], &st = stats[1], &sp = stats[2];
    auto first_break = [&](const SpeciesRun& r, int family) {
        for (const BreakEvent& e : r.run.breaks)
            if (r.bark.net.springs[e.spring].family == family) return e.t / r.params.T;
        return 1.0f;
    };
    *md += fmt("\nWidths: tallow's blocks come out narrower than camphor's strips (the paper: "
               "1.70 against 1.58, both observed 1.5). The two species share every subscript-2 "
               "value, so their vertical cracks start alike (first diagonal break at %.2f T and "
               "%.2f T), and camphor's smaller G even widens their spacing (the estimate "
               "column); only tallow's lower kappa1 adds horizontal cracks (first axial break at "
               "%.2f T, camphor's at %.2f T), and the narrowing comes with them. With both "
               "strains growing in proportion (Table 1's constant delta_r and delta_h) the "
               "vertical cracks always come first. A sweep of the shared chosen values (sigma, "
               "D, the two final strains, a common scale on every kappa - 1, the tolerance; "
               "tools/bark_table3_sweep.cpp) and a grid of D, sigma and the two strains together "
               "(tools/bark_table3_grid.sh; both in docs/papers/hirota1998.md §4) "
               "reverse the order in no setting: tallow nears camphor's width only where "
               "camphor's strips break into blocks (against *1), so it is reported, not tuned "
               "in.\n",
               double(first_break(*runs[0], 2)), double(first_break(*runs[1], 2)),
               double(first_break(*runs[1], 1)), double(first_break(*runs[0], 1)));
    *md += fmt("\nThe max row (chosen here, `bark/photograph_views.hpp`). §3.2 gives Table 3 as "
               "the crack spacings measured 'on these patterns', the ones Fig. 5 sets beside "
               "photographs; the observed column comes from trees of radius 5-10 cm (*3), and "
               "camphor's '(>20)' says its strips run out of a picture about 20 cm tall. So the "
               "max is the largest region in such a picture: each run is measured in views as "
               "tall as the section and a third of the circumference wide (%d of %d columns: "
               "the face a front view shows at least half-size, about the trunk's diameter), "
               "over the regions a view shows whole; mean and max are means over the %d view "
               "positions. A view shows %.0f camphor, %.0f tallow and %.0f pine regions; the "
               "whole section's max, over hundreds, is beside it. The widths and camphor's "
               "strips meet the paper's max; tallow's and pine's heights do not: their "
               "distributions have a long tail (a tenth of the section's regions are taller "
               "than %.2f and %.2f cm, %.2f and %.2f times the mean, where the paper's max is "
               "1.31 and 1.51 times its mean): where a "
               "horizontal crack stops short the blocks above and below it are one region, and "
               "pine, whose horizontal cracks come only from sigma and the stress at crack tips "
               "(the estimate column), keeps strips over half the section tall. A view cannot "
               "be made smaller than the paper's own numbers allow (over 20 cm tall, a trunk of "
               "radius 5 cm or more), and one that size still holds such a region; the paper's "
               "max/mean ratios of 1.2-1.5 point to a narrower spread of sizes than this "
               "model's; no shared setting of the grid (docs/papers/hirota1998.md §4) brings both "
               "within 30 %%. Reported, not tuned in.\n",
               photograph_view_columns(runs[0]->params.N_R), runs[0]->params.N_R,
               runs[0]->params.N_R, double(sc.avg(SeedStats::regions_per_view)),
               double(st.avg(SeedStats::regions_per_view)),
               double(sp.avg(SeedStats::regions_per_view)), double(st.avg(SeedStats::p90_h)),
               double(sp.avg(SeedStats::p90_h)),
               double(st.avg(SeedStats::p90_h) / st.avg(SeedStats::mean_h)),
               double(sp.avg(SeedStats::p90_h) / sp.avg(SeedStats::mean_h)));
}

// Table 3's notes on the fig05 runs, and its numbers over the seeds: enforced where this model
// meets them, reported where it does not.
Status table03_checks(FigureContext& ctx, const SpeciesRun* const runs[3],
                      const SeedStats stats[3], std::string* md) {
    const RegionReport &c = runs[0]->regions, &t = runs[1]->regions, &p = runs[2]->regions;
    const SeedStats &sc = stats[0], &st = stats[1], &sp = stats[2];
    struct Check {
        const char* what;
        bool ok, enforced;
    };
    const Check list[] = {
        {"camphor: mean height / mean width >= 4 (long vertical strips, *1)",
         c.mean_height >= 4.0f * c.mean_width, true},
        {"camphor: some regions span the whole section ('(>20)')", c.full_height > 0, true},
        {"Chinese tallow: aspect in [1.3, 3.0], no region spanning the section (closed blocks, *2)",
         t.mean_height >= 1.3f * t.mean_width && t.mean_height <= 3.0f * t.mean_width &&
             t.full_height == 0, true},
        {"pine: mean width >= 1.3 x tallow's and mean height >= 1.2 x tallow's (larger blocks, *3)",
         p.mean_width >= 1.3f * t.mean_width && p.mean_height >= 1.2f * t.mean_height, true},
        {"seeds: mean heights in the paper's order, camphor > pine > tallow",
         sc.avg(SeedStats::mean_h) > sp.avg(SeedStats::mean_h) &&
             sp.avg(SeedStats::mean_h) > st.avg(SeedStats::mean_h), true},
        {"seeds: pine the widest (paper: camphor < tallow < pine)",
         sp.avg(SeedStats::mean_w) > sc.avg(SeedStats::mean_w) &&
             sp.avg(SeedStats::mean_w) > st.avg(SeedStats::mean_w), true},
        {"seeds: camphor narrower than tallow (the paper's 1.58 < 1.70)",
         sc.avg(SeedStats::mean_w) < st.avg(SeedStats::mean_w), false},
    };
    *md += "\nChecks (Table 3 and its notes; 'reported' = not met by this model with Table 2 "
           "and one shared set of chosen values, not tuned in):\n\n";
    bool checks = true;
    for (const Check& k : list) {
        *md += fmt("- %s: **%s**%s\n", k.what, k.ok ? "pass" : (k.enforced ? "FAIL" : "not met"),
                   k.enforced ? "" : " (reported)");
        checks = checks && (k.ok || !k.enforced);
    }
    checks = number_checks(runs, stats, md) && checks;
    *md += fmt("\nTimes: camphor %.2f s, Chinese tallow %.2f s, pine %.2f s (build, growth and "
               "cracking of the seed-1998 runs; the paper gives none).\n",
               runs[0]->seconds, runs[1]->seconds, runs[2]->seconds);
    *md += "\nThe estimate column is the shear-lag largest spacing (reconstructed, "
           "`bark/spacing_estimate.hpp`) with this model's own k, k_sh and final strains; the "
           "paper says its simulated spacings come out smaller than the estimate, as ours do.\n";
    reported_notes(runs, stats, md);
    ctx.note(fmt("Measured in photograph views of a section of the trunk away from its cut ends "
                 "(see 'views' and 'section'); the whole section's and the whole cylinder's "
                 "numbers are beside them. Regions are the areas the crack map shows enclosed. %s",
                 ctx.quick() ? "Quick mode (32 x 24, one seed): checks printed, not enforced."
                             : (checks ? "All enforced checks pass." : "Some checks FAIL.")));
    SHITSUKAN_TRY(ctx.save_markdown(*md));
    if (!ctx.quick() && !checks)
        return Status::error(StatusCode::not_supported, "table03: a Table 3 check failed");
    return Status::success();
}

}  // namespace

namespace {

// "a [lo-hi]" for one SeedStats value.
std::string ranged(const SeedStats& st, int k) {
    return fmt("%.2f [%.2f-%.2f]", double(st.avg(k)), double(st.lo[k]), double(st.hi[k]));
}

// Table 3 beside the paper's: the photograph views over the seeds (Table 3's measure), with
// the ratios, and the whole section's numbers for comparison.
std::string seeds_table(const SpeciesRun* const runs[3], const SeedStats stats[3], int seeds) {
    std::string md = fmt(
        "Width x height in cm (width around the trunk, height along it). Paper: Table 3 "
        "(observed on real trees; simulated by the authors). Ours: the fig05 trunks at t = T, "
        "%d seeds (1998, 1, 2, ...), each measured in photograph views (a third of the "
        "circumference wide, the section's height, the regions a view shows whole; "
        "bark/photograph_views.hpp): mean over the seeds, [range]. '(>20)': the largest region "
        "runs out of the picture.\n\n| species | paper mean | ours mean | ours / paper | paper "
        "max | ours max | ours / paper | regions a view | whole section: mean, max |\n"
        "|---|---|---|---|---|---|---|---|---|\n",
        seeds);
    for (int i = 0; i < 3; ++i) {
        const SeedStats& st = stats[i];
        const PaperRow& p = kPaper[i];
        auto ratio = [&](int k, float paper) {
            return paper < 0 ? std::string("-") : fmt("%.2f", double(st.avg(k) / paper));
        };
        md += fmt("| %s | %s x %s | %s x %s | %s, %s | %s x %s | %s x %s | %s, %s | %.0f | "
                  "%.2f x %.2f, %.2f x %.2f |\n",
                  runs[i]->params.species.name, cm(p.mean_w).c_str(), cm(p.mean_h).c_str(),
                  ranged(st, SeedStats::mean_w).c_str(), ranged(st, SeedStats::mean_h).c_str(),
                  ratio(SeedStats::mean_w, p.mean_w).c_str(),
                  ratio(SeedStats::mean_h, p.mean_h).c_str(), cm(p.max_w).c_str(),
                  cm(p.max_h).c_str(), ranged(st, SeedStats::max_w).c_str(),
                  ranged(st, SeedStats::max_h).c_str(), ratio(SeedStats::max_w, p.max_w).c_str(),
                  ratio(SeedStats::max_h, p.max_h).c_str(),
                  double(st.avg(SeedStats::regions_per_view)),
                  double(st.avg(SeedStats::whole_mean_w)), double(st.avg(SeedStats::whole_mean_h)),
                  double(st.avg(SeedStats::whole_max_w)), double(st.avg(SeedStats::whole_max_h)));
    }
    return md;
}

}  // namespace

SHITSUKAN_FIGURE(hirota_table03, "hirota1998", "table03",
                 "Dimensions of the areas surrounded by cracks: the paper's and ours") {
    const SpeciesRun* runs[3];
    for (int i = 0; i < 3; ++i) SHITSUKAN_TRY(species_run(kSpecies[i], ctx.quick(), &runs[i]));
    record_parameters(ctx, runs[0]->params);
    const RegionOptions section = table3_section(ctx.quick());
    ctx.chosen("regions", "the areas the crack map (fig05) shows enclosed by cracks: connected "
                          "intact surface over springs in an intact triangle; width and height = "
                          "node extents + one cell; >= 3 nodes",
               "Table 3 is titled 'area surrounded by cracks' (*2 'closed regions') and was "
               "measured 'on these patterns' (§3.2), i.e. on pictures of the cracks; a lattice "
               "crack can open by sliding with one diagonal family broken and is drawn, so it "
               "bounds a region (crack_regions.hpp)");
    ctx.chosen("section", fmt("the rows %d..%d of %d: %d rows left out at each end (%.1f cm)",
                              section.end_rows, runs[0]->params.N_H - 1 - section.end_rows,
                              runs[0]->params.N_H, section.end_rows,
                              double(float(section.end_rows) * runs[0]->params.species.L0)),
               "as one measures a photograph of a long trunk: the cylinder's cut ends are free "
               "edges that suppress horizontal cracks within a shear-lag length "
               "(crack_regions.hpp, kSectionEndRows)");
    ctx.chosen("views", fmt("%d of %d columns (a third of the circumference) x the section; "
                            "the regions a view shows whole; mean and max averaged over the %d "
                            "view positions",
                            photograph_view_columns(runs[0]->params.N_R), runs[0]->params.N_R,
                            runs[0]->params.N_R),
               "§3.2 measured Table 3 on Fig. 5's patterns, set beside photographs of trunks of "
               "radius 5-10 cm (*3); '(>20)' is a strip running out of the picture. A front view "
               "shows a third of the trunk at least half-size (photograph_views.hpp)");
    const int seeds = ctx.quick() ? 1 : 5;
    SeedStats stats[3];
    for (int i = 0; i < 3; ++i) SHITSUKAN_TRY(seed_stats(*runs[i], ctx.quick(), seeds, &stats[i]));
    std::string md = seeds_table(runs, stats, seeds);
    md += fmt("\nThe fig05 runs (seed %u) in detail: measured on the whole section away from the "
              "cut ends (no views); the whole cylinder, ends included, for comparison.\n\n",
              runs[0]->params.seed);
    md += "| species | observed | paper mean | paper max | ours mean | ours max | regions "
          "(full section height / wrap) | ours / paper mean | whole cylinder mean, max | "
          "intercepts mean | estimate L_max (around x along) |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (int i = 0; i < 3; ++i) {
        const SpeciesRun& s = *runs[i];
        const RegionReport& r = s.regions;
        const PaperRow& p = kPaper[i];
        const float H = s.bark.H0 * (1.0f + axial_strain(s.params, s.params.T));
        const float section_h =
            H * float(s.params.N_H - 2 * section.end_rows) / float(s.params.N_H);
        const bool full_max = r.full_height > 0;
        md += fmt("| %s | %s x %s | %s x %s | %s x %s | %.2f x %.2f | %.2f x %s | %zu (%d / %d) "
                  "| %.2f, %.2f | %.2f x %.2f, %.2f x %.2f | %.2f x %.2f | %s |\n",
                  s.params.species.name, cm(p.observed_w).c_str(), cm(p.observed_h).c_str(),
                  cm(p.mean_w).c_str(), cm(p.mean_h).c_str(), cm(p.max_w).c_str(),
                  cm(p.max_h).c_str(), double(r.mean_width), double(r.mean_height),
                  double(r.max_width),
                  full_max ? fmt("> %.1f (the section)", double(section_h - s.params.species.L0)).c_str()
                           : fmt("%.2f", double(r.max_height)).c_str(),
                  r.regions.size(), r.full_height, r.wrapped, double(r.mean_width / p.mean_w),
                  double(r.mean_height / p.mean_h), double(s.whole.mean_width),
                  double(s.whole.mean_height), double(s.whole.max_width),
                  double(s.whole.max_height), double(r.intercept_mean_width),
                  double(r.intercept_mean_height), spacing_estimates(s).c_str());
    }
    return table03_checks(ctx, runs, stats, &md);
}
