#include "shitsukan/image/raster_canvas.hpp"

#include <algorithm>
#include <cmath>

#include "shitsukan/image/font.hpp"

namespace shitsukan {

namespace {

// Area of the pixel (a unit box) on the near side of a straight edge at signed distance t
// from its centre, for an edge whose unit normal is n. The box projected onto n spreads
// its area as the convolution of two uniform densities of widths a = |n.x| and b = |n.y|
// (a trapezoid), whose integral is this piecewise quadratic.
double box_area_below(double t, double a, double b) {
    if (a < b) std::swap(a, b);
    if (t < 0.0) return 1.0 - box_area_below(-t, a, b);
    double half_sum = 0.5 * (a + b), half_diff = 0.5 * (a - b);
    if (t >= half_sum) return 1.0;
    if (t <= half_diff) return 0.5 + t / a;          // flat top of the trapezoid
    double u = half_sum - t;                          // in the falling ramp
    return b > 1e-9 ? 1.0 - u * u / (2.0 * a * b) : 1.0;
}

// Coverage of a pixel by a band of half-width r whose axis passes at distance d >= 0 from
// the pixel centre, n being the band's unit normal there: the area between the two edges.
// Exact for straight bands; at round caps and rings the edge is taken as locally straight.
float band_coverage(double d, double r, double nx, double ny) {
    double a = std::fabs(nx), b = std::fabs(ny);
    double c = box_area_below(r - d, a, b) - box_area_below(-r - d, a, b);
    return c <= 0.0 ? 0.0f : (c >= 1.0 ? 1.0f : float(c));
}

// Distance from p to the segment [a, b], and the unit direction from the nearest point to p
// (the stroke's normal there; the segment's own normal when p lies on the axis). Double, so
// that far-away endpoints (clipped shapes) keep sub-pixel precision near the image.
double segment_distance(double px, double py, double ax, double ay, double bx, double by,
                        double* nx, double* ny) {
    double ex = bx - ax, ey = by - ay;
    double len2 = ex * ex + ey * ey;
    double t = len2 > 0.0 ? ((px - ax) * ex + (py - ay) * ey) / len2 : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    double dx = px - (ax + t * ex), dy = py - (ay + t * ey);
    double d = std::sqrt(dx * dx + dy * dy);
    if (d > 1e-9) {
        *nx = dx / d;
        *ny = dy / d;
    } else if (len2 > 0.0) {
        double len = std::sqrt(len2);
        *nx = -ey / len;
        *ny = ex / len;
    } else {
        *nx = 1.0;
        *ny = 0.0;
    }
    return d;
}

// Clamp a coordinate into [lo, hi] before converting to int (no overflow on huge values).
int clamp_to_int(double v, int lo, int hi) {
    if (!(v > double(lo))) return lo;  // also NaN
    if (v >= double(hi)) return hi;
    return int(v);
}

// The pixel range [first, last) whose cells overlap [lo, hi], clipped to [0, size).
void cell_range(double lo, double hi, int size, int* first, int* last) {
    *first = clamp_to_int(std::floor(lo), 0, size);
    *last = clamp_to_int(std::ceil(hi), 0, size);
}

bool finite_points(const Vec2* points, int count) {
    for (int i = 0; i < count; ++i)
        if (!is_finite(points[i])) return false;
    return true;
}

}  // namespace

RasterCanvas::RasterCanvas(RgbView target, bool antialias)
    : target_(target), antialias_(antialias) {}

void RasterCanvas::paint(int x, int y, Rgb8 color, float coverage) {
    if (!(coverage > 0.0f)) return;
    Rgb8& dst = target_.at(x, y);
    if (coverage >= 1.0f) {
        dst = color;
        return;
    }
    auto mix = [coverage](std::uint8_t d, std::uint8_t c) {
        float v = float(d) + (float(c) - float(d)) * coverage;  // dst + (color - dst)·c
        return std::uint8_t(std::floor(v + 0.5f));
    };
    dst = Rgb8{mix(dst.r, color.r), mix(dst.g, color.g), mix(dst.b, color.b)};
}

void RasterCanvas::clear(Rgb8 color) {
    if (!target_.empty()) fill(target_, color);
}

// ---- strokes ----

// Stroke a set of segments as one shape: each pixel keeps the largest coverage any segment
// gives it, then is painted once, so joins and crossings are not darkened twice.
void RasterCanvas::stroke(const Segment* segments, int count, Rgb8 color, float width) {
    if (target_.empty() || count <= 0 || !is_finite(width) || width <= 0.0f) return;
    double r = (antialias_ ? double(width) : std::max(double(width), 1.0)) * 0.5;
    double reach = r + 1.0;
    // Bounding box of all segments, clipped to the image.
    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
    for (int i = 0; i < count; ++i) {
        if (!is_finite(segments[i].a) || !is_finite(segments[i].b)) return;
        lo_x = std::min({lo_x, double(segments[i].a.x), double(segments[i].b.x)});
        lo_y = std::min({lo_y, double(segments[i].a.y), double(segments[i].b.y)});
        hi_x = std::max({hi_x, double(segments[i].a.x), double(segments[i].b.x)});
        hi_y = std::max({hi_y, double(segments[i].a.y), double(segments[i].b.y)});
    }
    int bx0, bx1, by0, by1;
    cell_range(lo_x - reach, hi_x + reach, target_.width, &bx0, &bx1);
    cell_range(lo_y - reach, hi_y + reach, target_.height, &by0, &by1);
    if (bx0 >= bx1 || by0 >= by1) return;
    int bw = bx1 - bx0;
    coverage_.assign(std::size_t(bw) * std::size_t(by1 - by0), 0.0f);

    for (int i = 0; i < count; ++i) {
        double ax = segments[i].a.x, ay = segments[i].a.y;
        double bx = segments[i].b.x, by = segments[i].b.y;
        int x0, x1, y0, y1;
        cell_range(std::min(ax, bx) - reach, std::max(ax, bx) + reach, target_.width, &x0, &x1);
        cell_range(std::min(ay, by) - reach, std::max(ay, by) + reach, target_.height, &y0, &y1);
        for (int y = y0; y < y1; ++y) {
            float* cov = &coverage_[std::size_t(y - by0) * std::size_t(bw)];
            for (int x = x0; x < x1; ++x) {
                double nx, ny;
                double d = segment_distance(x + 0.5, y + 0.5, ax, ay, bx, by, &nx, &ny);
                float c = antialias_ ? band_coverage(d, r, nx, ny) : (d < r ? 1.0f : 0.0f);
                float& slot = cov[x - bx0];
                if (c > slot) slot = c;
            }
        }
    }
    for (int y = by0; y < by1; ++y) {
        const float* cov = &coverage_[std::size_t(y - by0) * std::size_t(bw)];
        for (int x = bx0; x < bx1; ++x) paint(x, y, color, cov[x - bx0]);
    }
}

void RasterCanvas::stroke_path(const Vec2* points, int count, bool closed, Rgb8 color,
                               float width) {
    if (points == nullptr || count <= 0) return;
    segments_.clear();
    if (count == 1) segments_.push_back({points[0], points[0]});  // a lone point: a dot
    for (int i = 0; i + 1 < count; ++i) segments_.push_back({points[i], points[i + 1]});
    if (closed && count > 2) segments_.push_back({points[count - 1], points[0]});
    stroke(segments_.data(), int(segments_.size()), color, width);
}

void RasterCanvas::line(Vec2 a, Vec2 b, Rgb8 color, float width) {
    Segment s{a, b};
    stroke(&s, 1, color, width);
}

void RasterCanvas::polyline(const Vec2* points, int count, Rgb8 color, float width) {
    stroke_path(points, count, false, color, width);
}

void RasterCanvas::polygon_outline(const Vec2* points, int count, Rgb8 color, float width) {
    stroke_path(points, count, true, color, width);
}

// ---- fills ----

// Scanline fill of edges_ with the even-odd rule. A sample row at height y crosses the
// edges with y0 <= y < y1 (half-open, so a vertex shared by two edges counts once);
// between the 1st and 2nd, 3rd and 4th, ... crossing the shape is inside.
void RasterCanvas::fill_edges(Rgb8 color) {
    if (target_.empty() || edges_.empty()) return;
    std::sort(edges_.begin(), edges_.end(),
              [](const Edge& p, const Edge& q) { return p.y0 < q.y0; });
    double y_lo = edges_.front().y0, y_hi = y_lo;
    for (const Edge& e : edges_) y_hi = std::max(y_hi, double(e.y1));
    int row0, row1;
    cell_range(y_lo, y_hi, target_.height, &row0, &row1);
    const int w = target_.width;
    const int samples = antialias_ ? kSubScanlines : 1;
    const float weight = 1.0f / float(samples);
    if (antialias_) coverage_.assign(std::size_t(w), 0.0f);
    std::vector<int>& active = active_;  // indices into edges_ that started above the sample
    active.clear();
    std::size_t next = 0;
    for (int row = row0; row < row1; ++row) {
        int touched_lo = w, touched_hi = 0;
        for (int s = 0; s < samples; ++s) {
            // Sample heights: the pixel centre, or kSubScanlines evenly spaced sub-rows.
            double y = antialias_ ? row + (s + 0.5) / samples : row + 0.5;
            while (next < edges_.size() && edges_[next].y0 <= y) active.push_back(int(next++));
            crossings_.clear();
            std::size_t keep = 0;
            for (int idx : active) {
                const Edge& e = edges_[std::size_t(idx)];
                if (e.y1 <= y) continue;  // finished: dropped from the active list
                active[keep++] = idx;
                crossings_.push_back(e.x0 + (y - e.y0) * e.dxdy);
            }
            active.resize(keep);
            std::sort(crossings_.begin(), crossings_.end());
            for (std::size_t k = 0; k + 1 < crossings_.size(); k += 2) {
                double xa = crossings_[k], xb = crossings_[k + 1];
                if (!antialias_) {
                    // Pixels whose centre i + 1/2 lies in [xa, xb).
                    int i0 = clamp_to_int(std::ceil(xa - 0.5), 0, w);
                    int i1 = clamp_to_int(std::ceil(xb - 0.5), 0, w);
                    Rgb8* px = target_.row(row);
                    for (int i = i0; i < i1; ++i) px[i] = color;
                    continue;
                }
                // Exact coverage of the span [xa, xb) on this sub-row, clipped to the image.
                xa = std::max(xa, 0.0);
                xb = std::min(xb, double(w));
                if (!(xa < xb)) continue;
                int ia = int(xa), ib = int(xb);
                if (ia == ib) {
                    coverage_[std::size_t(ia)] += float(xb - xa) * weight;
                } else {
                    coverage_[std::size_t(ia)] += float(ia + 1 - xa) * weight;
                    for (int i = ia + 1; i < ib; ++i) coverage_[std::size_t(i)] += weight;
                    if (ib < w) coverage_[std::size_t(ib)] += float(xb - ib) * weight;
                }
                touched_lo = std::min(touched_lo, ia);
                touched_hi = std::max(touched_hi, std::min(ib + 1, w));
            }
        }
        for (int i = touched_lo; i < touched_hi; ++i) {
            paint(i, row, color, coverage_[std::size_t(i)]);
            coverage_[std::size_t(i)] = 0.0f;
        }
    }
}

void RasterCanvas::fill_contours(const Vec2* points, const int* contour_sizes, int contours,
                                 Rgb8 color) {
    if (target_.empty() || points == nullptr || contour_sizes == nullptr || contours <= 0) return;
    edges_.clear();
    int start = 0;
    for (int c = 0; c < contours; ++c) {
        int n = contour_sizes[c];
        if (n <= 0) continue;
        const Vec2* p = points + start;
        start += n;
        if (!finite_points(p, n)) {
            edges_.clear();
            return;
        }
        for (int i = 0; i < n; ++i) {
            Vec2 a = p[i], b = p[(i + 1) % n];
            if (a.y == b.y) continue;  // horizontal edges are never crossed
            if (a.y > b.y) std::swap(a, b);
            edges_.push_back({double(a.x), double(a.y), double(b.y),
                              (double(b.x) - a.x) / (double(b.y) - a.y)});
        }
    }
    fill_edges(color);
}

void RasterCanvas::fill_polygon(const Vec2* points, int count, Rgb8 color) {
    if (count < 3) return;
    fill_contours(points, &count, 1, color);
}

void RasterCanvas::fill_rect(Vec2 corner, Vec2 size, Rgb8 color) {
    if (target_.empty() || !is_finite(corner) || !is_finite(size)) return;
    double x0 = corner.x, y0 = corner.y, x1 = x0 + size.x, y1 = y0 + size.y;
    if (x1 < x0) std::swap(x0, x1);
    if (y1 < y0) std::swap(y0, y1);
    if (!antialias_) {
        // Pixel centres inside [x0, x1) x [y0, y1).
        int i0 = clamp_to_int(std::ceil(x0 - 0.5), 0, target_.width);
        int i1 = clamp_to_int(std::ceil(x1 - 0.5), 0, target_.width);
        int j0 = clamp_to_int(std::ceil(y0 - 0.5), 0, target_.height);
        int j1 = clamp_to_int(std::ceil(y1 - 0.5), 0, target_.height);
        for (int j = j0; j < j1; ++j)
            for (int i = i0; i < i1; ++i) target_.at(i, j) = color;
        return;
    }
    // Coverage = overlap of the pixel's cell with the rectangle, per axis.
    int i0, i1, j0, j1;
    cell_range(x0, x1, target_.width, &i0, &i1);
    cell_range(y0, y1, target_.height, &j0, &j1);
    for (int j = j0; j < j1; ++j) {
        double cy = std::min(y1, j + 1.0) - std::max(y0, double(j));
        for (int i = i0; i < i1; ++i) {
            double cx = std::min(x1, i + 1.0) - std::max(x0, double(i));
            paint(i, j, color, float(cx * cy));
        }
    }
}

// The stroke of a rectangle's edges: the outer rectangle minus the inner one (even-odd),
// which gives square corners.
void RasterCanvas::rect_outline(Vec2 corner, Vec2 size, Rgb8 color, float width) {
    if (!is_finite(corner) || !is_finite(size) || !is_finite(width) || width <= 0.0f) return;
    float h = (antialias_ ? width : std::max(width, 1.0f)) * 0.5f;
    float x0 = std::min(corner.x, corner.x + size.x), x1 = std::max(corner.x, corner.x + size.x);
    float y0 = std::min(corner.y, corner.y + size.y), y1 = std::max(corner.y, corner.y + size.y);
    Vec2 ring[8] = {{x0 - h, y0 - h}, {x1 + h, y0 - h}, {x1 + h, y1 + h}, {x0 - h, y1 + h},
                    {x0 + h, y0 + h}, {x1 - h, y0 + h}, {x1 - h, y1 - h}, {x0 + h, y1 - h}};
    bool hollow = x1 - x0 > 2.0f * h && y1 - y0 > 2.0f * h;
    int sizes[2] = {4, 4};
    fill_contours(ring, sizes, hollow ? 2 : 1, color);
}

// ---- discs, rings, markers ----

void RasterCanvas::fill_disc(Vec2 center, float radius, Rgb8 color) {
    if (target_.empty() || !is_finite(center) || !is_finite(radius) || radius <= 0.0f) return;
    double r = antialias_ ? radius : std::max(double(radius), 0.5);
    int x0, x1, y0, y1;
    cell_range(center.x - r - 1.0, center.x + r + 1.0, target_.width, &x0, &x1);
    cell_range(center.y - r - 1.0, center.y + r + 1.0, target_.height, &y0, &y1);
    if (x0 >= x1 || y0 >= y1) return;
    // The rim as a locally straight edge with the radial normal.
    auto coverage = [&](double px, double py) {
        double dx = px - center.x, dy = py - center.y;
        double d = std::sqrt(dx * dx + dy * dy);
        if (!antialias_) return d < r ? 1.0 : 0.0;
        double nx = d > 1e-9 ? dx / d : 1.0, ny = d > 1e-9 ? dy / d : 0.0;
        return box_area_below(r - d, std::fabs(nx), std::fabs(ny));
    };
    // The straight-rim estimate is poor when the disc is about a pixel wide: small dots
    // are rescaled so their total ink is their area pi·r² (chosen here: below r = 4; at r = 2.5
    // the estimate is still 1.3% high), counted over the whole, unclipped dot.
    double scale = 1.0;
    if (antialias_ && r < 4.0) {
        double sum = 0.0;
        double fx = std::floor(center.x), fy = std::floor(center.y);
        for (int j = -5; j <= 5; ++j)
            for (int i = -5; i <= 5; ++i) sum += coverage(fx + i + 0.5, fy + j + 0.5);
        if (sum > 0.0) scale = kPiD * r * r / sum;
    }
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) paint(x, y, color, float(coverage(x + 0.5, y + 0.5) * scale));
}

