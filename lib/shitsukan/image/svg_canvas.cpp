#include "shitsukan/image/svg_canvas.hpp"

#include <cmath>
#include <cstdio>

#include "shitsukan/core/output_file.hpp"
#include "shitsukan/image/font.hpp"

namespace shitsukan {

namespace {

// A number with at most SvgCanvas::kDecimals decimals, trailing zeros removed, no "-0".
void append_number(std::string& out, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", SvgCanvas::kDecimals, v);
    std::string s = buf;
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    if (s == "-0") s = "0";
    out += s;
}

void append_color(std::string& out, Rgb8 c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
    out += buf;
}

void append_utf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += char(cp);
    } else if (cp < 0x800) {
        out += char(0xC0 | (cp >> 6));
        out += char(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += char(0xE0 | (cp >> 12));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    } else {
        out += char(0xF0 | (cp >> 18));
        out += char(0x80 | ((cp >> 12) & 0x3F));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    }
}

bool finite_points(const Vec2* points, int count) {
    for (int i = 0; i < count; ++i)
        if (!is_finite(points[i])) return false;
    return true;
}

}  // namespace

std::string xml_escape(const std::string& text) {
    std::string out;
    const char* p = text.data();
    const char* end = p + text.size();
    while (p < end) {
        std::uint32_t cp = next_codepoint(&p, end);
        switch (cp) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default:
                // XML 1.0 forbids control characters, even as references; they become
                // U+FFFD, which keeps one character per character (the bitmap font draws its
                // fallback box there), so text_width() still measures the line.
                if (cp < 0x20 || cp == 0xFFFE || cp == 0xFFFF) cp = 0xFFFD;
                append_utf8(out, cp);
        }
    }
    return out;
}

SvgCanvas::SvgCanvas(int width, int height)
    : width_(width > 0 ? width : 0), height_(height > 0 ? height : 0) {}

SvgCanvas::SvgCanvas(int width, int height, Rgb8 background) : SvgCanvas(width, height) {
    clear(background);
}

void SvgCanvas::points_attribute(const Vec2* points, int count) {
    body_ += " points=\"";
    for (int i = 0; i < count; ++i) {
        if (i > 0) body_ += ' ';
        append_number(body_, points[i].x);
        body_ += ',';
        append_number(body_, points[i].y);
    }
    body_ += '"';
}

void SvgCanvas::stroke_attributes(Rgb8 color, float width) {
    body_ += " stroke=\"";
    append_color(body_, color);
    body_ += "\" stroke-width=\"";
    append_number(body_, width);
    body_ += "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
}

void SvgCanvas::line(Vec2 a, Vec2 b, Rgb8 color, float width) {
    if (!is_finite(a) || !is_finite(b) || !is_finite(width) || width <= 0.0f) return;
    body_ += "<line x1=\"";
    append_number(body_, a.x);
    body_ += "\" y1=\"";
    append_number(body_, a.y);
    body_ += "\" x2=\"";
    append_number(body_, b.x);
    body_ += "\" y2=\"";
    append_number(body_, b.y);
    body_ += '"';
    stroke_attributes(color, width);
    body_ += "/>\n";
    ++elements_;
}

void SvgCanvas::polyline(const Vec2* points, int count, Rgb8 color, float width) {
    if (points == nullptr || count < 1 || !finite_points(points, count) || !is_finite(width) ||
        width <= 0.0f)
        return;
    body_ += "<polyline";
    if (count == 1) {
        Vec2 twice[2] = {points[0], points[0]};  // a lone point shows as a round dot
        points_attribute(twice, 2);
    } else {
        points_attribute(points, count);
    }
    body_ += " fill=\"none\"";
    stroke_attributes(color, width);
    body_ += "/>\n";
    ++elements_;
}

