// tokai1994 figs. 13-15: the three cross-sections of Table 1 and the leather they give.
// (a) the section plot, (b) the shaded leather texture of the fig. 7 pattern, (c) a close-up.
// Examples: examples/50_leather_maps.cpp, examples/51_bezier_section.cpp.
#include <algorithm>
#include <cmath>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/relief.hpp"
#include "shitsukan/leather/scale_labels.hpp"
#include "tokai1994/fig11_19_common.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

// The key light of figs. 13-15 (chosen here, one value for the three figures): 3 window spans
// above the texture, about 65 degrees above the window's centre (see section_texture).
constexpr float kSectionKeyHeight = 3.0f;

const char* table1_text(Table1Section which) {
    switch (which) {
        case Table1Section::convex:
            return "(0.0, 0.1) (0.51, 0.1) (0.75, 0.13) (0.92, 0.0)";
        case Table1Section::concave:
            return "(0.0, 0.03) (0.8, 0.05) (0.9, 0.25) (0.94, 0.0)";
        case Table1Section::two_segment:
            return "(0.0, 0.25) (0.23, 0.07) (0.47, 0.07) (0.6, 0.25) + "
                   "(0.6, 0.25) (0.73, 0.2) (0.85, 0.13) (0.9, 0.0)";
    }
    return "";
}

void record_section(FigureContext& ctx, Table1Section which) {
    ctx.given("section control points", table1_text(which), "Table 1");
    tokai_relief::record_relief(ctx);
}

Status section_plot(FigureContext& ctx, Table1Section which) {
    record_section(ctx, which);
    const int w = ctx.quick() ? 360 : 720, h = ctx.quick() ? 180 : 360;
    const float s = float(w) / 720.0f;
    RgbImage img(w, h, Rgb8{255, 255, 255});
    RasterCanvas canvas(img.view());
    Canvas& cv = canvas;
    BezierChain section = table1_section(which);
    // Equal scales on r and z, as the section is used (z is not exaggerated).
    tokai_relief::PlotFrame f{70.0f * s, 0.80f * float(h), 0.60f * float(w)};
    tokai_relief::draw_axes(cv, f, {0.0f, 0.0f}, {1.05f, 0.40f}, 0.1f, "r", "z");
    for (int k = 0; k < section.count; ++k) {
        Vec2 ctrl[4];
        for (int i = 0; i < 4; ++i) ctrl[i] = f.to_pixel(section.segments[k].p[i]);
        cv.polyline(ctrl, 4, Rgb8{160, 160, 160}, 1.2f * s);
        for (int i = 0; i < 4; ++i)
            cv.marker(ctrl[i], MarkerShape::square, 9.0f * s,
                      k == 0 ? Rgb8{90, 90, 90} : Rgb8{170, 90, 40});
    }
    std::vector<Vec2> curve;
    for (int k = 0; k <= 400; ++k) {
        float r = float(k) / 400.0f;
        curve.push_back(f.to_pixel({r, section_at_r(section, r).z}));
    }
    cv.polyline(curve.data(), int(curve.size()), Rgb8{20, 60, 170}, 3.0f * s);
    cv.line(f.to_pixel({1.0f, 0.0f}), f.to_pixel({1.0f, 0.3f}), Rgb8{200, 40, 30}, 1.5f * s);
    cv.text(f.to_pixel({1.0f, 0.3f}) + Vec2{-30 * s, -14 * s}, "edge p", Rgb8{200, 40, 30}, 1);
    cv.text({10 * s, 8 * s},
            fmt("%s: blue z(r), grey control polygon%s", table1_section_name(which),
                section.count > 1 ? " (brown: 2nd segment)" : ""),
            Rgb8{0, 0, 0}, 1);
    return ctx.save_png(img.view());
}

