// fuzz/fuzz_voronoi.cpp — voronoi_cells (and build_delaunay, check_convex_region, the
// clipping under it) on any sites and any region. Contract: a non-ok Status, or cells that
// are finite and tile the region (areas, as fans of exact orientations, adding up to the
// region's within the rounding of the vertices: 8 ulps of the largest region coordinate along
// every edge).
#include <algorithm>
#include <cmath>
#include <vector>

#include "fuzz_input.hpp"
#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/geom/predicates.hpp"
#include "shitsukan/geom/voronoi.hpp"

using namespace shitsukan;

namespace {
// Area of a convex polygon as a fan of exact orientations (each term's leading component):
// polygon_area's doubles cannot see a triangle of area 0.4 with a vertex at 1e34 (found).
double fan_area(const Vec2d* v, int k) {
    double twice = 0.0;
    for (int i = 1; i + 1 < k; ++i) twice += orient2d_exact(v[0], v[i], v[i + 1]);
    return 0.5 * twice;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    const int m = 3 + in.take<std::uint8_t>() % 6;
    std::vector<Vec2d> region;
    if (in.take<std::uint8_t>() & 1) {  // an axis-parallel box
        double x0 = in.coordinate(), y0 = in.coordinate(), x1 = in.coordinate(),
               y1 = in.coordinate();
        region = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    } else {
        for (int i = 0; i < m; ++i) region.push_back({in.coordinate(), in.coordinate()});
    }
    std::vector<Vec2d> sites;
    while (in.left() >= 2 && sites.size() < 256) sites.push_back({in.coordinate(), in.coordinate()});
    if (sites.empty()) sites.push_back({0, 0});
    VoronoiCells cells;
    if (!voronoi_cells(sites.data(), int(sites.size()), region.data(), int(region.size()), cells))
        return 0;
    const int rm = int(region.size());
    FUZZ_REQUIRE(cells.cell_count() == int(sites.size()));
    double mag = 0.0;
    for (const Vec2d& r : region) mag = std::max({mag, std::fabs(r.x), std::fabs(r.y)});
    const double slack = 8.0 * mag * 2.220446049250313e-16;
    double allowed = 0.0, area = 0.0;
    for (int i = 0; i < rm; ++i) allowed += slack * length(region[(i + 1) % rm] - region[i]);
    for (int c = 0; c < cells.cell_count(); ++c) {
        int k;
        const Vec2d* v = cells.cell(c, &k);
        FUZZ_REQUIRE(k == 0 || k >= 3);
        for (int j = 0; j < k; ++j) {
            FUZZ_REQUIRE(is_finite(v[j]));
            allowed += slack * length(v[(j + 1) % k] - v[j]);
        }
        if (k) area += fan_area(v, k);
    }
    const double want = fan_area(region.data(), rm);
    FUZZ_REQUIRE(want > 0.0);
    FUZZ_REQUIRE(std::fabs(area - want) <= allowed + 1e-12 * want);
    return 0;
}
