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
// Fig. 15's inner part holds both walls of its ridge, which face opposite ways: the
// correlation mixes them (about +0.1) and fig. 15 is read by ridge_walls below instead.
struct LightSide {
    double correlation = 0;        // luma against s, inner part
    double near_minus_far = 0;     // mean luma (0..255) where s > 0.3 minus where s < -0.3
    double highlight_s = 0;        // median over the scales of the brightest tenth's mean s
    double highlight_near = 0;     // fraction of the scales whose brightest tenth has s > 0
};

struct ShadedPixel {
    float luma, s, rho;
};

// The scales' pixels (every other pixel: the statistics, at a quarter of the cost; every
// pixel below 256 x 256, where a scale of the quick figures is only about 11 pixels wide).
std::vector<std::vector<ShadedPixel>> scale_pixels(const ScalePattern& pattern,
                                                   const BezierChain& section, RgbImage& img,
                                                   Vec2 lo, Vec2 hi, Vec2 light,
                                                   const std::vector<int>& full, int lw, int lh) {
    const int w = img.width(), h = img.height();
    const Vec2 size = hi - lo;
    std::vector<std::vector<ShadedPixel>> per_scale(std::size_t(pattern.polygon_count()));
    const int step = w < 256 ? 1 : 2;
    for (int j = 0; j < h; j += step)
        for (int i = 0; i < w; i += step) {
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

// The look of a section under the key light, read from its own slope: seen from above with
// a light at zenith angle b, a pixel whose surface tilts by phi towards the scale's edge is
// lit by about cos(b - phi) on the side facing the light and cos(b + phi) on the far side, so
// the near-minus-far luma at a relative distance rho goes as 2·sin(b)·sin(phi), with
// sin(phi) = -z'(r) / sqrt(1 + z'^2) the outward tilt of eq. (4)'s normal. Per rho bin (0.05
// wide, 0.05-0.90), the luma where the pixel lies towards the light (cos theta = s / rho >
// 0.5) minus where it lies away (< -0.5), pooled over the scales; its correlation over the
// bins with the predicted sin(phi). A flat section gives no difference to correlate; a
// section drawn upside down gives a negative correlation.
struct RadialAgreement {
    double correlation = 0;  // over the bins, measured against predicted
    double gain = 0;         // least-squares luma per unit sin(phi), through the origin
};

RadialAgreement radial_profile_agreement(const std::vector<std::vector<ShadedPixel>>& per_scale,
                                const BezierChain& section) {
    constexpr int kBins = 17;
    double near[kBins] = {}, far[kBins] = {}, nn[kBins] = {}, nf[kBins] = {};
    for (const std::vector<ShadedPixel>& px : per_scale)
        for (const ShadedPixel& p : px) {
            const int b = int((p.rho - 0.05f) / 0.05f);
            if (p.rho < 0.05f || b < 0 || b >= kBins) continue;
            const float c = p.s / p.rho;
            if (c > 0.5f) near[b] += p.luma, nn[b] += 1;
            if (c < -0.5f) far[b] += p.luma, nf[b] += 1;
        }
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, n = 0;
    for (int b = 0; b < kBins; ++b) {
        if (nn[b] < 1 || nf[b] < 1) continue;
        const SectionSample q = section_at_r(section, 0.05f + 0.05f * (float(b) + 0.5f));
        const double slope = std::fabs(q.dr) > 1e-9f ? double(q.dz) / double(q.dr) : 0.0;
        const double x = -slope / std::sqrt(1.0 + slope * slope);
        const double y = near[b] / nn[b] - far[b] / nf[b];
        sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y, n += 1;
    }
    RadialAgreement out;
    if (n < 3 || sxx <= 0) return out;
    const double vx = sxx / n - (sx / n) * (sx / n), vy = syy / n - (sy / n) * (sy / n);
    out.correlation = vx > 0 && vy > 0 ? (sxy / n - (sx / n) * (sy / n)) / std::sqrt(vx * vy) : 0.0;
    out.gain = sxy / sxx;
    return out;
}

// Fig. 15's section (Table 1, two segments): the first segment falls from the middle
// (z = 0.25) to a moat (z = 0.115 at r = 0.34) and climbs again to 0.25 at r = 0.6, where
// the second segment starts falling to the groove at r = 0.9. The join is a ridge with a
// corner (dz/dr +1.38 inside, -0.38 outside): the "discontinuous section" of §3.2. Its two
// walls face opposite ways, so the light swaps them: on a scale's side towards the light the
// outer wall (facing out, towards the light) is brighter than the inner one; on the far side
// the inner wall (facing in, towards the light again) is. Per scale, the mean luma of the
// inner wall (from just above the moat's bottom to just inside the join) and of the outer
// wall (from just outside the join to just inside the groove), where cos theta = s / rho >
// 0.5 (near) and < -0.5 (far).
struct RidgeWalls {
    double near_step = 0;  // median over the scales: outer minus inner wall, near side
    double far_step = 0;   // median: inner minus outer wall, far side
    double both = 0;       // fraction of the scales with both steps > 0
    int scales = 0;
};

double median_of(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
}

RidgeWalls ridge_walls(const std::vector<std::vector<ShadedPixel>>& per_scale,
                       const BezierChain& section) {
    RidgeWalls out;
    if (section.count < 2) return out;
    const float join = section.segments[0].p[3].x, end = section_r_last(section);
    float moat = 0.0f, low = 1e30f;  // the first segment's lowest point
    for (int k = 0; k <= 200; ++k) {
        const float r = join * float(k) / 200.0f;
        const float z = section_at_r(section, r).z;
        if (z < low) low = z, moat = r;
    }
    const float in0 = moat + 0.05f, in1 = join - 0.02f, out0 = join + 0.02f, out1 = end - 0.04f;
    std::vector<double> near_steps, far_steps;
    std::size_t both = 0;
    for (const std::vector<ShadedPixel>& px : per_scale) {
        double sum[4] = {}, cnt[4] = {};  // inner near, outer near, inner far, outer far
        for (const ShadedPixel& p : px) {
            const int wall = p.rho >= in0 && p.rho <= in1 ? 0 : p.rho >= out0 && p.rho <= out1 ? 1 : -1;
            if (wall < 0) continue;
            const float c = p.s / p.rho;
            const int side = c > 0.5f ? 0 : c < -0.5f ? 2 : -1;
            if (side < 0) continue;
            sum[side + wall] += p.luma, cnt[side + wall] += 1;
        }
        if (cnt[0] < 3 || cnt[1] < 3 || cnt[2] < 3 || cnt[3] < 3) continue;
        const double near = sum[1] / cnt[1] - sum[0] / cnt[0];
        const double far = sum[2] / cnt[2] - sum[3] / cnt[3];
        near_steps.push_back(near);
        far_steps.push_back(far);
        both += near > 0 && far > 0 ? 1 : 0;
    }
    out.scales = int(near_steps.size());
    if (out.scales == 0) return out;
    out.both = double(both) / double(out.scales);
    out.near_step = median_of(near_steps);
    out.far_step = median_of(far_steps);
    return out;
}

// Measures the shading across the scales (notes) and checks it reads as the section.
Status check_section_shading(FigureContext& ctx, Table1Section which,
                             const std::vector<std::vector<ShadedPixel>>& pixels) {
    const LightSide side = light_side_profile(pixels);
    const RadialAgreement agreement = radial_profile_agreement(pixels, table1_section(which));
    const RidgeWalls ridge = ridge_walls(pixels, table1_section(which));
    ctx.note(fmt("Near-minus-far luma per relative distance (0.05-0.90) against the section's "
                 "predicted outward tilt sin(phi) = -z'/sqrt(1 + z'^2): correlation %+.2f, "
                 "%+.1f luma (0..255) per unit sin(phi).",
                 agreement.correlation, agreement.gain));
    if (ridge.scales > 0)
        ctx.note(fmt("The ridge where the two segments meet (r = 0.6): on the light's side the "
                     "outer wall is brighter than the inner one by %+.1f, on the far side the "
                     "inner wall brighter than the outer by %+.1f (luma 0..255, median over %d "
                     "scales); both in %.0f %% of the scales.",
                     ridge.near_step, ridge.far_step, ridge.scales, 100.0 * ridge.both));
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
    // All three sections: the light's side against the far side follows the section's own
    // slope, bin by bin (a flat or an upside-down section fails). Fig. 15 (§3.2: two curves
    // joined into a section with a corner): the ridge's walls swap brightness across the
    // scale. Thresholds chosen here, against a correlation of +0.63 to +0.97 and 37-236 luma
    // per unit sin(phi) for the three sections, and ridge steps of +10 to +29 (the sections
    // drawn flat: at most 7 luma and +1.0; drawn upside down: negative).
    if (agreement.correlation < 0.5 || agreement.gain < 20.0)
        return Status::error(StatusCode::not_supported,
                             "%s: the light's side against the far side does not follow the "
                             "section's slope (correlation %+.2f, %+.1f luma per unit sin(phi))",
                             table1_section_name(which), agreement.correlation, agreement.gain);
    if (which == Table1Section::two_segment && (ridge.near_step < 5.0 || ridge.far_step < 5.0))
        return Status::error(StatusCode::not_supported,
                             "%s: the ridge where the two segments meet does not show (outer "
                             "minus inner wall %+.1f on the light's side, inner minus outer "
                             "%+.1f on the far side)",
                             table1_section_name(which), ridge.near_step, ridge.far_step);
    return Status::success();
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
    const std::vector<std::vector<ShadedPixel>> pixels =
        scale_pixels(pattern, table1_section(which), img, lo, hi,
                     {lights[0].position.x, lights[0].position.y}, labels, mw, mw);
    SHITSUKAN_TRY(check_section_shading(ctx, which, pixels));
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
