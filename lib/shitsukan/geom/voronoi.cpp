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

// Whether a, b, c are three corners of an axis-parallel rectangle (two distinct x values and
// two distinct y values among them): *x, *y get those values (the rectangle's box).
// The conditions are combined with & and | (no branch to mispredict: a lattice's triangles
// take their corners in every order).
inline bool rectangle_corners(Vec2d a, Vec2d b, Vec2d c, double x[2], double y[2]) {
    x[0] = a.x, y[0] = a.y;
    x[1] = a.x != b.x ? b.x : c.x, y[1] = a.y != b.y ? b.y : c.y;
    const int xs = (int(b.x == a.x) | int(b.x == x[1])) & (int(c.x == a.x) | int(c.x == x[1])) &
                   int(x[1] != a.x);
    const int ys = (int(b.y == a.y) | int(b.y == y[1])) & (int(c.y == a.y) | int(c.y == y[1])) &
                   int(y[1] != a.y);
    return (xs & ys) != 0;
}

inline bool on_box(Vec2d p, const double x[2], const double y[2]) {
    return ((int(p.x == x[0]) | int(p.x == x[1])) & (int(p.y == y[0]) | int(p.y == y[1]))) != 0;
}

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

// The x87 80-bit extended format (64-bit significand) where the compiler maps long double to
// it AND the FPU really rounds to 64 bits: checked once at run time (1 + 2^-60 must differ
// from 1), so a platform that rounds long double to 53 bits (an x87 set to double precision,
// or valgrind's emulation) never trusts the 2^-64 error bounds below.
bool extended_precision_works() {
    if (std::numeric_limits<long double>::digits < 64) return false;
    static const bool works = [] {
        volatile long double one = 1.0L, tiny = std::ldexp(1.0L, -60);
        const long double sum = one + tiny;
        return sum != one;
    }();
    return works;
}

// As certain_rounding, from an extended-precision offset: the exact a + offset' (offset'
// within e of offset) rounds to r when it lies well inside r's rounding interval.
bool certain_rounding_extended(double a, long double offset, long double e, double* out) {
    constexpr long double u = std::numeric_limits<long double>::epsilon() / 2;  // 2^-64
    const long double v = (long double)a + offset;           // error <= u |v|
    const double r = double(v);
    const long double off_r = std::fabs(v - (long double)r);  // exact (v and r are close)
    if (!(off_r + e + u * std::fabs(v) < 0.99L * (long double)rounding_margin(r))) return false;
    *out = r;
    return true;
}

// Filter in x87 extended precision (where it works: see above): circumcentre_double's
// formula and error bound (below) with a rounding unit of 2^-64 instead of 2^-53 (the bound
// also counts the second rounding of the reciprocal), from the exact coordinate differences
// (exact in 64 bits far more often than in 53: the sites of a lattice). It proves the
// correctly rounded centre for ~97 % of the triangles of uniform sites where the double filter
// proves ~40 % (a centre at x < 0.25 has ulps 4x finer than the double filter's error of ~10
// ulps of the circumradius), at a fraction of the double-double construction's cost.
bool circumcentre_extended(Vec2d a, DoubleDouble dbx, DoubleDouble dby, DoubleDouble dcx,
                           DoubleDouble dcy, Vec2d* r) {
    using L = long double;
    constexpr L u = std::numeric_limits<L>::epsilon() / 2;
    L diff[4];
    const DoubleDouble exact[4] = {dbx, dby, dcx, dcy};
    for (int i = 0; i < 4; ++i) {  // hi + lo, exact when the rounding gave nothing away
        diff[i] = (long double)exact[i].hi + (long double)exact[i].lo;
        if (diff[i] - (long double)exact[i].hi != (long double)exact[i].lo) return false;
    }
    const L bx = diff[0], by = diff[1], cx = diff[2], cy = diff[3];
    const L p1 = bx * cy, p2 = by * cx, dh = p1 - p2;
    const L b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const L nx = cy * b2 - by * c2, ny = bx * c2 - cx * b2;
    const L inv = 1.0L / (2.0L * dh), ox = nx * inv, oy = ny * inv;  // 2 roundings: 2 u |ox|
    // the bounds (sums of positive terms) in doubles: their relative error, ~1e-15, is far
    // inside the factor 1.1
    const double ue = double(u), dhd = std::fabs(double(dh));
    const double ed = 2.1 * ue * (std::fabs(double(p1)) + std::fabs(double(p2)));  // |dh - det|
    if (!(dhd > 100.0 * ed)) return false;
    const double b2d = double(b2), c2d = double(c2);
    const double enx = 4.2 * ue * (std::fabs(double(cy)) * b2d + std::fabs(double(by)) * c2d);
    const double eny = 4.2 * ue * (std::fabs(double(bx)) * c2d + std::fabs(double(cx)) * b2d);
    const double eta = ed / (dhd - ed) + ue, oxd = std::fabs(double(ox));
    const double oyd = std::fabs(double(oy));
    const L ex = 1.1 * (oxd * eta + enx / (2.0 * dhd) + 2.0 * ue * oxd);
    const L ey = 1.1 * (oyd * eta + eny / (2.0 * dhd) + 2.0 * ue * oyd);
    return certain_rounding_extended(a.x, ox, ex, &r->x) &&
           certain_rounding_extended(a.y, oy, ey, &r->y);
}

