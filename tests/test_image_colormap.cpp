// Tests for lib/shitsukan/image/colormap and float_convert: colour map ends and lightness,
// float -> gray/RGB mapping, ranges, errors.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "shitsukan/image/colormap.hpp"
#include "shitsukan/image/float_convert.hpp"
#include "shitsukan/image/image.hpp"

using namespace shitsukan;

namespace {

// CIE L* of an sRGB colour (D65), the lightness a viewer perceives.
double lightness(Rgb8 c) {
    auto lin = [](std::uint8_t v) {
        double s = v / 255.0;
        return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
    };
    double y = 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b);
    return y > 0.008856 ? 116.0 * std::cbrt(y) - 16.0 : 903.3 * y;
}

}  // namespace

TEST_CASE("gray map: linear bytes, clamped, NaN visible") {
    CHECK(colormap(ColorMap::gray, 0.0f) == Rgb8{0, 0, 0});
    CHECK(colormap(ColorMap::gray, 1.0f) == Rgb8{255, 255, 255});
    CHECK(colormap(ColorMap::gray, 0.5f) == Rgb8{128, 128, 128});
    CHECK(colormap(ColorMap::gray, -3.0f) == Rgb8{0, 0, 0});
    CHECK(colormap(ColorMap::gray, 7.0f) == Rgb8{255, 255, 255});
    for (ColorMap m : {ColorMap::gray, ColorMap::perceptual, ColorMap::diverging})
        CHECK(colormap(m, NAN) == kColorMapNaN);
    CHECK(std::string(colormap_name(ColorMap::diverging)) == "diverging");
}

TEST_CASE("perceptual map: lightness rises monotonically and evenly from dark to light") {
    double prev = lightness(colormap(ColorMap::perceptual, 0.0f));
    CHECK(prev < 12.0);
    CHECK(lightness(colormap(ColorMap::perceptual, 1.0f)) > 88.0);
    double min_step = 1e9, max_step = 0.0;
    for (int i = 1; i <= 255; ++i) {
        double l = lightness(colormap(ColorMap::perceptual, float(i) / 255.0f));
        min_step = std::min(min_step, l - prev);
        max_step = std::max(max_step, l - prev);
        prev = l;
    }
    // Ideal: 80 / 255 = 0.31 per step; 8-bit rounding of the channels adds jitter.
    CHECK(min_step > 0.0);
    CHECK(max_step < 0.7);
}

TEST_CASE("diverging map: equal-lightness ends, lightest in the middle, monotone halves") {
    double lo = lightness(colormap(ColorMap::diverging, 0.0f));
    double hi = lightness(colormap(ColorMap::diverging, 1.0f));
    double mid = lightness(colormap(ColorMap::diverging, 0.5f));
    CHECK(std::fabs(lo - hi) < 3.0);
    CHECK(mid > 90.0);
    Rgb8 a = colormap(ColorMap::diverging, 0.0f), b = colormap(ColorMap::diverging, 1.0f);
    CHECK(a.b > a.r);  // cold = blue
    CHECK(b.r > b.b);  // warm = red
    double prev = lo;
    for (int i = 1; i <= 127; ++i) {
        double l = lightness(colormap(ColorMap::diverging, float(i) / 254.0f));
        CHECK(l >= prev - 1e-9);
        prev = l;
    }
    prev = hi;
    for (int i = 1; i <= 127; ++i) {
        double l = lightness(colormap(ColorMap::diverging, 1.0f - float(i) / 254.0f));
        CHECK(l >= prev - 1e-9);
        prev = l;
    }
}

TEST_CASE("value_range ignores NaN and infinities") {
    FloatImage img(3, 2, 1.0f);
    img.at(0, 0) = -2.5f;
    img.at(1, 0) = NAN;
    img.at(2, 0) = INFINITY;
    img.at(0, 1) = 4.0f;
    bool any = false;
    ValueRange r = value_range(img.view(), &any);
    CHECK(any);
    CHECK(r.lo == -2.5f);
    CHECK(r.hi == 4.0f);
    FloatImage nans(2, 2, NAN);
    r = value_range(nans.view(), &any);
    CHECK_FALSE(any);
    CHECK(r.lo == 0.0f);
    CHECK(r.hi == 0.0f);
}

