#include "shitsukan/leather/scale_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shitsukan {

Status measure_scale_statistics(const PlanarSubdivision& cells, float width, float height,
                                ScaleStatistics& out) {
    if (!(width > 0.0f) || !(height > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "measure_scale_statistics: need a region (got %g x %g)",
                             double(width), double(height));
    ScaleStatistics st;
    const double W = width, H = height, xc = 0.5 * W;
    double corners = 0.0;
    std::vector<Vec2d> v;
    for (int f = 0; f < cells.face_count(); ++f) {
        v.clear();
        for (int k = cells.face_offsets[std::size_t(f)]; k < cells.face_offsets[std::size_t(f) + 1];
             ++k)
            v.push_back(
                cells.vertices[std::size_t(cells.face_vertex(cells.face_edges[std::size_t(k)]))]);
        const int n = int(v.size());
        int c = 0;
        double lo = v[0].x, hi = v[0].x, ylo = v[0].y, yhi = v[0].y;
        for (int k = 0; k < n; ++k) {
            Vec2d a = v[std::size_t((k + n - 1) % n)], b = v[std::size_t(k)],
                  d = v[std::size_t((k + 1) % n)];
            if (std::fabs(cross(b - a, d - b)) > 1e-9 * length(b - a) * length(d - b)) ++c;
            lo = std::min(lo, b.x);
            hi = std::max(hi, b.x);
            ylo = std::min(ylo, b.y);
            yhi = std::max(yhi, b.y);
        }
        if (ylo <= 0.0 || yhi >= H) continue;  // cut by the top or bottom edge
        corners += c;
        ++st.cells;
        const double off = std::fabs(0.5 * (lo + hi) - xc) / W;
        if (lo > 0.0 && hi < W && off > 0.3 && off < 0.45) {
            st.edge_width += hi - lo;
            ++st.edge_cells;
        }
        if (off > 0.1 && off < 0.2) {
            st.centre_width += hi - lo;
            ++st.centre_cells;
        }
    }
    if (st.cells > 0) st.mean_corners = corners / st.cells;
    if (st.edge_cells > 0) st.edge_width /= st.edge_cells;
    if (st.centre_cells > 0) st.centre_width /= st.centre_cells;
    if (st.centre_width > 0.0) st.edge_to_centre = st.edge_width / st.centre_width;
    out = st;
    return Status::success();
}

}  // namespace shitsukan
