// Lesson 4: a plot with axes, drawn once for pixels and once for vectors.
// Figure: paper_figures/okada1987/fig06_interpolation.cpp.
//
// The papers' figures are not all renderings: many are curves (a spectrum, a section, a
// layer radius over time). shitsukan draws them through one interface, Canvas, so the
// same drawing code writes a PNG (RasterCanvas: pixels) and an SVG (SvgCanvas: vector
// elements that stay sharp when a reader zooms into the figure).
//
// What this program does:
//   1. picks a data range and maps it onto the canvas (Axes: data -> pixels, y up),
//   2. draws the frame, the "nice" ticks (steps of 1, 2 or 5 x 10^k) and the labels,
//   3. draws y = sin x as a polyline of 400 samples, and 13 points as a scatter,
//   4. saves 04_plot.png and 04_plot.svg.
// Run: make examples   (the files appear in build/examples/out/)
#include <cmath>
#include <cstdio>

#include "shitsukan/image/canvas.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/plot.hpp"

using namespace shitsukan;

// All drawing goes through Canvas&: this function does not know whether it makes pixels
// or SVG elements.
static Status draw_sine_plot(Canvas& canvas) {
    // Step 1: the data rectangle [0, 2 pi] x [-1.2, 1.2] inside the canvas margins.
    Axes axes = axes_in(canvas, 0.0, 2.0 * kPiD, -1.2, 1.2);

    // Step 2: axes first, so that the light grid lies under the data.
    SHITSUKAN_TRY(draw_axes(canvas, axes, {"y = sin x", "x (radians)", "y"}));

    // Step 3a: the curve. plot_function samples x evenly; each sample becomes a polyline
    // vertex at axes.to_pixel(x, sin x). 400 samples over 556 pixels: no visible corners.
    SHITSUKAN_TRY(plot_function(canvas, axes, [](double x) { return std::sin(x); }, 400,
                                Rgb8{20, 60, 190}, 2.0f));

    // Step 3b: a few exact values, as markers, to show the curve passes through them.
    float xs[13], ys[13];
    for (int i = 0; i < 13; ++i) {
        xs[i] = float(i) * float(kPiD) / 6.0f;  // every 30 degrees
        ys[i] = std::sin(xs[i]);
    }
    SHITSUKAN_TRY(plot_scatter(canvas, axes, xs, ys, 13, MarkerShape::circle, 8.0f,
                               Rgb8{200, 50, 20}));

    // A label placed in data coordinates: to_pixel gives where the point is on the canvas.
    Vec2 peak = axes.to_pixel(kPiD / 2.0, 1.0);
    canvas.text({peak.x + 8.0f, peak.y - 14.0f}, "max: sin(\u03c0/2) = 1", Rgb8{0, 0, 0}, 1);
    return Status::success();
}

int main() {
    // Pixels: a white 640 x 400 image, anti-aliased drawing.
    RgbImage image(640, 400, Rgb8{255, 255, 255});
    RasterCanvas raster(image.view());
    Status s = draw_sine_plot(raster);
    if (s) s = write_png("04_plot.png", image.view());

    // Vectors: the same calls recorded as SVG elements.
    SvgCanvas svg(640, 400, Rgb8{255, 255, 255});
    if (s) s = draw_sine_plot(svg);
    if (s) s = svg.save("04_plot.svg");

    if (!s) {
        std::fprintf(stderr, "04_plot: %s\n", s.message());
        return 1;
    }
    std::printf("wrote 04_plot.png and 04_plot.svg (%d SVG elements)\n", svg.element_count());
    return 0;
}