TEST_CASE("float_to_gray: fixed and automatic ranges, clamping, NaN, constant image") {
    FloatImage img(5, 1);
    const float v[5] = {-1.0f, 0.0f, 0.5f, 1.0f, 2.0f};
    for (int x = 0; x < 5; ++x) img.at(x, 0) = v[x];
    GrayImage g(5, 1);
    REQUIRE(float_to_gray(img.view(), g.view(), ValueRange{0.0f, 1.0f}).ok());
    CHECK(g.at(0, 0) == 0);
    CHECK(g.at(1, 0) == 0);
    CHECK(g.at(2, 0) == 128);
    CHECK(g.at(3, 0) == 255);
    CHECK(g.at(4, 0) == 255);
    REQUIRE(float_to_gray(img.view(), g.view()).ok());  // auto: [-1, 2]
    CHECK(g.at(0, 0) == 0);
    CHECK(g.at(1, 0) == to_byte(1.0f / 3.0f));
    CHECK(g.at(4, 0) == 255);
    img.at(2, 0) = NAN;
    img.at(3, 0) = -INFINITY;
    REQUIRE(float_to_gray(img.view(), g.view()).ok());
    CHECK(g.at(2, 0) == 0);
    CHECK(g.at(3, 0) == 0);
    FloatImage flat(4, 4, 3.0f);
    GrayImage fg(4, 4);
    REQUIRE(float_to_gray(flat.view(), fg.view()).ok());
    CHECK(fg.at(2, 2) == 128);  // constant image -> mid-gray (chosen)
}

TEST_CASE("float_to_rgb: colour map of the normalised value, strided views") {
    FloatImage big(8, 6);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) big.at(x, y) = float(x * 10 + y);
    FloatView src = big.view().subview(2, 1, 4, 3);  // values 21 .. 53
    RgbImage out(7, 5, Rgb8{1, 1, 1});
    RgbView dst = out.view().subview(1, 1, 4, 3);
    REQUIRE(float_to_rgb(src, dst, ColorMap::perceptual).ok());
    ValueRange r{21.0f, 53.0f};
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            CHECK(dst.at(x, y) ==
                  colormap(ColorMap::perceptual, float((src.at(x, y) - 21.0) / 32.0)));
    CHECK(dst.at(0, 0) == colormap(ColorMap::perceptual, 0.0f));
    CHECK(dst.at(3, 2) == colormap(ColorMap::perceptual, 1.0f));
    CHECK(out.at(0, 0) == Rgb8{1, 1, 1});  // outside the window: untouched
    CHECK(out.at(5, 4) == Rgb8{1, 1, 1});
    REQUIRE(float_to_rgb(src, dst, ColorMap::diverging, r).ok());
    CHECK(dst.at(0, 0) == colormap(ColorMap::diverging, 0.0f));
}

TEST_CASE("float conversions reject mismatched sizes, empty sources and bad ranges") {
    FloatImage img(4, 3, 0.5f);
    GrayImage small(3, 3, 7);
    Status s = float_to_gray(img.view(), small.view());
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("3 x 3") != std::string::npos);
    CHECK(small.at(0, 0) == 7);  // nothing written
    GrayImage g(4, 3, 7);
    CHECK(float_to_gray(img.view(), g.view(), ValueRange{1.0f, 0.0f}).code() ==
          StatusCode::invalid_argument);
    CHECK(float_to_gray(img.view(), g.view(), ValueRange{0.0f, NAN}).code() ==
          StatusCode::invalid_argument);
    CHECK(g.at(0, 0) == 7);
    FloatImage empty;
    GrayImage ge;
    CHECK(float_to_gray(empty.view(), ge.view()).code() == StatusCode::invalid_argument);
    RgbImage rgb(4, 2);
    CHECK(float_to_rgb(img.view(), rgb.view(), ColorMap::gray).code() ==
          StatusCode::invalid_argument);
}
