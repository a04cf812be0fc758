// Tests for lib/shitsukan/geom/{voronoi,delaunay,polygon,double_double} under hostile input:
// each defect class found by probing is a named regression case, and a seeded stress over
// sites an ulp apart, far sites, thin and tiny regions and lattices checks that an ok result
// is always a tiling of the region.
#include <doctest/doctest.h>
#include "measured.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "shitsukan/core/prng.hpp"
#include "shitsukan/geom/delaunay.hpp"
#include "shitsukan/geom/double_double.hpp"
#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/geom/predicates.hpp"
#include "shitsukan/geom/voronoi.hpp"

using namespace shitsukan;

namespace {

const Vec2d kSquare[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

struct TilingCheck {
    bool finite = true;
    bool convex = true;  // every cell turns left (or straight) at every vertex
    double area = 0.0;   // sum of the cells' areas
    double allowed = 0.0;  // what rounding the vertices to doubles may change in that sum
};

// The cells of an ok result must tile the region: finite, convex, and their areas must add up
// to the region's up to the rounding of the vertices (8 ulps of the region's largest
// coordinate along every edge). A missing or doubled piece of the region breaks it at once.
TilingCheck check_tiling(const VoronoiCells& cells, const Vec2d* region, int m) {
    TilingCheck r;
    double mag = 0.0;
    for (int i = 0; i < m; ++i) mag = std::max({mag, std::fabs(region[i].x), std::fabs(region[i].y)});
    const double slack = 8.0 * mag * 2.220446049250313e-16;
    for (int i = 0; i < m; ++i) r.allowed += slack * length(region[(i + 1) % m] - region[i]);
    for (int c = 0; c < cells.cell_count(); ++c) {
        int k;
        const Vec2d* v = cells.cell(c, &k);
        for (int j = 0; j < k; ++j) {
            r.finite = r.finite && is_finite(v[j]);
            r.allowed += slack * length(v[(j + 1) % k] - v[j]);
            const Vec2d a = v[j], b = v[(j + 1) % k], d = v[(j + 2) % k];
            if (cross(b - a, d - b) < -slack * (length(b - a) + length(d - b))) r.convex = false;
        }
        if (k) r.area += polygon_area(v, k);
    }
    return r;
}

void require_tiling(const Vec2d* sites, int n, const Vec2d* region, int m) {
    VoronoiCells cells;
    REQUIRE(voronoi_cells(sites, n, region, m, cells).ok());
    TilingCheck t = check_tiling(cells, region, m);
    CHECK(t.finite);
    CHECK(t.convex);
    const double want = polygon_area(region, m);
    CHECK(std::fabs(t.area - want) <= t.allowed + 1e-12 * want);
}

}  // namespace

TEST_CASE("voronoi robust: two sites one ulp apart give finite cells that tile the square") {
    const double h = std::nextafter(0.5, 1.0);
    const Vec2d cases[3][2] = {{{0.5, 0.5}, {h, 0.5}},     // along x
                               {{0.5, 0.5}, {0.5, h}},     // along y: used to cover 50 %
                               {{0.3, 0.5}, {std::nextafter(0.3, 1.0), h}}};  // diagonal: 0 %
    for (const auto& s : cases) require_tiling(s, 2, kSquare, 4);
    // the circumcentre of the frame corner and two sites an ulp apart: a NaN in doubles
    const Vec2d three[3] = {{0.5, 0.5}, {0.5, h}, {0.25, 0.75}};
    require_tiling(three, 3, kSquare, 4);
}

TEST_CASE("voronoi robust: a site far away owns all of a small region") {
    Vec2d hex[6];
    for (int i = 0; i < 6; ++i)
        hex[i] = {std::cos(i * 3.141592653589793 / 3), std::sin(i * 3.141592653589793 / 3)};
    for (Vec2d far : {Vec2d{1e8, 0}, Vec2d{1e8, 3e7}, Vec2d{-4e9, 1e9}}) {
        VoronoiCells cells;
        REQUIRE(voronoi_cells(&far, 1, hex, 6, cells).ok());
        int k;
        const Vec2d* v = cells.cell(0, &k);
        REQUIRE(k >= 6);  // it used to be empty, or 1.6 times the hexagon
        CHECK(polygon_area(v, k) == doctest::Approx(polygon_area(hex, 6)).epsilon(1e-14));
    }
    const Vec2d two[2] = {{1e8, 3e7}, {-1e8, 2}};
    require_tiling(two, 2, hex, 6);
}

TEST_CASE("voronoi robust: a small slanted triangle among far sites is tiled, not 1.09 times") {
    const Vec2d tri[3] = {{0, 0}, {1e-3, 1e-4}, {2e-4, 1e-3}};
    const Vec2d sites[3] = {{1e5, 1}, {-3e4, 7e4}, {5, -1e5}};
    require_tiling(sites, 3, tri, 3);
}

TEST_CASE("voronoi robust: a region 1e-13 thin keeps its cells (they used to be snapped away)") {
    const Vec2d thin[4] = {{0, 0}, {1, 0}, {1, 1e-13}, {0, 1e-13}};
    const Vec2d sites[3] = {{0.2, 0}, {0.5, 0}, {0.9, 0}};
    require_tiling(sites, 3, thin, 4);
    VoronoiCells cells;
    REQUIRE(voronoi_cells(sites, 3, thin, 4, cells).ok());
    for (int i = 0; i < 3; ++i) {
        int k;
        cells.cell(i, &k);
        CHECK(k == 4);
    }
}

TEST_CASE("delaunay robust: tiny cover boxes and point sets narrower than an ulp do not abort") {
    // a cover box below the coordinate range used to hit the insertion assertion
    const Vec2d origin{0, 0};
    DelaunayTriangulation dt;
    CHECK(build_delaunay(&origin, 1, dt, {0, 0}, {1e-81, 1e-81}).ok());
    CHECK(build_delaunay(&origin, 1, dt, {-1e-81, -1e-90}, {1e-81, 0}).ok());
    // two points 1e-17 apart at y = 0.5: the frame used to round onto the data
    const Vec2d narrow[2] = {{0, 0.5}, {1e-17, 0.5}};
    CHECK(build_delaunay(narrow, 2, dt).ok());
    require_tiling(narrow, 2, kSquare, 4);
    const Vec2d column[3] = {{0.5, 0.25}, {std::nextafter(0.5, 1.0), 0.5}, {0.5, 0.75}};
    CHECK(build_delaunay(column, 3, dt).ok());
    require_tiling(column, 3, kSquare, 4);
    // a region below the predicates' range is refused with a Status, not clipped wrongly
    const Vec2d tiny[4] = {{0, 0}, {1e-81, 0}, {1e-81, 1e-81}, {0, 1e-81}};
    VoronoiCells cells;
    Status s = voronoi_cells(&origin, 1, tiny, 4, cells);
    CHECK_FALSE(s.ok());
    CHECK(std::string(s.message()).find("1e-81") != std::string::npos);
}

TEST_CASE("check_convex_region: exact, refuses collinear, doubly wound and reflex outlines") {
    const Vec2d collinear[4] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};
    CHECK_FALSE(check_convex_region(collinear, 4).ok());
    const Vec2d twice[6] = {{0, 0}, {1, 0}, {0, 1}, {0, 0}, {1, 0}, {0, 1}};
    CHECK_FALSE(check_convex_region(twice, 6).ok());
    const Vec2d star[5] = {{1, 0}, {-0.809, 0.588}, {0.309, -0.951}, {0.309, 0.951},
                           {-0.809, -0.588}};  // pentagram: turns left everywhere, winds twice
    CHECK_FALSE(check_convex_region(star, 5).ok());
    const Vec2d repeated[5] = {{0, 0}, {1, 0}, {1, 1}, {1, 0}, {0, 1}};  // goes back along an edge
    CHECK_FALSE(check_convex_region(repeated, 5).ok());
    const Vec2d same[5] = {{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}};
    CHECK_FALSE(check_convex_region(same, 5).ok());
    const Vec2d spike[5] = {{0, 0}, {2, 0}, {1, 0}, {1, 1}, {0, 1}};
    CHECK_FALSE(check_convex_region(spike, 5).ok());
    // still accepted: a square with a straight-on vertex, far from the origin, tiny
    const Vec2d mid[5] = {{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}};
    CHECK(check_convex_region(mid, 5).ok());
    const Vec2d far[3] = {{1e17, 1e17}, {1e17 + 16, 1e17}, {1e17, 1e17 + 16}};
    CHECK(check_convex_region(far, 3).ok());
    CHECK(check_convex_region(kSquare, 4).ok());
}

