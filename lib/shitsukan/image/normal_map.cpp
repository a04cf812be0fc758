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
    for (int y = 0; y < height; ++y) {
        const float* row = heights + std::size_t(y) * w;
        for (int x = 0; x < width; ++x) {
            const float dx = difference(x, width, options.wrap, [&](int k) { return row[k]; });
            // rows run downwards, the normal's y upwards: d/dy(up) = -d/d(row)
            const float dy = -difference(y, height, options.wrap, [&](int k) {
                return heights[std::size_t(k) * w + std::size_t(x)];
            });
            Vec3 n{-options.strength * dx, -options.strength * dy, 1.0f};
            const float len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
            out[std::size_t(y) * w + std::size_t(x)] =
                std::isfinite(len) && len > 0.0f ? n * (1.0f / len) : Vec3{0.0f, 0.0f, 1.0f};
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
