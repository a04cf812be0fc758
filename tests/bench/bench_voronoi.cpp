// bench_voronoi — our Voronoi division (exact predicates, clipped cells) against
// Boost.Polygon's construct_voronoi (sweep line, integer input) on the same sites
// (tests/bench/bench_voronoi_sites.hpp): uniform, perturbed lattice and exact square lattice,
// 1e3 to 1e5 sites (1e6 without --quick).
// Boost takes integer coordinates: sites in [0, 1]^2 are scaled by 2^24 and rounded (the exact
// lattice is given to Boost as the exact integer lattice (2i + 1) k, so it stays cocircular);
// ours gets the sites as doubles, clipped to the unit square. Boost builds the unbounded
// diagram (half-edge structure, no clipping); ours also clips every cell and merges
// cocircular vertices, so ours does strictly more work. Memory per site: our cells against
// Boost's diagram (cells, half-edges, vertices).
#include <boost/polygon/voronoi.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench.hpp"
#include "bench_voronoi_sites.hpp"
#include "shitsukan/geom/voronoi.hpp"

using namespace shitsukan;

namespace {

using BoostPoint = boost::polygon::point_data<int>;
using BoostDiagram = boost::polygon::voronoi_diagram<double>;

std::vector<BoostPoint> boost_sites(SiteDistribution d, const std::vector<Vec2d>& sites) {
    std::vector<BoostPoint> out;
    const double scale = 16777216.0;  // 2^24
    const int side = int(std::lround(std::sqrt(double(sites.size()))));
    const int k = int(scale) / (2 * side);
    for (const Vec2d& p : sites) {
        if (d == SiteDistribution::lattice)  // (i + 0.5) / side -> (2i + 1) k exactly
            out.emplace_back(int(std::lround(p.x * 2 * side)) * k,
                             int(std::lround(p.y * 2 * side)) * k);
        else
            out.emplace_back(int(std::lround(p.x * scale)), int(std::lround(p.y * scale)));
    }
    return out;
}

}  // namespace

SHITSUKAN_BENCH(voronoi_vs_boost_polygon) {
    const Vec2d square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const bool quick = bench::g_min_seconds < 0.1;
    for (SiteDistribution d :
         {SiteDistribution::uniform, SiteDistribution::perturbed, SiteDistribution::lattice})
        for (int n : {1000, 10000, 100000, 1000000}) {
            if (quick && n > 100000) continue;
            const std::vector<Vec2d> sites = bench_voronoi_sites(d, n);
            const int count = int(sites.size());
            const std::vector<BoostPoint> isites = boost_sites(d, sites);
            const std::string what = "Voronoi of " + std::to_string(count) + " " +
                                     site_distribution_name(d) + " sites";
            VoronoiCells cells;
            bool ok = true;
            std::size_t boost_bytes = 0;
            const bench::Pair t = bench::in_turns(
                [&] {
                    Status s = voronoi_cells(sites.data(), count, square, 4, cells);
                    ok = ok && s.ok();
                    bench::sink(s.ok() ? cells.vertices.size() : 0);
                },
                [&] {
                    BoostDiagram vd;
                    boost::polygon::construct_voronoi(isites.begin(), isites.end(), &vd);
                    boost_bytes = vd.num_cells() * sizeof(BoostDiagram::cell_type) +
                                  vd.num_edges() * sizeof(BoostDiagram::edge_type) +
                                  vd.num_vertices() * sizeof(BoostDiagram::vertex_type);
                    bench::sink(vd.num_vertices());
                });
            if (!bench::timed_calls_ok(ok, what.c_str())) continue;
            // The exact square lattice up to 1e5 sites: at least as fast as Boost (goal).
            const bool goal = d == SiteDistribution::lattice && n <= 100000;
            bench::report(what, t, "boost::polygon::construct_voronoi", goal ? 1.0 : 0.0);
            const double our_bytes =
                double(cells.vertices.capacity() * sizeof(Vec2d) +
                       cells.on_region_edge.capacity() * sizeof(int) +
                       cells.offsets.capacity() * sizeof(int) +
                       cells.duplicate_of.capacity() * sizeof(int));
            char text[160];
            std::snprintf(text, sizeof text,
                          "memory per site: shitsukan cells %.0f B, boost diagram %.0f B",
                          our_bytes / count, double(boost_bytes) / count);
            bench::info(what, text);
        }
    // Exactness on a lattice: every interior cell of a 100 x 100 square lattice.
    const std::vector<Vec2d> lattice = bench_voronoi_sites(SiteDistribution::lattice, 10000);
    VoronoiCells cells;
    Status s = voronoi_cells(lattice.data(), int(lattice.size()), square, 4, cells);
    int four = 0;
    for (int c = 0; c < cells.cell_count(); ++c) {
        int k;
        cells.cell(c, &k);
        four += (k == 4);
    }
    const std::vector<BoostPoint> ilattice = boost_sites(SiteDistribution::lattice, lattice);
    BoostDiagram vd;
    boost::polygon::construct_voronoi(ilattice.begin(), ilattice.end(), &vd);
    bench::info("square lattice 100 x 100",
                std::string(s.ok() ? "" : "error ") + "shitsukan " + std::to_string(four) +
                    " of 10000 cells have exactly 4 vertices; boost (integer input) " +
                    std::to_string(vd.num_vertices()) +
                    " Voronoi vertices (99 x 99 = 9801 expected)");
}
