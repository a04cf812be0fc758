// Tests for lib/shitsukan/geom/{predicates,delaunay,voronoi,polygon}: exact predicates, the
// nearest-site property, exact lattice cells, the stated degenerate cases, bad input.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shitsukan/core/prng.hpp"
#include "shitsukan/geom/delaunay.hpp"
#include "shitsukan/geom/double_double.hpp"
#include "shitsukan/geom/planar_subdivision.hpp"
#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/geom/predicates.hpp"
#include "shitsukan/geom/voronoi.hpp"

using namespace shitsukan;

namespace {

const Vec2d kSquare[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

std::vector<Vec2d> random_sites(int n, std::uint64_t seed) {
    Pcg32 rng(seed, 7);
    std::vector<Vec2d> s(static_cast<std::size_t>(n));
    for (auto& p : s) p = {rng.uniform_double(), rng.uniform_double()};
    return s;
}

// Every sample of cell i is at least as near to site i as to any other site (1e-12 slack).
void check_nearest_site(const std::vector<Vec2d>& sites, const VoronoiCells& cells,
                        int samples_per_cell) {
    Pcg32 rng(99, 3);
    for (int i = 0; i < cells.cell_count(); ++i) {
        int k;
        const Vec2d* v = cells.cell(i, &k);
        if (k == 0) continue;
        Vec2d lo = v[0], hi = v[0];
        for (int j = 0; j < k; ++j) {
            lo = {std::min(lo.x, v[j].x), std::min(lo.y, v[j].y)};
            hi = {std::max(hi.x, v[j].x), std::max(hi.y, v[j].y)};
        }
        int tested = 0;
        for (int tries = 0; tested < samples_per_cell && tries < 50 * samples_per_cell; ++tries) {
            Vec2d q{lo.x + (hi.x - lo.x) * rng.uniform_double(),
                    lo.y + (hi.y - lo.y) * rng.uniform_double()};
            if (!point_in_polygon(v, k, q)) continue;
            ++tested;
            double own = length_squared(q - sites[std::size_t(i)]);
            for (const Vec2d& s : sites) REQUIRE(own <= length_squared(q - s) + 1e-12);
        }
    }
}

double total_area(const VoronoiCells& cells) {
    double a = 0;
    for (int i = 0; i < cells.cell_count(); ++i) {
        int k;
        const Vec2d* v = cells.cell(i, &k);
        if (k) a += polygon_area(v, k);
    }
    return a;
}

}  // namespace

TEST_CASE("predicates: exact signs where the floating-point value is wrong") {
    // Shewchuk's classic: points nearly on the line y = x, perturbed by one ulp.
    Vec2d a{0.5, 0.5}, b{12, 12}, c{24, 24};
    CHECK(orient2d(a, b, c) == 0.0);
    Vec2d d{0.5 + std::ldexp(1.0, -53), 0.5};
    CHECK(orient2d(d, b, c) < 0.0);  // d is one ulp below the line: d, b, c turn clockwise
    CHECK(orient2d(d, b, c) == orient2d_exact(d, b, c));
    // four cocircular lattice points and a point one ulp off the circle
    Vec2d p{0.1, 0.1}, q{0.2, 0.1}, r{0.2, 0.2}, s{0.1, 0.2};
    CHECK(incircle(p, q, r, s) == 0.0);
    CHECK(incircle_exact(p, q, r, s) == 0.0);
    CHECK(incircle(p, q, r, Vec2d{0.1, std::nextafter(0.2, 0.0)}) > 0.0);
    CHECK(incircle(p, q, r, Vec2d{0.1, std::nextafter(0.2, 1.0)}) < 0.0);
    // random agreement of filter and exact path
    Pcg32 rng(5, 5);
    for (int i = 0; i < 2000; ++i) {
        Vec2d v[4];
        for (auto& x : v) x = {rng.uniform_double(), rng.uniform_double()};
        CHECK((orient2d(v[0], v[1], v[2]) > 0) == (orient2d_exact(v[0], v[1], v[2]) > 0));
        double f = incircle(v[0], v[1], v[2], v[3]), e = incircle_exact(v[0], v[1], v[2], v[3]);
        CHECK((f > 0) == (e > 0));
        CHECK((f < 0) == (e < 0));
    }
}

TEST_CASE("predicates: in-circle on a rounded lattice, every stage against the exact sum") {
    // Sites (i + 0.5) / side rounded to doubles: four of them on one lattice circle are off
    // it by ~1e-16 of the determinant's size (the double-double stage decides those), some are
    // exactly on it (the expansions decide), axis-parallel rectangles are 0 by comparisons.
    // The sign must be the exact one for every quadruple (the double-double stage).
    const int side = 100;
    auto p = [&](int i, int j) { return Vec2d{(i + 0.5) / side, (j + 0.5) / side}; };
    Pcg32 rng(18, 4);
    int zero = 0, near_zero = 0;
    for (int k = 0; k < 20000; ++k) {
        const int i = int(rng.uniform_int(90)), j = int(rng.uniform_int(90));
        Vec2d v[4];
        for (Vec2d& q : v) q = p(i + int(rng.uniform_int(6)), j + int(rng.uniform_int(6)));
        if (orient2d(v[0], v[1], v[2]) <= 0.0) continue;  // a counter-clockwise triangle
        const double f = incircle(v[0], v[1], v[2], v[3]);
        const double e = incircle_exact(v[0], v[1], v[2], v[3]);
        REQUIRE((f > 0) == (e > 0));
        REQUIRE((f < 0) == (e < 0));
        zero += e == 0.0;
        near_zero += e != 0.0 && std::fabs(e) < 1e-20;
    }
    CHECK(zero > 100);  // the cases exist: exactly cocircular ...
    CHECK(near_zero > 100);  // ... and cocircular on the lattice but not in doubles
}

TEST_CASE("predicates: in-circle with inexact coordinate differences, against the exact sum") {
    // Near the origin of a rounded lattice ((i + 0.5) / side, i < 40) the sites differ in
    // magnitude (0.005 against 0.035): their differences are not exact in doubles, and the
    // double-double stage for inexact differences decides the quadruples that lie on one
    // circle of the lattice (off it by rounding only; before, the fixed-point sum alone
    // decided them). Every sign must be the exact one, also with a coordinate one ulp off.
    const int side = 100;
    auto p = [&](int i, int j) { return Vec2d{(i + 0.5) / side, (j + 0.5) / side}; };
    Pcg32 rng(18, 6);
    int inexact = 0, near_zero = 0, zero = 0;
    for (int k = 0; k < 4000; ++k) {
        // the lattice points on the circle through a random one, about a random centre (in
        // doubled coordinates 2i + 1, where the squared radii are integers)
        const int ai = int(rng.uniform_int(40)), aj = int(rng.uniform_int(40));
        const int cx = int(rng.uniform_int(80)), cy = int(rng.uniform_int(80));
        auto r2 = [&](int i, int j) {
            return (2 * i + 1 - cx) * (2 * i + 1 - cx) + (2 * j + 1 - cy) * (2 * j + 1 - cy);
        };
        std::vector<Vec2d> on;
        for (int i = 0; i < 40; ++i)
            for (int j = 0; j < 40; ++j)
                if (r2(i, j) == r2(ai, aj) && (i != ai || j != aj)) on.push_back(p(i, j));
        if (on.size() < 3) continue;
        Vec2d v[4] = {p(ai, aj), on[0], on[on.size() / 2], on.back()};
        if (v[1] == v[2] || v[2] == v[3]) continue;
        std::swap(v[int(rng.uniform_int(4))], v[3]);
        if (k % 2) v[3].x = std::nextafter(v[3].x, 1.0);
        const double f = incircle_unfiltered(v[0], v[1], v[2], v[3]);
        const double e = incircle_exact(v[0], v[1], v[2], v[3]);
        REQUIRE((f > 0) == (e > 0));
        REQUIRE((f < 0) == (e < 0));
        bool exact = true;
        for (int m = 0; m < 3; ++m)
            exact = exact && dd_diff(v[m].x, v[3].x).lo == 0.0 && dd_diff(v[m].y, v[3].y).lo == 0.0;
        inexact += !exact;
        near_zero += !exact && e != 0.0;
        zero += !exact && e == 0.0;
    }
    CHECK(inexact > 1000);    // the differences really are inexact ...
    CHECK(near_zero > 1000);  // ... on quadruples the filter cannot decide
    CHECK(zero > 20);         // and some are exactly cocircular even so
}

TEST_CASE("predicates: mirrored chords of a rounded lattice are 0, one ulp off them is not") {
    // Isosceles trapezoids whose axis is horizontal, vertical or diagonal (incircle_unfiltered
    // proves these 0 by exact sums): every one is checked against the exact sum, and so is
    // the same set with one coordinate moved one ulp (rounding can make either of the two
    // exactly cocircular: the sums decide, never the lattice's picture).
    const int side = 100;
    auto p = [&](int i, int j) { return Vec2d{(i + 0.5) / side, (j + 0.5) / side}; };
    Pcg32 rng(18, 5);
    int zeros = 0, checked = 0;
    for (int k = 0; k < 4000; ++k) {
        const int i = 10 + int(rng.uniform_int(70)), j = 10 + int(rng.uniform_int(70));
        const int s = 1 + int(rng.uniform_int(4)), t = 1 + int(rng.uniform_int(4));
        const int u = int(rng.uniform_int(4));
        Vec2d v[4];
        switch (k % 3) {
            case 0:  // vertical chords, mirrored about a horizontal line
                v[0] = p(i, j), v[1] = p(i, j + s), v[2] = p(i + t, j - u), v[3] = p(i + t, j + s + u);
                break;
            case 1:  // horizontal chords
                v[0] = p(i, j), v[1] = p(i + s, j), v[2] = p(i - u, j + t), v[3] = p(i + s + u, j + t);
                break;
            default:  // diagonal chords, mirrored about x + y = const
                v[0] = p(i, j), v[1] = p(i + s, j + s), v[2] = p(i + s + t, j - t),
                v[3] = p(i + t + s + u, j - t + u);
                if (k % 2) std::swap(v[1].x, v[1].y), std::swap(v[0].x, v[0].y);
                break;
        }
        for (int move = 0; move < 2; ++move) {
            Vec2d w[4] = {v[0], v[1], v[2], v[3]};
            if (move) w[3].y = std::nextafter(w[3].y, 2.0);
            const double e = incircle_exact(w[0], w[1], w[2], w[3]);
            const double f = incircle_unfiltered(w[0], w[1], w[2], w[3]);
            REQUIRE((f > 0) == (e > 0));
            REQUIRE((f < 0) == (e < 0));
            zeros += move == 0 && f == 0.0;
            ++checked;
        }
    }
    CHECK(zeros > 1000);  // most of the unmoved sets are exactly cocircular in doubles
    CHECK(checked == 8000);
}

TEST_CASE("delaunay: empty circumcircles on random points") {
    auto sites = random_sites(300, 1);
    DelaunayTriangulation dt;
    REQUIRE(build_delaunay(sites.data(), int(sites.size()), dt).ok());
    for (const auto& t : dt.triangles) {
        CHECK(orient2d(dt.points[std::size_t(t.v[0])], dt.points[std::size_t(t.v[1])],
                       dt.points[std::size_t(t.v[2])]) > 0);
        for (std::size_t p = 0; p < sites.size(); ++p)
            REQUIRE(incircle(dt.points[std::size_t(t.v[0])], dt.points[std::size_t(t.v[1])],
                             dt.points[std::size_t(t.v[2])], sites[p]) <= 0.0);
    }
    CHECK(dt.triangles.size() == 2 * (sites.size() + 4) - 2 - 4);  // Euler, 4 hull points
}

TEST_CASE("voronoi: every sample is nearest to its own site, cells tile the region") {
    for (int n : {1, 2, 10, 200}) {
        auto sites = random_sites(n, std::uint64_t(n));
        VoronoiCells cells;
        REQUIRE(voronoi_cells(sites.data(), n, kSquare, 4, cells).ok());
        CHECK(total_area(cells) == doctest::Approx(1.0).epsilon(1e-12));
        check_nearest_site(sites, cells, 40);
    }
}

TEST_CASE("voronoi: a = 0 square lattice -> equal squares with exactly 4 vertices") {
    std::vector<Vec2d> sites;
    const double D = 1.0 / 7.0;
    for (int j = -1; j <= 7; ++j)
        for (int i = -1; i <= 7; ++i) sites.push_back({(i + 0.5) * D, (j + 0.5) * D});
    VoronoiCells cells;
    REQUIRE(voronoi_cells(sites.data(), int(sites.size()), kSquare, 4, cells).ok());
    int interior = 0;
    for (int c = 0; c < cells.cell_count(); ++c) {
        int k;
        const Vec2d* v = cells.cell(c, &k);
        Vec2d s = sites[std::size_t(c)];
        if (s.x < 0 || s.x > 1 || s.y < 0 || s.y > 1) {
            CHECK(k == 0);
            continue;
        }
        ++interior;
        REQUIRE(k == 4);
        CHECK(polygon_area(v, k) == doctest::Approx(D * D).epsilon(1e-12));
        for (int j = 0; j < k; ++j) CHECK(std::fabs(std::fabs(v[j].x - s.x) - D / 2) < 1e-12);
    }
    CHECK(interior == 49);
    check_nearest_site(sites, cells, 20);
}

TEST_CASE("voronoi: a = 0 triangular lattice -> equal regular hexagons with exactly 6 vertices") {
    std::vector<Vec2d> sites;
    const double D = 0.1, h = D * std::sqrt(3.0) / 2.0;
    for (int j = -2; j <= 14; ++j)
        for (int i = -2; i <= 12; ++i) sites.push_back({(i + 0.5 * (j & 1)) * D, j * h});
    VoronoiCells cells;
    REQUIRE(voronoi_cells(sites.data(), int(sites.size()), kSquare, 4, cells).ok());
    int hexagons = 0;
    const double side = D / std::sqrt(3.0);
    for (int c = 0; c < cells.cell_count(); ++c) {
        int k;
        const Vec2d* v = cells.cell(c, &k);
        Vec2d s = sites[std::size_t(c)];
        if (s.x < side || s.x > 1 - side || s.y < side || s.y > 1 - side)
            continue;  // may be clipped
        ++hexagons;
        REQUIRE(k == 6);
        CHECK(polygon_area(v, k) ==
              doctest::Approx(1.5 * std::sqrt(3.0) * side * side).epsilon(1e-12));
        for (int j = 0; j < k; ++j) CHECK(length(v[j] - s) == doctest::Approx(side).epsilon(1e-12));
    }
    CHECK(hexagons > 60);
    check_nearest_site(sites, cells, 10);
    CHECK(total_area(cells) == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("voronoi: stated degenerate cases") {
    VoronoiCells cells;
    SUBCASE("single site owns the region") {
        Vec2d s{0.3, 0.9};
        REQUIRE(voronoi_cells(&s, 1, kSquare, 4, cells).ok());
        int k;
        const Vec2d* v = cells.cell(0, &k);
        CHECK(k == 4);
        CHECK(polygon_area(v, k) == 1.0);
    }
    SUBCASE("duplicates: the first occurrence owns the cell, the copy is empty") {
        std::vector<Vec2d> s = {{0.2, 0.2}, {0.7, 0.6}, {0.2, 0.2}, {0.4, 0.9}};
        REQUIRE(voronoi_cells(s.data(), 4, kSquare, 4, cells).ok());
        int k;
        cells.cell(2, &k);
        CHECK(k == 0);
        CHECK(cells.duplicate_of[2] == 0);
        cells.cell(0, &k);
        CHECK(k >= 3);
        CHECK(total_area(cells) == doctest::Approx(1.0).epsilon(1e-12));
    }
    SUBCASE("collinear sites: parallel strips") {
        std::vector<Vec2d> s;
        for (int i = 0; i < 5; ++i) s.push_back({0.1 + 0.2 * i, 0.5});
        REQUIRE(voronoi_cells(s.data(), 5, kSquare, 4, cells).ok());
        for (int i = 0; i < 5; ++i) {
            int k;
            const Vec2d* v = cells.cell(i, &k);
            CHECK(k == 4);
            CHECK(polygon_area(v, k) == doctest::Approx(0.2).epsilon(1e-12));
        }
    }
    SUBCASE("sites on the region boundary and corners") {
        std::vector<Vec2d> s = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}, {0.5, 0.5}};
        REQUIRE(voronoi_cells(s.data(), int(s.size()), kSquare, 4, cells).ok());
        CHECK(total_area(cells) == doctest::Approx(1.0).epsilon(1e-12));
        check_nearest_site(s, cells, 50);
    }
}

TEST_CASE("voronoi: the same cells, bit for bit, whatever the input order") {
    std::vector<Vec2d> sites;
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i) sites.push_back({(i + 0.5) / 6.0, (j + 0.5) / 6.0});
    auto extra = random_sites(30, 4);
    sites.insert(sites.end(), extra.begin(), extra.end());
    VoronoiCells a, b;
    REQUIRE(voronoi_cells(sites.data(), int(sites.size()), kSquare, 4, a).ok());
    std::vector<int> perm(sites.size());
    for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = int((i * 37 + 11) % perm.size());
    std::vector<Vec2d> shuffled(sites.size());
    for (std::size_t i = 0; i < perm.size(); ++i) shuffled[i] = sites[std::size_t(perm[i])];
    REQUIRE(voronoi_cells(shuffled.data(), int(shuffled.size()), kSquare, 4, b).ok());
    for (std::size_t i = 0; i < perm.size(); ++i) {
        int ka, kb;
        const Vec2d* va = a.cell(perm[i], &ka);
        const Vec2d* vb = b.cell(int(i), &kb);
        REQUIRE(ka == kb);
        for (int j = 0; j < ka; ++j) CHECK(va[j] == vb[j]);
    }
}