// The shading across the scales, measured on the shaded image. Every pixel of a scale has a
// signed position s = (x - m)·l / |p - m| towards the key light (l: the horizontal unit
// vector from the scale's centroid m to the key light; s > 0 on the side facing the light).
//  - correlation: over each scale's inner part (relative distance rho in [0.3, 0.85]: the
//    floor or the shoulder, not the groove), the correlation of the luma with s. A raised
//    (convex) scale is lit on the side towards the light (> 0); a sunken one on the far side,
//    its floor rising to the rim there faces the light (< 0).
//  - highlight side: per scale, over all its pixels, the mean s of its brightest tenth. The
//    eye reads the highlight: on a raised scale it lies on the near slope (s > 0), in a dish
//    on the far inner slope (s < 0). A thin bright rim on the near side (the dish's steep
//    outer wall) puts it at s > 0 and the dish reads as a raised plate.
struct LightSide {
    double correlation = 0;        // luma against s, inner part
    double near_minus_far = 0;     // mean luma (0..255) where s > 0.3 minus where s < -0.3
    double highlight_s = 0;        // median over the scales of the brightest tenth's mean s
    double highlight_near = 0;     // fraction of the scales whose brightest tenth has s > 0
};

struct ShadedPixel {
    float luma, s, rho;
};

// The scales' pixels (every other pixel: the statistics, at a quarter of the cost).
std::vector<std::vector<ShadedPixel>> scale_pixels(const ScalePattern& pattern,
                                                   const BezierChain& section, RgbImage& img,
                                                   Vec2 lo, Vec2 hi, Vec2 light,
                                                   const std::vector<int>& full, int lw, int lh) {
    const int w = img.width(), h = img.height();
    const Vec2 size = hi - lo;
    std::vector<std::vector<ShadedPixel>> per_scale(std::size_t(pattern.polygon_count()));
    for (int j = 0; j < h; j += 2)
        for (int i = 0; i < w; i += 2) {
            const Vec2 x{lo.x + (float(i) + 0.5f) / float(w) * size.x,
                         hi.y - (float(j) + 0.5f) / float(h) * size.y};
            const int li = int(x.x / pattern.width * float(lw));
            const int lj = int(x.y / pattern.height * float(lh));
            if (li < 0 || lj < 0 || li >= lw || lj >= lh) continue;
            const int id = full[std::size_t(lj) * std::size_t(lw) + std::size_t(li)];
            if (id < 0) continue;
            int count = 0;
            const Vec2* poly = pattern.polygon(id, &count);
            const Vec2 m = pattern.centroids[std::size_t(id)];
            ReliefSample r;
            scale_relief(poly, count, m, x, section, ReliefOptions{}, &r);
            const Rgb8 c = img.view().at(i, j);
            const float l = 0.299f * c.r + 0.587f * c.g + 0.114f * c.b;
            const Vec2 towards = normalize(light - m);
            const float sp = dot(x - m, towards) / length(r.edge_point - m);
            per_scale[std::size_t(id)].push_back({l, sp, r.rho});
        }
    return per_scale;
}

// Mean s of the brightest tenth of one scale's pixels; false when it has too few.
bool highlight_position(std::vector<ShadedPixel> px, double* s) {
    if (px.size() < 20) return false;
    const std::size_t top = px.size() / 10;
    std::nth_element(px.begin(), px.begin() + std::ptrdiff_t(top), px.end(),
                     [](const ShadedPixel& a, const ShadedPixel& b) { return a.luma > b.luma; });
    double sum = 0;
    for (std::size_t k = 0; k < top; ++k) sum += double(px[k].s);
    *s = sum / double(top);
    return true;
}

LightSide light_side_profile(const std::vector<std::vector<ShadedPixel>>& per_scale) {
    LightSide out;
    double sl = 0, ss = 0, sll = 0, sss = 0, sls = 0, n = 0, near = 0, nn = 0, far = 0, nf = 0;
    std::vector<double> highlights;
    for (const std::vector<ShadedPixel>& px : per_scale) {
        double hs;
        if (highlight_position(px, &hs)) highlights.push_back(hs);
        for (const ShadedPixel& p : px) {
            if (p.rho < 0.3f || p.rho > 0.85f) continue;
            const double l = p.luma, sp = p.s;
            sl += l, ss += sp, sll += l * l, sss += sp * sp, sls += l * sp, n += 1;
            if (sp > 0.3) near += l, nn += 1;
            if (sp < -0.3) far += l, nf += 1;
        }
    }
    if (n < 2 || nn < 1 || nf < 1 || highlights.empty()) return out;
    const double cov = sls / n - (sl / n) * (ss / n);
    const double vl = sll / n - (sl / n) * (sl / n), vs = sss / n - (ss / n) * (ss / n);
    out.correlation = vl > 0 && vs > 0 ? cov / std::sqrt(vl * vs) : 0.0;
    out.near_minus_far = near / nn - far / nf;
    std::size_t count_near = 0;
    for (double h : highlights) count_near += h > 0.0 ? 1 : 0;
    out.highlight_near = double(count_near) / double(highlights.size());
    std::nth_element(highlights.begin(), highlights.begin() + std::ptrdiff_t(highlights.size() / 2),
                     highlights.end());
    out.highlight_s = highlights[highlights.size() / 2];
    return out;
}