TEST_CASE("polygon_area: relative to the first vertex, right far from the origin") {
    const Vec2d far[3] = {{1e17, 1e17}, {1e17 + 16, 1e17}, {1e17, 1e17 + 16}};
    CHECK(polygon_area(far, 3) == 128.0);  // was 0 or negative: x * y products cancel
    const Vec2d shifted[4] = {{1e9, 1e9}, {1e9 + 1, 1e9}, {1e9 + 1, 1e9 + 1}, {1e9, 1e9 + 1}};
    CHECK(polygon_area(shifted, 4) == 1.0);
}

TEST_CASE("double-double: the circumcentre determinant of sites an ulp apart is not 0") {
    // b - a and c - a for a = frame corner (-4.5, 5.5), b = (0.5, 0.5), c = (0.5, 0.5 + ulp):
    // bx * cy - by * cx rounds to 0 in doubles
    const double u = std::nextafter(0.5, 1.0) - 0.5;
    const DoubleDouble bx = dd_diff(0.5, -4.5), by = dd_diff(0.5, 5.5);
    const DoubleDouble cx = dd_diff(0.5, -4.5), cy = dd_diff(0.5 + u, 5.5);
    const double plain = 5.0 * (0.5 + u - 5.5) - (-5.0) * 5.0;
    CHECK(plain == 0.0);
    const DoubleDouble d = dd_sub(dd_mul(bx, cy), dd_mul(by, cx));
    CHECK(dd_round(d) == 5.0 * u);
    CHECK(dd_round(dd_div(dd_from(1.0), dd_from(3.0))) == 1.0 / 3.0);
}

