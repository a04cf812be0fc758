// small-device: yes (no allocation, no exceptions)
#include "shitsukan/image/float_convert.hpp"

#include <cmath>

namespace shitsukan {

namespace {

Status check_views(const FloatView& src, int dst_width, int dst_height, bool dst_empty) {
    if (src.empty())
        return Status::error(StatusCode::invalid_argument, "float image is empty (%d x %d)",
                             src.width, src.height);
    if (dst_empty || dst_width != src.width || dst_height != src.height)
        return Status::error(StatusCode::invalid_argument,
                             "destination is %d x %d but the float image is %d x %d", dst_width,
                             dst_height, src.width, src.height);
    return Status::success();
}

Status check_range(ValueRange r) {
    if (!std::isfinite(r.lo) || !std::isfinite(r.hi) || r.hi < r.lo)
        return Status::error(StatusCode::invalid_argument,
                             "value range must be finite with lo <= hi (got [%g, %g])",
                             double(r.lo), double(r.hi));
    return Status::success();
}

}  // namespace

ValueRange value_range(const FloatView& src, bool* any_finite) {
    bool found = false;
    ValueRange r{0.0f, 0.0f};
    for (int y = 0; y < src.height && !src.empty(); ++y) {
        const float* row = src.row(y);
        for (int x = 0; x < src.width; ++x) {
            float v = row[x];
            if (!std::isfinite(v)) continue;
            if (!found) {
                r = {v, v};
                found = true;
            }
            if (v < r.lo) r.lo = v;
            if (v > r.hi) r.hi = v;
        }
    }
    if (any_finite) *any_finite = found;
    return r;
}

float normalized_value(float v, ValueRange range) {
    if (std::isnan(v)) return v;
    if (!(range.hi > range.lo)) return std::isfinite(v) ? 0.5f : (v > 0.0f ? 1.0f : 0.0f);
    // double: (v - lo) must not overflow for ranges near the float limits.
    double t = (double(v) - double(range.lo)) / (double(range.hi) - double(range.lo));
    return t <= 0.0 ? 0.0f : (t >= 1.0 ? 1.0f : float(t));
}

Status float_to_gray(const FloatView& src, const GrayView& dst, ValueRange range) {
    SHITSUKAN_TRY(check_views(src, dst.width, dst.height, dst.empty()));
    SHITSUKAN_TRY(check_range(range));
    for (int y = 0; y < src.height; ++y) {
        const float* in = src.row(y);
        std::uint8_t* out = dst.row(y);
        for (int x = 0; x < src.width; ++x) out[x] = to_byte(normalized_value(in[x], range));
    }
    return Status::success();
}

Status float_to_gray(const FloatView& src, const GrayView& dst) {
    return float_to_gray(src, dst, value_range(src));
}

Status float_to_rgb(const FloatView& src, const RgbView& dst, ColorMap map, ValueRange range) {
    SHITSUKAN_TRY(check_views(src, dst.width, dst.height, dst.empty()));
    SHITSUKAN_TRY(check_range(range));
    for (int y = 0; y < src.height; ++y) {
        const float* in = src.row(y);
        Rgb8* out = dst.row(y);
        for (int x = 0; x < src.width; ++x) out[x] = colormap(map, normalized_value(in[x], range));
    }
    return Status::success();
}

Status float_to_rgb(const FloatView& src, const RgbView& dst, ColorMap map) {
    return float_to_rgb(src, dst, map, value_range(src));
}

}  // namespace shitsukan
