// tokai1994 figs. 7-10: the scale pattern after both divisions (fig. 7: d = 1.0 D, a = 0.25,
// p = 0.015) and the effect of d (fig. 8), a (fig. 9) and the perturbation p (fig. 10), each
// varied around the fig. 7 values.
// Example: examples/41_crocodile_scales.cpp.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/image/png16.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/scale_labels.hpp"
#include "shitsukan/leather/scale_statistics.hpp"
#include "tokai1994/scale_drawing.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;
using namespace shitsukan::figures::tokai;

namespace {

struct Panel {
    ScaleParams prm;
    std::string label;
};

// Total length of the scales' outlines (each interior edge counted from both sides, the
// border once): how much the perturbation lengthens the edges.
double total_edge_length(const ScalePattern& pattern) {
    double sum = 0;
    for (int i = 0; i < pattern.polygon_count(); ++i) {
        int n = 0;
        const Vec2* v = pattern.polygon(i, &n);
        for (int k = 0; k < n; ++k) sum += double(length(v[(k + 1) % n] - v[k]));
    }
    return sum;
}

// The scales touching the left or right border against the inner ones (touching no border):
// mean widths (area / extent in y), the narrowest and widest border scale over the median
// inner scale. Whole edge scales, not cells cut through their middle, give about 0.5 and more.
void border_scale_widths(const ScalePattern& pattern, double* narrowest, double* widest,
                         int* count) {
    std::vector<double> inner, border;
    for (int i = 0; i < pattern.polygon_count(); ++i) {
        int n = 0;
        const Vec2* v = pattern.polygon(i, &n);
        double area = 0, x0 = 1e30, x1 = -1e30, y0 = 1e30, y1 = -1e30;
        for (int k = 0; k < n; ++k) {
            const Vec2 p = v[k], q = v[(k + 1) % n];
            area += 0.5 * (double(p.x) * double(q.y) - double(q.x) * double(p.y));
            x0 = std::min(x0, double(p.x)), x1 = std::max(x1, double(p.x));
            y0 = std::min(y0, double(p.y)), y1 = std::max(y1, double(p.y));
        }
        const double eps = 1e-6;
        const bool left_right = x0 <= eps || x1 >= double(pattern.width) - eps;
        const bool top_bottom = y0 <= eps || y1 >= double(pattern.height) - eps;
        if (left_right) border.push_back(area / (y1 - y0));
        if (!left_right && !top_bottom) inner.push_back(area / (y1 - y0));
    }
    std::sort(inner.begin(), inner.end());
    const double median = inner.empty() ? 1.0 : inner[inner.size() / 2];
    *narrowest = border.empty() ? 0.0 : *std::min_element(border.begin(), border.end()) / median;
    *widest = border.empty() ? 0.0 : *std::max_element(border.begin(), border.end()) / median;
    *count = int(border.size());
}

// The distance from each scale's centroid to each of its edges inside the region (the height
// of the fan triangle a curve of that edge may use a share of, edge_perturbation.hpp): median.
double median_centroid_distance(const ScalePattern& pattern) {
    std::vector<double> h;
    const double eps = 1e-6;
    auto on_border = [&](Vec2 v) {
        return v.x <= eps || v.y <= eps || v.x >= pattern.width - eps ||
               v.y >= pattern.height - eps;
    };
    for (int i = 0; i < pattern.polygon_count(); ++i) {
        int n = 0;
        const Vec2* v = pattern.polygon(i, &n);
        const Vec2 c = pattern.centroids[std::size_t(i)];
        for (int k = 0; k < n; ++k) {
            const Vec2 a = v[k], b = v[(k + 1) % n];
            if (on_border(a) && on_border(b)) continue;
            const double l = double(length(b - a));
            if (l > 0.0) h.push_back(std::fabs(double(cross(b - a, c - a))) / l);
        }
    }
    std::sort(h.begin(), h.end());
    return h.empty() ? 0.0 : h[h.size() / 2];
}

Status panels_figure(FigureContext& ctx, const std::vector<Panel>& panels, const char* varied,
                     std::vector<double>* lengths = nullptr,
                     std::vector<double>* realised_share = nullptr) {
    double first_length = 1.0;
    record_scale_params(ctx, ScaleParams{});
    const int side = ctx.quick() ? 128 : 256, gap = side / 12, caption = 24;
    const int width = int(panels.size()) * side + (int(panels.size()) + 1) * gap;
    const int height = side + 2 * gap + caption;
    std::vector<ScalePattern> patterns(panels.size());
    std::string note = std::string("Varied: ") + varied + ".";
    for (std::size_t i = 0; i < panels.size(); ++i) {
        ScaleDivision steps;
        SHITSUKAN_TRY(generate_scale_pattern(panels[i].prm, patterns[i], &steps));
        const PerturbationReport& r = steps.perturbation;
        const double length = total_edge_length(patterns[i]);
        if (i == 0) first_length = length;
        note += fmt(
            " %s: %d scales, RMS edge offset %.5f of %.5f requested (%.0f %%; %d of %d "
            "edges scaled down), largest offset %.4f; edges %.3f long (%.1f %% longer "
            "than the first panel's).",
            panels[i].label.c_str(), patterns[i].polygon_count(), r.realised_rms, r.requested_rms,
            r.requested_rms > 0 ? 100.0 * r.realised_rms / r.requested_rms : 100.0, r.shrunk,
            r.edges, r.max_offset, length, 100.0 * (length / first_length - 1.0));
        if (lengths) lengths->push_back(length);
        if (realised_share)
            realised_share->push_back(
                r.requested_rms > 0 ? 100.0 * r.realised_rms / r.requested_rms : 100.0);
    }
    ctx.note(note);
    return save_png_and_svg(ctx, width, height, [&](Canvas& c) {
        for (std::size_t i = 0; i < panels.size(); ++i) {
            const Frame f{float(gap + int(i) * (side + gap)), float(gap), float(side)};
            draw_pattern(c, patterns[i], f, kInk, 1.0f);
            draw_border(c, f, 1, 1, kInk, 1.2f);
            c.text({f.ox, float(gap + side + 8)}, panels[i].label, kInk, ctx.quick() ? 1 : 2);
        }
    });
}

}  // namespace

