// shitsukan/image/plot.hpp — plot axes on any Canvas: data -> pixels, ticks, labels, series.
//
// Manual
//   RgbImage img(640, 400, Rgb8{255, 255, 255});
//   RasterCanvas canvas(img.view());                       // or an SvgCanvas: same calls
//   Axes axes = axes_in(canvas, 0.0, 6.2832, -1.2, 1.2);   // data area = canvas - margins
//   Status s = draw_axes(canvas, axes, {"sin x", "x", "y"});  // first: the grid stays under data
//   if (s) s = plot_function(canvas, axes, [](double x) { return std::sin(x); }, 400,
//                            Rgb8{0, 0, 200});
//   const float xs[3] = {1, 2, 3}, ys[3] = {0.5f, -0.5f, 0.8f};
//   if (s) s = plot_series(canvas, axes, xs, ys, 3, Rgb8{200, 0, 0}, 1.5f);  // through the points
//   if (s) s = plot_scatter(canvas, axes, xs, ys, 3, MarkerShape::circle, 7.0f, Rgb8{0, 120, 0});
//   FloatImage field(32, 16, 0.3f);
//   field.at(5, 5) = 1.0f;
//   if (s) s = plot_heatmap(canvas, axes, field.view(), ColorMap::perceptual,
//                           value_range(field.view()));
//   if (s) s = draw_colorbar(canvas, {600, 40}, {16, 200}, ColorMap::perceptual,
//                            value_range(field.view()));
//   return s;
//
// Axes: the data rectangle [x_lo, x_hi] x [y_lo, y_hi] drawn in the pixel rectangle
//   corner .. corner + size; x grows to the right and y UPWARDS (mathematical plots).
//   Ranges are double so that tick arithmetic stays exact; x_lo < x_hi and y_lo < y_hi.
// Ticks: nice_ticks() picks a step of 1, 2 or 5 times a power of ten giving about `target`
//   ticks inside the range (the usual "nice numbers"), at least 2; labels use as many
//   decimals as the step needs (step 0.5 -> "1.5", "2.0"), and "%g" for values beyond 1e6
//   or steps below 1e-4.
// Layout of draw_axes: light grid lines at the ticks (optional), the frame, outward tick
//   marks, tick labels below / left of the frame, the x title centred under the x labels,
//   the y title above the frame's top-left corner (the bitmap font does not rotate), the
//   title centred above everything. PlotMargins' defaults leave room for all of it at
//   text scale 1 and title scale 2.
// Series: points with a non-finite coordinate break the line; lines are clipped to the data
//   rectangle (Liang-Barsky), scatter points more than half a pixel outside it are skipped.
// Heat maps: value (i, j) of the view fills the cell of column i and row j, row 0 at the
//   TOP (image order: row j spans data y from y_hi - j·dy down to y_hi - (j+1)·dy), the
//   cells together covering the data rectangle; cell edges are rounded to whole pixels so
//   neighbouring cells meet without seams. With more cells than pixels some rows/columns
//   are not shown: resample first.
// Errors (Status, nothing drawn): ranges not finite or empty, a pixel rectangle of no area,
//   null arrays with n > 0, n < 0, an empty heat map, fewer than 2 function samples.
// Host side: std::string labels and std::vector scratch.
#pragma once

#include <string>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/image/colormap.hpp"
#include "shitsukan/image/float_convert.hpp"

namespace shitsukan {

struct Axes {
    Vec2 corner{0.0f, 0.0f};  // top-left of the data area in pixels
    Vec2 size{0.0f, 0.0f};    // extent of the data area in pixels
    double x_lo = 0.0, x_hi = 1.0;
    double y_lo = 0.0, y_hi = 1.0;

    Vec2 to_pixel(double x, double y) const;  // y up: y_lo at the bottom edge
    double from_pixel_x(float px) const;
    double from_pixel_y(float py) const;
    bool contains(double x, double y) const;  // inside the data rectangle (edges included)
    Status check() const;                     // the ranges and rectangle are usable
};

struct PlotMargins {
    float left = 60.0f, right = 24.0f, top = 48.0f, bottom = 42.0f;  // chosen here: fit labels
};

// The data area of `canvas` inside the margins (its pixel rectangle may be empty when the
// canvas is too small: Axes::check reports it).
Axes axes_in(const Canvas& canvas, double x_lo, double x_hi, double y_lo, double y_hi,
             const PlotMargins& margins = PlotMargins());

struct AxesLabels {
    std::string title, x, y;
};

struct AxesStyle {
    Rgb8 frame{0, 0, 0};
    Rgb8 text{0, 0, 0};
    Rgb8 grid{222, 222, 222};
    bool draw_grid = true;
    int text_scale = 1;
    int title_scale = 2;
    float tick_length = 4.0f;
    int x_ticks = 7;  // about how many ticks (nice_ticks target)
    int y_ticks = 6;
};

// Tick values k·step within [lo, hi] (with a tolerance of 1e-9 steps at the ends).
std::vector<double> nice_ticks(double lo, double hi, int target);
double nice_step(double lo, double hi, int target);  // 1, 2 or 5 x 10^k
std::string format_tick(double value, double step);

Status draw_axes(Canvas& canvas, const Axes& axes, const AxesLabels& labels = AxesLabels(),
                 const AxesStyle& style = AxesStyle());

Status plot_series(Canvas& canvas, const Axes& axes, const float* xs, const float* ys, int n,
                   Rgb8 color, float width = 1.5f);
Status plot_series(Canvas& canvas, const Axes& axes, const double* xs, const double* ys, int n,
                   Rgb8 color, float width = 1.5f);
Status plot_scatter(Canvas& canvas, const Axes& axes, const float* xs, const float* ys, int n,
                    MarkerShape shape, float size, Rgb8 color);

// y = f(x) sampled at `samples` evenly spaced x over the axes' x range.
template <class F>
Status plot_function(Canvas& canvas, const Axes& axes, F f, int samples, Rgb8 color,
                     float width = 1.5f) {
    if (samples < 2)
        return Status::error(StatusCode::invalid_argument,
                             "plot_function needs at least 2 samples (got %d)", samples);
    SHITSUKAN_TRY(axes.check());
    std::vector<double> xs(static_cast<std::size_t>(samples)), ys(xs.size());
    for (int i = 0; i < samples; ++i) {
        double t = double(i) / double(samples - 1);
        xs[std::size_t(i)] = axes.x_lo + (axes.x_hi - axes.x_lo) * t;
        ys[std::size_t(i)] = double(f(xs[std::size_t(i)]));
    }
    return plot_series(canvas, axes, xs.data(), ys.data(), samples, color, width);
}

Status plot_heatmap(Canvas& canvas, const Axes& axes, const FloatView& values, ColorMap map,
                    ValueRange range);

// A vertical colour bar (lo at the bottom) in the pixel rectangle corner .. corner + size,
// framed, with nice tick labels on its right.
Status draw_colorbar(Canvas& canvas, Vec2 corner, Vec2 size, ColorMap map, ValueRange range,
                     const AxesStyle& style = AxesStyle());

}  // namespace shitsukan