TEST_CASE("voronoi robust: seeded stress, every ok result tiles its region") {
    // sites an ulp apart, one site 1e8 regions away, near-collinear rows, exact lattices; on
    // regions from 1e-10 to 1e10 wide, up to 1e10 from the origin, aspect down to 1e-10
    Pcg32 rng(17, 5);
    int checked = 0;
    for (int it = 0; it < 3000; ++it) {
        const int kind = it % 5;
        const double scale = std::pow(10.0, -10 + 20 * rng.uniform_double());
        const double off = rng.uniform_double() < 0.5 ? 0.0 : std::pow(10.0, -5 + 15 * rng.uniform_double());
        const double aspect = rng.uniform_double() < 0.3 ? std::pow(10.0, -10 * rng.uniform_double()) : 1.0;
        const int m = 3 + int(rng.uniform_double() * 5);
        std::vector<Vec2d> region;
        for (int i = 0; i < m; ++i) {
            double a = 6.283185307179586 * i / m + 0.3 * rng.uniform_double() / m;
            region.push_back({off + scale * std::cos(a), off + scale * aspect * std::sin(a)});
        }
        if (!check_convex_region(region.data(), m)) continue;
        const int n = 1 + int(rng.uniform_double() * 30);
        std::vector<Vec2d> sites;
        for (int i = 0; i < n; ++i) {
            Vec2d p{off + scale * (2 * rng.uniform_double() - 1),
                    off + scale * aspect * (2 * rng.uniform_double() - 1)};
            if (kind == 1 && i > 0) {  // an ulp or three from an earlier site
                p = sites[rng.next_u32() % sites.size()];
                for (unsigned j = 0; j <= rng.next_u32() % 3; ++j)
                    p.x = std::nextafter(p.x, (rng.next_u32() & 1) ? 1e300 : -1e300);
                if (rng.next_u32() & 1) p.y = std::nextafter(p.y, 1e300);
            }
            if (kind == 2 && i == 0)
                p = {off + scale * 1e8 * (2 * rng.uniform_double() - 1),
                     off + scale * 1e8 * (2 * rng.uniform_double() - 1)};
            if (kind == 3)  // nearly collinear
                p.y = off + scale * aspect * 0.3 + (p.x - off) * 1e-3 +
                      ((rng.next_u32() & 1) ? 0.0 : scale * 1e-15);
            if (kind == 4) {  // exact lattice points
                const double D = scale / 4;
                p = {off + D * std::floor(8 * rng.uniform_double() - 4),
                     off + D * std::floor(8 * rng.uniform_double() - 4)};
            }
            sites.push_back(p);
        }
        VoronoiCells cells;
        if (!voronoi_cells(sites.data(), n, region.data(), m, cells)) continue;
        ++checked;
        TilingCheck t = check_tiling(cells, region.data(), m);
        const double want = polygon_area(region.data(), m);
        INFO("case " << it << " kind " << kind << " scale " << scale << " offset " << off);
        REQUIRE(t.finite);
        REQUIRE(std::fabs(t.area - want) <= t.allowed + 1e-12 * want);
    }
    MEASURED("voronoi stress: " << checked << " ok results, every one a tiling");
    CHECK(checked > 2000);
}