void SvgCanvas::polygon_outline(const Vec2* points, int count, Rgb8 color, float width) {
    if (points == nullptr || count < 2 || !finite_points(points, count) || !is_finite(width) ||
        width <= 0.0f)
        return;
    body_ += "<polygon";
    points_attribute(points, count);
    body_ += " fill=\"none\"";
    stroke_attributes(color, width);
    body_ += "/>\n";
    ++elements_;
}

void SvgCanvas::fill_polygon(const Vec2* points, int count, Rgb8 color) {
    if (points == nullptr || count < 3 || !finite_points(points, count)) return;
    body_ += "<polygon";
    points_attribute(points, count);
    body_ += " fill=\"";
    append_color(body_, color);
    body_ += "\" fill-rule=\"evenodd\"/>\n";
    ++elements_;
}

void SvgCanvas::fill_contours(const Vec2* points, const int* contour_sizes, int contours,
                              Rgb8 color) {
    if (points == nullptr || contour_sizes == nullptr || contours <= 0) return;
    int total = 0;
    for (int c = 0; c < contours; ++c) total += contour_sizes[c] > 0 ? contour_sizes[c] : 0;
    if (total < 3 || !finite_points(points, total)) return;
    body_ += "<path d=\"";
    int start = 0;
    for (int c = 0; c < contours; ++c) {
        int n = contour_sizes[c];
        if (n <= 0) continue;
        for (int i = 0; i < n; ++i) {
            body_ += i == 0 ? (c == 0 ? "M" : " M") : " L";
            append_number(body_, points[start + i].x);
            body_ += ' ';
            append_number(body_, points[start + i].y);
        }
        body_ += " Z";
        start += n;
    }
    body_ += "\" fill=\"";
    append_color(body_, color);
    body_ += "\" fill-rule=\"evenodd\"/>\n";
    ++elements_;
}

void SvgCanvas::fill_rect(Vec2 corner, Vec2 size, Rgb8 color) {
    if (!is_finite(corner) || !is_finite(size)) return;
    body_ += "<rect x=\"";
    append_number(body_, std::fmin(corner.x, corner.x + size.x));
    body_ += "\" y=\"";
    append_number(body_, std::fmin(corner.y, corner.y + size.y));
    body_ += "\" width=\"";
    append_number(body_, std::fabs(size.x));
    body_ += "\" height=\"";
    append_number(body_, std::fabs(size.y));
    body_ += "\" fill=\"";
    append_color(body_, color);
    body_ += "\"/>\n";
    ++elements_;
}

void SvgCanvas::rect_outline(Vec2 corner, Vec2 size, Rgb8 color, float width) {
    if (!is_finite(corner) || !is_finite(size) || !is_finite(width) || width <= 0.0f) return;
    body_ += "<rect x=\"";
    append_number(body_, std::fmin(corner.x, corner.x + size.x));
    body_ += "\" y=\"";
    append_number(body_, std::fmin(corner.y, corner.y + size.y));
    body_ += "\" width=\"";
    append_number(body_, std::fabs(size.x));
    body_ += "\" height=\"";
    append_number(body_, std::fabs(size.y));
    body_ += "\" fill=\"none\" stroke=\"";
    append_color(body_, color);
    body_ += "\" stroke-width=\"";
    append_number(body_, width);
    body_ += "\" stroke-linejoin=\"miter\"/>\n";
    ++elements_;
}

void SvgCanvas::clear(Rgb8 color) {
    fill_rect({0.0f, 0.0f}, {float(width_), float(height_)}, color);
}

