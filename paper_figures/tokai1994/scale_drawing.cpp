#include "tokai1994/scale_drawing.hpp"

#include <cmath>

namespace shitsukan::figures::tokai {

void draw_pattern(Canvas& c, const ScalePattern& pattern, const Frame& f, Rgb8 color, float width) {
    std::vector<Vec2> px;
    for (int i = 0; i < pattern.polygon_count(); ++i) {
        int n;
        const Vec2* v = pattern.polygon(i, &n);
        px.clear();
        for (int k = 0; k < n; ++k) px.push_back(f(v[k]));
        c.polygon_outline(px.data(), n, color, width);
    }
}

void draw_subdivision(Canvas& c, const PlanarSubdivision& sub, const Frame& f, Rgb8 color,
                      float width) {
    for (const auto& e : sub.edges)
        c.line(f(sub.vertices[std::size_t(e.v0)]), f(sub.vertices[std::size_t(e.v1)]), color,
               width);
}

void draw_seeds(Canvas& c, const std::vector<Vec2d>& seeds, const Frame& f, MarkerShape shape,
                float size, Rgb8 color, Vec2d lo, Vec2d hi) {
    for (const Vec2d& s : seeds)
        if (s.x >= lo.x && s.x <= hi.x && s.y >= lo.y && s.y <= hi.y)
            c.marker(f(s), shape, size, color);
}

void draw_border(Canvas& c, const Frame& f, float width, float height, Rgb8 color, float line) {
    c.rect_outline(f(Vec2{0, 0}), Vec2{width * f.scale, height * f.scale}, color, line);
}

void draw_dimension(Canvas& c, Vec2 a, Vec2 b, const std::string& label, Rgb8 color,
                    Vec2 label_offset) {
    c.line(a, b, color, 1.2f);
    Vec2 d{b.x - a.x, b.y - a.y};
    float len = std::sqrt(d.x * d.x + d.y * d.y);
    if (len <= 0.0f) return;
    Vec2 u{d.x / len, d.y / len}, n{-u.y, u.x};
    const float head = 6.0f, spread = 3.0f;
    for (int end = 0; end < 2; ++end) {
        Vec2 tip = end == 0 ? a : b;
        float sgn = end == 0 ? 1.0f : -1.0f;
        Vec2 base{tip.x + sgn * u.x * head, tip.y + sgn * u.y * head};
        Vec2 tri[3] = {tip,
                       {base.x + n.x * spread, base.y + n.y * spread},
                       {base.x - n.x * spread, base.y - n.y * spread}};
        c.fill_polygon(tri, 3, color);
    }
    Vec2 mid{0.5f * (a.x + b.x) + label_offset.x, 0.5f * (a.y + b.y) + label_offset.y};
    c.text(mid, label, color, 2);
}

void record_scale_params(FigureContext& ctx, const ScaleParams& prm) {
    ctx.chosen("pattern region", fmt("[0, %g] x [0, %g]", double(prm.width), double(prm.height)),
               "the paper's square, in units of its side");
    ctx.chosen("D", fmt("%g", double(prm.D)),
               "seed spacing: 10 stage-1 rows on the square; not printed");
    ctx.given("d", fmt("%g D", double(prm.d / prm.D)),
              "§3.1, fig. 7: d = 1.0 D (varied in fig. 8)");
    ctx.given("a", fmt("%g", double(prm.a)),
              "§3.1, fig. 7: a = 0.25 (varied in fig. 9); eq. (1) M = D a Rnd");
    ctx.given("p", fmt("%g", double(prm.perturbation.p)),
              "§3.1, fig. 7: p = 0.015 (varied in fig. 10)");
    ctx.chosen(
        "stage-2 spacing law",
        fmt("s(u) = D (1 - (1 - r) u^2), r = %g, u = |x - W/2| / (W/2)", double(prm.edge_ratio)),
        "the paper says only that the spacing narrows toward the edges");
    ctx.chosen("stage-2 rows", "one row through each stage-1 seed, moved along x by s_k a Rnd",
               "the paper does not say where the rows lie; this puts one scale row in each stage-1 "
               "polygon");
    ctx.chosen("stage-2 border columns",
               "none on x = 0 and x = W: each edge lies midway between the outermost column and "
               "its mirror image, and each row's outermost seed is mirrored about it",
               "the border is then a Voronoi edge, so the edge scales are whole (a column on the "
               "border cut them to 0.28-0.51 of the median width)");
    ctx.chosen(
        "perturbation recursion",
        fmt("%d levels, amplitude p decay^(k-1), decay %g, Rnd hashed from the edge's end points",
            prm.perturbation.levels, double(prm.perturbation.decay)),
        "midpoint displacement is cited without details");
    ctx.chosen("perturbation bound",
               fmt("requested p kept; a curve leaving %g of its fan triangles' height, or "
                   "turning back around its scale's centroid, is scaled down just enough",
                   double(prm.perturbation.safety)),
               "keeps the polygons a tiling and star-shaped (edge_perturbation.hpp)");
    ctx.chosen("random seed", fmt("%u", prm.seed),
               "any; the pattern is a deterministic function of it");
}

Status save_png_and_svg(FigureContext& ctx, int width, int height,
                        const std::function<void(Canvas&)>& draw) {
    RgbImage img(width, height, kPaper);
    RasterCanvas raster(img.view());
    draw(raster);
    SHITSUKAN_TRY(ctx.save_png(img.view()));
    SvgCanvas svg(width, height, kPaper);
    draw(svg);
    return ctx.save_text(".svg", svg.str());
}

}  // namespace shitsukan::figures::tokai