Status section_texture(FigureContext& ctx, Table1Section which, bool close_up) {
    record_section(ctx, which);
    tokai_relief::record_shading(ctx);
    ScalePattern pattern;
    SHITSUKAN_TRY(tokai_relief::crocodile_pattern(ctx, &pattern));
    const int out = ctx.quick() ? 128 : 512;
    // The close-up shows the middle third of the pattern (the centre line) at 3x.
    const int zoom = close_up ? 3 : 1;
    LeatherMaps maps;
    // The label image is drawn once: for the maps and for the measure of the shading below.
    const int mw = out * zoom;
    std::vector<int> labels(std::size_t(mw) * std::size_t(mw));
    SHITSUKAN_TRY(rasterize_scale_labels(pattern, mw, mw, labels.data()));
    SHITSUKAN_TRY(make_leather_maps(pattern, labels.data(), mw, mw, table1_section(which),
                                    ReliefOptions{}, maps));
    ctx.chosen("map resolution", fmt("%d x %d", out * zoom, out * zoom),
               close_up ? "3x the texture, so the close-up has one map texel per pixel"
                        : "one texel per output pixel");
    RgbImage img(out, out);
    Vec2 lo{0, 0}, hi{pattern.width, pattern.height};
    if (close_up) {
        Vec2 c = (lo + hi) * 0.5f, half = (hi - lo) * (0.5f / 3.0f);
        lo = c - half;
        hi = c + half;
        ctx.chosen("close-up window",
                   fmt("[%.3f, %.3f] x [%.3f, %.3f]", double(lo.x), double(hi.x), double(lo.y),
                       double(hi.y)),
                   "the centre line of the belly, 3x");
    }
    // Figs. 13-15 are lit alike (the text says nothing of different lights). What tells
    // fig. 14's sunken scales from fig. 13's raised ones is the shading across a scale, and
    // above all where its highlight falls. Seen from straight above, the highlight lies where
    // the surface tilts towards the light by half the light's angle from the zenith. Table 1's
    // concave section is a shallow dish: z(r) rises from 0.03 at the middle to 0.124 at
    // r = 0.83 (dz/dr at most 0.185, 10.5 degrees; eq. (4) gives the normal that slope, so the
    // height is not exaggerated), then drops to the groove in a steep outer wall (dz/dr down
    // to -6.3). A key light about 35 degrees up (1 span) puts the highlight at 27.5 degrees of
    // tilt, which only that outer wall has: a thin bright rim on the side facing the light,
    // where a raised scale has its highlight too, and the dishes read as raised plates (the
    // brightest tenth of each scale at s = -0.23 and -0.13, median, in 14(b) and 14(c)). About
    // 65 degrees up (3 spans) it needs 12.5 degrees, which the dish's far inner slope has:
    // the far side of the dish is lit and the middle is sunken (s = -0.49, -0.44); the convex
    // scales keep their highlight on the near shoulder (s = +0.62, +0.64).
    ctx.chosen("key light height", fmt("%.2f window spans", double(kSectionKeyHeight)),
               "the same for figs. 13-15 (about 65 degrees above the window's centre): the "
               "highlight falls where a scale tilts 12.5 degrees towards the light, on fig. 14's "
               "dish floor (at most 10.5 degrees) rather than its steep outer rim, which is where "
               "it fell at 35 degrees (1 span) and made the dishes read as raised (notes)");
    tokai_relief::shade_flat_texture(maps, lo, hi, img.view(), tokai_relief::leather_material(),
                                     kSectionKeyHeight);
    // Measured: the relief's contrast under the common light (RMS of the luma, 0..255).
    double sum = 0, sum2 = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const Rgb8 c = img.view().at(x, y);
            const double l = 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
            sum += l;
            sum2 += l * l;
        }
    const double n = double(img.width()) * double(img.height());
    const double mean = sum / n;
    ctx.note(
        fmt("%d scales; largest height %.4f pattern units; luma mean %.1f, RMS contrast %.1f "
            "(0..255) under the light shared by figs. 13-15.",
            pattern.polygon_count(), double(maps.max_height), mean,
            std::sqrt(std::fmax(0.0, sum2 / n - mean * mean))));
    PointLight lights[2];
    tokai_relief::flat_texture_lights(lo, hi, kSectionKeyHeight, lights);
    const LightSide side = light_side_profile(scale_pixels(
        pattern, table1_section(which), img, lo, hi, {lights[0].position.x, lights[0].position.y},
        labels, mw, mw));
    ctx.note(
        fmt("Shading across the scales, s the position towards the key light (-1 far edge, +1 "
            "near edge): over each scale's inner part (rho 0.3-0.85) the luma's correlation "
            "with s %+.2f, mean luma on the light's side minus the far side %+.1f (0..255); "
            "each scale's brightest tenth lies at s = %+.2f (median), on the light's side in "
            "%.0f %% of the scales. Raised scales: > 0, highlight on the near slope; sunken "
            "(dish): < 0, highlight on the far inner slope.",
            side.correlation, side.near_minus_far, side.highlight_s, 100.0 * side.highlight_near));
    // The property the figures exist for (§3.2, figs. 13-14): raised against sunken scales,
    // both in the shading of the inner part and in where each scale's highlight falls.
    // Thresholds chosen here: a correlation of 0.3 and the highlight a third of the way to
    // the edge (35 degrees up, figs. 14(b)/(c) had their highlights at -0.23 and -0.13).
    const bool raised = side.correlation >= 0.3 && side.highlight_s > 0.3;
    const bool sunken = side.correlation <= -0.3 && side.highlight_s < -0.3;
    if ((which == Table1Section::convex && !raised) ||
        (which == Table1Section::concave && !sunken))
        return Status::error(StatusCode::not_supported,
                             "%s: the shading across the scales (correlation %+.2f, highlight "
                             "at s = %+.2f) does not read as %s",
                             table1_section_name(which), side.correlation, side.highlight_s,
                             which == Table1Section::convex ? "raised" : "sunken");
    return ctx.save_png(img.view());
}

}  // namespace

