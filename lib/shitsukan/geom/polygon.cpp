#include "shitsukan/geom/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shitsukan/geom/double_double.hpp"
#include "shitsukan/geom/predicates.hpp"

namespace shitsukan {
namespace {

template <class V> double area_of(const V* v, int n) {
    if (n < 3) return 0.0;
    // Relative to the first vertex: far from the origin the products x * y would cancel.
    const double ox = double(v[0].x), oy = double(v[0].y);
    double twice = 0.0;
    for (int i = 1; i + 1 < n; ++i) {
        double ax = double(v[i].x) - ox, ay = double(v[i].y) - oy;
        double bx = double(v[i + 1].x) - ox, by = double(v[i + 1].y) - oy;
        twice += ax * by - bx * ay;
    }
    return 0.5 * twice;
}

template <class V> Vec2d centroid_of(const V* v, int n) {
    double twice = 0.0, cx = 0.0, cy = 0.0;
    // Relative to the first vertex: keeps the products small for polygons far from the origin.
    const double ox = double(v[0].x), oy = double(v[0].y);
    for (int i = 0; i < n; ++i) {
        double ax = double(v[i].x) - ox, ay = double(v[i].y) - oy;
        double bx = double(v[(i + 1) % n].x) - ox, by = double(v[(i + 1) % n].y) - oy;
        double c = ax * by - bx * ay;
        twice += c;
        cx += (ax + bx) * c;
        cy += (ay + by) * c;
    }
    if (twice == 0.0) {  // degenerate: vertex mean
        double sx = 0, sy = 0;
        for (int i = 0; i < n; ++i) {
            sx += double(v[i].x);
            sy += double(v[i].y);
        }
        return {sx / n, sy / n};
    }
    return {ox + cx / (3.0 * twice), oy + cy / (3.0 * twice)};
}

template <class V, class S> bool inside_of(const V* v, int n, V q) {
    bool inside = false;
    for (int i = 0; i < n; ++i) {
        V a = v[i], b = v[(i + 1) % n];
        if (b.y < a.y || (b.y == a.y && b.x < a.x)) {  // canonical order: lower end first
            V t = a;
            a = b;
            b = t;
        }
        if (!(q.y >= a.y && q.y < b.y)) continue;  // half-open in y
        S t = (S(q.y) - S(a.y)) / (S(b.y) - S(a.y));
        S x = S(a.x) + t * (S(b.x) - S(a.x));
        if (S(q.x) < x) inside = !inside;
    }
    return inside;
}

void add_label(ClipVertex& v, int k) {
    if (v.on[0] == k || v.on[1] == k) return;
    if (v.on[0] < 0)
        v.on[0] = k;
    else if (v.on[1] < 0)
        v.on[1] = k;
}

bool has_label(const ClipVertex& v, int k) { return k >= 0 && (v.on[0] == k || v.on[1] == k); }

bool lex_less(Vec2d a, Vec2d b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

}  // namespace

double polygon_area(const Vec2d* v, int n) { return area_of(v, n); }
double polygon_area(const Vec2* v, int n) { return area_of(v, n); }
Vec2d polygon_centroid(const Vec2d* v, int n) { return centroid_of(v, n); }
Vec2d polygon_centroid(const Vec2* v, int n) { return centroid_of(v, n); }
bool point_in_polygon(const Vec2d* v, int n, Vec2d q) { return inside_of<Vec2d, double>(v, n, q); }
bool point_in_polygon(const Vec2* v, int n, Vec2 q) { return inside_of<Vec2, double>(v, n, q); }

// 0 for a direction in [0, pi) (measured from +x), 1 for [pi, 2 pi).
int direction_half(Vec2d d) { return (d.y < 0.0 || (d.y == 0.0 && d.x < 0.0)) ? 1 : 0; }

Status check_convex_region(const Vec2d* region, int m) {
    if (region == nullptr || m < 3)
        return Status::error(StatusCode::invalid_argument,
                             "region: need a convex polygon of at least 3 vertices (got %d)", m);
    for (int i = 0; i < m; ++i) {
        if (!is_finite(region[i]))
            return Status::error(StatusCode::invalid_argument,
                                 "region: vertex %d = (%g, %g) is not finite", i, region[i].x,
                                 region[i].y);
    }
    for (int i = 0; i < m; ++i)
        if (region[i] == region[(i + 1) % m])
            return Status::error(StatusCode::invalid_argument,
                                 "region: vertices %d and %d are the same point (%g, %g)", i,
                                 (i + 1) % m, region[i].x, region[i].y);
    int left_turns = 0, wraps = 0;
    for (int i = 0; i < m; ++i) {
        const Vec2d a = region[i], b = region[(i + 1) % m], c = region[(i + 2) % m];
        const double o = orient2d(a, b, c);
        if (o < 0.0)
            return Status::error(StatusCode::invalid_argument,
                                 "region: not convex and counter-clockwise at vertex %d",
                                 (i + 1) % m);
        // straight on: the next edge must not turn back along this one (exact: the edges are
        // collinear, so comparing coordinates decides the direction)
        if (o == 0.0 && ((b.x - a.x > 0.0) != (c.x - b.x > 0.0) ||
                         (b.x - a.x < 0.0) != (c.x - b.x < 0.0) ||
                         (b.y - a.y > 0.0) != (c.y - b.y > 0.0) ||
                         (b.y - a.y < 0.0) != (c.y - b.y < 0.0)))
            return Status::error(StatusCode::invalid_argument,
                                 "region: the outline turns back at vertex %d", (i + 1) % m);
        left_turns += o > 0.0;
        // every turn is in [0, pi): the direction angle passes 2 pi -> 0 exactly when it goes
        // from the lower half to the upper half
        wraps += direction_half(b - a) == 1 && direction_half(c - b) == 0;
    }
    if (left_turns == 0)
        return Status::error(StatusCode::invalid_argument,
                             "region: all %d vertices are collinear (area 0)", m);
    if (wraps != 1)
        return Status::error(StatusCode::invalid_argument,
                             "region: the outline winds %d times around (must be once: a convex "
                             "counter-clockwise polygon)",
                             wraps);
    return Status::success();
}

double clip_snap_distance(const Vec2d* region, int m) {
    // Snap distance: rounded Voronoi vertices of a lattice that should lie ON the boundary
    // miss it by an ulp and would leave cells 1e-17 wide. Relative to the smaller of the
    // diameter and the width (the largest distance of a vertex from an edge's line, smallest
    // over the edges), so a thin region is not snapped away.
    double diameter = 0.0, width = std::numeric_limits<double>::infinity();
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j)
            diameter = std::max(diameter, length(region[i] - region[j]));
    for (int k = 0; k < m; ++k) {
        const Vec2d b0 = region[k], e = region[(k + 1) % m] - b0;
        const double el = length(e);
        if (!(el > 0.0)) continue;
        double reach = 0.0;
        for (int i = 0; i < m; ++i) reach = std::max(reach, std::fabs(cross(e, region[i] - b0)) / el);
        width = std::min(width, reach);
    }
    return kClipSnapRelative * std::min(diameter, width);
}

void clip_to_convex_region(std::vector<ClipVertex>* poly, const Vec2d* region, int m,
                           std::vector<ClipVertex>* scratch) {
    clip_to_convex_region(poly, region, m, clip_snap_distance(region, m), scratch);
}

namespace {

// The point where the bisector of s and t meets the line b0 -> b1, in double-double:
// X = b0 + u (b1 - b0), u = (|t - b0|^2 - |s - b0|^2) / (2 (b1 - b0) . (t - s)). s, t in
// lexicographic order, so both cells of the edge get the same bits. False when parallel.
bool bisector_meets_line(Vec2d s, Vec2d t, Vec2d b0, Vec2d b1, Vec2d* x) {
    if (lex_less(t, s)) std::swap(s, t);
    const DoubleDouble sx = dd_diff(s.x, b0.x), sy = dd_diff(s.y, b0.y);
    const DoubleDouble tx = dd_diff(t.x, b0.x), ty = dd_diff(t.y, b0.y);
    const DoubleDouble ex = dd_diff(b1.x, b0.x), ey = dd_diff(b1.y, b0.y);
    const DoubleDouble dx = dd_diff(t.x, s.x), dy = dd_diff(t.y, s.y);
    const DoubleDouble num = dd_sub(dd_add(dd_mul(tx, tx), dd_mul(ty, ty)),
                                    dd_add(dd_mul(sx, sx), dd_mul(sy, sy)));
    const DoubleDouble den = dd_scale(dd_add(dd_mul(ex, dx), dd_mul(ey, dy)), 2.0);
    if (den.hi == 0.0) return false;
    // num and den carry ~2^-104 of their terms' size as error; if that could move the point
    // by more than ~2^-60 of its own coordinates (sites far closer to each other than to the
    // line), the interpolation between the edge's end points is used instead
    const double num_terms = tx.hi * tx.hi + ty.hi * ty.hi + sx.hi * sx.hi + sy.hi * sy.hi;
    const double den_terms = 2.0 * (std::fabs(ex.hi * dx.hi) + std::fabs(ey.hi * dy.hi));
    const double e_len = std::fabs(ex.hi) + std::fabs(ey.hi);
    const double u_error = std::ldexp(num_terms + std::fabs(num.hi / den.hi) * den_terms, -100) /
                           std::fabs(den.hi);
    const double u_estimate = std::fabs(num.hi / den.hi);
    const double mag = std::fabs(b0.x) + std::fabs(b0.y) + e_len * (1.0 + u_estimate);
    if (!(u_error * e_len <= std::ldexp(mag, -60))) return false;  // relative to the point
    const DoubleDouble u = dd_div(num, den);
    *x = {dd_round(dd_add(dd_from(b0.x), dd_mul(u, ex))),
          dd_round(dd_add(dd_from(b0.y), dd_mul(u, ey)))};
    return is_finite(*x);
}

// The point where the line a0 -> a1 meets the line b0 -> b1 (double-double). False when
// parallel.
bool lines_meet(Vec2d a0, Vec2d a1, Vec2d b0, Vec2d b1, Vec2d* x) {
    // a0 + u (a1 - a0) on line b: u = cross(b1 - b0, b0 - a0) / cross(b1 - b0, a1 - a0)
    const DoubleDouble ex = dd_diff(b1.x, b0.x), ey = dd_diff(b1.y, b0.y);
    const DoubleDouble fx = dd_diff(a1.x, a0.x), fy = dd_diff(a1.y, a0.y);
    const DoubleDouble gx = dd_diff(b0.x, a0.x), gy = dd_diff(b0.y, a0.y);
    const DoubleDouble num = dd_sub(dd_mul(ex, gy), dd_mul(ey, gx));
    const DoubleDouble den = dd_sub(dd_mul(ex, fy), dd_mul(ey, fx));
    if (den.hi == 0.0) return false;
    const DoubleDouble u = dd_div(num, den);
    *x = {dd_round(dd_add(dd_from(a0.x), dd_mul(u, fx))),
          dd_round(dd_add(dd_from(a0.y), dd_mul(u, fy)))};
    return is_finite(*x);
}

}  // namespace

namespace {

// The line a clip step cuts with: region edge k (k >= 0: labels and snapping apply) or edge j
// of the guard box (k = -2 - j: no labels, no snapping; see clip_to_guard_box).
struct ClipLine {
    Vec2d b0, b1;
    int k;
};

// The line along which the edge leaving a vertex runs (ClipVertex::along), as two points.
void along_line(int along, const Vec2d* region, int m, const Vec2d* box, Vec2d* p0, Vec2d* p1) {
    if (along >= 0) {
        *p0 = region[along];
        *p1 = region[(along + 1) % m];
    } else {
        const int j = -2 - along;
        *p0 = box[j];
        *p1 = box[(j + 1) % 4];
    }
}

// Sutherland-Hodgman step 1: the exact side of every vertex (orient2d > 0: inside), with
// vertices within `snap` of a region edge's line moved onto it and labelled: across the line,
// along its normal (moving along the edge left a vertex off the line, labelled as on it, and
// the sliver between belonged to no cell). Not onto a corner when the vertex is on the
// neighbouring edge too: two nearly collinear edges lie within the snap distance of each other
// over their whole length (fuzz_voronoi: a corner of 180 - 5e-18 degrees), and a vertex moved
// to their corner moved by 1440 units. Returns true when every vertex is strictly inside.
bool classify_vertices(std::vector<ClipVertex>& in, const ClipLine& line, double snap,
                       double* side) {
    const Vec2d b0 = line.b0, b1 = line.b1;
    const int k = line.k;
    const double edge_length = length(b1 - b0);
    bool all_inside = true;
    for (std::size_t i = 0; i < in.size(); ++i) {
        ClipVertex& v = in[i];
        double s = has_label(v, k) ? 0.0 : orient2d(b0, b1, v.p);
        if (k >= 0 && s != 0.0 && std::fabs(s) <= snap * edge_length) {  // |s| = dist * |b1 - b0|
            s = 0.0;
            const Vec2d e = b1 - b0;
            if (b0.x == b1.x)
                v.p.x = b0.x;
            else if (b0.y == b1.y)
                v.p.y = b0.y;
            else  // minus the normal (-e.y, e.x) times the signed distance over |e|
                v.p = v.p - Vec2d{-e.y, e.x} * (cross(e, v.p - b0) / (edge_length * edge_length));
        }
        if (s == 0.0 && k >= 0) add_label(v, k);
        side[i] = s;
        all_inside = all_inside && s > 0.0;
    }
    return all_inside;
}

// Sutherland-Hodgman step 2, the intersection: where the polygon edge cur -> nxt crosses the
// line, constructed from the edge's support (a bisector or a line it runs along) when it has
// one, else interpolated between the end points in lexicographic order (same bits from both
// cells that share the edge).
ClipVertex cut_edge(const ClipVertex& cur, const ClipVertex& nxt, double sc, double sn,
                    const ClipLine& line, const Vec2d* region, int m, const Vec2d* box) {
    const Vec2d b0 = line.b0, b1 = line.b1;
    const int k = line.k;
    const ClipVertex* a = &cur;
    const ClipVertex* b = &nxt;
    double sa = sc, sb = sn;
    if (lex_less(b->p, a->p)) {
        a = &nxt;
        b = &cur;
        sa = sn;
        sb = sc;
    }
    ClipVertex x;
    bool made = false;
    if (cur.has_bisector) {
        made = bisector_meets_line(cur.bisector[0], cur.bisector[1], b0, b1, &x.p);
    } else if (cur.along != -1) {
        const int j = cur.along;
        const int lines = k >= 0 ? m : 4;  // consecutive edges of one polygon: their vertex
        if ((j >= 0) == (k >= 0) && ((j >= 0 ? j : -2 - j) + 1) % lines == (k >= 0 ? k : -2 - k))
            x.p = b0, made = true;
        else if ((j >= 0) == (k >= 0) &&
                 ((k >= 0 ? k : -2 - k) + 1) % lines == (j >= 0 ? j : -2 - j))
            x.p = b1, made = true;
        else {
            Vec2d p0, p1;
            along_line(j, region, m, box, &p0, &p1);
            made = lines_meet(p0, p1, b0, b1, &x.p);
        }
    }
    if (!made) {
        double t = sa / (sa - sb);
        x.p = {a->p.x + t * (b->p.x - a->p.x), a->p.y + t * (b->p.y - a->p.y)};
    }
    if (b0.x == b1.x) x.p.x = b0.x;  // on an axis-parallel edge: exact coordinate
    if (b0.y == b1.y) x.p.y = b0.y;
    if (k >= 0) add_label(x, k);
    for (int j = 0; j < 2; ++j)
        if (a->on[j] >= 0 && has_label(*b, a->on[j])) add_label(x, a->on[j]);
    if (sc > 0.0) {  // leaving: the boundary continues along the line
        x.along = k;
    } else {  // entering: the rest of the cut edge
        x.has_bisector = cur.has_bisector;
        x.bisector[0] = cur.bisector[0];
        x.bisector[1] = cur.bisector[1];
        x.along = cur.along;
    }
    return x;
}

// One Sutherland-Hodgman step (Sutherland & Hodgman 1974): the part of *poly on the inner
// side of the line (left of b0 -> b1), in place.
void clip_step(std::vector<ClipVertex>* poly, const ClipLine& line, double snap,
               const Vec2d* region, int m, const Vec2d* box, std::vector<ClipVertex>* scratch,
               std::vector<double>* side_heap) {
    constexpr int kStackSides = 64;
    double side_stack[kStackSides];
    std::vector<ClipVertex>& in = *poly;
    const int n = int(in.size());
    double* side = side_stack;
    if (n > kStackSides) {
        side_heap->resize(std::size_t(n));
        side = side_heap->data();
    }
    if (classify_vertices(in, line, snap, side)) return;  // the common case inside the region
    std::vector<ClipVertex>& out = *scratch;
    out.clear();
    for (int i = 0; i < n; ++i) {
        const ClipVertex& cur = in[std::size_t(i)];
        const ClipVertex& nxt = in[std::size_t((i + 1) % n)];
        const double sc = side[i], sn = side[(i + 1) % n];
        if (sc >= 0.0) {
            out.push_back(cur);
            if (sc == 0.0 && sn <= 0.0) {  // the boundary continues along the line
                out.back().has_bisector = false;
                out.back().along = line.k;
            }
        }
        if ((sc > 0.0 && sn < 0.0) || (sc < 0.0 && sn > 0.0))
            out.push_back(cut_edge(cur, nxt, sc, sn, line, region, m, box));
    }
    poly->swap(out);
}

// The guard box: the region's bounding box grown by its larger side on every side (chosen
// here: far enough that no region point is near it, near enough that its points are rounded
// at the region's scale). A cell whose vertices reach beyond it (Voronoi vertices 1e49 away,
// from a site 1e48 away) is first clipped to it: otherwise such a vertex, rounded by ~1e33,
// is on the wrong side of a region edge 1.7 away from the edge it was constructed on, and
// the clip invents a wrong cell (fuzz finding 8: nearly parallel hexagon edges). The box
// holds the region, so this changes no exact result.
void guard_box(const Vec2d* region, int m, Vec2d box[4]) {
    Vec2d lo = region[0], hi = region[0];
    for (int i = 1; i < m; ++i) {
        lo = {std::min(lo.x, region[i].x), std::min(lo.y, region[i].y)};
        hi = {std::max(hi.x, region[i].x), std::max(hi.y, region[i].y)};
    }
    const double w = std::max(hi.x - lo.x, hi.y - lo.y);
    lo = {lo.x - w, lo.y - w};
    hi = {hi.x + w, hi.y + w};
    box[0] = lo;
    box[1] = {hi.x, lo.y};
    box[2] = hi;
    box[3] = {lo.x, hi.y};
}

bool reaches_beyond(const std::vector<ClipVertex>& poly, const Vec2d box[4]) {
    for (const ClipVertex& v : poly)
        if (!(v.p.x >= box[0].x && v.p.x <= box[2].x && v.p.y >= box[0].y && v.p.y <= box[2].y))
            return true;
    return false;
}

// The end of clipping: repeated points dropped (a vertex exactly on a line can meet an
// intersection's bits), their labels merged; fewer than 3 vertices: empty.
void drop_repeated_points(std::vector<ClipVertex>& v) {
    std::size_t w = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (w > 0 && v[w - 1].p == v[i].p) {
            for (int k : v[i].on)
                if (k >= 0) add_label(v[w - 1], k);
            continue;
        }
        v[w++] = v[i];
    }
    v.resize(w);
    while (v.size() > 1 && v.front().p == v.back().p) {
        for (int k : v.back().on)
            if (k >= 0) add_label(v.front(), k);
        v.pop_back();
    }
    if (v.size() < 3) v.clear();
}

}  // namespace

void clip_to_convex_region(std::vector<ClipVertex>* poly, const Vec2d* region, int m, double snap,
                           std::vector<ClipVertex>* scratch) {
    std::vector<double> side_heap;
    Vec2d box[4];
    guard_box(region, m, box);
    if (reaches_beyond(*poly, box))
        for (int j = 0; j < 4 && !poly->empty(); ++j)
            clip_step(poly, {box[j], box[(j + 1) % 4], -2 - j}, snap, region, m, box, scratch,
                      &side_heap);
    for (int k = 0; k < m && !poly->empty(); ++k)
        clip_step(poly, {region[k], region[(k + 1) % m], k}, snap, region, m, box, scratch,
                  &side_heap);
    drop_repeated_points(*poly);
}

}  // namespace shitsukan
