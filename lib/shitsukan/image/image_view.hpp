// shitsukan/image/image_view.hpp — images over caller memory (small-device: no allocation).
//
// Manual
//   Rgb8 px{255, 128, 0};
//   Rgb8 buffer[64 * 32];
//   RgbView view{buffer, 64, 32, 64};        // pixels, width, height, stride (in pixels)
//   view.at(3, 5) = px;                      // x right, y down, (0, 0) top-left
//   fill(view, Rgb8{0, 0, 0});
//   // GrayView (uint8_t), FloatView (float), Gray16View (uint16_t, e.g. height maps).
//   // A view with width or height 0 is empty; functions given one do nothing and say so.
// Views never own memory; the owning Image (image.hpp, host side) hands out views. Row y starts at
// pixels + y·stride, so a view can be a band or a window of a larger buffer (subview).
#pragma once

#include <cstddef>
#include <cstdint>

#include "shitsukan/core/assert.hpp"

namespace shitsukan {

struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
};
inline bool operator==(Rgb8 a, Rgb8 b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
inline bool operator!=(Rgb8 a, Rgb8 b) { return !(a == b); }

template <class P> struct ImageView {
    P* pixels = nullptr;
    int width = 0;
    int height = 0;
    int stride = 0;  // pixels between the starts of two rows, >= width

    bool empty() const { return pixels == nullptr || width <= 0 || height <= 0; }
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
    P& at(int x, int y) const {
        SHITSUKAN_ASSERT(contains(x, y));
        return pixels[std::size_t(y) * std::size_t(stride) + std::size_t(x)];
    }
    P* row(int y) const {
        SHITSUKAN_ASSERT(y >= 0 && y < height);
        return pixels + std::size_t(y) * std::size_t(stride);
    }
    // The rectangle [x0, x0+w) x [y0, y0+h), clipped to this view.
    ImageView subview(int x0, int y0, int w, int h) const {
        // in 64 bits: x0 + w and w + x0 overflow int for large arguments
        long long lx = x0, ly = y0, lw = w, lh = h;
        if (lx < 0) {
            lw += lx;
            lx = 0;
        }
        if (ly < 0) {
            lh += ly;
            ly = 0;
        }
        if (lx + lw > width) lw = width - lx;
        if (ly + lh > height) lh = height - ly;
        if (lw <= 0 || lh <= 0 || empty()) return ImageView{};
        x0 = int(lx);
        y0 = int(ly);
        w = int(lw);
        h = int(lh);
        return ImageView{pixels + std::size_t(y0) * std::size_t(stride) + std::size_t(x0), w, h,
                         stride};
    }
};

using RgbView = ImageView<Rgb8>;
using GrayView = ImageView<std::uint8_t>;
using Gray16View = ImageView<std::uint16_t>;
using FloatView = ImageView<float>;

template <class P> void fill(const ImageView<P>& view, P value) {
    for (int y = 0; y < view.height; ++y) {
        P* r = view.row(y);
        for (int x = 0; x < view.width; ++x) r[x] = value;
    }
}

// Host-side owning image. Sizes are clamped at 0; width·height must fit in memory.

// Float in [0, 1] -> byte, rounded, clamped; NaN -> 0.
inline std::uint8_t to_byte(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return std::uint8_t(v * 255.0f + 0.5f);
}

}  // namespace shitsukan