SHITSUKAN_FIGURE(tokai_fig07, "tokai1994", "fig07",
                 "Scale pattern after both divisions (d = 1.0 D, a = 0.25, p = 0.015)") {
    ScaleParams prm;
    record_scale_params(ctx, prm);
    ScaleDivision steps;
    ScalePattern pattern;
    SHITSUKAN_TRY(generate_scale_pattern(prm, pattern, &steps));
    ScaleStatistics st;
    SHITSUKAN_TRY(measure_scale_statistics(steps.cells, prm.width, prm.height, st));
    ctx.note(
        fmt("Measured before perturbation: mean corner count of the %d inner scales %.2f "
            "(feature (1): near-quadrilateral); mean width %.4f at 0.3-0.45 W from the "
            "centre line vs %.4f at 0.1-0.2 W, ratio %.2f (feature (3)).",
            st.cells, st.mean_corners, st.edge_width, st.centre_width, st.edge_to_centre));
    double narrowest = 0, widest = 0;
    int border = 0;
    border_scale_widths(pattern, &narrowest, &widest, &border);
    ctx.note(fmt("The %d scales touching the left or right border are whole scales of the edge "
                 "spacing: mean width (area / height) %.2f-%.2f of the median of the scales "
                 "touching no border (stage-2 columns mirrored about x = 0 and x = W).",
                 border, narrowest, widest));
    ctx.note(fmt(
        "%d scales in %d stage-1 polygons; %d interior edges perturbed once each with p = 0.015: "
        "RMS offset %.5f of %.5f requested (%.0f %%), %d edges scaled down to keep the tiling, "
        "max offset %.4f. "
        "Look for (1) near-quadrilateral scales in regular rows, (2) the joint pattern along the "
        "centre line, (3) scales narrowing toward the left and right edges.",
        pattern.polygon_count(), steps.stage1.face_count(), steps.perturbation.edges,
        steps.perturbation.realised_rms, steps.perturbation.requested_rms,
        100.0 * steps.perturbation.realised_rms / steps.perturbation.requested_rms,
        steps.perturbation.shrunk, steps.perturbation.max_offset));
    const int size = ctx.quick() ? 256 : 512, margin = size / 32;
    const Frame f{float(margin), float(margin), float(size - 2 * margin)};
    SHITSUKAN_TRY(save_png_and_svg(ctx, size, size, [&](Canvas& c) {
        draw_pattern(c, pattern, f, kInk, 1.3f);
        draw_border(c, f, 1, 1, kInk, 1.5f);
    }));
    // The same polygons as data for the relief step (fig07.csv) and as a label image
    // (fig07_labels.png: 16-bit gray, value = polygon id, every pixel exactly one polygon).
    std::string csv = "polygon,centroid_x,centroid_y,vertex_count,vertices (x y ...)\n";
    for (int i = 0; i < pattern.polygon_count(); ++i) {
        int n;
        const Vec2* v = pattern.polygon(i, &n);
        csv += fmt("%d,%.7g,%.7g,%d,", i, double(pattern.centroids[std::size_t(i)].x),
                   double(pattern.centroids[std::size_t(i)].y), n);
        for (int k = 0; k < n; ++k)
            csv += fmt("%s%.7g %.7g", k ? " " : "", double(v[k].x), double(v[k].y));
        csv += "\n";
    }
    SHITSUKAN_TRY(ctx.save_text(".csv", csv));
    const int n = size;
    std::vector<std::int32_t> labels(std::size_t(n) * std::size_t(n));
    SHITSUKAN_TRY(rasterize_scale_labels(pattern, n, n, labels.data()));
    Gray16Image ids(n, n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            ids.at(i, j) = std::uint16_t(labels[std::size_t(j) * std::size_t(n) + std::size_t(i)]);
    return write_png16(ctx.path("_labels.png").c_str(), ids.view());
}

SHITSUKAN_FIGURE(tokai_fig08, "tokai1994", "fig08",
                 "Effect of the distance d from the centre line") {
    std::vector<Panel> panels;
    for (float k : {0.25f, 0.5f, 1.0f, 2.0f}) {
        Panel p;
        p.prm.d = k * p.prm.D;
        p.label = fmt("d = %g D", double(k));
        panels.push_back(p);
    }
    ctx.chosen("d values", "0.25 D, 0.5 D, 1.0 D, 2.0 D", "the paper's values are not printed");
    return panels_figure(ctx, panels, "d (a = 0.25, p = 0.015)");
}

SHITSUKAN_FIGURE(tokai_fig09, "tokai1994", "fig09", "Effect of the relative displacement a") {
    std::vector<Panel> panels;
    for (float a : {0.0f, 0.1f, 0.25f, 0.5f}) {
        Panel p;
        p.prm.a = a;
        p.label = fmt("a = %g", double(a));
        panels.push_back(p);
    }
    ctx.chosen("a values", "0, 0.1, 0.25, 0.5", "the paper's values are not printed");
    return panels_figure(ctx, panels, "a (d = 1.0 D, p = 0.015)");
}

SHITSUKAN_FIGURE(tokai_fig10, "tokai1994", "fig10", "Effect of the perturbation p") {
    std::vector<Panel> panels;
    for (float pv : {0.0f, 0.0075f, 0.015f, 0.03f}) {
        Panel p;
        p.prm.perturbation.p = pv;
        p.label = fmt("p = %g", double(pv));
        panels.push_back(p);
    }
    ctx.chosen("p values", "0, 0.0075, 0.015, 0.03",
               "the paper prints only fig. 7's p = 0.015; 0.03 already nearly reaches the "
               "roughness the tiling allows (the ceiling measured in the notes), so a larger p "
               "would draw the same picture");
    ctx.note(
        "Each curve is made with the requested p; only the curves that would leave their fan "
        "triangles or break a scale's star shape are scaled down (edge_perturbation.hpp), so "
        "the panels grow rougher from left to right: compare the realised RMS offsets.");
    std::vector<double> lengths, realised_share;
    SHITSUKAN_TRY(panels_figure(ctx, panels, "p (d = 1.0 D, a = 0.25)", &lengths, &realised_share));
    // Why the largest p is not realised in full: the ceiling. With 4x the largest p nearly every
    // curve is scaled down to the most its fan triangles and the star shape (which the relief's
    // rays from the centroid need, eq. 4) allow; the realised RMS and the edge length stop there.
    ScalePattern ceiling;
    ScaleParams top = panels.back().prm;
    top.perturbation.p = 4.0f * panels.back().prm.perturbation.p;
    ScaleDivision steps;
    SHITSUKAN_TRY(generate_scale_pattern(top, ceiling, &steps));
    ScaleDivision last_steps;
    ScalePattern last;
    SHITSUKAN_TRY(generate_scale_pattern(panels.back().prm, last, &last_steps));
    const double ceiling_rms = steps.perturbation.realised_rms;
    const double ceiling_length = total_edge_length(ceiling);
    // Why: the largest offset the recursion asks, p (1 + decay + decay^2 + ...), against the
    // room a curve has, `safety` of the distance from its edge to its scale's centroid.
    ScalePattern straight;
    ScaleParams flat = panels.front().prm;
    SHITSUKAN_TRY(generate_scale_pattern(flat, straight));
    const PerturbationParams& pp = top.perturbation;
    double reach = 0.0, amplitude = double(panels.back().prm.perturbation.p);
    for (int k = 0; k < pp.levels; ++k, amplitude *= double(pp.decay)) reach += amplitude;
    const double room = median_centroid_distance(straight);
    ctx.note(
        fmt("Why the largest p is not realised in full: at p = %g a curve's offsets reach "
            "up to %.4f (p (1 + %g + %g^2 + ...), %d levels; requested RMS %.4f), while the "
            "median distance from an edge to its scale's centroid is %.4f and a curve may use "
            "%g of it, %.4f (its fan triangles), besides keeping every scale star-shaped from "
            "its centroid (the relief's rays, eq. 4). The "
            "edges that would swing further are scaled down, so p = %g realises %.0f %% of "
            "its RMS, p = %g %.0f %% and p = %g %.0f %%.",
            double(panels.back().prm.perturbation.p), reach, double(pp.decay), double(pp.decay),
            pp.levels, last_steps.perturbation.requested_rms, room, double(pp.safety),
            double(pp.safety) * room, double(panels.back().prm.perturbation.p),
            100.0 * last_steps.perturbation.realised_rms / last_steps.perturbation.requested_rms,
            double(panels[1].prm.perturbation.p), realised_share[1],
            double(panels[2].prm.perturbation.p), realised_share[2]));
    ctx.note(
        fmt("The ceiling (measured with p = %g, 4x the largest panel's): RMS offset %.5f, "
            "edges %.1f %% longer than at p = 0, with %d of %d edges scaled down. The "
            "largest panel realises %.0f %% of that RMS (%.0f %% of its own request): a "
            "larger p cannot make the pattern rougher without scales overlapping or "
            "losing the star shape from their centroid; with D = %.2f the offsets stop at "
            "about %.0f %% of D.",
            double(top.perturbation.p), ceiling_rms,
            100.0 * (ceiling_length / lengths.front() - 1.0), steps.perturbation.shrunk,
            steps.perturbation.edges, 100.0 * last_steps.perturbation.realised_rms / ceiling_rms,
            100.0 * last_steps.perturbation.realised_rms / last_steps.perturbation.requested_rms,
            double(top.D), 100.0 * ceiling_rms / double(top.D)));
    // The property the figure is for: each step of p lengthens the edges (rougher outlines) by
    // more than 0.5 % (chosen here: p = 0.0075 adds 0.9 % to the 120 whole scales' outlines)
    for (std::size_t i = 1; i < lengths.size(); ++i)
        if (!(lengths[i] > lengths[i - 1] * 1.005))
            return Status::error(StatusCode::not_supported,
                                 "fig10: panel %d is not rougher than panel %d (edges %.3f vs "
                                 "%.3f)",
                                 int(i) + 1, int(i), lengths[i], lengths[i - 1]);
    return Status::success();
}
