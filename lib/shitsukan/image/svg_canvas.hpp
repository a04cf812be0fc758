// shitsukan/image/svg_canvas.hpp — the Canvas that records SVG elements (vector output).
//
// Manual
//   SvgCanvas svg(640, 480);                       // or SvgCanvas(640, 480, background)
//   svg.line({10, 10}, {200, 50}, Rgb8{0, 0, 0}, 1.5f);
//   auto draw_figure = [](Canvas& c) { c.text({20, 20}, "fig. 2", Rgb8{0, 0, 0}, 2); };
//   draw_figure(svg);                              // the same code that draws a RasterCanvas
//   Status s = svg.save("fig02.svg");              // io_error with the path on failure
//   std::string text = svg.str();                  // the whole document
//   return s;
// Each call appends one element, in drawing order (later elements paint over earlier ones):
//   line -> <line>, polyline -> <polyline>, polygon_outline -> <polygon fill="none">,
//   fill_polygon -> <polygon fill-rule="evenodd">, fill_contours -> <path fill-rule=
//   "evenodd">, fill_rect / rect_outline -> <rect>, markers -> <circle>, <rect>, <path>,
//   <polygon>, text -> one <text> per line.
// Conventions match RasterCanvas (canvas.hpp): round caps and joins, even-odd fills, marker
// sizes. Text uses a generic monospace font sized so that one character advances 6·scale
// pixels; textLength pins each line to text_width() so layouts computed with font.hpp hold.
// Coordinates are written with at most kDecimals decimals; text is XML-escaped (& < > " '),
// control characters (forbidden in XML) and malformed UTF-8 become U+FFFD. Calls with
// non-finite coordinates record nothing (as RasterCanvas draws nothing).
#pragma once

#include <string>

#include "shitsukan/image/canvas.hpp"

namespace shitsukan {

class SvgCanvas : public Canvas {
public:
    static constexpr int kDecimals = 2;  // chosen here: 1/100 pixel is below any visible step

    SvgCanvas(int width, int height);
    SvgCanvas(int width, int height, Rgb8 background);

    int width() const override { return width_; }
    int height() const override { return height_; }
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

    std::string str() const;             // the complete SVG document
    // Writes str() through core/output_file.hpp; io_error names the path and the reason.
    Status save(const char* path) const;
    Status save(const std::string& path) const { return save(path.c_str()); }
    int element_count() const { return elements_; }

private:
    void points_attribute(const Vec2* points, int count);
    void stroke_attributes(Rgb8 color, float width);

    int width_, height_;
    std::string body_;
    int elements_ = 0;
};

// XML-escape UTF-8 text for an SVG/XML text node or attribute value (see the manual above;
// a '\n' is a control character here: SvgCanvas::text splits lines before escaping).
std::string xml_escape(const std::string& text);

}  // namespace shitsukan
