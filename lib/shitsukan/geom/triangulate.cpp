#include "shitsukan/geom/triangulate.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "shitsukan/core/memory_budget.hpp"

namespace shitsukan {

namespace {

struct P {
    double x, y;
};

double orient(P a, P b, P c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

bool same(P a, P b) { return a.x == b.x && a.y == b.y; }

// Proper crossing of segments ab and cd (touching at end points does not count).
bool segments_cross(P a, P b, P c, P d) {
    if (same(a, c) || same(a, d) || same(b, c) || same(b, d)) return false;
    double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return true;
    // Collinear overlap also blocks a bridge.
    auto on = [](P p, P q, P r) {  // r on segment pq (collinear assumed)
        return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) &&
               std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
    };
    if (o1 == 0 && on(a, b, c)) return true;
    if (o2 == 0 && on(a, b, d)) return true;
    return false;
}

// Even-odd point-in-polygon (crossing number) for a ring of points.
bool inside_ring(const std::vector<Vec2>& ring, P p) {
    bool in = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        P a{ring[i].x, ring[i].y}, b{ring[j].x, ring[j].y};
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            in = !in;
    }
    return in;
}

bool inside_triangle(P a, P b, P c, P p) {  // closed triangle, a b c counter-clockwise
    return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

}  // namespace

double signed_area2(const std::vector<Vec2>& ring) {
    double s = 0;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const Vec2& a = ring[i];
        const Vec2& b = ring[(i + 1) % n];
        s += double(a.x) * double(b.y) - double(b.x) * double(a.y);
    }
    return s;
}