TEST_CASE("voronoi: bad input gives a status, not a crash") {
    VoronoiCells cells;
    Vec2d s{0.5, 0.5};
    CHECK(voronoi_cells(&s, 0, kSquare, 4, cells).code() == StatusCode::invalid_argument);
    Vec2d nan_site{std::nan(""), 0.5};
    CHECK(!voronoi_cells(&nan_site, 1, kSquare, 4, cells).ok());
    const Vec2d flat[4] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};
    CHECK(!voronoi_cells(&s, 1, flat, 4, cells).ok());
    const Vec2d clockwise[4] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    CHECK(!voronoi_cells(&s, 1, clockwise, 4, cells).ok());
    CHECK(!voronoi_cells(&s, 1, kSquare, 2, cells).ok());
}

TEST_CASE(
    "voronoi: degenerate stress (lattice, duplicates, lines) still gives shared-edge tilings") {
    std::vector<Vec2d> sites;
    for (int j = 0; j <= 20; ++j)
        for (int i = 0; i <= 20; ++i) sites.push_back({i / 20.0, j / 20.0});  // on the border too
    for (int i = 0; i < 50; ++i) sites.push_back(sites[std::size_t(i * 7)]);  // duplicates
    for (int i = 0; i < 30; ++i) sites.push_back({0.013 + i * 0.031, 0.5});   // a line of seeds
    auto extra = random_sites(100, 8);
    sites.insert(sites.end(), extra.begin(), extra.end());
    VoronoiCells cells;
    REQUIRE(voronoi_cells(sites.data(), int(sites.size()), kSquare, 4, cells).ok());
    CHECK(total_area(cells) == doctest::Approx(1.0).epsilon(1e-12));
    check_nearest_site(sites, cells, 5);
    // the cells share their edges vertex for vertex: they form one planar subdivision
    std::vector<Vec2d> verts;
    std::vector<int> offsets(1, 0);
    for (int i = 0; i < cells.cell_count(); ++i) {
        int k;
        const Vec2d* v = cells.cell(i, &k);
        if (k < 3 || !(polygon_area(v, k) > 0)) continue;
        verts.insert(verts.end(), v, v + k);
        offsets.push_back(int(verts.size()));
    }
    PlanarSubdivision sub;
    REQUIRE(
        build_planar_subdivision(verts.data(), offsets.data(), int(offsets.size()) - 1, sub).ok());
    CHECK(outer_edges_on_box(sub, {0, 0}, {1, 1}));
    int interior = 0;
    for (const auto& e : sub.edges) interior += e.right >= 0;
    CHECK(interior > 0);
    // Euler's formula for a connected planar subdivision of a disc: V - E + F = 1
    CHECK(int(sub.vertices.size()) - int(sub.edges.size()) + sub.face_count() == 1);
}