void RasterCanvas::circle_outline(Vec2 center, float radius, Rgb8 color, float width) {
    if (target_.empty() || !is_finite(center) || !is_finite(radius) || radius < 0.0f ||
        !is_finite(width) || width <= 0.0f)
        return;
    double h = (antialias_ ? double(width) : std::max(double(width), 1.0)) * 0.5;
    double reach = radius + h + 1.0;
    int x0, x1, y0, y1;
    cell_range(center.x - reach, center.x + reach, target_.width, &x0, &x1);
    cell_range(center.y - reach, center.y + reach, target_.height, &y0, &y1);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            double dx = x + 0.5 - center.x, dy = y + 0.5 - center.y;
            double rho = std::sqrt(dx * dx + dy * dy);
            double d = std::fabs(rho - radius);
            double nx = rho > 1e-9 ? dx / rho : 1.0, ny = rho > 1e-9 ? dy / rho : 0.0;
            paint(x, y, color, antialias_ ? band_coverage(d, h, nx, ny) : (d < h ? 1.0f : 0.0f));
        }
}

void RasterCanvas::marker(Vec2 center, MarkerShape shape, float size, Rgb8 color) {
    if (!is_finite(center) || !is_finite(size) || size <= 0.0f) return;
    float sw = std::max(1.0f, size / 8.0f);  // stroke width of the outlined markers
    float half = size * 0.5f;
    float inner = std::max(0.0f, half - sw * 0.5f);  // stroke centre, so the extent is `size`
    switch (shape) {
        case MarkerShape::dot: fill_disc(center, half, color); break;
        case MarkerShape::circle: circle_outline(center, inner, color, sw); break;
        case MarkerShape::square:
            rect_outline({center.x - inner, center.y - inner}, {2 * inner, 2 * inner}, color, sw);
            break;
        case MarkerShape::cross: {
            float k = inner * 0.70710678f;  // the arms reach the circle of radius `inner`
            Segment s[2] = {{{center.x - k, center.y - k}, {center.x + k, center.y + k}},
                            {{center.x - k, center.y + k}, {center.x + k, center.y - k}}};
            stroke(s, 2, color, sw);
            break;
        }
        case MarkerShape::plus: {
            Segment s[2] = {{{center.x - inner, center.y}, {center.x + inner, center.y}},
                            {{center.x, center.y - inner}, {center.x, center.y + inner}}};
            stroke(s, 2, color, sw);
            break;
        }
        case MarkerShape::triangle: {
            // Apex up, inscribed in the circle of radius `inner` (angles -90, 30, 150 degrees).
            Vec2 t[3] = {{center.x, center.y - inner},
                         {center.x + inner * 0.8660254f, center.y + inner * 0.5f},
                         {center.x - inner * 0.8660254f, center.y + inner * 0.5f}};
            polygon_outline(t, 3, color, sw);
            break;
        }
    }
}