namespace {

// The steps of triangulate_polygon (Eberly, "Triangulation by Ear Clipping"), in order.

using Rings = std::vector<std::vector<Vec2>>;
using Loop = std::vector<std::uint32_t>;

// Step 1: every ring has 3 or more finite vertices, the request fits the memory budget, the
// outer ring has area.
Status check_rings(const Rings& rings) {
    if (rings.empty())
        return Status::error(StatusCode::invalid_argument, "triangulate_polygon: no rings");
    for (std::size_t r = 0; r < rings.size(); ++r) {
        if (rings[r].size() < 3)
            return Status::error(StatusCode::invalid_argument,
                                 "triangulate_polygon: ring %zu has %zu vertices (need >= 3)", r,
                                 rings[r].size());
        for (const Vec2& v : rings[r])
            if (!is_finite(v))
                return Status::error(StatusCode::invalid_argument,
                                     "triangulate_polygon: ring %zu has a non-finite vertex", r);
    }
    std::uint64_t vertex_count = 0;
    for (const std::vector<Vec2>& ring : rings)
        vertex_count = budget_add(vertex_count, ring.size());
    SHITSUKAN_TRY(check_memory_budget(budget_mul(vertex_count, kTriangulateBytesPerVertex),
                                      "triangulate_polygon: the vertex table and ear lists"));
    if (signed_area2(rings[0]) == 0.0)
        return Status::error(StatusCode::degenerate,
                             "triangulate_polygon: outer ring has zero area");
    return Status::success();
}

// Step 2: holes lie inside the outer ring and outside each other, and no two edges of
// different rings cross: otherwise "outer minus holes" is not what the caller meant.
Status check_holes(const Rings& rings) {
    for (std::size_t r = 1; r < rings.size(); ++r) {
        for (const Vec2& v : rings[r])
            if (!inside_ring(rings[0], P{v.x, v.y}))
                return Status::error(StatusCode::invalid_argument,
                                     "triangulate_polygon: hole %zu has a vertex outside the outer "
                                     "ring",
                                     r);
        for (std::size_t q = 1; q < rings.size(); ++q)
            if (q != r && inside_ring(rings[q], P{rings[r][0].x, rings[r][0].y}))
                return Status::error(StatusCode::invalid_argument,
                                     "triangulate_polygon: hole %zu lies inside hole %zu", r, q);
    }
    for (std::size_t r = 0; r < rings.size(); ++r)
        for (std::size_t q = r + 1; q < rings.size(); ++q)
            for (std::size_t i = 0; i < rings[r].size(); ++i)
                for (std::size_t j = 0; j < rings[q].size(); ++j) {
                    const Vec2 &a = rings[r][i], &b = rings[r][(i + 1) % rings[r].size()];
                    const Vec2 &c = rings[q][j], &d = rings[q][(j + 1) % rings[q].size()];
                    if (segments_cross(P{a.x, a.y}, P{b.x, b.y}, P{c.x, c.y}, P{d.x, d.y}))
                        return Status::error(StatusCode::invalid_argument,
                                             "triangulate_polygon: rings %zu and %zu cross", r, q);
                }
    return Status::success();
}

// Step 3, the vertex table: every ring vertex once; rings as index loops with the orientation
// fixed (outer counter-clockwise, holes clockwise) so that the interior is always on the left.
std::vector<Loop> vertex_table(const Rings& rings, std::vector<Vec2>* points) {
    std::vector<Loop> loops;
    for (std::size_t r = 0; r < rings.size(); ++r) {
        Loop loop;
        for (const Vec2& v : rings[r]) {
            loop.push_back(std::uint32_t(points->size()));
            points->push_back(v);
        }
        bool ccw = signed_area2(rings[r]) > 0;
        if ((r == 0) != ccw) std::reverse(loop.begin(), loop.end());
        loops.push_back(loop);
    }
    return loops;
}

struct Vertices {
    const std::vector<Vec2>& points;
    P operator()(std::uint32_t i) const { return P{points[i].x, points[i].y}; }
};

// Step 4 (within it), a mutually visible vertex (Eberly §3): the polygon vertex V nearest to the hole's
// rightmost vertex M such that MV crosses no edge of the polygon or of a hole not yet joined,
// and leaves V into the polygon's interior. poly.size() when there is none.
std::size_t visible_vertex(const Loop& poly, const std::vector<Loop>& loops,
                           const std::vector<bool>& merged, P m, Vertices pt) {
    auto blocked = [&](P a, P b) {
        for (std::size_t k = 0; k < poly.size(); ++k)
            if (segments_cross(a, b, pt(poly[k]), pt(poly[(k + 1) % poly.size()]))) return true;
        for (std::size_t h = 1; h < loops.size(); ++h) {
            if (merged[h]) continue;
            const auto& l = loops[h];
            for (std::size_t k = 0; k < l.size(); ++k)
                if (segments_cross(a, b, pt(l[k]), pt(l[(k + 1) % l.size()]))) return true;
        }
        return false;
    };
    std::size_t best = poly.size();
    double best_d = 1e300;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        P v = pt(poly[k]);
        double d = (v.x - m.x) * (v.x - m.x) + (v.y - m.y) * (v.y - m.y);
        if (d < best_d && !blocked(m, v)) {
            // The bridge must leave V into the polygon's interior (between its edges).
            P prev = pt(poly[(k + poly.size() - 1) % poly.size()]),
              next = pt(poly[(k + 1) % poly.size()]);
            bool convex = orient(prev, v, next) >= 0;
            bool in_cone = convex ? (orient(v, next, m) >= 0 && orient(prev, v, m) >= 0)
                                  : !(orient(v, next, m) < 0 && orient(prev, v, m) < 0);
            if (!in_cone) continue;
            best = k;
            best_d = d;
        }
    }
    return best;
}

