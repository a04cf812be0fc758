// bench_voronoi — our Voronoi division (exact predicates, clipped cells) against
// Boost.Polygon's construct_voronoi (sweep line, integer input) on the same sites.
// Boost takes integer coordinates: random sites in [0, 1]^2 are scaled by 2^24 and rounded;
// ours gets exactly those rounded sites divided by 2^24, clipped to the unit square.
// Boost builds the unbounded diagram (half-edge structure, no clipping); ours also clips
// every cell and merges cocircular vertices, so ours does strictly more work.
#include <boost/polygon/voronoi.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "bench.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/geom/delaunay.hpp"
#include "shitsukan/geom/voronoi.hpp"

using namespace shitsukan;

SHITSUKAN_BENCH(voronoi_vs_boost_polygon) {
    const Vec2d square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const double scale = 16777216.0;  // 2^24
    for (int n : {1000, 10000, 100000}) {
        Pcg32 rng(2026, 11);
        std::vector<boost::polygon::point_data<int>> isites;
        std::vector<Vec2d> sites;
        for (int i = 0; i < n; ++i) {
            int x = int(std::lround(rng.uniform_double() * scale));
            int y = int(std::lround(rng.uniform_double() * scale));
            isites.emplace_back(x, y);
            sites.push_back({x / scale, y / scale});
        }
        VoronoiCells cells;
        double ours = bench::ns_per_op([&] {
            Status s = voronoi_cells(sites.data(), n, square, 4, &cells);
            bench::sink(s.ok() ? cells.vertices.size() : 0);
        });
        double peer = bench::ns_per_op([&] {
            boost::polygon::voronoi_diagram<double> vd;
            boost::polygon::construct_voronoi(isites.begin(), isites.end(), &vd);
            bench::sink(vd.num_vertices());
        });
        bench::report("Voronoi of " + std::to_string(n) + " random sites", ours,
                      "boost::polygon::construct_voronoi", peer);
    }
    // Exactness on a lattice: every interior cell of a 100 x 100 square lattice.
    std::vector<Vec2d> lattice;
    std::vector<boost::polygon::point_data<int>> ilattice;
    for (int j = 0; j < 100; ++j)
        for (int i = 0; i < 100; ++i) {
            lattice.push_back({(i + 0.5) / 100.0, (j + 0.5) / 100.0});
            ilattice.emplace_back(2 * i + 1, 2 * j + 1);
        }
    VoronoiCells cells;
    Status s = voronoi_cells(lattice.data(), int(lattice.size()), square, 4, &cells);
    int four = 0;
    for (int c = 0; c < cells.cell_count(); ++c) {
        int k;
        cells.cell(c, &k);
        four += (k == 4);
    }
    boost::polygon::voronoi_diagram<double> vd;
    boost::polygon::construct_voronoi(ilattice.begin(), ilattice.end(), &vd);
    bench::info("square lattice 100 x 100",
                std::string(s.ok() ? "" : "error ") + "shitsukan " + std::to_string(four) +
                    " of 10000 cells have exactly 4 vertices; boost (integer input) " +
                    std::to_string(vd.num_vertices()) +
                    " Voronoi vertices (99 x 99 = 9801 expected)");
}
