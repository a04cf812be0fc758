// shitsukan/image/raster_canvas.hpp — the Canvas that draws into pixels.
//
// Manual
//   RgbImage img(640, 480, Rgb8{255, 255, 255});
//   RasterCanvas canvas(img.view());          // anti-aliased by default
//   canvas.line({10.5f, 10.5f}, {200.5f, 50.5f}, Rgb8{0, 0, 0}, 1.5f);
//   canvas.set_antialias(false);              // exact pixel art from here on
//   const Vec2 points[4] = {{20, 20}, {100, 20}, {100, 80}, {20, 80}};
//   canvas.fill_polygon(points, 4, Rgb8{200, 40, 40});
// Drawing conventions: canvas.hpp. Colours are painted over the pixels: with coverage c in
// [0, 1] a pixel becomes dst + (color - dst)·c (straight in 8-bit sRGB values, no gamma).
//
// Anti-aliasing (on by default):
//   strokes  coverage of the pixel's 1x1 box by a band of the stroke width, taken across
//            the distance d from the pixel centre to the capsule's axis (exact for
//            axis-aligned lines: a horizontal line of length L and width w deposits L·w);
//            a polyline is stroked as one shape (each pixel keeps its largest coverage),
//            so joins are not painted twice.
//   fills    kSubScanlines sub-scanlines per pixel row, each with exact horizontal span
//            coverage (the area error of a big shape is far below 1%).
// Without anti-aliasing a pixel is painted when its centre is inside: a stroke's capsule
// (its width counts as at least 1 so thin lines stay connected), a fill's polygon (centres
// on a left edge are in, on a right edge out), a rectangle [x0, x1) x [y0, y1).
// Text is never anti-aliased: the bitmap font is snapped to whole pixels (top-left rounded).
//
// Host side: strokes and fills use scratch buffers that grow as needed (std::vector),
// kept between calls; the target view is never written outside its width x height.
#pragma once

#include <vector>

#include "shitsukan/image/canvas.hpp"

namespace shitsukan {

class RasterCanvas : public Canvas {
public:
    static constexpr int kSubScanlines = 8;  // chosen here: 9 coverage levels along edges

    explicit RasterCanvas(RgbView target, bool antialias = true);

    void set_antialias(bool on) { antialias_ = on; }
    bool antialias() const { return antialias_; }
    const RgbView& target() const { return target_; }

    int width() const override { return target_.empty() ? 0 : target_.width; }
    int height() const override { return target_.empty() ? 0 : target_.height; }
    void line(Vec2 a, Vec2 b, Rgb8 color, float width = 1.0f) override;
    void polyline(const Vec2* points, int count, Rgb8 color, float width = 1.0f) override;
    void polygon_outline(const Vec2* points, int count, Rgb8 color, float width = 1.0f) override;
    void fill_polygon(const Vec2* points, int count, Rgb8 color) override;
    void fill_rect(Vec2 corner, Vec2 size, Rgb8 color) override;
    void rect_outline(Vec2 corner, Vec2 size, Rgb8 color, float width = 1.0f) override;
    void marker(Vec2 center, MarkerShape shape, float size, Rgb8 color) override;
    void text(Vec2 top_left, const std::string& text, Rgb8 color, int scale = 1) override;
    void fill_contours(const Vec2* points, const int* contour_sizes, int contours,
                       Rgb8 color) override;
    void clear(Rgb8 color) override;

    // A disc of the given radius (the dot marker), and a ring of radius `radius` stroked
    // `width` wide (the circle marker).
    void fill_disc(Vec2 center, float radius, Rgb8 color);
    void circle_outline(Vec2 center, float radius, Rgb8 color, float width = 1.0f);

private:
    struct Segment {
        Vec2 a, b;
    };
    struct Edge {
        double x0, y0, y1, dxdy;  // y0 < y1; x at y is x0 + (y - y0)·dxdy
    };

    void paint(int x, int y, Rgb8 color, float coverage);
    void stroke(const Segment* segments, int count, Rgb8 color, float width);
    void stroke_path(const Vec2* points, int count, bool closed, Rgb8 color, float width);
    void fill_edges(Rgb8 color);

    RgbView target_;
    bool antialias_;
    std::vector<Segment> segments_;  // scratch: the segments of a polyline
    std::vector<float> coverage_;    // scratch: per-pixel coverage of a stroke / a fill row
    std::vector<Edge> edges_;        // scratch: the edges of a fill
    std::vector<int> active_;        // scratch: edges crossing the current sub-scanline
    std::vector<double> crossings_;  // scratch: span ends on one sub-scanline
};

}  // namespace shitsukan
