// tokai1994 figs. 4-6: the stage-1 seed layout (fig. 4, d and D marked), the pattern after
// the vertical division (fig. 5), and the stage-2 seed layout with columns narrowing toward
// the left and right edges (fig. 6). Open circles: original seeds; dots: moved seeds.
// Example: examples/41_crocodile_scales.cpp.
#include <cmath>

#include "driver/figure.hpp"
#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "tokai1994/scale_drawing.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;
using namespace shitsukan::figures::tokai;

namespace {

void draw_centre_line(Canvas& c, const Frame& f, float width, float height) {
    const float x = 0.5f * width;
    const int dashes = 40;
    for (int i = 0; i < dashes; ++i) {
        float y0 = height * i / dashes, y1 = height * (i + 0.6f) / dashes;
        c.line(f(Vec2{x, y0}), f(Vec2{x, y1}), kBlue, 1.0f);
    }
}

void draw_moves(Canvas& c, const SeedLayout& s, const Frame& f, float marker, Vec2d lo, Vec2d hi) {
    for (std::size_t i = 0; i < s.moved.size(); ++i) {
        Vec2d o = s.original[i];
        if (o.x < lo.x || o.x > hi.x || o.y < lo.y || o.y > hi.y) continue;
        c.line(f(o), f(s.moved[i]), kAccent, 1.0f);
        c.marker(f(o), MarkerShape::circle, marker, kInk);
        c.marker(f(s.moved[i]), MarkerShape::dot, marker * 0.8f, kAccent);
    }
}

// "o original seed, (red dot) moved seed, <text>" in one line starting at `at` (its middle).
void draw_legend(Canvas& c, Vec2 at, float marker, const std::string& text) {
    float x = at.x + marker;
    c.marker({x, at.y}, MarkerShape::circle, marker, kInk);
    c.text({x + marker, at.y - 4.0f}, "original seed", kInk, 1);
    x += marker + 6.0f * 14 + 2.0f * marker;
    c.marker({x, at.y}, MarkerShape::dot, marker * 0.8f, kAccent);
    c.text({x + marker, at.y - 4.0f}, "moved seed;  " + text, kInk, 1);
}

}  // namespace

SHITSUKAN_FIGURE(
    tokai_fig04, "tokai1994", "fig04",
    "Stage-1 (vertical) division: seed rows at distance d from the centre line, spacing D, "
    "moved along y") {
    ScaleParams prm;
    record_scale_params(ctx, prm);
    ScaleDivision steps;
    SHITSUKAN_TRY(divide_scales(prm, steps));
    const int size = ctx.quick() ? 300 : 600, margin = size / 12;
    const Frame f{float(margin), float(margin), float(size - 2 * margin)};
    const float marker = size / 60.0f;
    ctx.note(
        "Open circles: seeds on the lattice (processing 1); red dots: after the move of eq. (1) "
        "along y (processing 2); grey: the Voronoi division of the moved seeds (processing 3).");
    return save_png_and_svg(ctx, size, size, [&](Canvas& c) {
        draw_subdivision(c, steps.stage1, f, kFaint, 1.0f);
        draw_border(c, f, 1, 1, kInk, 1.5f);
        draw_centre_line(c, f, 1, 1);
        draw_moves(c, steps.stage1_seeds, f, marker, {0, 0}, {1, 1});
        // d: from the centre line to the left row; D: between two original seeds of the right row
        const double xc = 0.5;
        Vec2 a = f(Vec2d{xc - prm.d, -0.55 * prm.D}), b = f(Vec2d{xc, -0.55 * prm.D});
        for (double x : {xc - double(prm.d), xc})  // extension lines down to the row and the axis
            c.line(f(Vec2d{x, -0.75 * prm.D}), f(Vec2d{x, -0.1 * prm.D}), kInk, 0.8f);
        draw_dimension(c, a, b, "d", kInk, {-0.5f * (b.x - a.x) - 18.0f, -8.0f});
        Vec2 p = f(Vec2d{xc + prm.d + 0.45 * prm.D, 4.0 * prm.D});
        Vec2 q = f(Vec2d{xc + prm.d + 0.45 * prm.D, 5.0 * prm.D});
        c.line(f(Vec2d{xc + prm.d + 0.15 * prm.D, 4.0 * prm.D}),
               f(Vec2d{xc + prm.d + 0.6 * prm.D, 4.0 * prm.D}), kInk, 0.8f);
        c.line(f(Vec2d{xc + prm.d + 0.15 * prm.D, 5.0 * prm.D}),
               f(Vec2d{xc + prm.d + 0.6 * prm.D, 5.0 * prm.D}), kInk, 0.8f);
        draw_dimension(c, p, q, "D", kInk, {8.0f, -8.0f});
        draw_legend(c, {float(margin), float(size - margin) + 14.0f}, marker,
                    fmt("d = %g D, a = %g, moved along y", double(prm.d / prm.D), double(prm.a)));
    });
}

