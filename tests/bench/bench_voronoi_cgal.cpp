// bench_voronoi_cgal — our Delaunay triangulation and clipped Voronoi cells against CGAL 5
// (Delaunay_triangulation_2, exact predicates and inexact constructions, spatially sorted
// range insertion), on the same sites (tests/bench/bench_voronoi_sites.hpp): uniform,
// perturbed lattice and exact square lattice, 1e3 to 1e5 sites (1e6 without --quick).
// The clipped-cells peer inserts the same 4 frame points ours adds (10 half-extents out), so
// every input site has a bounded cell, then walks each site's faces, takes their circumcentres
// (CGAL::circumcenter, inexact; Triangulation::dual is ~40 us per face in CGAL 5.5, so it is
// not used) and clips the polygon to the unit square (Sutherland-Hodgman in doubles). Ours
// does more: exact cocircular merging, double-double constructions, and output in input order
// with region-edge labels. Each size also prints the hash of our cells (locked by
// tests/test_geom_voronoi_cells_hash.cpp) and the memory per site of both results.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench.hpp"
#include "bench_voronoi_sites.hpp"
#include "shitsukan/geom/delaunay.hpp"
#include "shitsukan/geom/voronoi.hpp"

using namespace shitsukan;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangulation = CGAL::Delaunay_triangulation_2<Kernel>;
using Point = Kernel::Point_2;

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

struct CgalCells {
    std::vector<Point> out;
    std::vector<int> offsets;
};

void cgal_clipped_cells(const std::vector<Point>& pts, CgalCells* cells, std::size_t* bytes) {
    // the same frame as ours (10 half-extents around the unit square's centre), inserted
    // before the sorted range (in the range it would spoil CGAL's spatial sort)
    const Point frame[4] = {Point(-4.5, -4.5), Point(5.5, -4.5), Point(5.5, 5.5),
                            Point(-4.5, 5.5)};
    Triangulation t;
    for (const Point& f : frame) t.insert(f);
    t.insert(pts.begin(), pts.end());
    std::vector<Point> poly, tmp;
    cells->out.clear();
    cells->offsets.assign(1, 0);
    for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v) {
        const Point& p = v->point();
        if (p.x() < -1 || p.x() > 2) continue;  // a frame point
        poly.clear();
        auto fc = t.incident_faces(v), done = fc;
        do {
            poly.push_back(CGAL::circumcenter(fc->vertex(0)->point(), fc->vertex(1)->point(),
                                              fc->vertex(2)->point()));
        } while (++fc != done);
        clip_unit_square(&poly, &tmp);
        cells->out.insert(cells->out.end(), poly.begin(), poly.end());
        cells->offsets.push_back(int(cells->out.size()));
    }
    if (bytes)  // the triangulation (vertices and faces) and the cells, as held at the end
        *bytes = t.number_of_vertices() * sizeof(Triangulation::Vertex) +
                 t.number_of_faces() * sizeof(Triangulation::Face) +
                 cells->out.capacity() * sizeof(Point) + cells->offsets.capacity() * sizeof(int);
}

std::size_t our_cell_bytes(const VoronoiCells& c) {
    return c.vertices.capacity() * sizeof(Vec2d) + c.on_region_edge.capacity() * sizeof(int) +
           c.offsets.capacity() * sizeof(int) + c.duplicate_of.capacity() * sizeof(int);
}

}  // namespace

SHITSUKAN_BENCH(voronoi_vs_cgal) {
    const Vec2d square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const bool quick = bench::g_min_seconds < 0.1;
    for (SiteDistribution d :
         {SiteDistribution::uniform, SiteDistribution::perturbed, SiteDistribution::lattice})
        for (int n : {1000, 10000, 100000, 1000000}) {
            const std::vector<Vec2d> sites = bench_voronoi_sites(d, n);
            const int count = int(sites.size());
            const std::string what = std::string(site_distribution_name(d)) + " " +
                                     std::to_string(count) + " sites";
            if (quick && n > 100000) {
                bench::info(what, "skipped with --quick (make bench times it)");
                continue;
            }
            std::vector<Point> pts;
            for (const Vec2d& p : sites) pts.emplace_back(p.x, p.y);
            DelaunayTriangulation dt;
            bool ok = true;
            const bench::Pair dt_t = bench::in_turns(
                [&] {
                    Status s = build_delaunay(sites.data(), count, dt);
                    ok = ok && s.ok();
                    bench::sink(s.ok() ? dt.triangles.size() : 0);
                },
                [&] {
                    Triangulation t;
                    t.insert(pts.begin(), pts.end());
                    bench::sink(t.number_of_faces());
                });
            if (!bench::timed_calls_ok(ok, what.c_str())) continue;
            bench::report("Delaunay, " + what, dt_t, "CGAL Delaunay_triangulation_2 (Epick)");
            VoronoiCells cells;
            CgalCells cgal_cells;
            const bench::Pair vc_t = bench::in_turns(
                [&] {
                    Status s = voronoi_cells(sites.data(), count, square, 4, cells);
                    ok = ok && s.ok();
                    bench::sink(s.ok() ? cells.vertices.size() : 0);
                },
                [&] {
                    cgal_clipped_cells(pts, &cgal_cells, nullptr);
                    bench::sink(cgal_cells.out.size());
                });
            if (!bench::timed_calls_ok(ok, what.c_str())) continue;
            bench::report("Voronoi cells clipped to the square, " + what, vc_t,
                          "CGAL Delaunay_triangulation_2 + circumcenters + clip");
            std::size_t cgal_bytes = 0;
            cgal_clipped_cells(pts, &cgal_cells, &cgal_bytes);
            char text[200];
            std::snprintf(text, sizeof text,
                          "memory per site: shitsukan cells %.0f B (working set at most %d B), "
                          "CGAL triangulation + cells %.0f B; cells hash 0x%016llx",
                          double(our_cell_bytes(cells)) / count, int(kVoronoiBytesPerSite),
                          double(cgal_bytes) / count,
                          static_cast<unsigned long long>(voronoi_cells_hash(cells)));
            bench::info("Voronoi cells, " + what, text);
        }
}
