// fuzz/fuzz_delaunay.cpp — build_delaunay on any points and any box to cover. Contract: a
// non-ok Status, or counter-clockwise triangles (exact orient2d > 0) with consistent
// neighbours, every input point in some triangle (or a duplicate), and no point strictly
// inside any triangle's circumcircle (exact incircle).
#include <vector>

#include "fuzz_input.hpp"
#include "shitsukan/geom/delaunay.hpp"
#include "shitsukan/geom/predicates.hpp"

using namespace shitsukan;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    const bool cover = in.take<std::uint8_t>() & 1;
    Vec2d lo{in.coordinate(), in.coordinate()}, hi{in.coordinate(), in.coordinate()};
    std::vector<Vec2d> pts;
    while (in.left() >= 2 && pts.size() < 64) pts.push_back({in.coordinate(), in.coordinate()});
    if (pts.empty()) return 0;
    DelaunayTriangulation dt;
    Status s = cover ? build_delaunay(pts.data(), int(pts.size()), dt, lo, hi)
                     : build_delaunay(pts.data(), int(pts.size()), dt);
    if (!s) return 0;
    const int n = int(pts.size());
    const int tc = int(dt.triangles.size());
    for (int t = 0; t < tc; ++t) {
        const DelaunayTriangle& tri = dt.triangles[std::size_t(t)];
        const Vec2d a = dt.points[std::size_t(tri.v[0])], b = dt.points[std::size_t(tri.v[1])],
                    c = dt.points[std::size_t(tri.v[2])];
        FUZZ_REQUIRE(orient2d(a, b, c) > 0.0);
        for (int i = 0; i < 3; ++i) {
            const int nb = tri.n[i];
            if (nb < 0) continue;
            FUZZ_REQUIRE(nb < tc);
            bool back = false;
            for (int j = 0; j < 3; ++j) back = back || dt.triangles[std::size_t(nb)].n[j] == t;
            FUZZ_REQUIRE(back);
        }
        for (int p = 0; p < n; ++p)
            if (dt.duplicate_of[std::size_t(p)] < 0)
                FUZZ_REQUIRE(incircle(a, b, c, pts[std::size_t(p)]) <= 0.0);
    }
    for (int p = 0; p < n; ++p)
        FUZZ_REQUIRE((dt.point_triangle[std::size_t(p)] >= 0) ==
                     (dt.duplicate_of[std::size_t(p)] < 0));
    return 0;
}
