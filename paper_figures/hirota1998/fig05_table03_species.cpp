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

SHITSUKAN_FIGURE(hirota_fig05, "hirota1998", "fig05",
                 "Bark patterns of camphor, Chinese tallow and pine (Table 2), grown to T") {
    const SpeciesRun* runs[3];
    for (int i = 0; i < 3; ++i) {
        ctx.progress("growing %s", species_name(kSpecies[i]));
        SHITSUKAN_TRY(species_run(kSpecies[i], ctx.quick(), &runs[i]));
    }
    record_parameters(ctx, runs[0]->params);
    const float px_per_cm = 24.0f;  // chosen here: a 0.33 cm cell is 8 px
    const float min_crack = 1.0f / px_per_cm;
    ctx.chosen("crack map", fmt("%.0f px/cm; cracks are Fig. 4 ribbons (width l - l0), at least "
                                "1 px; intact springs in no intact triangle (a crack opened by "
                                "sliding) drawn 1 px",
                                double(px_per_cm)),
               "cracks of 0.01-0.05 cm would vanish at this scale");
    ctx.chosen("plate shading", "each region's plates x0.88-1.12 (hash of the region)",
               "so the crack-bounded regions Table 3 measures can be seen");
    ctx.chosen("view", "top: the trunk rendered with the rasterizer, the crack map as texture, "
                       "Lambert light from the upper left; bottom: a 13 cm wide window of the "
                       "unrolled map, full height",
               "the paper's photograph row cannot be reproduced");
    const int col = 360, render_h = 480;
    const float window_cm = 13.0f;
    const BarkCylinder& b0 = runs[0]->bark;
    const float Hmax = b0.H0 * (1.0f + axial_strain(runs[0]->params, runs[0]->params.T));
    const int map_h = int(std::ceil(Hmax * px_per_cm));
    const int header = 24, gap = 12, footer = 40;
    RgbImage out(3 * col, header + render_h + gap + map_h + footer, Rgb8{250, 250, 248});
    RasterCanvas page(out.view());
    for (int i = 0; i < 3; ++i) {
        const SpeciesRun& s = *runs[i];
        const float T = s.params.T;
        const float C = s.bark.circumference * (1.0f + hoop_strain(s.params, T));
        const float H = s.bark.H0 * (1.0f + axial_strain(s.params, T));
        RgbImage map(int(std::ceil(C * px_per_cm)), int(std::ceil(H * px_per_cm)),
                     Rgb8{250, 250, 248});
        RasterCanvas mc(map.view());
        CrackMapStyle style;
        style.origin = {0.0f, float(map.height())};
        style.px_per_cm = px_per_cm;
        style.min_width_cm = min_crack;
        style.plate = kBarkPlate;
        style.crack = kCrack;
        style.regions = &s.regions;
        SHITSUKAN_TRY(draw_crack_map(mc, s.bark, T, s.bark.net.W.data(), style));
        RgbImage render(col, render_h);
        SHITSUKAN_TRY(render_trunk(s, map, px_per_cm, render.view()));
        for (int y = 0; y < render_h; ++y)
            for (int x = 0; x < col; ++x) out.at(i * col + x, header + y) = render.at(x, y);
        // The window: 13 cm of the map (its middle), full height.
        const int ww = std::min(int(window_cm * px_per_cm), map.width());  // quick: whole map
        const int x0 = (map.width() - ww) / 2;
        const int ox = i * col + (col - ww) / 2, oy = header + render_h + gap;
        for (int y = 0; y < map.height() && oy + y < out.height(); ++y)
            for (int x = 0; x < ww; ++x) out.at(ox + x, oy + y) = map.at(x0 + x, y);
        page.text({float(i * col + 8), 6.0f}, fmt("(%d) %s", i + 1, s.params.species.name),
                  Rgb8{20, 20, 20}, 2);
        page.text({float(i * col + 8), float(oy + map.height() + 6)},
                  fmt("regions %.2f x %.2f cm (mean)", double(s.regions.mean_width),
                      double(s.regions.mean_height)),
                  Rgb8{20, 20, 20}, 1);
        page.text({float(i * col + 8), float(oy + map.height() + 20)},
                  fmt("%zu breaks, %zu regions", s.run.breaks.size(), s.regions.regions.size()),
                  Rgb8{90, 90, 90}, 1);
        SHITSUKAN_TRY(write_crack_svg(s.bark, T, s.bark.net.W.data(),
                                      ctx.path(fmt("_%d.svg", i + 1)).c_str(), px_per_cm));
        SHITSUKAN_TRY(write_bark_csv(s.bark, T, s.bark.net.W.data(),
                                     ctx.path(fmt("_%d", i + 1)).c_str()));
        TriangleMesh trunk;
        SHITSUKAN_TRY(make_trunk_mesh(s.bark, T, s.bark.net.W.data(), trunk));
        SHITSUKAN_TRY(write_obj(ctx.path(fmt("_%d.obj", i + 1)).c_str(), trunk));
    }
    // "Cracks widen as the trunk grows": the cracks that exist at 0.6 T, measured later.
    std::string widen;
    bool widening = true;
    for (int i = 0; i < 3; ++i) {
        const SpeciesRun& s = *runs[i];
        std::vector<std::uint32_t> early;
        for (const BreakEvent& e : s.run.breaks)
            if (e.t <= s.run.snapshots[0].t) early.push_back(e.spring);
        widen += fmt("%s%s:", i ? "; " : "", s.params.species.name);
        float last = 0;
        for (const CrackSnapshot& snap : s.run.snapshots) {
            const float w = mean_crack_width(s.bark, early.data(), int(early.size()), snap.t,
                                             snap.W.data());
            widen += fmt(" %.4f", double(w));
            widening = widening && w > last;
            last = w;
        }
    }
    ctx.note(fmt("What to see: camphor in long vertical strips, many reaching the full height "
                 "(Table 3 *1); Chinese tallow in small closed blocks (*2); pine in larger blocks "
                 "(*3). Mean crack width (cm) of the cracks present at 0.6 T, measured at 0.6, "
                 "0.75, 0.9 and 1.0 T: %s (%s). Each species' crack network is also written as "
                 "fig05_N.svg, the deformed trunk as fig05_N.obj and the network as CSV "
                 "(fig05_N_nodes/_springs/_triangles.csv) for independent measurement.",
                 widen.c_str(), widening ? "they widen as the trunk grows" : "NOT widening"));
    return ctx.save_png(out.view());
}