void SvgCanvas::marker(Vec2 center, MarkerShape shape, float size, Rgb8 color) {
    if (!is_finite(center) || !is_finite(size) || size <= 0.0f) return;
    // Same geometry as RasterCanvas::marker.
    float sw = std::fmax(1.0f, size / 8.0f);
    float half = size * 0.5f;
    float inner = std::fmax(0.0f, half - sw * 0.5f);
    switch (shape) {
        case MarkerShape::dot:
        case MarkerShape::circle:
            body_ += "<circle cx=\"";
            append_number(body_, center.x);
            body_ += "\" cy=\"";
            append_number(body_, center.y);
            body_ += "\" r=\"";
            append_number(body_, shape == MarkerShape::dot ? half : inner);
            if (shape == MarkerShape::dot) {
                body_ += "\" fill=\"";
                append_color(body_, color);
                body_ += "\"/>\n";
            } else {
                body_ += "\" fill=\"none\" stroke=\"";
                append_color(body_, color);
                body_ += "\" stroke-width=\"";
                append_number(body_, sw);
                body_ += "\"/>\n";
            }
            ++elements_;
            break;
        case MarkerShape::square:
            rect_outline({center.x - inner, center.y - inner}, {2 * inner, 2 * inner}, color, sw);
            break;
        case MarkerShape::cross:
        case MarkerShape::plus: {
            float k = shape == MarkerShape::cross ? inner * 0.70710678f : inner;
            Vec2 ends[4];
            if (shape == MarkerShape::cross) {
                ends[0] = {center.x - k, center.y - k}; ends[1] = {center.x + k, center.y + k};
                ends[2] = {center.x - k, center.y + k}; ends[3] = {center.x + k, center.y - k};
            } else {
                ends[0] = {center.x - k, center.y}; ends[1] = {center.x + k, center.y};
                ends[2] = {center.x, center.y - k}; ends[3] = {center.x, center.y + k};
            }
            body_ += "<path d=\"";
            for (int i = 0; i < 4; ++i) {
                body_ += i == 0 ? "M" : (i == 2 ? " M" : " L");
                append_number(body_, ends[i].x);
                body_ += ' ';
                append_number(body_, ends[i].y);
            }
            body_ += "\" fill=\"none\"";
            stroke_attributes(color, sw);
            body_ += "/>\n";
            ++elements_;
            break;
        }
        case MarkerShape::triangle: {
            Vec2 t[3] = {{center.x, center.y - inner},
                         {center.x + inner * 0.8660254f, center.y + inner * 0.5f},
                         {center.x - inner * 0.8660254f, center.y + inner * 0.5f}};
            polygon_outline(t, 3, color, sw);
            break;
        }
    }
}

void SvgCanvas::text(Vec2 top_left, const std::string& text, Rgb8 color, int scale) {
    if (!is_finite(top_left) || text.empty()) return;
    if (scale < 1) scale = 1;
    std::size_t start = 0;
    for (int line = 0; start <= text.size(); ++line) {
        std::size_t stop = text.find('\n', start);
        if (stop == std::string::npos) stop = text.size();
        std::string piece = text.substr(start, stop - start);
        start = stop + 1;
        int length = text_width(piece, scale);
        if (length == 0) continue;
        // Baseline under glyph row 6; a monospace face of size 10·scale advances ~6·scale.
        double baseline = top_left.y + double(line * kFontLineAdvance + kFontBaseline) * scale;
        body_ += "<text x=\"";
        append_number(body_, top_left.x);
        body_ += "\" y=\"";
        append_number(body_, baseline);
        body_ += "\" font-family=\"monospace\" font-size=\"";
        append_number(body_, 10.0 * scale);
        body_ += "\" textLength=\"";
        append_number(body_, length);
        body_ += "\" lengthAdjust=\"spacingAndGlyphs\" xml:space=\"preserve\" fill=\"";
        append_color(body_, color);
        body_ += "\">";
        body_ += xml_escape(piece);
        body_ += "</text>\n";
        ++elements_;
    }
}

std::string SvgCanvas::str() const {
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    char head[256];
    std::snprintf(head, sizeof head,
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                  "viewBox=\"0 0 %d %d\">\n",
                  width_, height_, width_, height_);
    out += head;
    out += body_;
    out += "</svg>\n";
    return out;
}

Status SvgCanvas::save(const char* path) const {
    if (path == nullptr || path[0] == '\0')
        return Status::error(StatusCode::invalid_argument, "SVG path is empty");
    return write_text_file(path, str());
}

}  // namespace shitsukan