// Filtered construction in doubles: the centre with a forward error bound; when the bound
// proves the correctly rounded result, that is returned, and it is the double-double result
// too (which is accurate to ~2^-100 and lies in the same rounding cell with margin). False
// for inexact differences, flat triangles and results near a rounding boundary.
bool circumcentre_double(Vec2d a, DoubleDouble dbx, DoubleDouble dby, DoubleDouble dcx,
                         DoubleDouble dcy, Vec2d* r) {
    constexpr double u = 1.1102230246251565e-16;  // 2^-53
    if (!(dbx.lo == 0.0 && dby.lo == 0.0 && dcx.lo == 0.0 && dcy.lo == 0.0)) return false;
    const double bx = dbx.hi, by = dby.hi, cx = dcx.hi, cy = dcy.hi;
    const double p1 = bx * cy, p2 = by * cx, dh = p1 - p2;
    const double ed = 2.1 * u * (std::fabs(p1) + std::fabs(p2));  // |dh - det| <= ed
    if (!(std::fabs(dh) > 100.0 * ed)) return false;
    const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const double nx = cy * b2 - by * c2, ny = bx * c2 - cx * b2;
    const double enx = 4.2 * u * (std::fabs(cy) * b2 + std::fabs(by) * c2);
    const double eny = 4.2 * u * (std::fabs(bx) * c2 + std::fabs(cx) * b2);
    const double d = 2.0 * dh, ox = nx / d, oy = ny / d;
    const double eta = ed / (std::fabs(dh) - ed) + u;  // relative error of d, and /
    const double ex = 1.1 * (std::fabs(ox) * eta + enx / std::fabs(d) + u * std::fabs(ox));
    const double ey = 1.1 * (std::fabs(oy) * eta + eny / std::fabs(d) + u * std::fabs(oy));
    return certain_rounding(a.x, ox, ex, &r->x) && certain_rounding(a.y, oy, ey, &r->y);
}

// The centre, correctly rounded: the extended-precision filter where it works (it decides
// ~97 % of the triangles of uniform sites, the double filter only ~40 %), else the double
// filter, and the double-double construction for what they leave. Same bits either way.
Vec2d circumcentre(Vec2d a, Vec2d b, Vec2d c) {
    // three corners of an axis-parallel rectangle (every triangle of a square lattice): the
    // centre is the midpoint of the rectangle's diagonal, (x0 + x1) / 2 and (y0 + y1) / 2 of
    // the two distinct x and y values; halving is exact, so rounding the sum once gives the
    // correctly rounded centre (the same bits as the filters below)
    double x[2], y[2];
    if (rectangle_corners(a, b, c, x, y)) return {0.5 * (x[0] + x[1]), 0.5 * (y[0] + y[1])};
    const DoubleDouble dbx = dd_diff(b.x, a.x), dby = dd_diff(b.y, a.y);
    const DoubleDouble dcx = dd_diff(c.x, a.x), dcy = dd_diff(c.y, a.y);
    Vec2d r;
    if (extended_precision_works() ? circumcentre_extended(a, dbx, dby, dcx, dcy, &r)
                                   : circumcentre_double(a, dbx, dby, dcx, dcy, &r))
        return r;
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
    return build_delaunay(sites, count, *dt, lo, hi, true);  // Hilbert numbering
}