TEST_CASE("fuzz finding: sites 2e-40 apart seen from 5 away are refused, not a NaN vertex") {
    // The double-double determinant loses the 2e-40 difference next to terms of size 30; the
    // clip points of such a bisector fall back to interpolation. Before: a NaN vertex and
    // cells covering 6.5 times the square with an ok Status.
    const Vec2d sites[4] = {{0.5, 1e-40}, {0.5, 3e-40}, {0.5, 0.1}, {0.5, -0.1}};
    VoronoiCells cells;
    Status s = voronoi_cells(sites, 4, kSquare, 4, cells);
    CHECK(s.code() == StatusCode::degenerate);
    CHECK(std::string(s.message()).find("cannot be constructed") != std::string::npos);
    // the same rows 1e-12 apart are constructed and tile the square
    const Vec2d near[4] = {{0.5, 1e-12}, {0.5, 3e-12}, {0.5, 0.1}, {0.5, -0.1}};
    require_tiling(near, 4, kSquare, 4);
}

TEST_CASE("fuzz finding: a triangle reaching 1e34 (area 0.4): exact checks, no wrong cells") {
    const Vec2d tri[3] = {{1.0507238912670181e+34, 0.0250244140625}, {-31.625, 0}, {0, 0}};
    CHECK(check_convex_region(tri, 3).ok());  // exact: counter-clockwise, area > 0
    CHECK(polygon_area(tri, 3) == 0.0);       // the documented limit of double shoelace areas
    CHECK(orient2d_exact(tri[0], tri[1], tri[2]) > 0.0);
    // sites 10 apart next to frame points 5e34 away: refused by name, or cells with area
    const Vec2d sites[2] = {{0, 0}, {-10, 0.01}};
    VoronoiCells cells;
    Status s = voronoi_cells(sites, 2, tri, 3, cells);
    if (!s.ok()) {
        CHECK(s.code() == StatusCode::degenerate);
        return;
    }
    double twice = 0.0;
    for (int c = 0; c < 2; ++c) {
        int k;
        const Vec2d* v = cells.cell(c, &k);
        for (int i = 1; i + 1 < k; ++i) twice += orient2d_exact(v[0], v[i], v[i + 1]);
    }
    CHECK(twice > 0.0);
}

TEST_CASE("fuzz finding: a site 2.3e48 away and one at 25600 from a unit hexagon") {
    // The bisector meets the hexagon's edge lines ~1e48 away; its construction was judged
    // against the hexagon's size instead of the point's, fell back to interpolating between
    // vertices 1e49 apart, and gave the far site a clockwise cell of area -6e15.
    Vec2d hex[6];
    for (int i = 0; i < 6; ++i)
        hex[i] = {std::cos(i * 3.141592653589793 / 3), std::sin(i * 3.141592653589793 / 3)};
    const Vec2d sites[2] = {{2.3346204133704415e+48, 24624}, {-25600, 0.5078125}};
    VoronoiCells cells;
    REQUIRE(voronoi_cells(sites, 2, hex, 6, cells).ok());
    int k0, k1;
    cells.cell(0, &k0);
    const Vec2d* v1 = cells.cell(1, &k1);
    CHECK(k0 == 0);
    REQUIRE(k1 == 6);
    CHECK(polygon_area(v1, k1) == doctest::Approx(polygon_area(hex, 6)).epsilon(1e-15));
}

