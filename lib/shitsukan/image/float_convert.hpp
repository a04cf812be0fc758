// shitsukan/image/float_convert.hpp — show a float image: values -> gray or colour-mapped RGB.
//
// Manual
//   #include "shitsukan/image/image.hpp"  // owning images; this header works on views
//   FloatImage height(512, 512);
//   height.at(3, 4) = 2.0f;                      // ... a height map
//   GrayImage gray(512, 512);
//   Status s = float_to_gray(height.view(), gray.view());                // auto range
//   if (s) s = float_to_gray(height.view(), gray.view(), {0.0f, 2.5f});  // fixed range
//   RgbImage rgb(512, 512);
//   if (s) s = float_to_rgb(height.view(), rgb.view(), ColorMap::perceptual);  // auto range
//   ValueRange r = value_range(height.view());   // min/max of the finite values
//   return s;
// A value v maps to t = (v - lo) / (hi - lo), clamped to [0, 1], then to a byte (gray) or
// through the colour map (colormap.hpp). Auto range = value_range(src). When lo == hi
// (a constant image) every finite value maps to t = 0.5, mid-gray (chosen here: neither
// black nor white, which would look like clipping). Non-finite values: NaN -> black in
// gray and kColorMapNaN (magenta) in colour; +inf / -inf clamp to 1 / 0.
// Errors: source and destination sizes differ, an empty source, a range that is not
// finite or has hi < lo -> invalid_argument; nothing is written then.
// No allocation; views with a stride (bands, windows) work.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/image/colormap.hpp"
#include "shitsukan/image/image_view.hpp"

namespace shitsukan {

struct ValueRange {
    float lo = 0.0f;
    float hi = 1.0f;
};

// Min and max of the finite values; {0, 0} with *any_finite = false when there are none.
ValueRange value_range(const FloatView& src, bool* any_finite = nullptr);

Status float_to_gray(const FloatView& src, const GrayView& dst, ValueRange range);
Status float_to_gray(const FloatView& src, const GrayView& dst);  // auto range
Status float_to_rgb(const FloatView& src, const RgbView& dst, ColorMap map, ValueRange range);
Status float_to_rgb(const FloatView& src, const RgbView& dst, ColorMap map);  // auto range

// The t in [0, 1] (or NaN) of one value, as the conversions above compute it.
float normalized_value(float v, ValueRange range);

}  // namespace shitsukan