// Step 3, union of cocircular triangles: triangles that share a circumcircle (exact incircle
// == 0 across their edge) are one Voronoi vertex. root[t]: the group of triangle t (its
// smallest triangle).
std::vector<int> merge_cocircular_triangles(const DelaunayTriangulation& dt, bool* any_merged) {
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
            // the vertex of nb across the shared edge (no branch to mispredict)
            const int d = other.v[int(other.n[1] == t) + 2 * int(other.n[2] == t)];
            if (incircle(pts[std::size_t(tri.v[0])], pts[std::size_t(tri.v[1])],
                         pts[std::size_t(tri.v[2])], pts[std::size_t(d)]) == 0.0) {
                int ra = find_root(parent, t), rb = find_root(parent, nb);
                if (ra != rb) parent[std::size_t(std::max(ra, rb))] = std::min(ra, rb);
                *any_merged = true;
            }
        }
    }
    for (int t = 0; t < tcount; ++t) parent[std::size_t(t)] = find_root(parent, t);
    return parent;
}

// The groups of more than one triangle: best[3 * root] = -3 where every site of the group
// is a corner of the root triangle's axis-parallel rectangle (at most its 4 corners: every
// square of a square lattice), else -2. Any three corners give the same centre bits
// (circumcentre's rectangle case), so such a group needs no search for its smallest sites.
void mark_merged_groups(const DelaunayTriangulation& dt, const std::vector<int>& root,
                        std::vector<int>* best) {
    const std::vector<DelaunayTriangle>& tris = dt.triangles;
    const std::vector<Vec2d>& pts = dt.points;
    const int tcount = int(tris.size());
    for (int t = 0; t < tcount; ++t) {
        const int r = root[std::size_t(t)];
        if (r == t) continue;
        int& mark = (*best)[std::size_t(r) * 3];
        if (mark == -2) continue;  // not a rectangle (seen before)
        const int* v = tris[std::size_t(r)].v;
        double x[2], y[2];
        bool box = rectangle_corners(pts[std::size_t(v[0])], pts[std::size_t(v[1])],
                                     pts[std::size_t(v[2])], x, y);
        for (int k = 0; k < 3 && box; ++k) box = on_box(pts[std::size_t(tris[t].v[k])], x, y);
        mark = box ? -3 : -2;
    }
}

