// paper_figures/tokai1994/scale_drawing.hpp — drawing helpers shared by figs. 2-10 (the
// scale-pattern line drawings): pattern coordinates to pixels, polygon outlines, seeds, and
// saving one drawing as PNG and SVG (designers use the vector line art).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/geom/planar_subdivision.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/scale_pattern.hpp"

namespace shitsukan::figures::tokai {

// Pattern point (x, y) -> pixel (ox + x s, oy + y s): no flip, the same orientation as the
// label image (row 0 at y = 0).
struct Frame {
    float ox = 0, oy = 0, scale = 1;
    Vec2 operator()(Vec2d p) const { return {ox + float(p.x) * scale, oy + float(p.y) * scale}; }
    Vec2 operator()(Vec2 p) const { return {ox + p.x * scale, oy + p.y * scale}; }
};

const Rgb8 kInk{20, 20, 20};
const Rgb8 kPaper{255, 255, 255};
const Rgb8 kFaint{175, 175, 175};
const Rgb8 kAccent{200, 40, 30};
const Rgb8 kBlue{30, 80, 200};

// Each polygon as one closed outline (in the SVG: one <polygon> per scale).
void draw_pattern(Canvas& c, const ScalePattern& pattern, const Frame& f, Rgb8 color, float width);
// Each edge of a subdivision once, as a straight segment.
void draw_subdivision(Canvas& c, const PlanarSubdivision& sub, const Frame& f, Rgb8 color,
                      float width);
// Seeds inside [lo, hi] (pattern units) as markers.
void draw_seeds(Canvas& c, const std::vector<Vec2d>& seeds, const Frame& f, MarkerShape shape,
                float size, Rgb8 color, Vec2d lo, Vec2d hi);
// The pattern rectangle's border.
void draw_border(Canvas& c, const Frame& f, float width, float height, Rgb8 color, float line);
// A two-headed dimension arrow from a to b (pixels) with a label beside its middle.
void draw_dimension(Canvas& c, Vec2 a, Vec2 b, const std::string& label, Rgb8 color,
                    Vec2 label_offset);

// The parameter table of a two-stage pattern (given by §3.1 / fig. 7, or chosen here).
void record_scale_params(FigureContext& ctx, const ScaleParams& prm);

// Draw the same picture into a PNG (<id>.png) and an SVG (<id>.svg).
Status save_png_and_svg(FigureContext& ctx, int width, int height,
                        const std::function<void(Canvas&)>& draw);

}  // namespace shitsukan::figures::tokai
