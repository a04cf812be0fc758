#include "shitsukan/image/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "shitsukan/image/font.hpp"

namespace shitsukan {

// ---- Axes: data <-> pixels ----

Vec2 Axes::to_pixel(double x, double y) const {
    double u = (x - x_lo) / (x_hi - x_lo);
    double v = (y - y_lo) / (y_hi - y_lo);
    return {float(corner.x + u * size.x), float(corner.y + (1.0 - v) * size.y)};  // y up
}

double Axes::from_pixel_x(float px) const {
    return x_lo + (double(px) - corner.x) / size.x * (x_hi - x_lo);
}

double Axes::from_pixel_y(float py) const {
    return y_lo + (1.0 - (double(py) - corner.y) / size.y) * (y_hi - y_lo);
}

bool Axes::contains(double x, double y) const {
    return x >= x_lo && x <= x_hi && y >= y_lo && y <= y_hi;
}

Status Axes::check() const {
    if (!std::isfinite(x_lo) || !std::isfinite(x_hi) || !std::isfinite(x_hi - x_lo) ||
        !(x_lo < x_hi))
        return Status::error(StatusCode::invalid_argument,
                             "plot x range must be finite with x_lo < x_hi (got [%g, %g])", x_lo,
                             x_hi);
    if (!std::isfinite(y_lo) || !std::isfinite(y_hi) || !std::isfinite(y_hi - y_lo) ||
        !(y_lo < y_hi))
        return Status::error(StatusCode::invalid_argument,
                             "plot y range must be finite with y_lo < y_hi (got [%g, %g])", y_lo,
                             y_hi);
    if (!is_finite(corner) || !is_finite(size) || !(size.x > 0.0f) || !(size.y > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "plot area must have a positive size (got %g x %g at %g, %g)",
                             double(size.x), double(size.y), double(corner.x), double(corner.y));
    return Status::success();
}

Axes axes_in(const Canvas& canvas, double x_lo, double x_hi, double y_lo, double y_hi,
             const PlotMargins& m) {
    Axes a;
    a.corner = {m.left, m.top};
    a.size = {float(canvas.width()) - m.left - m.right, float(canvas.height()) - m.top - m.bottom};
    a.x_lo = x_lo;
    a.x_hi = x_hi;
    a.y_lo = y_lo;
    a.y_hi = y_hi;
    return a;
}

// ---- ticks ----

namespace {

int tick_count(double lo, double hi, double step) {
    return int(std::floor(hi / step + 1e-9) - std::ceil(lo / step - 1e-9)) + 1;
}

// The next smaller step of the 1-2-5 sequence.
double smaller_nice(double step) {
    double magnitude = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    double norm = step / magnitude;
    return norm > 4.0 ? 2.0 * magnitude : (norm > 1.5 ? magnitude : 0.5 * magnitude);
}

}  // namespace

// The smallest of 1, 2, 5, 10 times 10^k that is at least (hi - lo) / target: at most
// target + 1 ticks. A range that this leaves with fewer than 2 ticks (e.g. [10.2, 14.6]
// with step 5) takes the next smaller steps until 2 ticks fit, so an axis is never bare.
double nice_step(double lo, double hi, int target) {
    if (target < 1) target = 1;
    double raw = (hi - lo) / double(target);
    if (!std::isfinite(raw) || !(raw > 0.0)) return 0.0;
    double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double norm = raw / magnitude;
    double step = (norm <= 1.0 ? 1.0 : (norm <= 2.0 ? 2.0 : (norm <= 5.0 ? 5.0 : 10.0))) *
                  magnitude;
    for (int guard = 0; guard < 8 && tick_count(lo, hi, step) < 2; ++guard)
        step = smaller_nice(step);
    return step;
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
    std::vector<double> ticks;
    double step = nice_step(lo, hi, target);
    if (step == 0.0) return ticks;
    // Ticks are integer multiples of the step, so 0 is exact and 0.3 prints as 0.3.
    double k0 = std::ceil(lo / step - 1e-9), k1 = std::floor(hi / step + 1e-9);
    for (double k = k0; k <= k1 && ticks.size() < 1000; k += 1.0) ticks.push_back(k * step);
    return ticks;
}

std::string format_tick(double value, double step) {
    char buf[64];
    if (!(step > 0.0) || std::fabs(value) < step * 1e-6) value = 0.0;  // no "-0" or 1e-17
    if (std::fabs(value) >= 1e6 || (step > 0.0 && step < 1e-4)) {
        std::snprintf(buf, sizeof buf, "%.6g", value);
    } else {
        int decimals = step >= 1.0 ? 0 : int(std::ceil(-std::log10(step) - 1e-9));
        std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
    }
    return buf;
}

// ---- drawing axes ----

namespace {

// A 1-pixel line lands on whole pixels when its centre is at n + 1/2: the frame sits just
// outside the data area, on the pixel row/column left of / above / right of / below it.
float outer_lo(float v) { return std::floor(v) - 0.5f; }
float outer_hi(float v) { return std::ceil(v) + 0.5f; }
float crisp(float v) { return std::floor(v) + 0.5f; }
float whole(float v) { return std::floor(v + 0.5f); }

}  // namespace

Status draw_axes(Canvas& canvas, const Axes& axes, const AxesLabels& labels,
                 const AxesStyle& style) {
    SHITSUKAN_TRY(axes.check());
    const int ts = std::max(1, style.text_scale), tts = std::max(1, style.title_scale);
    const float tick = std::max(0.0f, style.tick_length);
    const float left = outer_lo(axes.corner.x), right = outer_hi(axes.corner.x + axes.size.x);
    const float top = outer_lo(axes.corner.y), bottom = outer_hi(axes.corner.y + axes.size.y);
    const std::vector<double> xt = nice_ticks(axes.x_lo, axes.x_hi, style.x_ticks);
    const std::vector<double> yt = nice_ticks(axes.y_lo, axes.y_hi, style.y_ticks);
    const double x_step = nice_step(axes.x_lo, axes.x_hi, style.x_ticks);
    const double y_step = nice_step(axes.y_lo, axes.y_hi, style.y_ticks);

    // Grid under everything else, skipping lines that would sit on the frame.
    if (style.draw_grid) {
        for (double v : xt) {
            float px = crisp(axes.to_pixel(v, axes.y_lo).x);
            if (px > left + 1.0f && px < right - 1.0f)
                canvas.line({px, top + 1.0f}, {px, bottom - 1.0f}, style.grid, 1.0f);
        }
        for (double v : yt) {
            float py = crisp(axes.to_pixel(axes.x_lo, v).y);
            if (py > top + 1.0f && py < bottom - 1.0f)
                canvas.line({left + 1.0f, py}, {right - 1.0f, py}, style.grid, 1.0f);
        }
    }
    canvas.rect_outline({left, top}, {right - left, bottom - top}, style.frame, 1.0f);

    // x ticks and labels below the frame.
    const float x_label_top = bottom + tick + 3.0f;
    for (double v : xt) {
        float px = crisp(axes.to_pixel(v, axes.y_lo).x);
        if (tick > 0.0f) canvas.line({px, bottom}, {px, bottom + tick}, style.frame, 1.0f);
        std::string s = format_tick(v, x_step);
        canvas.text({whole(px - 0.5f * float(text_width(s, ts))), x_label_top}, s, style.text, ts);
    }
    // y ticks and labels left of the frame, right-aligned, centred on the capital height.
    float label_left = left - tick - 3.0f;
    for (double v : yt) {
        float py = crisp(axes.to_pixel(axes.x_lo, v).y);
        if (tick > 0.0f) canvas.line({left - tick, py}, {left, py}, style.frame, 1.0f);
        std::string s = format_tick(v, y_step);
        float x = left - tick - 3.0f - float(text_width(s, ts));
        label_left = std::min(label_left, x);
        canvas.text({whole(x), whole(py - 0.5f * float((kFontBaseline - 1) * ts))}, s,
                    style.text, ts);
    }
    // Titles.
    if (!labels.x.empty()) {
        float cx = 0.5f * (left + right) - 0.5f * float(text_width(labels.x, ts));
        float y = x_label_top + float(text_height(ts)) + 5.0f;
        canvas.text({whole(cx), y}, labels.x, style.text, ts);
    }
    float above = top - 5.0f;  // bottom of the next text stacked above the frame
    if (!labels.y.empty()) {
        above -= float(text_block_height(labels.y, ts));
        canvas.text({whole(label_left), whole(above)}, labels.y, style.text, ts);
        above -= 4.0f;
    }
    if (!labels.title.empty()) {
        above -= float(text_block_height(labels.title, tts));
        float cx = 0.5f * (left + right) - 0.5f * float(text_width(labels.title, tts));
        canvas.text({whole(cx), whole(above)}, labels.title, style.text, tts);
    }
    return Status::success();
}

// ---- series ----

namespace {

// Liang-Barsky: the part t in [t0, t1] of a + t·d inside [lo, hi] on one axis.
bool clip_axis(double a, double d, double lo, double hi, double* t0, double* t1) {
    if (d == 0.0) return a >= lo && a <= hi;
    double ta = (lo - a) / d, tb = (hi - a) / d;
    if (ta > tb) std::swap(ta, tb);
    *t0 = std::max(*t0, ta);
    *t1 = std::min(*t1, tb);
    return *t0 <= *t1;
}

template <class T>
Status plot_series_impl(Canvas& canvas, const Axes& axes, const T* xs, const T* ys, int n,
                        Rgb8 color, float width) {
    SHITSUKAN_TRY(axes.check());
    if (n < 0) return Status::error(StatusCode::invalid_argument, "series length %d < 0", n);
    if (n > 0 && (xs == nullptr || ys == nullptr))
        return Status::error(StatusCode::invalid_argument, "series of %d points without data", n);
    if (!std::isfinite(width) || width <= 0.0f)
        return Status::error(StatusCode::invalid_argument, "line width must be > 0 (got %g)",
                             double(width));
    std::vector<Vec2> run;  // the current unbroken, unclipped stretch, in pixels
    auto flush = [&]() {
        if (!run.empty()) canvas.polyline(run.data(), int(run.size()), color, width);
        run.clear();
    };
    if (n == 1 && std::isfinite(double(xs[0])) && std::isfinite(double(ys[0])) &&
        axes.contains(double(xs[0]), double(ys[0]))) {
        Vec2 p = axes.to_pixel(double(xs[0]), double(ys[0]));
        canvas.polyline(&p, 1, color, width);
    }
    for (int i = 1; i < n; ++i) {
        double ax = xs[i - 1], ay = ys[i - 1], bx = xs[i], by = ys[i];
        if (!std::isfinite(ax) || !std::isfinite(ay) || !std::isfinite(bx) || !std::isfinite(by)) {
            flush();  // a gap in the data breaks the line
            continue;
        }
        double t0 = 0.0, t1 = 1.0;
        if (!clip_axis(ax, bx - ax, axes.x_lo, axes.x_hi, &t0, &t1) ||
            !clip_axis(ay, by - ay, axes.y_lo, axes.y_hi, &t0, &t1)) {
            flush();
            continue;
        }
        Vec2 pa = axes.to_pixel(ax + t0 * (bx - ax), ay + t0 * (by - ay));
        Vec2 pb = axes.to_pixel(ax + t1 * (bx - ax), ay + t1 * (by - ay));
        if (t0 > 0.0) flush();  // entering the rectangle starts a new stretch
        if (run.empty()) run.push_back(pa);
        run.push_back(pb);
        if (t1 < 1.0) flush();  // leaving it ends one
    }
    flush();
    return Status::success();
}

}  // namespace

Status plot_series(Canvas& canvas, const Axes& axes, const float* xs, const float* ys, int n,
                   Rgb8 color, float width) {
    return plot_series_impl(canvas, axes, xs, ys, n, color, width);
}

Status plot_series(Canvas& canvas, const Axes& axes, const double* xs, const double* ys, int n,
                   Rgb8 color, float width) {
    return plot_series_impl(canvas, axes, xs, ys, n, color, width);
}

Status plot_scatter(Canvas& canvas, const Axes& axes, const float* xs, const float* ys, int n,
                    MarkerShape shape, float size, Rgb8 color) {
    SHITSUKAN_TRY(axes.check());
    if (n < 0) return Status::error(StatusCode::invalid_argument, "scatter length %d < 0", n);
    if (n > 0 && (xs == nullptr || ys == nullptr))
        return Status::error(StatusCode::invalid_argument, "scatter of %d points without data", n);
    if (!std::isfinite(size) || size <= 0.0f)
        return Status::error(StatusCode::invalid_argument, "marker size must be > 0 (got %g)",
                             double(size));
    for (int i = 0; i < n; ++i) {
        double x = xs[i], y = ys[i];
        if (!std::isfinite(x) || !std::isfinite(y)) continue;
        // Judged in pixels with half a pixel of slack, so that a point on the edge whose
        // float value rounded just past the range (float(2 pi) > 2 pi) is still shown.
        Vec2 p = axes.to_pixel(x, y);
        if (p.x < axes.corner.x - 0.5f || p.x > axes.corner.x + axes.size.x + 0.5f ||
            p.y < axes.corner.y - 0.5f || p.y > axes.corner.y + axes.size.y + 0.5f)
            continue;
        canvas.marker(p, shape, size, color);
    }
    return Status::success();
}

// ---- heat map and colour bar ----

Status plot_heatmap(Canvas& canvas, const Axes& axes, const FloatView& values, ColorMap map,
                    ValueRange range) {
    SHITSUKAN_TRY(axes.check());
    if (values.empty())
        return Status::error(StatusCode::invalid_argument, "heat map of an empty image (%d x %d)",
                             values.width, values.height);
    if (!std::isfinite(range.lo) || !std::isfinite(range.hi) || range.hi < range.lo)
        return Status::error(StatusCode::invalid_argument,
                             "heat map range must be finite with lo <= hi (got [%g, %g])",
                             double(range.lo), double(range.hi));
    // Cell edges rounded to whole pixels: neighbours share an edge exactly, no seams.
    auto edge = [](float start, float extent, int k, int count) {
        return std::floor(start + extent * float(k) / float(count) + 0.5f);
    };
    for (int j = 0; j < values.height; ++j) {
        float y0 = edge(axes.corner.y, axes.size.y, j, values.height);
        float y1 = edge(axes.corner.y, axes.size.y, j + 1, values.height);
        if (y1 <= y0) continue;  // more rows than pixels: this row is not shown
        const float* row = values.row(j);
        for (int i = 0; i < values.width; ++i) {
            float x0 = edge(axes.corner.x, axes.size.x, i, values.width);
            float x1 = edge(axes.corner.x, axes.size.x, i + 1, values.width);
            if (x1 <= x0) continue;
            canvas.fill_rect({x0, y0}, {x1 - x0, y1 - y0},
                             colormap(map, normalized_value(row[i], range)));
        }
    }
    return Status::success();
}

Status draw_colorbar(Canvas& canvas, Vec2 corner, Vec2 size, ColorMap map, ValueRange range,
                     const AxesStyle& style) {
    if (!is_finite(corner) || !is_finite(size) || !(size.x >= 1.0f) || !(size.y >= 2.0f))
        return Status::error(StatusCode::invalid_argument,
                             "colour bar needs at least 1 x 2 pixels (got %g x %g)",
                             double(size.x), double(size.y));
    if (!std::isfinite(range.lo) || !std::isfinite(range.hi) || range.hi < range.lo)
        return Status::error(StatusCode::invalid_argument,
                             "colour bar range must be finite with lo <= hi (got [%g, %g])",
                             double(range.lo), double(range.hi));
    const float x0 = whole(corner.x), y0 = whole(corner.y);
    const int w = std::max(1, int(whole(size.x))), h = std::max(2, int(whole(size.y)));
    for (int k = 0; k < h; ++k) {
        float t = 1.0f - (float(k) + 0.5f) / float(h);  // top row = hi
        canvas.fill_rect({x0, y0 + float(k)}, {float(w), 1.0f}, colormap(map, t));
    }
    canvas.rect_outline({x0 - 0.5f, y0 - 0.5f}, {float(w) + 1.0f, float(h) + 1.0f}, style.frame,
                        1.0f);
    const int ts = std::max(1, style.text_scale);
    const float tick = std::max(0.0f, style.tick_length);
    const float right = x0 + float(w) + 0.5f;
    std::vector<double> ticks;
    double step = 0.0;
    if (range.hi > range.lo) {
        ticks = nice_ticks(range.lo, range.hi, style.y_ticks);
        step = nice_step(range.lo, range.hi, style.y_ticks);
    } else {
        ticks.push_back(range.lo);  // a constant field: one label in the middle
    }
    for (double v : ticks) {
        double t = range.hi > range.lo ? (v - range.lo) / (double(range.hi) - range.lo) : 0.5;
        float py = crisp(y0 + float((1.0 - t) * h));
        if (tick > 0.0f) canvas.line({right, py}, {right + tick, py}, style.frame, 1.0f);
        std::string s = step > 0.0 ? format_tick(v, step) : format_tick(v, std::fabs(v) / 100.0);
        canvas.text({right + tick + 3.0f, whole(py - 0.5f * float((kFontBaseline - 1) * ts))}, s,
                    style.text, ts);
    }
    return Status::success();
}

}  // namespace shitsukan