TEST_CASE("fuzz finding 8: a far site's cell is not invented between nearly parallel edges") {
    // A hexagon whose opposite edges 0 and 3 are parallel only up to 1e-16 (their lines meet
    // 3.7e16 away) and sites 2.3e48 and 25600 away. The far site's cell (x > 1.17e48) reached
    // the hexagon's edge lines at points 1e48 out, rounded by ~1e32: a point constructed on
    // edge 0's line then fell on the wrong side of edge 3's line, 1.7 away, and the clip
    // joined the two lines at their meeting point: a cell of area -3e16 with an ok Status.
    // Cells reaching beyond a guard box around the region are now clipped to it first.
    const Vec2d hex[6] = {{0x1p+0, 0x0p+0},
                          {0x1.0000000000001p-1, 0x1.bb67ae8584caap-1},
                          {-0x1.ffffffffffffcp-2, 0x1.bb67ae8584cabp-1},
                          {-0x1p+0, 0x1.1a62632145c07p-53},
                          {-0x1.0000000000002p-1, -0x1.bb67ae8584ca8p-1},
                          {0x1.0000000000001p-1, -0x1.bb67ae8584c96p-1}};
    const Vec2d sites[2] = {{0x1.98f00000141p+160, 0x1.80cp+14}, {-0x1.9p+14, 0x1.04p-1}};
    REQUIRE(check_convex_region(hex, 6).ok());
    VoronoiCells cells;
    REQUIRE(voronoi_cells(sites, 2, hex, 6, cells).ok());
    int k0, k1;
    cells.cell(0, &k0);
    const Vec2d* v1 = cells.cell(1, &k1);
    CHECK(k0 == 0);  // before: 4 vertices, one at (-1.9e16, 3.2e16)
    REQUIRE(k1 == 6);
    for (int i = 0; i < 6; ++i) CHECK(v1[i] == hex[(i + 3) % 6]);  // from the smallest vertex
    require_tiling(sites, 2, hex, 6);
    // the same far cell seen through the public clip: nothing of it is in the hexagon
    std::vector<ClipVertex> poly(3), scratch;
    poly[0].p = {0x1.0p+160, -0x1.0p+163};
    poly[1].p = {0x1.0p+163, 0.0};
    poly[2].p = {0x1.0p+160, 0x1.0p+163};
    clip_to_convex_region(&poly, hex, 6, &scratch);
    CHECK(poly.empty());
}

TEST_CASE("incircle_exact: fixed-point sum, signs consistent under swaps, rotations, scaling") {
    // incircle_exact sums 192 products of four doubles in a 2048-bit integer (the
    // expansion version needed 37.8 KB of stack). Its sign was compared with the expansion
    // version on 2.8 million inputs (0 differences, 435,040 exact zeros) when it was written;
    // here: properties that any exact sign has, on inputs whose differences are inexact
    // (magnitudes 1e-40 .. 1e40 mixed), and exact zeros of scaled cocircular points.
    Pcg32 rng(12, 5);
    int checked = 0;
    for (int it = 0; it < 20000; ++it) {
        Vec2d v[4];
        for (Vec2d& p : v) {
            const double big = std::ldexp(1.0, int(rng.uniform_double() * 200) - 100);
            p = {(rng.uniform_double() - 0.5) * big, (rng.uniform_double() - 0.5) * big};
        }
        if (it % 2) v[3] = v[0] + Vec2d{std::ldexp(v[0].x, -60), 0.0};  // nearly on the circle
        const double s = incircle_exact(v[0], v[1], v[2], v[3]);
        const double swapped = incircle_exact(v[1], v[0], v[2], v[3]);
        const double rotated = incircle_exact(v[1], v[2], v[0], v[3]);
        const double scaled = incircle_exact(v[0] * 0x1p-40, v[1] * 0x1p-40, v[2] * 0x1p-40,
                                             v[3] * 0x1p-40);
        CHECK((s > 0) == (swapped < 0));
        CHECK((s < 0) == (swapped > 0));
        CHECK((s > 0) == (rotated > 0));
        CHECK((s < 0) == (rotated < 0));
        CHECK((s > 0) == (scaled > 0));
        CHECK((s < 0) == (scaled < 0));
        ++checked;
    }
    CHECK(checked == 20000);
    // (3, 4), (5, 0), (0, 5), (-4, 3) on the circle of radius 5, scaled by 2^-130 and 2^130
    for (double k : {0x1p-130, 1.0, 0x1p130}) {
        const Vec2d a{3 * k, 4 * k}, b{-4 * k, 3 * k}, c{0, -5 * k}, d{5 * k, 0};
        CHECK(incircle_exact(a, b, c, d) == 0.0);
        CHECK(incircle_exact(a, b, c, Vec2d{4.5 * k, 0}) > 0.0);
        CHECK(incircle_exact(a, b, c, Vec2d{std::nextafter(5 * k, 10 * k), 0}) < 0.0);
    }
}

