// shitsukan/image/canvas.hpp — 2D drawing for the papers' diagrams and plots (CONTRACT).
//
// Manual
//   RgbImage img(640, 480, Rgb8{255, 255, 255});
//   RasterCanvas canvas(img.view());            // draws into pixels (anti-aliased lines)
//   SvgCanvas svg(640, 480);                    // records the same calls as SVG elements
//   Canvas& c = canvas;                         // figure code draws through the interface
//   const Vec2 points[3] = {{20, 20}, {120, 40}, {60, 140}};
//   const Rgb8 color{200, 40, 40};
//   c.line({10, 10}, {200, 50}, Rgb8{0, 0, 0}, 1.5f);
//   c.polyline(points, 3, color, 2.0f);   c.polygon_outline(points, 3, color, 1.0f);
//   c.fill_polygon(points, 3, color);     // even-odd rule, any simple or complex polygon
//   c.fill_rect({300, 20}, {40, 30}, color);    c.rect_outline({300, 20}, {40, 30}, color);
//   c.marker({400, 100}, MarkerShape::dot, 4.0f, color);
//   c.text({400, 200}, "k = 16", color, 1);  // built-in bitmap font, top-left anchored,
//                                            // scale = integer magnification
//   svg.line({10, 10}, {200, 50}, Rgb8{0, 0, 0}, 1.5f);
//   Status s = svg.save("fig02.svg");        // svg.str() gives the text
//   // Axes: see image/plot.hpp (data -> pixel mapping, ticks, labels, drawn on any Canvas).
// Coordinates are pixels, x right, y down, (0, 0) the top-left corner of the image.
// Pixel (i, j) covers [i, i+1) x [j, j+1): the centre of pixel (i, j) is (i + 0.5, j + 0.5).
//
// Conventions shared by every canvas (RasterCanvas: raster_canvas.hpp, SvgCanvas:
// svg_canvas.hpp; this header includes both):
// - Strokes are centred on the geometry, `width` pixels wide, with round caps and round
//   joins (a line is the capsule of radius width/2 around the segment). A 1-pixel line
//   lands exactly on pixel row j when drawn at y = j + 0.5.
// - Fills use the even-odd rule; fill_contours() takes several contours at once (holes).
// - Rectangles: corner + size; a negative size extends to the left / upwards. rect_outline
//   strokes the rectangle's edges with square corners.
// - Markers: `size` is the full extent in pixels. dot = filled disc, circle / square /
//   triangle = outlines, cross = x, plus = +; their stroke is max(1, size/8) wide.
// - Text: the built-in font (font.hpp), 6·scale pixels per character, 9·scale per line,
//   top-left anchored, '\n' starts a new line, UTF-8 for the Greek letters; text_width()
//   and text_height() in font.hpp measure it (both canvases use the same metrics).
//   scale < 1 counts as 1.
// - Non-finite coordinates (NaN, inf) draw nothing; shapes partly or fully outside the
//   canvas are clipped, never written outside the image.
#pragma once

#include <string>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/image/font.hpp"
#include "shitsukan/image/image.hpp"

namespace shitsukan {

// Text metrics of the built-in font (font.hpp) for std::string, as Canvas::text takes.
inline int text_width(const std::string& text, int scale = 1) {
    return text_width(text.c_str(), scale);
}
inline int text_block_height(const std::string& text, int scale = 1) {
    return text_block_height(text.c_str(), scale);
}

enum class MarkerShape { dot, circle, square, cross, plus, triangle };

class Canvas {
public:
    virtual ~Canvas() = default;
    virtual int width() const = 0;
    virtual int height() const = 0;
    virtual void line(Vec2 a, Vec2 b, Rgb8 color, float width = 1.0f) = 0;
    virtual void polyline(const Vec2* points, int count, Rgb8 color, float width = 1.0f) = 0;
    virtual void polygon_outline(const Vec2* points, int count, Rgb8 color, float width = 1.0f) = 0;
    virtual void fill_polygon(const Vec2* points, int count, Rgb8 color) = 0;
    virtual void fill_rect(Vec2 corner, Vec2 size, Rgb8 color) = 0;
    virtual void rect_outline(Vec2 corner, Vec2 size, Rgb8 color, float width = 1.0f) = 0;
    virtual void marker(Vec2 center, MarkerShape shape, float size, Rgb8 color) = 0;
    virtual void text(Vec2 top_left, const std::string& text, Rgb8 color, int scale = 1) = 0;

    // Added with the implementations (defaults built on the calls above):
    // fill several closed contours as one shape, even-odd rule (a contour inside another is
    // a hole). contour_sizes[i] points are taken in turn from `points`.
    virtual void fill_contours(const Vec2* points, const int* contour_sizes, int contours,
                               Rgb8 color);
    // Paint the whole canvas.
    virtual void clear(Rgb8 color);
};

}  // namespace shitsukan

// The two implementations, so that including the contract is enough to draw.
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/image/svg_canvas.hpp"
