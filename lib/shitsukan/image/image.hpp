// shitsukan/image/image.hpp — owning images (host side) on top of the views.
//
// Manual
//   RgbImage img(512, 512);                   // owning (std::vector)
//   fill(img.view(), Rgb8{0, 0, 0});          // any view function works on img.view()
//   img.at(10, 20) = Rgb8{255, 0, 0};
//   GrayImage g(4, 4);  FloatImage f(4, 4);  Gray16Image h(4, 4);  // uint8_t, float, uint16_t
// The views themselves (RgbView, ...) are in image_view.hpp, which allocates nothing and is
// what small-device code includes.
#pragma once

#include <cstddef>
#include <vector>

#include "shitsukan/image/image_view.hpp"

namespace shitsukan {

// Host-side owning image. Sizes are clamped at 0; width·height must fit in memory.
template <class P> class Image {
public:
    Image() = default;
    Image(int width, int height, P value = P{}) { resize(width, height, value); }
    void resize(int width, int height, P value = P{}) {
        width_ = width > 0 ? width : 0;
        height_ = height > 0 ? height : 0;
        data_.assign(std::size_t(width_) * std::size_t(height_), value);
    }
    ImageView<P> view() {
        return ImageView<P>{data_.empty() ? nullptr : data_.data(), width_, height_, width_};
    }
    ImageView<const P> const_view() const {
        return ImageView<const P>{data_.empty() ? nullptr : data_.data(), width_, height_, width_};
    }
    P& at(int x, int y) { return view().at(x, y); }
    const P& at(int x, int y) const {
        return data_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
    }
    int width() const { return width_; }
    int height() const { return height_; }
    P* data() { return data_.data(); }
    const P* data() const { return data_.data(); }

private:
    std::vector<P> data_;
    int width_ = 0, height_ = 0;
};

using RgbImage = Image<Rgb8>;
using GrayImage = Image<std::uint8_t>;
using Gray16Image = Image<std::uint16_t>;
using FloatImage = Image<float>;

}  // namespace shitsukan