// A Voronoi vertex within the snap distance of a slanted region edge is moved onto that edge's
// line (polygon.cpp, classify_vertices): across the line, along its normal. Moving it along the
// edge instead left it where it was, labelled as on the line, and the sliver between it and the
// line belonged to no cell (fuzz_voronoi: the cells' areas 6.1e-13 short of the region's).
TEST_CASE("voronoi robust: a vertex snapped onto a slanted edge is moved onto its line") {
    const Vec2d tri[3] = {{0, 0}, {1, 0}, {0, 1}};
    const double snap = kClipSnapRelative * std::sqrt(0.5);  // min(diameter, width) = width
    for (double fraction : {0.3, 0.6, 0.9}) {
        CAPTURE(fraction);
        const double t = fraction * snap;  // the vertex's distance inside the hypotenuse
        const Vec2d c = {0.5 - t / std::sqrt(2.0), 0.5 - t / std::sqrt(2.0)};
        Vec2d sites[3];
        const double angles[3] = {3.141592653589793, 1.25 * 3.141592653589793,
                                  1.5 * 3.141592653589793};
        for (int i = 0; i < 3; ++i)
            sites[i] = {c.x + 0.2 * std::cos(angles[i]), c.y + 0.2 * std::sin(angles[i])};
        VoronoiCells cells;
        REQUIRE(voronoi_cells(sites, 3, tri, 3, cells).ok());
        double area = 0.0, worst_outside = 0.0;
        for (int i = 0; i < cells.cell_count(); ++i) {
            int k;
            const Vec2d* v = cells.cell(i, &k);
            area += polygon_area(v, k);
            for (int j = 0; j < k; ++j)  // beyond x + y = 1 (an ulp or two of rounding)
                worst_outside = std::max(worst_outside, v[j].x + v[j].y - 1.0);
        }
        CHECK(std::fabs(area - 0.5) <= 1e-15);  // the sliver was t·0.2 = 1.3e-13 .. 3.9e-13
        CHECK(worst_outside <= 4e-16);
    }
}

// fuzz_voronoi, after the snap above was first written: a quadrilateral whose corner (0, 96)
// turns by 5e-18 degrees. Its two edges there lie within the snap distance of each other along
// their whole length, so a vertex snapped onto one is "near" the other too; moving such a vertex
// to the corner (as tried) moved it by up to 1440 units and the cells covered 2.5 times the
// region. Vertices are only projected, never sent to a corner.
TEST_CASE("voronoi robust: a corner of 180 - 5e-18 degrees: the cells still tile the region") {
    const Vec2d region[4] = {{7.1055358092511153e-15, 1536}, {0, 96}, {0, 0},
                             {1.9822998046875, 252.984375}};
    const Vec2d sites[3] = {{252.984375, 252.984375}, {252.984375, 252.984375}, {0, 0}};
    require_tiling(sites, 3, region, 4);
}
