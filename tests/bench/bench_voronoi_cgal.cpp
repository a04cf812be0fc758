// bench_voronoi_cgal — our Delaunay triangulation and clipped Voronoi cells against CGAL 5
// (Delaunay_triangulation_2, exact predicates and inexact constructions, spatially sorted
// range insertion), on the same sites: uniform random and the exact square lattice (the
// papers' own starting point), 1e4 and 1e5 sites.
// The clipped-cells peer inserts the same 4 frame points ours adds (10 half-extents out), so
// every input site has a bounded cell, then walks each site's faces, takes their circumcentres
// (CGAL::circumcenter, inexact; Triangulation::dual is ~40 us per face in CGAL 5.5, so it is
// not used) and clips the polygon to the unit square (Sutherland-Hodgman in doubles). Ours does more: exact cocircular merging, double-double constructions, and
// output in input order with region-edge labels.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <string>
#include <vector>

#include "bench.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/geom/delaunay.hpp"
#include "shitsukan/geom/voronoi.hpp"

using namespace shitsukan;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangulation = CGAL::Delaunay_triangulation_2<Kernel>;
using Point = Kernel::Point_2;

std::vector<Vec2d> bench_sites(int n, bool lattice) {
    std::vector<Vec2d> s;
    if (lattice) {
        const int side = int(std::lround(std::sqrt(double(n))));
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i) s.push_back({(i + 0.5) / side, (j + 0.5) / side});
        return s;
    }
    Pcg32 rng(2026, 18);
    for (int i = 0; i < n; ++i) s.push_back({rng.uniform_double(), rng.uniform_double()});
    return s;
}

// The polygon clipped to the unit square (Sutherland-Hodgman, doubles).
void clip_unit_square(std::vector<Point>* poly, std::vector<Point>* tmp) {
    for (int k = 0; k < 4; ++k) {
        auto inside = [&](const Point& p) {
            return k == 0 ? p.y() >= 0 : k == 1 ? p.x() <= 1 : k == 2 ? p.y() <= 1 : p.x() >= 0;
        };
        auto cut = [&](const Point& a, const Point& b) {
            double t;
            if (k == 0) t = (0 - a.y()) / (b.y() - a.y());
            else if (k == 1) t = (1 - a.x()) / (b.x() - a.x());
            else if (k == 2) t = (1 - a.y()) / (b.y() - a.y());
            else t = (0 - a.x()) / (b.x() - a.x());
            return Point(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
        };
        tmp->clear();
        const std::size_t n = poly->size();
        for (std::size_t i = 0; i < n; ++i) {
            const Point& a = (*poly)[i];
            const Point& b = (*poly)[(i + 1) % n];
            const bool ia = inside(a), ib = inside(b);
            if (ia) tmp->push_back(a);
            if (ia != ib) tmp->push_back(cut(a, b));
        }
        poly->swap(*tmp);
    }
}

}  // namespace

SHITSUKAN_BENCH(voronoi_vs_cgal) {
    const Vec2d square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (bool lattice : {false, true})
        for (int n : {10000, 100000}) {
            const std::vector<Vec2d> sites = bench_sites(n, lattice);
            const int count = int(sites.size());
            std::vector<Point> pts;
            for (const Vec2d& p : sites) pts.emplace_back(p.x, p.y);
            const std::string what = std::string(lattice ? "lattice " : "uniform ") +
                                     std::to_string(count) + " sites";
            DelaunayTriangulation dt;
            const double ours_dt = bench::ns_per_op([&] {
                Status s = build_delaunay(sites.data(), count, &dt);
                bench::sink(s.ok() ? dt.triangles.size() : 0);
            });
            const double cgal_dt = bench::ns_per_op([&] {
                Triangulation t;
                t.insert(pts.begin(), pts.end());
                bench::sink(t.number_of_faces());
            });
            bench::report("Delaunay, " + what, ours_dt,
                          "CGAL Delaunay_triangulation_2 (Epick)", cgal_dt);
            // the same frame as ours (10 half-extents around the unit square's centre), inserted
            // before the sorted range (in the range it would spoil CGAL's spatial sort)
            const Point frame[4] = {Point(-4.5, -4.5), Point(5.5, -4.5), Point(5.5, 5.5),
                                    Point(-4.5, 5.5)};
            VoronoiCells cells;
            const double ours_vc = bench::ns_per_op([&] {
                Status s = voronoi_cells(sites.data(), count, square, 4, &cells);
                bench::sink(s.ok() ? cells.vertices.size() : 0);
            });
            std::vector<Point> poly, tmp, out;
            std::vector<int> offsets;
            const double cgal_vc = bench::ns_per_op([&] {
                Triangulation t;
                for (const Point& f : frame) t.insert(f);
                t.insert(pts.begin(), pts.end());
                out.clear();
                offsets.assign(1, 0);
                for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v) {
                    const Point& p = v->point();
                    if (p.x() < -1 || p.x() > 2) continue;  // a frame point
                    poly.clear();
                    auto fc = t.incident_faces(v), done = fc;
                    do {
                        poly.push_back(CGAL::circumcenter(fc->vertex(0)->point(),
                                                          fc->vertex(1)->point(),
                                                          fc->vertex(2)->point()));
                    } while (++fc != done);
                    clip_unit_square(&poly, &tmp);
                    out.insert(out.end(), poly.begin(), poly.end());
                    offsets.push_back(int(out.size()));
                }
                bench::sink(out.size());
            });
            bench::report("Voronoi cells clipped to the square, " + what, ours_vc,
                          "CGAL Delaunay_triangulation_2 + dual + clip", cgal_vc);
        }
}