SHITSUKAN_FIGURE(hirota_table03, "hirota1998", "table03",
                 "Dimensions of the areas surrounded by cracks: the paper's and ours") {
    const SpeciesRun* runs[3];
    for (int i = 0; i < 3; ++i) SHITSUKAN_TRY(species_run(kSpecies[i], ctx.quick(), &runs[i]));
    record_parameters(ctx, runs[0]->params);
    ctx.chosen("regions", "connected intact surface over springs in an intact triangle; width "
                          "and height = node extents + one cell; >= 3 nodes",
               "Table 3 is titled 'area surrounded by cracks'; a lattice crack can open by "
               "sliding with one diagonal family broken (docs/papers/hirota1998.md §2)");
    std::string md;
    md += "Width x height in cm (width around the trunk, height along it). Paper: Table 3 "
          "(observed on real trees; simulated by the authors). Ours: the fig05 runs at t = T.\n\n";
    md += "| species | observed | paper mean | paper max | ours mean | ours max | regions "
          "(full height / wrap) | ours / paper mean | intercepts mean | estimate L_max (around "
          "x along) |\n|---|---|---|---|---|---|---|---|---|---|\n";
    bool checks = true;
    for (int i = 0; i < 3; ++i) {
        const SpeciesRun& s = *runs[i];
        const RegionReport& r = s.regions;
        const PaperRow& p = kPaper[i];
        const float H = s.bark.H0 * (1.0f + axial_strain(s.params, s.params.T));
        auto ours_h = [&](float h, bool full) {
            return full ? fmt("> %.1f (full height)", double(H - 0.5f * s.params.species.L0))
                        : fmt("%.2f", double(h));
        };
        // §1.12 estimate with this model's own constants: around (diagonals, hoop-dominated
        // strain 0.75 e_theta + 0.25 e_z), along (vertical springs, e_z).
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
        const bool full_max = r.max_height >= H - s.params.species.L0;
        md += fmt("| %s | %s x %s | %s x %s | %s x %s | %.2f x %.2f | %.2f x %s | %zu (%d / %d) "
                  "| %.2f, %s | %.2f x %.2f | %s x %s |\n",
                  s.params.species.name, cm(p.observed_w).c_str(), cm(p.observed_h).c_str(),
                  cm(p.mean_w).c_str(), cm(p.mean_h).c_str(), cm(p.max_w).c_str(),
                  cm(p.max_h).c_str(), double(r.mean_width), double(r.mean_height),
                  double(r.max_width), ours_h(r.max_height, full_max).c_str(), r.regions.size(),
                  r.full_height, r.wrapped, double(r.mean_width / p.mean_w),
                  fmt("%.2f", double(r.mean_height / p.mean_h)).c_str(),
                  double(r.intercept_mean_width), double(r.intercept_mean_height),
                  std::isinf(L_around) ? "inf" : fmt("%.2f", double(L_around)).c_str(),
                  std::isinf(L_along) ? "inf (no horizontal cracks predicted)"
                                      : fmt("%.2f", double(L_along)).c_str());
    }
    const RegionReport &c = runs[0]->regions, &t = runs[1]->regions, &p = runs[2]->regions;
    struct Check {
        const char* what;
        bool ok;
    };
    const Check list[] = {
        {"camphor: mean height / mean width >= 4 (long vertical strips, *1)",
         c.mean_height >= 4.0f * c.mean_width},
        {"camphor: some regions reach the full height ('(>20)')", c.full_height > 0},
        {"Chinese tallow: aspect in [1.3, 3.0], no full-height region (closed blocks, *2)",
         t.mean_height >= 1.3f * t.mean_width && t.mean_height <= 3.0f * t.mean_width &&
             t.full_height == 0},
        {"pine: mean width >= 1.3 x tallow's and mean height >= 1.2 x tallow's (larger blocks, *3)",
         p.mean_width >= 1.3f * t.mean_width && p.mean_height >= 1.2f * t.mean_height},
        {"mean heights: camphor > pine > tallow",
         c.mean_height > p.mean_height && p.mean_height > t.mean_height},
    };
    md += "\nChecks (Table 3's notes):\n\n";
    for (const Check& k : list) {
        md += fmt("- %s: **%s**\n", k.what, k.ok ? "pass" : "FAIL");
        checks = checks && k.ok;
    }
    md += fmt("\nTimes: camphor %.2f s, Chinese tallow %.2f s, pine %.2f s (build, growth and "
              "cracking; the paper gives none).\n",
              runs[0]->seconds, runs[1]->seconds, runs[2]->seconds);
    md += "\nThe estimate column is the shear-lag largest spacing (reconstructed, "
          "`bark/spacing_estimate.hpp`) with this model's own k, k_sh and final strains; the "
          "paper says its simulated spacings come out smaller than the estimate, as ours do.\n";
    ctx.note(fmt("Camphor's strips come out wider than tallow's blocks (paper: 1.58 vs 1.70; "
                 "both 1.5 observed): not checked. %s",
                 ctx.quick() ? "Quick mode (32 x 24): checks printed, not enforced."
                             : (checks ? "All checks pass." : "Some checks FAIL.")));
    SHITSUKAN_TRY(ctx.save_markdown(md));
    if (!ctx.quick() && !checks)
        return Status::error(StatusCode::not_supported, "table03: a Table 3 check failed");
    return Status::success();
}