TEST_CASE("planar subdivision: overlaps and T junctions are reported") {
    // two squares on top of each other
    std::vector<Vec2d> v = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<int> off = {0, 4, 8};
    PlanarSubdivision sub;
    CHECK(!build_planar_subdivision(v.data(), off.data(), 2, sub).ok());
    // a T junction: the left square's edge holds the right squares' shared corner
    std::vector<Vec2d> t = {{0, 0}, {1, 0}, {1, 2}, {0, 2}, {1, 0}, {2, 0},
                            {2, 1}, {1, 1}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
    std::vector<int> toff = {0, 4, 8, 12};
    REQUIRE(build_planar_subdivision(t.data(), toff.data(), 3, sub).ok());
    CHECK(!outer_edges_on_box(sub, {0, 0}, {2, 2}));  // edge (1,0)-(1,2) has one side only
}

TEST_CASE("predicates: exact cocircular points far from the origin, and one-ulp moves off them") {
    // Points (cx + x, cy + y) with x^2 + y^2 = 5^16 exactly (integers): every four of them are
    // cocircular, but the in-circle terms (~2^80) round in floating point, so the filter cannot
    // decide and the exact expansion path must return exactly 0. Moving the fourth point one
    // ulp toward the centre (along x) must put it inside (> 0), away from it outside (< 0).
    const std::int64_t r = 390625;  // 5^8
    const double cx = 1234567.25, cy = -7654321.5;
    std::vector<Vec2d> on;
    for (std::int64_t x = -r; x <= r; ++x) {
        const std::int64_t y2 = r * r - x * x;
        auto y = std::int64_t(std::llround(std::sqrt(double(y2))));
        while (y * y > y2) --y;
        while ((y + 1) * (y + 1) <= y2) ++y;
        if (y * y != y2 || x == 0 || y == 0) continue;  // x == 0: no x-move toward the centre
        on.push_back({cx + double(x), cy + double(y)});
        on.push_back({cx + double(x), cy - double(y)});
    }
    REQUIRE(on.size() >= 40);
    auto angle = [&](Vec2d p) { return std::atan2(p.y - cy, p.x - cx); };
    std::sort(on.begin(), on.end(), [&](Vec2d a, Vec2d b) { return angle(a) < angle(b); });
    Pcg32 rng(11, 2);
    int exact_zero = 0;
    for (int trial = 0; trial < 300; ++trial) {
        int idx[4];
        for (int& i : idx) i = int(rng.next_u32() % std::uint32_t(on.size()));
        std::sort(idx, idx + 3);  // increasing angle: a, b, c counter-clockwise
        if (idx[0] == idx[1] || idx[1] == idx[2]) continue;
        const Vec2d a = on[std::size_t(idx[0])], b = on[std::size_t(idx[1])],
                    c = on[std::size_t(idx[2])], d = on[std::size_t(idx[3])];
        REQUIRE(orient2d(a, b, c) > 0.0);
        REQUIRE(incircle(a, b, c, d) == 0.0);
        REQUIRE(incircle_exact(a, b, c, d) == 0.0);
        ++exact_zero;
        const Vec2d in{std::nextafter(d.x, cx), d.y},
            out{std::nextafter(d.x, d.x + (d.x - cx)), d.y};
        CHECK(incircle(a, b, c, in) > 0.0);
        CHECK(incircle(a, b, c, out) < 0.0);
        CHECK(incircle_exact(a, b, c, in) > 0.0);
    }
    CHECK(exact_zero > 200);
}
