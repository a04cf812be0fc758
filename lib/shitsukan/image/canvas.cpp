#include "shitsukan/image/canvas.hpp"

#include <vector>

namespace shitsukan {

// One polygon that visits every contour and returns along the same bridge: each bridge edge
// is crossed twice, which the even-odd rule cancels, so the result equals the contours
// filled together.
void Canvas::fill_contours(const Vec2* points, const int* contour_sizes, int contours,
                           Rgb8 color) {
    if (points == nullptr || contour_sizes == nullptr || contours <= 0) return;
    std::vector<Vec2> path;
    int start = 0;
    for (int c = 0; c < contours; ++c) {
        int n = contour_sizes[c];
        if (n <= 0) continue;
        for (int i = 0; i < n; ++i) path.push_back(points[start + i]);
        path.push_back(points[start]);  // close this contour
        if (c > 0) path.push_back(points[0]);  // bridge back to the first contour's start
        start += n;
    }
    if (path.size() >= 3) fill_polygon(path.data(), int(path.size()), color);
}

void Canvas::clear(Rgb8 color) {
    fill_rect({0.0f, 0.0f}, {float(width()), float(height())}, color);
}

}  // namespace shitsukan