// ---- text ----

void RasterCanvas::text(Vec2 top_left, const std::string& text, Rgb8 color, int scale) {
    if (target_.empty() || !is_finite(top_left) || text.empty()) return;
    if (scale < 1) scale = 1;
    // Snap to whole pixels; work in 64-bit so far-away text cannot overflow.
    const int kFar = 1000000000;
    const long long ox = clamp_to_int(std::floor(double(top_left.x) + 0.5), -kFar, kFar);
    long long oy = clamp_to_int(std::floor(double(top_left.y) + 0.5), -kFar, kFar);
    const long long w = target_.width, h = target_.height;
    long long x = ox;
    const char* p = text.data();
    const char* end = p + text.size();
    while (p < end) {
        std::uint32_t cp = next_codepoint(&p, end);
        if (cp == '\n') {
            x = ox;
            oy += (long long)kFontLineAdvance * scale;
            continue;
        }
        const Glyph& g = font_glyph(cp);
        bool visible = x < w && x + (long long)kFontGlyphWidth * scale > 0 && oy < h &&
                       oy + (long long)kFontGlyphRows * scale > 0;
        for (int row = 0; visible && row < kFontGlyphRows; ++row)
            for (int col = 0; col < kFontGlyphWidth; ++col) {
                if (!glyph_pixel(g, col, row)) continue;
                long long px0 = x + (long long)col * scale, py0 = oy + (long long)row * scale;
                // One font pixel = a scale x scale block, clipped to the image.
                for (long long py = std::max(py0, 0LL); py < std::min(py0 + scale, h); ++py)
                    for (long long px = std::max(px0, 0LL); px < std::min(px0 + scale, w); ++px)
                        target_.at(int(px), int(py)) = color;
            }
        x += (long long)kFontAdvance * scale;
    }
}

}  // namespace shitsukan
