// Tests for lib/shitsukan/geom/voronoi: the cells of `make bench`'s inputs, locked vertex by
// vertex. Every bit of every cell (offsets, vertices, region-edge labels, duplicates) is
// hashed (tests/bench/bench_voronoi_sites.hpp); the values below were computed with the
// implementation before the Voronoi code was split into steps, before its guard box and its
// fixed-point in-circle, and are the same with it and with the coarse-to-fine insertion order
// (also at 1e6 sites, checked by hand:
// uniform 0x3bc2a5f7d529e5e3, perturbed 0xe91f67b25c17db62, lattice 0x05e97270af1a00d7).
// A speed-up or a refactoring that changes any cell fails here.
#include <doctest/doctest.h>

#include <cstdint>
#include <vector>

#include "bench/bench_voronoi_sites.hpp"
#include "shitsukan/geom/voronoi.hpp"

using namespace shitsukan;

namespace {

// Clustered sites: 1 + n / 200 cluster centres uniform in [0.1, 0.9)^2, each site a centre
// plus an offset of spread 0.03 per axis (a sum of 4 uniforms: no libm), kept in [0, 1)^2.
std::vector<Vec2d> clustered_sites(int n) {
    Pcg32 rng(2026, 19);
    const int k = 1 + n / 200;
    std::vector<Vec2d> centres;
    for (int i = 0; i < k; ++i)
        centres.push_back({0.1 + 0.8 * rng.uniform_double(), 0.1 + 0.8 * rng.uniform_double()});
    std::vector<Vec2d> sites;
    while (int(sites.size()) < n) {
        const Vec2d m = centres[rng.uniform_int(std::uint32_t(k))];
        double ox = 0, oy = 0;
        for (int j = 0; j < 4; ++j) ox += rng.uniform_double(), oy += rng.uniform_double();
        const Vec2d p{m.x + 0.03 * (ox - 2.0), m.y + 0.03 * (oy - 2.0)};
        if (p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1) sites.push_back(p);
    }
    return sites;
}

}  // namespace

TEST_CASE("voronoi cells of the bench inputs: the same bits as before (hash of every cell)") {
    const Vec2d square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    struct Case {
        SiteDistribution d;
        int n;
        std::uint64_t hash;
    };
    const Case cases[] = {
        {SiteDistribution::uniform, 1000, 0xd69995944b9938a0ULL},
        {SiteDistribution::uniform, 10000, 0x831b0db13f15051bULL},
        {SiteDistribution::uniform, 100000, 0x398460021656d3a7ULL},
        {SiteDistribution::perturbed, 1000, 0x300eec65c308bf7aULL},
        {SiteDistribution::perturbed, 10000, 0x328543f2b255e855ULL},
        {SiteDistribution::perturbed, 100000, 0x47689cfd649d4385ULL},
        {SiteDistribution::lattice, 1000, 0xcec1a872c3a450c6ULL},
        {SiteDistribution::lattice, 10000, 0xfd2b799d906d9922ULL},
        {SiteDistribution::lattice, 100000, 0x7774e5c8d6519614ULL},
    };
    for (const Case& c : cases) {
        const std::vector<Vec2d> sites = bench_voronoi_sites(c.d, c.n);
        VoronoiCells cells;
        REQUIRE(voronoi_cells(sites.data(), int(sites.size()), square, 4, cells).ok());
        INFO(site_distribution_name(c.d) << " " << c.n);
        CHECK(voronoi_cells_hash(cells) == c.hash);
    }
}

TEST_CASE("voronoi cells of clustered sites: the same bits as before (hash of every cell)") {
    // About 200 sites per cluster, clusters ~0.1 wide, empty space between: the values were
    // computed before the coarse-to-fine insertion order and the double-double stage for
    // inexact differences, and are the same with them.
    const Vec2d square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const std::uint64_t hashes[3] = {0x908c4779aa6ae54bULL, 0x1faa133082949fc3ULL,
                                     0x2063299bd432c842ULL};
    for (int k = 0; k < 3; ++k) {
        const int n = k == 0 ? 1000 : (k == 1 ? 10000 : 100000);
        const std::vector<Vec2d> sites = clustered_sites(n);
        VoronoiCells cells;
        REQUIRE(voronoi_cells(sites.data(), n, square, 4, cells).ok());
        INFO("clustered " << n);
        CHECK(voronoi_cells_hash(cells) == hashes[k]);
    }
}
