// shitsukan/image/image.hpp — owning images (host side) on top of the views.
//
// Manual
//   RgbImage img(512, 512);                   // owning (std::vector)
//   fill(img.view(), Rgb8{0, 0, 0});          // any view function works on img.view()
//   img.at(10, 20) = Rgb8{255, 0, 0};
//   int user_w = 640, user_h = 480;
//   Status s = img.try_resize(user_w, user_h);  // checked against the memory budget
//   if (!s) return s;
//   GrayImage g(4, 4);  FloatImage f(4, 4);  Gray16Image h(4, 4);  // uint8_t, float, uint16_t
// The views themselves (RgbView, ...) are in image_view.hpp, which allocates nothing and is
// what small-device code includes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/image/image_view.hpp"

namespace shitsukan {

// Host-side owning image. Sizes are clamped at 0. The constructor and resize() trust their
// sizes (a size beyond memory throws std::bad_alloc, as std::vector does); for sizes that come
// from a user, try_resize() checks width·height·sizeof(P) against the memory budget
// (core/memory_budget.hpp) first and refuses at once with the byte count.
template <class P> class Image {
public:
    Image() = default;
    Image(int width, int height, P value = P{}) { resize(width, height, value); }
    void resize(int width, int height, P value = P{}) {
        width_ = width > 0 ? width : 0;
        height_ = height > 0 ? height : 0;
        data_.assign(std::size_t(width_) * std::size_t(height_), value);
    }
    Status try_resize(int width, int height, P value = P{}) {
        const std::uint64_t w = width > 0 ? std::uint64_t(width) : 0;
        const std::uint64_t h = height > 0 ? std::uint64_t(height) : 0;
        SHITSUKAN_TRY(check_memory_budget(budget_mul(budget_mul(w, h), sizeof(P)), "image"));
        resize(width, height, value);
        return Status::success();
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
