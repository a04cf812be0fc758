// tests/tile_seams.hpp — is a map seamless when tiled 2 x 2? The test tiles a W x H map with
// itself and measures, per column of the tiling, the mean |value jump| to the next column and
// the mean |second difference| (the gradient's jump), over all rows; the same per row. The
// seam columns are those across the tile's edge (x = W - 1 -> 0). A seamless map's seam
// columns are ordinary columns: no larger than the largest interior one and within a factor
// of the median. A map with a seam (or a crease, issue-style "kink") stands out.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace shitsukan::test {

struct SeamMeasure {
    double seam_value = 0, seam_gradient = 0;         // at the tile's edge
    double median_value = 0, max_value = 0;           // interior columns
    double median_gradient = 0, max_gradient = 0;
};

// Along x (columns); pass transpose = true for rows. h: row-major w x rows.
inline SeamMeasure measure_seams(const float* h, int w, int rows, bool transpose = false) {
    const int n = transpose ? rows : w, m = transpose ? w : rows;
    auto at = [&](int i, int j) {  // i along the measured axis (wrapped: the 2 x 2 tiling)
        i = (i % n + n) % n;
        return double(transpose ? h[std::size_t(i) * std::size_t(w) + std::size_t(j)]
                                : h[std::size_t(j) * std::size_t(w) + std::size_t(i)]);
    };
    std::vector<double> value(std::size_t(n), 0.0), gradient(std::size_t(n), 0.0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            value[std::size_t(i)] += std::fabs(at(i + 1, j) - at(i, j)) / m;
            gradient[std::size_t(i)] += std::fabs(at(i + 1, j) - 2 * at(i, j) + at(i - 1, j)) / m;
        }
    SeamMeasure s;
    s.seam_value = value[std::size_t(n - 1)];
    s.seam_gradient = std::max(gradient[0], gradient[std::size_t(n - 1)]);
    std::vector<double> v(value.begin(), value.end() - 1), g(gradient.begin() + 1, gradient.end() - 1);
    s.max_value = *std::max_element(v.begin(), v.end());
    s.max_gradient = *std::max_element(g.begin(), g.end());
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    std::nth_element(g.begin(), g.begin() + long(g.size() / 2), g.end());
    s.median_value = v[v.size() / 2];
    s.median_gradient = g[g.size() / 2];
    return s;
}

}  // namespace shitsukan::test
