// tests/bench/bench_voronoi_sites.hpp — the sites `make bench` times the Voronoi division and
// the Delaunay triangulation on, shared with tests/test_geom_voronoi_cells_hash.cpp (which
// locks the cells of these inputs, vertex by vertex, through a hash).
//
// Manual
//   std::vector<Vec2d> s = bench_voronoi_sites(SiteDistribution::lattice, 10000);
//   std::uint64_t h = voronoi_cells_hash(cells);   // every bit of every cell
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/geom/voronoi.hpp"

namespace shitsukan {

// uniform: n sites uniform in [0, 1)^2. perturbed: the square lattice of about n sites, each
// moved uniformly by up to 0.1 of the spacing per axis (chosen here: the jittered lattices of
// the leather seeds). lattice: the exact square lattice ((i + 0.5) / side), every square of 4
// sites cocircular: the exact predicates' hardest case, and the papers' own starting point.
enum class SiteDistribution { uniform, perturbed, lattice };

inline const char* site_distribution_name(SiteDistribution d) {
    return d == SiteDistribution::uniform ? "uniform"
                                          : (d == SiteDistribution::perturbed ? "perturbed"
                                                                              : "lattice");
}

inline std::vector<Vec2d> bench_voronoi_sites(SiteDistribution d, int n) {
    std::vector<Vec2d> s;
    Pcg32 rng(2026, 18);
    if (d == SiteDistribution::uniform) {
        for (int i = 0; i < n; ++i) s.push_back({rng.uniform_double(), rng.uniform_double()});
        return s;
    }
    const int side = int(std::lround(std::sqrt(double(n))));
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            Vec2d p{(i + 0.5) / side, (j + 0.5) / side};
            if (d == SiteDistribution::perturbed)
                p = p + Vec2d{(rng.uniform_double() - 0.5) * 0.2 / side,
                              (rng.uniform_double() - 0.5) * 0.2 / side};
            s.push_back(p);
        }
    return s;
}

// A hash of every bit of the cells: offsets, vertices, region-edge labels, duplicates.
inline std::uint64_t voronoi_cells_hash(const VoronoiCells& c) {
    std::uint64_t h = hash_start(18, 17);
    for (int o : c.offsets) h = hash_add(h, std::uint64_t(std::uint32_t(o)));
    for (const Vec2d& v : c.vertices) {
        std::uint64_t x, y;
        std::memcpy(&x, &v.x, 8);
        std::memcpy(&y, &v.y, 8);
        h = hash_add(hash_add(h, x), y);
    }
    for (int l : c.on_region_edge) h = hash_add(h, std::uint64_t(std::uint32_t(l)));
    for (int l : c.duplicate_of) h = hash_add(h, std::uint64_t(std::uint32_t(l)));
    return h;
}

}  // namespace shitsukan
