// paper_figures/okada1987/okada_plot.cpp — scalar fields painted with the diverging map.
#include "okada1987/okada_plot.hpp"

#include "shitsukan/image/colormap.hpp"

namespace shitsukan::okada {

void paint_field(const RgbView& img, int x0, int y0, int w, int h,
                 const std::function<float(float, float)>& fn, float lo, float hi) {
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            if (!img.contains(x0 + i, y0 + j)) continue;
            const float v = fn((float(i) + 0.5f) / float(w), (float(j) + 0.5f) / float(h));
            img.at(x0 + i, y0 + j) = colormap(ColorMap::diverging, (v - lo) / (hi - lo));
        }
}

}  // namespace shitsukan::okada