SHITSUKAN_FIGURE(tokai1994_fig13a, "tokai1994", "fig13a", "Convex section (Table 1, fig. 13a)") {
    return section_plot(ctx, Table1Section::convex);
}
SHITSUKAN_FIGURE(tokai1994_fig13b, "tokai1994", "fig13b", "Convex leather texture (fig. 13b)") {
    return section_texture(ctx, Table1Section::convex, false);
}
SHITSUKAN_FIGURE(tokai1994_fig13c, "tokai1994", "fig13c",
                 "Convex leather texture, close-up (fig. 13c)") {
    return section_texture(ctx, Table1Section::convex, true);
}
SHITSUKAN_FIGURE(tokai1994_fig14a, "tokai1994", "fig14a", "Concave section (Table 1, fig. 14a)") {
    return section_plot(ctx, Table1Section::concave);
}
SHITSUKAN_FIGURE(tokai1994_fig14b, "tokai1994", "fig14b", "Concave leather texture (fig. 14b)") {
    return section_texture(ctx, Table1Section::concave, false);
}
SHITSUKAN_FIGURE(tokai1994_fig14c, "tokai1994", "fig14c",
                 "Concave leather texture, close-up (fig. 14c)") {
    return section_texture(ctx, Table1Section::concave, true);
}
SHITSUKAN_FIGURE(tokai1994_fig15a, "tokai1994", "fig15a",
                 "Two-segment section (Table 1, fig. 15a)") {
    return section_plot(ctx, Table1Section::two_segment);
}
SHITSUKAN_FIGURE(tokai1994_fig15b, "tokai1994", "fig15b",
                 "Two-segment leather texture (fig. 15b)") {
    return section_texture(ctx, Table1Section::two_segment, false);
}
SHITSUKAN_FIGURE(tokai1994_fig15c, "tokai1994", "fig15c",
                 "Two-segment leather texture, close-up (fig. 15c)") {
    return section_texture(ctx, Table1Section::two_segment, true);
}