// The 3 lexicographically smallest sites of every group of more than one triangle that is
// not a rectangle, in best[3 * root .. 3 * root + 2] (sorted); best[3 * root] < 0 for the
// other triangles (-1 a single triangle, -3 a rectangle: sorted directly by the caller).
std::vector<int> smallest_sites_of_groups(const DelaunayTriangulation& dt,
                                          const std::vector<int>& root) {
    const std::vector<DelaunayTriangle>& tris = dt.triangles;
    const std::vector<Vec2d>& pts = dt.points;
    const int tcount = int(tris.size());
    std::vector<int> best(std::size_t(tcount) * 3, -1);
    mark_merged_groups(dt, root, &best);
    for (int t = 0; t < tcount; ++t) {
        int* b = &best[std::size_t(root[std::size_t(t)]) * 3];
        if (b[0] == -1 || b[0] == -3) continue;  // a single triangle or a rectangle
        if (b[0] == -2) b[0] = -1;
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
    return best;
}

// Step 4, the Voronoi vertices: one canonical circumcentre per group of cocircular triangles,
// from the group's 3 lexicographically smallest sites (the same bits whatever the order). A
// group of one triangle (all of them on sites in general position) just sorts its 3 sites.
Status voronoi_vertices(const DelaunayTriangulation& dt, const std::vector<int>& root,
                        bool any_merged, std::vector<Vec2d>* centre) {
    const std::vector<DelaunayTriangle>& tris = dt.triangles;
    const std::vector<Vec2d>& pts = dt.points;
    const int tcount = int(tris.size());
    const std::vector<int> best = any_merged ? smallest_sites_of_groups(dt, root)
                                             : std::vector<int>();
    centre->resize(static_cast<std::size_t>(tcount));
    for (int t = 0; t < tcount; ++t) {
        if (root[std::size_t(t)] != t) continue;
        const int* v = tris[std::size_t(t)].v;
        Vec2d p0 = pts[std::size_t(v[0])], p1 = pts[std::size_t(v[1])], p2 = pts[std::size_t(v[2])];
        double x[2], y[2];
        // a single triangle or a rectangle group whose sites make an axis-parallel rectangle:
        // its midpoint (any three corners, in any order, give the same bits)
        const bool own_sites = !any_merged || best[std::size_t(t) * 3] < 0;
        if (own_sites && rectangle_corners(p0, p1, p2, x, y)) {
            (*centre)[std::size_t(t)] = {0.5 * (x[0] + x[1]), 0.5 * (y[0] + y[1])};
            continue;
        }
        if (any_merged && best[std::size_t(t) * 3] >= 0) {
            const int* b = &best[std::size_t(t) * 3];
            p0 = pts[std::size_t(b[0])], p1 = pts[std::size_t(b[1])], p2 = pts[std::size_t(b[2])];
        } else {  // sort the 3 (distinct) sites
            if (lex_less(p1, p0)) std::swap(p0, p1);
            if (lex_less(p2, p1)) std::swap(p1, p2);
            if (lex_less(p1, p0)) std::swap(p0, p1);
        }
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

// Step 6a, the vertices that need no clipping: a group's centre is INSIDE when it lies
// strictly inside every region edge's line and farther than the snap distance from it, the
// same exact test (orient2d, polygon.hpp) that clip_to_convex_region makes for each vertex;
// a cell whose vertices are all inside comes out of the clipping unchanged. Decided once per
// Voronoi vertex, not once per cell (a vertex is shared by three cells or more).
std::vector<unsigned char> centres_inside(const DelaunayTriangulation& dt,
                                          const std::vector<int>& root,
                                          const std::vector<Vec2d>& centre, const Vec2d* region,
                                          int region_count, double snap) {
    std::vector<double> reach(static_cast<std::size_t>(region_count));
    for (int k = 0; k < region_count; ++k)
        reach[std::size_t(k)] = snap * length(region[(k + 1) % region_count] - region[k]);
    const int tcount = int(dt.triangles.size());
    std::vector<unsigned char> inside(static_cast<std::size_t>(tcount), 0);
    for (int t = 0; t < tcount; ++t) {
        if (root[std::size_t(t)] != t) continue;
        const Vec2d c = centre[std::size_t(t)];
        bool in = true;
        for (int k = 0; k < region_count && in; ++k) {
            const double s = orient2d(region[k], region[(k + 1) % region_count], c);
            in = s > 0.0 && !(std::fabs(s) <= reach[std::size_t(k)]);
        }
        inside[std::size_t(t)] = in ? 1 : 0;
    }
    return inside;
}

// The groups around site s counter-clockwise, each once (the vertices of its unclipped cell),
// as the dual walk visits them, appended to *ring. False when one of them is not inside (the
// cell needs the clipping); nothing is appended then.
bool inside_cell(const DelaunayTriangulation& dt, const std::vector<int>& root,
                 const std::vector<unsigned char>& inside, int s, std::vector<int>* ring) {
    const std::vector<DelaunayTriangle>& tris = dt.triangles;
    const std::size_t first = ring->size();
    const int t0 = dt.point_triangle[std::size_t(s)];
    int t = t0;
    do {
        const DelaunayTriangle& tri = tris[std::size_t(t)];
        const int i = int(tri.v[1] == s) + 2 * int(tri.v[2] == s);  // no branch to mispredict
        const int g = root[std::size_t(t)];
        if (!inside[std::size_t(g)]) {
            ring->resize(first);
            return false;
        }
        if (ring->size() == first || ring->back() != g) ring->push_back(g);
        t = tri.n[i == 2 ? 0 : i + 1];  // next triangle counter-clockwise, as in dual_walk
    } while (t != t0);
    if (ring->size() - first > 1 && ring->back() == (*ring)[first]) ring->pop_back();
    return true;
}

// An unclipped cell as clip_to_convex_region leaves it, first half: repeated points dropped
// (two groups whose centres round to the same bits) and fewer than 3 vertices made empty, in
// place on groups[0 .. n). Returns the count left.
int drop_repeated_centres(int* groups, int n, const std::vector<Vec2d>& centre) {
    int w = 0;
    for (int k = 0; k < n; ++k) {
        if (w > 0 && centre[std::size_t(groups[w - 1])] == centre[std::size_t(groups[k])])
            continue;
        groups[w++] = groups[k];
    }
    while (w > 1 && centre[std::size_t(groups[0])] == centre[std::size_t(groups[w - 1])]) --w;
    return w < 3 ? 0 : w;
}

// The second half: the cell's vertices written to cell[0 .. n), started at the
// lexicographically smallest.
void write_inside_cell(const int* groups, int n, const std::vector<Vec2d>& centre, Vec2d* cell) {
    int m = 0;
    Vec2d smallest = centre[std::size_t(groups[0])];
    for (int k = 1; k < n; ++k) {
        const Vec2d p = centre[std::size_t(groups[k])];
        if (lex_less(p, smallest)) m = k, smallest = p;
    }
    for (int k = m; k < n; ++k) *cell++ = centre[std::size_t(groups[k])];
    for (int k = 0; k < m; ++k) *cell++ = centre[std::size_t(groups[k])];
}

// The cells that reach the region's boundary (few: O(sqrt n) on spread-out sites), clipped,
// in Hilbert order of their sites.
struct ClippedCells {
    std::vector<int> ring, ring_start;  // per Hilbert number: the inside cells' groups
    std::vector<int> site;              // Hilbert number of the site
    std::vector<int> start;
    std::vector<Vec2d> points;
    std::vector<int> labels;  // 2 per point
};

// Step 6b, clipping: a cell with a vertex not inside is clipped to the region (polygon.hpp)
// and started at its lexicographically smallest vertex; the others are only counted. Sites
// are visited in Hilbert order (memory stays local). out->offsets[i + 1] gets the size of
// input site i's cell.
void clip_cells(const DelaunayTriangulation& dt, const std::vector<int>& root,
                const std::vector<Vec2d>& centre, const std::vector<unsigned char>& inside,
                const Vec2d* region, int region_count, double snap, ClippedCells* clipped,
                VoronoiCells* out) {
    const int count = dt.input_count;
    std::vector<ClipVertex> poly, scratch;
    out->offsets.assign(std::size_t(count) + 1, 0);
    clipped->ring.reserve(std::size_t(count) * 6 + 64);
    clipped->ring_start.resize(std::size_t(count) + 1);
    for (int s = 0; s < count; ++s) {  // s: Hilbert number of the site
        const std::size_t site = std::size_t(dt.insertion_order[std::size_t(s)]);
        const std::size_t first = clipped->ring.size();
        clipped->ring_start[std::size_t(s)] = int(first);
        if (dt.point_triangle[std::size_t(s)] < 0) continue;  // a duplicate site: empty
        if (inside_cell(dt, root, inside, s, &clipped->ring)) {
            const int n = drop_repeated_centres(clipped->ring.data() + first,
                                                int(clipped->ring.size() - first), centre);
            clipped->ring.resize(first + std::size_t(n));
            out->offsets[site + 1] = n;
            continue;
        }
        dual_walk(dt, root, centre, s, &poly);
        clip_to_convex_region(&poly, region, region_count, snap, &scratch);
        std::size_t m = 0;
        for (std::size_t k = 1; k < poly.size(); ++k)
            if (lex_less(poly[k].p, poly[m].p)) m = k;
        std::rotate(poly.begin(), poly.begin() + std::ptrdiff_t(m), poly.end());
        clipped->site.push_back(s);
        clipped->start.push_back(int(clipped->points.size()));
        for (const ClipVertex& v : poly) {
            clipped->points.push_back(v.p);
            clipped->labels.push_back(v.on[0]);
            clipped->labels.push_back(v.on[1]);
        }
        out->offsets[site + 1] = int(poly.size());
    }
    clipped->ring_start[std::size_t(count)] = int(clipped->ring.size());
}

// Step 7: the cells in input order (cell i belongs to sites[i]), written straight into the
// result: offsets from the sizes, then the inside cells made from their groups and the
// clipped ones copied.
void cells_in_input_order(const DelaunayTriangulation& dt, const std::vector<Vec2d>& centre,
                          const ClippedCells& clipped, VoronoiCells* out) {
    const int count = dt.input_count;
    for (int i = 0; i < count; ++i)
        out->offsets[std::size_t(i) + 1] += out->offsets[std::size_t(i)];
    const std::size_t total = std::size_t(out->offsets[std::size_t(count)]);
    out->vertices.resize(total);
    out->on_region_edge.assign(2 * total, -1);
    out->duplicate_of = dt.duplicate_of;
    std::size_t next = 0;  // the next clipped cell (they are in Hilbert order)
    for (int s = 0; s < count; ++s) {
        const std::size_t site = std::size_t(dt.insertion_order[std::size_t(s)]);
        const std::size_t first = std::size_t(out->offsets[site]);
        const int size = out->offsets[site + 1] - out->offsets[site];
        if (next < clipped.site.size() && clipped.site[next] == s) {
            const std::size_t from = std::size_t(clipped.start[next++]);
            for (int k = 0; k < size; ++k) {
                out->vertices[first + std::size_t(k)] = clipped.points[from + std::size_t(k)];
                out->on_region_edge[2 * (first + std::size_t(k))] =
                    clipped.labels[2 * (from + std::size_t(k))];
                out->on_region_edge[2 * (first + std::size_t(k)) + 1] =
                    clipped.labels[2 * (from + std::size_t(k)) + 1];
            }
        } else if (size > 0) {  // its groups, after the repeated ones were dropped
            const int from = clipped.ring_start[std::size_t(s)];
            write_inside_cell(clipped.ring.data() + from, size, centre,
                              out->vertices.data() + first);
        }
    }
}

}  // namespace

Status voronoi_cells(const Vec2d* sites, int count, const Vec2d* region, int region_count,
                     VoronoiCells& out) {
    SHITSUKAN_TRY(check_voronoi_arguments(sites, count, region, region_count, &out));
    DelaunayTriangulation dt;
    SHITSUKAN_TRY(triangulate_sites(sites, count, region, region_count, &dt));
    bool any_merged = false;
    std::vector<int> root = merge_cocircular_triangles(dt, &any_merged);
    std::vector<Vec2d> centre;
    SHITSUKAN_TRY(voronoi_vertices(dt, root, any_merged, &centre));
    const double snap = clip_snap_distance(region, region_count);
    std::vector<unsigned char> inside = centres_inside(dt, root, centre, region, region_count, snap);
    ClippedCells clipped;
    clip_cells(dt, root, centre, inside, region, region_count, snap, &clipped, &out);
    // the triangulation is walked no more: freed before the result is allocated (the peak
    // working set is the larger of the two halves, not their sum)
    std::vector<DelaunayTriangle>().swap(dt.triangles);
    std::vector<Vec2d>().swap(dt.points);
    std::vector<int>().swap(dt.point_triangle);
    std::vector<int>().swap(root);
    std::vector<unsigned char>().swap(inside);
    cells_in_input_order(dt, centre, clipped, &out);
    return Status::success();
}

}  // namespace shitsukan
