#include "shitsukan/geom/voronoi.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/geom/delaunay.hpp"
#include "shitsukan/geom/double_double.hpp"
#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/geom/predicates.hpp"

namespace shitsukan {
namespace {

bool lex_less(Vec2d a, Vec2d b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

int find_root(std::vector<int>& parent, int t) {
    while (parent[std::size_t(t)] != t) {
        parent[std::size_t(t)] = parent[std::size_t(parent[std::size_t(t)])];  // path halving
        t = parent[std::size_t(t)];
    }
    return t;
}

// Circumcentre of a, b, c, relative to a (the lexicographically smallest), in double-double:
// the differences are exact and the determinants keep ~106 bits, so three sites an ulp apart
// (whose determinant rounds to 0 in doubles: a NaN vertex) still give the correctly rounded
// centre. d != 0 for every triangle of the triangulation (exact orient2d > 0).
Vec2d circumcentre_dd(Vec2d a, Vec2d b, Vec2d c) {
    const DoubleDouble bx = dd_diff(b.x, a.x), by = dd_diff(b.y, a.y);
    const DoubleDouble cx = dd_diff(c.x, a.x), cy = dd_diff(c.y, a.y);
    const DoubleDouble d = dd_scale(dd_sub(dd_mul(bx, cy), dd_mul(by, cx)), 2.0);
    // d carries ~2^-104 of its terms' size as error: when it is not far above that (sites
    // 1e-40 apart seen from 5 away), the centre cannot be constructed: NaN, reported by the
    // caller as a Status
    const double terms = std::fabs(bx.hi * cy.hi) + std::fabs(by.hi * cx.hi);
    if (!(std::fabs(d.hi) > std::ldexp(terms, -94)))
        return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    const DoubleDouble b2 = dd_add(dd_mul(bx, bx), dd_mul(by, by));
    const DoubleDouble c2 = dd_add(dd_mul(cx, cx), dd_mul(cy, cy));
    const DoubleDouble ux = dd_div(dd_sub(dd_mul(cy, b2), dd_mul(by, c2)), d);
    const DoubleDouble uy = dd_div(dd_sub(dd_mul(bx, c2), dd_mul(cx, b2)), d);
    return {dd_round(dd_add(dd_from(a.x), ux)), dd_round(dd_add(dd_from(a.y), uy))};
}

// The largest distance from s at which every real number still rounds to s (a normal double
// with |s| >= 2^-969, else 0): half the gap to the nearer neighbour.
double rounding_margin(double s) {
    std::uint64_t bits;
    std::memcpy(&bits, &s, 8);
    const std::uint64_t exponent = (bits >> 52) & 0x7ff;
    if (exponent < 54 || exponent == 0x7ff) return 0.0;
    const std::uint64_t ulp_bits = (exponent - 52) << 52;  // 2^(e - 52): one ulp of s
    double ulp;
    std::memcpy(&ulp, &ulp_bits, 8);
    const bool power_of_two = (bits & 0x000fffffffffffffULL) == 0;
    return power_of_two ? 0.25 * ulp : 0.5 * ulp;  // below a power of two the gap halves
}

// a + offset rounded, when the offset's error bound e cannot change the rounding: the exact
// sum hi + lo (two_sum) and everything within e of it round to hi. False otherwise.
bool certain_rounding(double a, double offset, double e, double* out) {
    const DoubleDouble s = dd_add(dd_from(a), dd_from(offset));
    if (!(std::fabs(s.lo) + e < 0.99 * rounding_margin(s.hi))) return false;
    *out = s.hi;
    return true;
}

// Fast path (filtered construction): the centre in doubles with a forward error bound; when
// the bound proves the correctly rounded result, that is returned, and it is the double-double
// result too (which is accurate to ~2^-100 and lies in the same rounding cell with margin).
// Most triangles pass; the others (inexact differences, flat triangles, results near a
// rounding boundary) take the double-double path. Same bits either way.
Vec2d circumcentre(Vec2d a, Vec2d b, Vec2d c) {
    constexpr double u = 1.1102230246251565e-16;  // 2^-53
    const DoubleDouble dbx = dd_diff(b.x, a.x), dby = dd_diff(b.y, a.y);
    const DoubleDouble dcx = dd_diff(c.x, a.x), dcy = dd_diff(c.y, a.y);
    if (dbx.lo == 0.0 && dby.lo == 0.0 && dcx.lo == 0.0 && dcy.lo == 0.0) {
        const double bx = dbx.hi, by = dby.hi, cx = dcx.hi, cy = dcy.hi;
        const double p1 = bx * cy, p2 = by * cx, dh = p1 - p2;
        const double ed = 2.1 * u * (std::fabs(p1) + std::fabs(p2));  // |dh - det| <= ed
        if (std::fabs(dh) > 100.0 * ed) {
            const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
            const double nx = cy * b2 - by * c2, ny = bx * c2 - cx * b2;
            const double enx = 4.2 * u * (std::fabs(cy) * b2 + std::fabs(by) * c2);
            const double eny = 4.2 * u * (std::fabs(bx) * c2 + std::fabs(cx) * b2);
            const double d = 2.0 * dh, ox = nx / d, oy = ny / d;
            const double eta = ed / (std::fabs(dh) - ed) + u;  // relative error of d, and /
            const double ex = 1.1 * (std::fabs(ox) * eta + enx / std::fabs(d) + u * std::fabs(ox));
            const double ey = 1.1 * (std::fabs(oy) * eta + eny / std::fabs(d) + u * std::fabs(oy));
            Vec2d r;
            if (certain_rounding(a.x, ox, ex, &r.x) && certain_rounding(a.y, oy, ey, &r.y))
                return r;
        }
    }
    return circumcentre_dd(a, b, c);
}

// The steps of voronoi_cells (voronoi.hpp: "Algorithm"), in order.

// Step 1: the arguments, the region (exact) and the coordinate range.
Status check_voronoi_arguments(const Vec2d* sites, int count, const Vec2d* region,
                               int region_count, VoronoiCells* out) {
    if (out == nullptr)
        return Status::error(StatusCode::invalid_argument, "voronoi_cells: out is null");
    if (count < 1 || sites == nullptr)
        return Status::error(StatusCode::invalid_argument,
                             "voronoi_cells: need at least 1 site (got %d)", count);
    SHITSUKAN_TRY(check_memory_budget(budget_mul(std::uint64_t(count), kVoronoiBytesPerSite),
                                      "voronoi_cells: the cells of the sites"));
    SHITSUKAN_TRY(check_convex_region(region, region_count));
    for (int i = 0; i < region_count; ++i)  // the clipping's exact sides need the range too
        for (double c : {region[i].x, region[i].y})
            if (c != 0.0 &&
                !(std::fabs(c) >= kDelaunayMinCoordinate && std::fabs(c) <= kDelaunayMaxCoordinate))
                return Status::error(StatusCode::invalid_argument,
                                     "voronoi_cells: region vertex %d = (%g, %g): each coordinate "
                                     "must be 0 or of magnitude in [%g, %g] (exact predicates)",
                                     i, region[i].x, region[i].y, kDelaunayMinCoordinate,
                                     kDelaunayMaxCoordinate);
    return Status::success();
}

// Step 2: the Delaunay triangulation, its frame covering the region's bounding box, in
// Hilbert numbering.
Status triangulate_sites(const Vec2d* sites, int count, const Vec2d* region, int region_count,
                         DelaunayTriangulation* dt) {
    Vec2d lo = region[0], hi = region[0];
    for (int i = 0; i < region_count; ++i) {
        lo = {std::min(lo.x, region[i].x), std::min(lo.y, region[i].y)};
        hi = {std::max(hi.x, region[i].x), std::max(hi.y, region[i].y)};
    }
    return build_delaunay(sites, count, dt, lo, hi, true);  // Hilbert numbering
}

// Step 3, union of cocircular triangles: triangles that share a circumcircle (exact incircle
// == 0 across their edge) are one Voronoi vertex. root[t]: the group of triangle t (its
// smallest triangle).
std::vector<int> merge_cocircular_triangles(const DelaunayTriangulation& dt) {
    const std::vector<DelaunayTriangle>& tris = dt.triangles;
    const std::vector<Vec2d>& pts = dt.points;
    const int tcount = int(tris.size());
    std::vector<int> parent(static_cast<std::size_t>(tcount));
    for (int t = 0; t < tcount; ++t) parent[std::size_t(t)] = t;
    for (int t = 0; t < tcount; ++t) {
        const DelaunayTriangle& tri = tris[std::size_t(t)];
        for (int i = 0; i < 3; ++i) {
            int nb = tri.n[i];
            if (nb <= t) continue;  // each edge once (nb == -1: the frame)
            const DelaunayTriangle& other = tris[std::size_t(nb)];
            int d = -1;
            for (int j = 0; j < 3; ++j)
                if (other.n[j] == t) d = other.v[j];
            if (incircle(pts[std::size_t(tri.v[0])], pts[std::size_t(tri.v[1])],
                         pts[std::size_t(tri.v[2])], pts[std::size_t(d)]) == 0.0) {
                int ra = find_root(parent, t), rb = find_root(parent, nb);
                if (ra != rb) parent[std::size_t(std::max(ra, rb))] = std::min(ra, rb);
            }
        }
    }
    for (int t = 0; t < tcount; ++t) parent[std::size_t(t)] = find_root(parent, t);
    return parent;
}

// Step 4, the Voronoi vertices: one canonical circumcentre per group of cocircular triangles,
// from the group's 3 lexicographically smallest sites (the same bits whatever the order).
Status voronoi_vertices(const DelaunayTriangulation& dt, const std::vector<int>& root,
                        std::vector<Vec2d>* centre) {
    const std::vector<DelaunayTriangle>& tris = dt.triangles;
    const std::vector<Vec2d>& pts = dt.points;
    const int tcount = int(tris.size());
    std::vector<int> best(std::size_t(tcount) * 3, -1);
    for (int t = 0; t < tcount; ++t) {
        int* b = &best[std::size_t(root[std::size_t(t)]) * 3];
        for (int v : tris[std::size_t(t)].v) {
            if (v == b[0] || v == b[1] || v == b[2]) continue;
            // insert v into the sorted top-3
            int k = 3;
            while (k > 0 &&
                   (b[k - 1] < 0 || lex_less(pts[std::size_t(v)], pts[std::size_t(b[k - 1])])))
                --k;
            if (k >= 3) continue;
            for (int j = 2; j > k; --j) b[j] = b[j - 1];
            b[k] = v;
        }
    }
    centre->resize(static_cast<std::size_t>(tcount));
    for (int t = 0; t < tcount; ++t) {
        if (root[std::size_t(t)] != t) continue;
        const int* b = &best[std::size_t(t) * 3];
        const Vec2d p0 = pts[std::size_t(b[0])], p1 = pts[std::size_t(b[1])],
                    p2 = pts[std::size_t(b[2])];
        (*centre)[std::size_t(t)] = circumcentre(p0, p1, p2);
        if (!is_finite((*centre)[std::size_t(t)]))
            return Status::error(StatusCode::degenerate,
                                 "voronoi_cells: the Voronoi vertex of (%.17g, %.17g), (%.17g, "
                                 "%.17g), (%.17g, %.17g) cannot be constructed in double-double: "
                                 "the sites are closer than ~2^-94 of their distances",
                                 p0.x, p0.y, p1.x, p1.y, p2.x, p2.y);
    }
    return Status::success();
}

// Step 5, the dual walk: the Voronoi polygon of site s, its vertices the groups of s's
// triangles counter-clockwise, each once; each vertex carries the bisector its leaving edge
// lies on (the support the clipping constructs from).
void dual_walk(const DelaunayTriangulation& dt, const std::vector<int>& root,
               const std::vector<Vec2d>& centre, int s, std::vector<ClipVertex>* poly) {
    const std::vector<DelaunayTriangle>& tris = dt.triangles;
    const std::vector<Vec2d>& pts = dt.points;
    poly->clear();
    const int t0 = dt.point_triangle[std::size_t(s)];
    if (t0 < 0) return;  // a duplicate site: empty
    int t = t0, last_group = -1, first_group = -1;
    do {
        const DelaunayTriangle& tri = tris[std::size_t(t)];
        int i = tri.v[0] == s ? 0 : (tri.v[1] == s ? 1 : 2);
        int g = root[std::size_t(t)];
        if (g != last_group) {
            ClipVertex cv;
            cv.p = centre[std::size_t(g)];
            cv.has_bisector = true;
            cv.bisector[0] = pts[std::size_t(s)];
            poly->push_back(cv);
            if (first_group < 0) first_group = g;
            last_group = g;
        }
        // the Voronoi edge leaving this vertex lies on the bisector of s and the site across
        // the Delaunay edge (s, v[i + 2]) that the walk crosses last in a group
        poly->back().bisector[1] = pts[std::size_t(tri.v[(i + 2) % 3])];
        t = tri.n[(i + 1) % 3];  // across the edge (s, v[i + 2]): next triangle CCW
        SHITSUKAN_ASSERT(t >= 0);
    } while (t != t0);
    if (poly->size() > 1 && last_group == first_group) poly->pop_back();
}

// Cells in Hilbert order, compact (a ClipVertex carries its edge's support: 64 bytes).
struct HilbertCells {
    std::vector<Vec2d> points;
    std::vector<int> labels;
    std::vector<int> start, size;  // per input site
};

// Step 6, clipping: each site's polygon clipped to the region (polygon.hpp), started at its
// lexicographically smallest vertex. Sites are visited in Hilbert order (memory stays local).
void clip_cells(const DelaunayTriangulation& dt, const std::vector<int>& root,
                const std::vector<Vec2d>& centre, const Vec2d* region, int region_count,
                HilbertCells* cells) {
    const int count = dt.input_count;
    std::vector<ClipVertex> poly, scratch;
    const double snap = clip_snap_distance(region, region_count);
    cells->points.reserve(std::size_t(count) * 6);
    cells->labels.reserve(std::size_t(count) * 12);
    cells->start.assign(static_cast<std::size_t>(count), 0);
    cells->size.assign(static_cast<std::size_t>(count), 0);
    for (int s = 0; s < count; ++s) {  // s: Hilbert number of the site
        dual_walk(dt, root, centre, s, &poly);
        if (!poly.empty()) {
            clip_to_convex_region(&poly, region, region_count, snap, &scratch);
            std::size_t m = 0;
            for (std::size_t k = 1; k < poly.size(); ++k)
                if (lex_less(poly[k].p, poly[m].p)) m = k;
            std::rotate(poly.begin(), poly.begin() + std::ptrdiff_t(m), poly.end());
        }
        const std::size_t site = std::size_t(dt.insertion_order[std::size_t(s)]);
        cells->start[site] = int(cells->points.size());
        cells->size[site] = int(poly.size());
        for (const ClipVertex& v : poly) {
            cells->points.push_back(v.p);
            cells->labels.push_back(v.on[0]);
            cells->labels.push_back(v.on[1]);
        }
    }
}

// Step 7: the cells in input order (cell i belongs to sites[i]).
void cells_in_input_order(const HilbertCells& cells, const DelaunayTriangulation& dt,
                          VoronoiCells* out) {
    const int count = dt.input_count;
    out->vertices.resize(cells.points.size());
    out->on_region_edge.resize(cells.labels.size());
    out->offsets.resize(std::size_t(count) + 1);
    out->duplicate_of = dt.duplicate_of;
    std::size_t w = 0;
    for (int s = 0; s < count; ++s) {
        out->offsets[std::size_t(s)] = int(w);
        const std::size_t first = std::size_t(cells.start[std::size_t(s)]);
        for (int k = 0; k < cells.size[std::size_t(s)]; ++k, ++w) {
            out->vertices[w] = cells.points[first + std::size_t(k)];
            out->on_region_edge[2 * w] = cells.labels[2 * (first + std::size_t(k))];
            out->on_region_edge[2 * w + 1] = cells.labels[2 * (first + std::size_t(k)) + 1];
        }
    }
    out->offsets[std::size_t(count)] = int(w);
}

}  // namespace

Status voronoi_cells(const Vec2d* sites, int count, const Vec2d* region, int region_count,
                     VoronoiCells* out) {
    SHITSUKAN_TRY(check_voronoi_arguments(sites, count, region, region_count, out));
    DelaunayTriangulation dt;
    SHITSUKAN_TRY(triangulate_sites(sites, count, region, region_count, &dt));
    const std::vector<int> root = merge_cocircular_triangles(dt);
    std::vector<Vec2d> centre;
    SHITSUKAN_TRY(voronoi_vertices(dt, root, &centre));
    HilbertCells cells;
    clip_cells(dt, root, centre, region, region_count, &cells);
    cells_in_input_order(cells, dt, out);
    return Status::success();
}

}  // namespace shitsukan
