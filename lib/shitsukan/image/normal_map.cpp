// A normal map from a height map (normal_map.hpp).
#include "shitsukan/image/normal_map.hpp"

#include <cmath>

namespace shitsukan {

namespace {

// Central difference along one axis at index i of n samples read by at(k); one-sided at the
// ends, or across them when wrapping.
template <class At> float difference(int i, int n, bool wrap, At at) {
    if (n == 1) return 0.0f;
    int lo = i - 1, hi = i + 1;
    float span = 2.0f;
    if (wrap) {
        lo = (lo + n) % n;
        hi = hi % n;
    } else {
        if (lo < 0) lo = 0, span = 1.0f;
        if (hi >= n) hi = n - 1, span = 1.0f;
    }
    return (at(hi) - at(lo)) / span;
}

// Every height finite: a NaN or infinite height has no slope (a normal from it would be made
// up), so the map is refused, naming the first one.
Status check_heights(const float* heights, int width, int height) {
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float h = heights[std::size_t(y) * std::size_t(width) + std::size_t(x)];
            if (!std::isfinite(h))
                return Status::error(StatusCode::invalid_argument,
                                     "height_map_normals: the height at (%d, %d) is %g: heights "
                                     "must be finite",
                                     x, y, double(h));
        }
    return Status::success();
}

}  // namespace

Status height_map_normals(const float* heights, int width, int height,
                          const HeightNormalOptions& options, Vec3* out) {
    if (heights == nullptr || out == nullptr)
        return Status::error(StatusCode::invalid_argument, "height_map_normals: null pointer");
    if (width < 1 || height < 1)
        return Status::error(StatusCode::invalid_argument,
                             "height_map_normals: size %d x %d, both must be >= 1", width,
                             height);
    if (!std::isfinite(options.strength))
        return Status::error(StatusCode::invalid_argument,
                             "height_map_normals: strength must be finite (got %g)",
                             double(options.strength));
    const std::size_t w = std::size_t(width);
    SHITSUKAN_TRY(check_heights(heights, width, height));
    for (int y = 0; y < height; ++y) {
        const float* row = heights + std::size_t(y) * w;
        for (int x = 0; x < width; ++x) {
            const float dx = difference(x, width, options.wrap, [&](int k) { return row[k]; });
            // rows run downwards, the normal's y upwards: d/dy(up) = -d/d(row)
            const float dy = -difference(y, height, options.wrap, [&](int k) {
                return heights[std::size_t(k) * w + std::size_t(x)];
            });
            const float gx = -options.strength * dx, gy = -options.strength * dy;
            if (!std::isfinite(gx) || !std::isfinite(gy))
                return Status::error(StatusCode::out_of_range,
                                     "height_map_normals: the slope at (%d, %d) overflows a "
                                     "float (dh/dx %g, dh/dy %g, strength %g): scale the "
                                     "heights down",
                                     x, y, double(dx), double(dy), double(options.strength));
            // (gx, gy, 1) / |.| through (gx, gy, 1) / m, m = max(|gx|, |gy|, 1): the squares
            // stay below 3 however steep the slope, so the length never overflows.
            float m = std::fabs(gx) > std::fabs(gy) ? std::fabs(gx) : std::fabs(gy);
            if (m < 1.0f) m = 1.0f;
            const Vec3 n{gx / m, gy / m, 1.0f / m};
            const float len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
            out[std::size_t(y) * w + std::size_t(x)] = n * (1.0f / len);
        }
    }
    return Status::success();
}

void encode_normal_rgb8(const Vec3* normals, std::size_t count, std::uint8_t* rgb) {
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c) {
            float v = (normals[i][c] + 1.0f) * 0.5f * 255.0f + 0.5f;
            v = v < 0.0f ? 0.0f : (v > 255.0f ? 255.0f : v);
            rgb[3 * i + std::size_t(c)] = std::uint8_t(v);
        }
}

}  // namespace shitsukan