SHITSUKAN_FIGURE(tokai_fig05, "tokai1994", "fig05",
                 "Pattern after the vertical (stage-1) division: the overlapping centre pattern") {
    ScaleParams prm;
    record_scale_params(ctx, prm);
    ScaleDivision steps;
    ScalePattern final_pattern;
    SHITSUKAN_TRY(generate_scale_pattern(prm, final_pattern, &steps));
    const ScalePattern& stage1 = steps.stage1_pattern;
    int interior = 0;
    for (const PlanarSubdivision::Edge& e : steps.stage1.edges) interior += e.right >= 0;
    ctx.note(fmt(
        "%d stage-1 polygons, each of the %d interior stage-1 edges bent once (processing 4) "
        "before stage 2, as the paper orders it: these curves are fig. 7's row boundaries point "
        "for point (perturb_two_stage). Left and right polygons meet along the centre line in a "
        "zig-zag: the joint pattern of §2 (2).",
        stage1.polygon_count(), interior));
    const int size = ctx.quick() ? 256 : 512, margin = size / 32;
    const Frame f{float(margin), float(margin), float(size - 2 * margin)};
    return save_png_and_svg(ctx, size, size, [&](Canvas& c) {
        draw_pattern(c, stage1, f, kInk, 1.3f);
        draw_border(c, f, 1, 1, kInk, 1.5f);
    });
}

SHITSUKAN_FIGURE(
    tokai_fig06, "tokai1994", "fig06",
    "Stage-2 (horizontal) division: seed rows parallel to x, spacing narrowing toward the edges, "
    "moved along x") {
    ScaleParams prm;
    record_scale_params(ctx, prm);
    ScaleDivision steps;
    SHITSUKAN_TRY(divide_scales(prm, steps));
    const int size = ctx.quick() ? 300 : 600, margin = size / 12;
    const Frame f{float(margin), float(margin), float(size - 2 * margin)};
    const float marker = size / 75.0f;
    std::string spacing;
    for (std::size_t k = 0; k < steps.columns.x.size(); ++k)
        if (steps.columns.index[k] >= 0)
            spacing += fmt("%s%.3f", spacing.empty() ? "" : ", ", steps.columns.spacing[k]);
    ctx.note("Spacings s_k from the centre column outward: " + spacing + ".");
    return save_png_and_svg(ctx, size, size, [&](Canvas& c) {
        draw_subdivision(c, steps.cells, f, kFaint, 1.0f);
        draw_subdivision(c, steps.stage1, f, kInk, 1.4f);
        draw_border(c, f, 1, 1, kInk, 1.5f);
        // the seeds of each row that fall inside their own stage-1 polygon
        std::vector<Vec2d> poly;
        for (std::size_t i = 0; i < steps.stage2_seeds.moved.size(); ++i) {
            int face = steps.stage2_row[i];
            poly.clear();
            const PlanarSubdivision& s1 = steps.stage1;
            for (int k = s1.face_offsets[std::size_t(face)];
                 k < s1.face_offsets[std::size_t(face) + 1]; ++k)
                poly.push_back(
                    s1.vertices[std::size_t(s1.face_vertex(s1.face_edges[std::size_t(k)]))]);
            Vec2d o = steps.stage2_seeds.original[i], m = steps.stage2_seeds.moved[i];
            if (!point_in_polygon(poly.data(), int(poly.size()), o) &&
                !point_in_polygon(poly.data(), int(poly.size()), m))
                continue;
            c.line(f(o), f(m), kAccent, 1.0f);
            c.marker(f(o), MarkerShape::circle, marker, kInk);
            c.marker(f(m), MarkerShape::dot, marker * 0.8f, kAccent);
        }
        // column ticks under the square: the spacing law
        for (double x : steps.columns.x) {
            if (x < 0.0 || x > 1.0) continue;
            Vec2 t = f(Vec2d{x, 1.0});
            c.line({t.x, t.y + 4.0f}, {t.x, t.y + 14.0f}, kBlue, 1.5f);
        }
        // the spacing at the centre (the two columns beside the centre line) and at the edge
        const Stage2Columns& col = steps.columns;
        std::size_t mid = 0, last = 0;
        for (std::size_t k = 0; k < col.x.size(); ++k) {
            if (col.index[k] == 1) mid = k;
            if (col.x[k] <= 1.0) last = k;
        }
        if (mid > 0 && last > 0) {
            const float y = f(Vec2d{0.0, 1.0}).y + 9.0f;
            draw_dimension(c, {f(Vec2d{col.x[mid - 1], 1.0}).x, y},
                           {f(Vec2d{col.x[mid], 1.0}).x, y}, "", kBlue, {0, 0});
            draw_dimension(c, {f(Vec2d{col.x[last - 1], 1.0}).x, y},
                           {f(Vec2d{col.x[last], 1.0}).x, y}, "", kBlue, {0, 0});
            c.text({f(Vec2d{0.5, 1.0}).x - 3.0f, y + 6.0f}, "D", kBlue, 1);
            c.text({f(Vec2d{col.x[last - 1], 1.0}).x - 24.0f, y + 6.0f},
                   fmt("%.2g D", (col.x[last] - col.x[last - 1]) / double(prm.D)), kBlue, 1);
        }
        draw_legend(c, {float(margin), float(size - margin) + 36.0f}, marker,
                    fmt("ticks: s(u) = D (1 - %g u^2); a = %g along x",
                        double(1.0f - prm.edge_ratio), double(prm.a)));
    });
}