// Step 4, joining the holes (Eberly §3): the hole reaching furthest right first, a bridge from
// its rightmost vertex M to a mutually visible polygon vertex V, the hole's loop spliced in
// (V, M, ..., M, V). One loop results.
Status bridge_holes(const std::vector<Loop>& loops, Vertices pt, Loop* poly) {
    *poly = loops[0];
    std::vector<std::size_t> order;
    for (std::size_t r = 1; r < loops.size(); ++r) order.push_back(r);
    auto max_x = [&](std::size_t r) {
        double m = -1e300;
        for (std::uint32_t i : loops[r]) m = std::max(m, pt(i).x);
        return m;
    };
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return max_x(a) > max_x(b); });
    std::vector<bool> merged(loops.size(), false);
    for (std::size_t r : order) {
        const Loop& hole = loops[r];
        std::size_t mi = 0;
        for (std::size_t k = 1; k < hole.size(); ++k)
            if (pt(hole[k]).x > pt(hole[mi]).x) mi = k;
        const std::size_t best = visible_vertex(*poly, loops, merged, pt(hole[mi]), pt);
        if (best == poly->size())
            return Status::error(StatusCode::invalid_argument,
                                 "triangulate_polygon: hole %zu is not inside the outer ring", r);
        Loop joined(poly->begin(), poly->begin() + std::ptrdiff_t(best) + 1);
        for (std::size_t k = 0; k <= hole.size(); ++k)
            joined.push_back(hole[(mi + k) % hole.size()]);
        joined.insert(joined.end(), poly->begin() + std::ptrdiff_t(best), poly->end());
        poly->swap(joined);
        merged[r] = true;
    }
    return Status::success();
}

// Step 5, ear clipping (Eberly §2): a convex corner whose triangle holds no other polygon
// vertex is an ear; cut it off until a triangle remains.
Status clip_ears(Loop v, Vertices pt, std::vector<std::uint32_t>* triangles) {
    std::size_t guard = 0;
    while (v.size() > 3) {
        bool clipped = false;
        for (std::size_t k = 0; k < v.size(); ++k) {
            std::size_t kp = (k + v.size() - 1) % v.size(), kn = (k + 1) % v.size();
            P a = pt(v[kp]), b = pt(v[k]), c = pt(v[kn]);
            double o = orient(a, b, c);
            // A reflex or straight corner is no ear. (Dropping a straight corner without a
            // triangle would leave a T-junction: its vertex is still used on the other side.)
            if (o <= 0) continue;
            bool ear = true;
            for (std::size_t q = 0; q < v.size() && ear; ++q) {
                if (q == k || q == kp || q == kn) continue;
                P p = pt(v[q]);
                if (same(p, a) || same(p, b) || same(p, c)) continue;
                if (inside_triangle(a, b, c, p)) ear = false;
            }
            if (!ear) continue;
            triangles->push_back(v[kp]);
            triangles->push_back(v[k]);
            triangles->push_back(v[kn]);
            v.erase(v.begin() + std::ptrdiff_t(k));
            clipped = true;
            break;
        }
        if (!clipped) {
            double left = 0;  // only straight or doubled-back corners remain: zero area, done
            for (std::size_t k = 0; k < v.size(); ++k) {
                P a = pt(v[k]), b = pt(v[(k + 1) % v.size()]);
                left += a.x * b.y - b.x * a.y;
            }
            if (left == 0.0) break;
        }
        if (!clipped || ++guard > 100000)
            return Status::error(StatusCode::invalid_argument,
                                 "triangulate_polygon: no ear left (self-intersecting polygon?)");
    }
    if (v.size() == 3 && orient(pt(v[0]), pt(v[1]), pt(v[2])) > 0) {
        triangles->push_back(v[0]);
        triangles->push_back(v[1]);
        triangles->push_back(v[2]);
    }
    return Status::success();
}

}  // namespace

Status triangulate_polygon(const std::vector<std::vector<Vec2>>& rings, std::vector<Vec2>& points,
                           std::vector<std::uint32_t>& triangles) {
    points.clear();
    triangles.clear();
    SHITSUKAN_TRY(check_rings(rings));
    SHITSUKAN_TRY(check_holes(rings));
    const std::vector<Loop> loops = vertex_table(rings, &points);
    const Vertices pt{points};
    Loop poly;
    SHITSUKAN_TRY(bridge_holes(loops, pt, &poly));
    return clip_ears(std::move(poly), pt, &triangles);
}

}  // namespace shitsukan
