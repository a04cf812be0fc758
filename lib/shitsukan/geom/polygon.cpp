#include "shitsukan/geom/polygon.hpp"

#include <algorithm>
#include <cmath>

#include "shitsukan/geom/predicates.hpp"

namespace shitsukan {
namespace {

template <class V> double area_of(const V* v, int n) {
    double twice = 0.0;
    for (int i = 0; i < n; ++i) {
        const V& a = v[i];
        const V& b = v[(i + 1) % n];
        twice += double(a.x) * double(b.y) - double(b.x) * double(a.y);
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
    for (int i = 0; i < m; ++i) {
        if (orient2d(region[i], region[(i + 1) % m], region[(i + 2) % m]) < 0.0)
            return Status::error(StatusCode::invalid_argument,
                                 "region: not convex and counter-clockwise at vertex %d",
                                 (i + 1) % m);
    }
    double area = polygon_area(region, m);
    if (!(area > 0.0))
        return Status::error(StatusCode::invalid_argument,
                             "region: empty (area %g); need a convex counter-clockwise polygon",
                             area);
    return Status::success();
}

double clip_snap_distance(const Vec2d* region, int m) {
    // Snap distance: rounded Voronoi vertices of a lattice that should lie ON the boundary
    // (x = 7 * (1/7) ...) miss it by an ulp and would leave cells 1e-17 wide.
    double diameter = 0.0;
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j)
            diameter = std::max(diameter, length(region[i] - region[j]));
    return kClipSnapRelative * diameter;
}

void clip_to_convex_region(std::vector<ClipVertex>* poly, const Vec2d* region, int m,
                           std::vector<ClipVertex>* scratch) {
    clip_to_convex_region(poly, region, m, clip_snap_distance(region, m), scratch);
}

void clip_to_convex_region(std::vector<ClipVertex>* poly, const Vec2d* region, int m, double snap,
                           std::vector<ClipVertex>* scratch) {
    constexpr int kStackSides = 64;
    double side_stack[kStackSides];
    std::vector<double> side_heap;
    for (int k = 0; k < m && !poly->empty(); ++k) {
        const Vec2d b0 = region[k], b1 = region[(k + 1) % m];
        const double edge_length = length(b1 - b0);
        std::vector<ClipVertex>& in = *poly;
        std::vector<ClipVertex>& out = *scratch;
        out.clear();
        const int n = int(in.size());
        double* side = side_stack;
        if (n > kStackSides) {
            side_heap.resize(std::size_t(n));
            side = side_heap.data();
        }
        bool all_inside = true;
        for (int i = 0; i < n; ++i) {
            ClipVertex& v = in[std::size_t(i)];
            double s = has_label(v, k) ? 0.0 : orient2d(b0, b1, v.p);
            if (s != 0.0 && std::fabs(s) <= snap * edge_length) {  // |s| = distance * |b1 - b0|
                s = 0.0;
                if (b0.x == b1.x)
                    v.p.x = b0.x;
                else if (b0.y == b1.y)
                    v.p.y = b0.y;
                else
                    v.p =
                        v.p - (b1 - b0) * (cross(b1 - b0, v.p - b0) / (edge_length * edge_length));
            }
            if (s == 0.0) add_label(v, k);
            side[i] = s;
            all_inside = all_inside && s > 0.0;
        }
        if (all_inside) continue;  // nothing to cut (the common case inside the region)
        for (int i = 0; i < n; ++i) {
            const ClipVertex& cur = in[std::size_t(i)];
            const ClipVertex& nxt = in[std::size_t((i + 1) % n)];
            double sc = side[i];
            double sn = side[(i + 1) % n];
            if (sc >= 0.0) out.push_back(cur);
            if ((sc > 0.0 && sn < 0.0) || (sc < 0.0 && sn > 0.0)) {
                // canonical order of the segment's end points: the same bits from both cells
                const ClipVertex* a = &cur;
                const ClipVertex* b = &nxt;
                double sa = sc, sb = sn;
                if (lex_less(b->p, a->p)) {
                    a = &nxt;
                    b = &cur;
                    sa = sn;
                    sb = sc;
                }
                double t = sa / (sa - sb);
                ClipVertex x;
                x.p = {a->p.x + t * (b->p.x - a->p.x), a->p.y + t * (b->p.y - a->p.y)};
                if (b0.x == b1.x) x.p.x = b0.x;  // on an axis-parallel edge: exact coordinate
                if (b0.y == b1.y) x.p.y = b0.y;
                add_label(x, k);
                for (int j = 0; j < 2; ++j)
                    if (a->on[j] >= 0 && has_label(*b, a->on[j])) add_label(x, a->on[j]);
                out.push_back(x);
            }
        }
        poly->swap(out);
    }
    // drop repeated points (a vertex exactly on a line can meet an intersection's bits)
    std::vector<ClipVertex>& v = *poly;
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

}  // namespace shitsukan
