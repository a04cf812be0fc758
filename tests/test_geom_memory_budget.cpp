// Tests for the memory budget in lib/shitsukan/geom/{voronoi,delaunay,triangulate,
// planar_subdivision}: a request over the budget is refused at once with a
// too_large Status that names the call and gives the bytes, before anything is allocated.
#include <doctest/doctest.h>

#include <chrono>
#include <cstring>
#include <string>
#include <vector>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/geom/delaunay.hpp"
#include "shitsukan/geom/planar_subdivision.hpp"
#include "shitsukan/geom/triangulate.hpp"
#include "shitsukan/geom/voronoi.hpp"

using namespace shitsukan;

namespace {
// Restores the default budget when a test ends, even when it fails.
struct BudgetScope {
    explicit BudgetScope(std::uint64_t bytes) { set_memory_budget(bytes); }
    ~BudgetScope() { set_memory_budget(0); }
};
}  // namespace

TEST_CASE("memory budget: voronoi_cells and build_delaunay refuse at once with the bytes") {
    const Vec2d square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const int n = 100000;
    std::vector<Vec2d> sites(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        sites[std::size_t(i)] = {(i % 316 + 0.5) / 316, (i / 316 + 0.5) / 317};
    BudgetScope scope(std::uint64_t(1) << 20);  // 1 MiB: far below 1e5 sites' need
    const auto t0 = std::chrono::steady_clock::now();
    VoronoiCells cells;
    Status s = voronoi_cells(sites.data(), n, square, 4, cells);
    REQUIRE_FALSE(s.ok());
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::strstr(s.message(), "voronoi_cells") != nullptr);
    const std::string need = std::to_string(std::uint64_t(n) * kVoronoiBytesPerSite);
    CHECK(std::strstr(s.message(), need.c_str()) != nullptr);  // 25600000 bytes
    CHECK(std::strstr(s.message(), "1048576") != nullptr);     // the budget
    CHECK(cells.vertices.empty());
    DelaunayTriangulation dt;
    Status d = build_delaunay(sites.data(), n, dt);
    CHECK(d.code() == StatusCode::too_large);
    CHECK(std::strstr(d.message(),
                      std::to_string(std::uint64_t(n) * kDelaunayBytesPerPoint).c_str()) !=
          nullptr);
    CHECK(dt.triangles.empty());
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    CHECK(ms < 50.0);  // at once: nothing is built before the refusal
    // within the budget the same calls work
    set_memory_budget(std::uint64_t(n) * kVoronoiBytesPerSite);
    CHECK(voronoi_cells(sites.data(), n, square, 4, cells).ok());
}

TEST_CASE("memory budget: 2e7 Voronoi sites are over the default 4 GiB budget, 1e7 fit") {
    // 1e7 sites took 4.6 GB before they died of std::bad_alloc; the Voronoi rework
    // brought the working set from 461 to 221 B per site, so 1e7 sites (2.6 GB) now fit the
    // default budget and 2e7 (5.1 GB) are refused at once (the calls themselves are not made
    // here: the sites alone would take 320 MB)
    set_memory_budget(0);
    Status s = check_memory_budget(budget_mul(20000000, kVoronoiBytesPerSite), "voronoi_cells");
    CHECK(s.code() == StatusCode::too_large);
    CHECK(budget_mul(20000000, kVoronoiBytesPerSite) > kDefaultMemoryBudget);
    CHECK(check_memory_budget(budget_mul(10000000, kVoronoiBytesPerSite), "voronoi_cells").ok());
}

TEST_CASE("memory budget: triangulate_polygon and build_planar_subdivision refuse over it") {
    const std::vector<std::vector<Vec2>> rings = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    std::vector<Vec2> points;
    std::vector<std::uint32_t> tris;
    {
        BudgetScope scope(4 * kTriangulateBytesPerVertex - 1);
        Status s = triangulate_polygon(rings, points, tris);
        CHECK(s.code() == StatusCode::too_large);
        CHECK(std::strstr(s.message(), "triangulate_polygon") != nullptr);
    }
    CHECK(triangulate_polygon(rings, points, tris).ok());
    const Vec2d v[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const int offsets[2] = {0, 4};
    PlanarSubdivision sub;
    {
        BudgetScope scope(4 * kPlanarSubdivisionBytesPerVertex - 1);
        Status s = build_planar_subdivision(v, offsets, 1, sub);
        CHECK(s.code() == StatusCode::too_large);
        CHECK(std::strstr(s.message(), "512 bytes") != nullptr);
    }
    CHECK(build_planar_subdivision(v, offsets, 1, sub).ok());
}
