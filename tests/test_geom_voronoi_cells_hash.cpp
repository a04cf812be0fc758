// Tests for lib/shitsukan/geom/voronoi: the cells of `make bench`'s inputs, locked vertex by
// vertex. Every bit of every cell (offsets, vertices, region-edge labels, duplicates) is
// hashed (tests/bench/bench_voronoi_sites.hpp); the values below were computed with the
// implementation before the Voronoi code was split into steps, before its guard box and its
// fixed-point in-circle, and are the same with it (also at 1e6 sites, checked by hand:
// uniform 0x3bc2a5f7d529e5e3, perturbed 0xe91f67b25c17db62, lattice 0x05e97270af1a00d7).
// A speed-up or a refactoring that changes any cell fails here.
#include <doctest/doctest.h>

#include <cstdint>

#include "bench/bench_voronoi_sites.hpp"
#include "shitsukan/geom/voronoi.hpp"

using namespace shitsukan;

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
