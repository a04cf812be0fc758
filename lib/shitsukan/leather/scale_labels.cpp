#include "shitsukan/leather/scale_labels.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shitsukan {
namespace {

// Clamped in double before the conversion: a vertex far outside the image (1e30) must not
// overflow the int.
int clamp_to_int(double v, int lo, int hi) {
    return int(std::min(double(hi), std::max(double(lo), v)));
}

}  // namespace

Status rasterize_scale_labels(const ScalePattern& pattern, int width, int height,
                              std::int32_t* labels) {
    if (labels == nullptr || width <= 0 || height <= 0 || width > 65536 || height > 65536)
        return Status::error(
            StatusCode::invalid_argument,
            "rasterize_scale_labels: image size must be 1..65536 a side (got %d x %d)", width,
            height);
    if (!(pattern.width > 0.0f && pattern.height > 0.0f) || !is_finite(pattern.width) ||
        !is_finite(pattern.height))
        return Status::error(StatusCode::invalid_argument,
                             "rasterize_scale_labels: pattern is %g x %g", double(pattern.width),
                             double(pattern.height));
    // A NaN or infinite vertex would turn the row and column bounds below into undefined
    // float -> int conversions.
    for (std::size_t k = 0; k < pattern.vertices.size(); ++k)
        if (!is_finite(pattern.vertices[k]))
            return Status::error(StatusCode::invalid_argument,
                                 "rasterize_scale_labels: vertex %d = (%g, %g) is not finite",
                                 int(k), double(pattern.vertices[k].x),
                                 double(pattern.vertices[k].y));
    for (std::size_t k = 1; k < pattern.polygon_offsets.size(); ++k)
        if (pattern.polygon_offsets[0] < 0 ||
            pattern.polygon_offsets[k] < pattern.polygon_offsets[k - 1] ||
            std::size_t(pattern.polygon_offsets[k]) > pattern.vertices.size())
            return Status::error(StatusCode::invalid_argument,
                                 "rasterize_scale_labels: polygon_offsets[%d] = %d is not in "
                                 "[offsets[%d], %d]",
                                 int(k), pattern.polygon_offsets[k], int(k) - 1,
                                 int(pattern.vertices.size()));
    const std::size_t total = std::size_t(width) * std::size_t(height);
    std::fill(labels, labels + total, -1);
    const double px = double(pattern.width) / width, py = double(pattern.height) / height;
    auto centre_x = [&](int i) { return (i + 0.5) * px; };
    std::vector<double> xs;
    for (int f = 0; f < pattern.polygon_count(); ++f) {
        int n;
        const Vec2* v = pattern.polygon(f, &n);
        if (n < 3) continue;
        float lo = v[0].y, hi = v[0].y;
        for (int k = 0; k < n; ++k) {
            lo = std::min(lo, v[k].y);
            hi = std::max(hi, v[k].y);
        }
        const int j0 = clamp_to_int(std::floor(double(lo) / py - 0.5), 0, height);
        const int j1 = clamp_to_int(std::ceil(double(hi) / py), -1, height - 1);
        for (int j = j0; j <= j1; ++j) {
            const double y = (j + 0.5) * py;
            xs.clear();
            for (int k = 0; k < n; ++k) {
                Vec2 a = v[k], b = v[(k + 1) % n];
                if (b.y < a.y || (b.y == a.y && b.x < a.x)) std::swap(a, b);  // lower end first
                if (!(y >= double(a.y) && y < double(b.y))) continue;         // half-open in y
                double t = (y - double(a.y)) / (double(b.y) - double(a.y));
                xs.push_back(double(a.x) + t * (double(b.x) - double(a.x)));
            }
            std::sort(xs.begin(), xs.end());
            for (std::size_t s = 0; s + 1 < xs.size(); s += 2) {
                // pixels whose centre lies in [xs[s], xs[s + 1])
                int i = clamp_to_int(std::floor(xs[s] / px - 0.5), 0, width);
                while (i < width && centre_x(i) < xs[s]) ++i;
                for (; i < width && centre_x(i) < xs[s + 1]; ++i) {
                    std::int32_t& l = labels[std::size_t(j) * std::size_t(width) + std::size_t(i)];
                    if (l >= 0)
                        return Status::error(
                            StatusCode::degenerate,
                            "rasterize_scale_labels: polygons %d and %d overlap at pixel (%d, %d)",
                            int(l), f, i, j);
                    l = f;
                }
            }
        }
    }
    for (std::size_t k = 0; k < total; ++k)
        if (labels[k] < 0)
            return Status::error(StatusCode::degenerate,
                                 "rasterize_scale_labels: pixel (%d, %d) is in no polygon",
                                 int(k % std::size_t(width)), int(k / std::size_t(width)));
    return Status::success();
}

}  // namespace shitsukan
