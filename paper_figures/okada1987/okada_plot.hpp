// paper_figures/okada1987/okada_plot.hpp — painting a scalar field into a panel of an image
// (the okada diagrams fig01, fig02, fig07); axes and curves come from image/plot.hpp.
//
// Manual
//   okada::paint_field(img.view(), x0, y0, w, h, [&](float u, float v) { return ...; }, -2, 2);
//   // u, v in [0, 1] across the panel (v down); diverging colour map, lo blue .. hi red
//   Axes a = okada::panel_axes(x0, y0, w, h, x_lo, x_hi, y_lo, y_hi);   // a plot in a panel
#pragma once

#include <functional>

#include "shitsukan/image/image.hpp"
#include "shitsukan/image/plot.hpp"

namespace shitsukan::okada {

const Rgb8 kInk{20, 20, 20};

void paint_field(const RgbView& img, int x0, int y0, int w, int h,
                 const std::function<float(float, float)>& fn, float lo, float hi);

inline Axes panel_axes(float x0, float y0, float w, float h, double x_lo, double x_hi,
                       double y_lo, double y_hi) {
    Axes a;
    a.corner = Vec2{x0, y0};
    a.size = Vec2{w, h};
    a.x_lo = x_lo, a.x_hi = x_hi, a.y_lo = y_lo, a.y_hi = y_hi;
    return a;
}

}  // namespace shitsukan::okada
