#include "shitsukan/geom/delaunay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/geom/predicates.hpp"

namespace shitsukan {
namespace {

// Index of (x, y) on a Hilbert curve over a 2^16 x 2^16 grid: the classic xy -> d loop, its
// quadrant rotations (swap x and y; complement both, which commutes with the swap) kept as
// two state bits applied to the original coordinates. hilbert_bits runs that loop over the
// `bits` lowest bits of x and y from a state (bit 0: swapped, bit 1: flipped) and returns the
// index bits, the state after them in *state.
std::uint32_t hilbert_bits(std::uint32_t x, std::uint32_t y, int bits, std::uint32_t* state) {
    std::uint32_t d = 0, swapped = *state & 1u, flipped = *state >> 1;
    for (int b = bits - 1; b >= 0; --b) {
        const std::uint32_t xb = (x >> b) & 1u, yb = (y >> b) & 1u;
        const std::uint32_t rx = ((xb & ~swapped) | (yb & swapped)) ^ flipped;
        const std::uint32_t ry = ((yb & ~swapped) | (xb & swapped)) ^ flipped;
        d |= ((3u * rx) ^ ry) << (2 * b);
        const std::uint32_t turn = ry ^ 1u;  // ry == 0: rotate the quadrant
        flipped ^= turn & rx;                // rx == 1 too: complement
        swapped ^= turn;
    }
    *state = swapped | (flipped << 1);
    return d;
}

// The loop four bits of x and y at a time, from a table of its 4 states x 256 nibble pairs
// (made once by the loop itself, so the same index; the bit loop was ~4 % of a lattice's
// Voronoi cells).
struct HilbertNibbles {
    std::uint8_t index[4][256], next[4][256];
    HilbertNibbles() {
        for (std::uint32_t s = 0; s < 4; ++s)
            for (std::uint32_t xy = 0; xy < 256; ++xy) {
                std::uint32_t state = s;
                index[s][xy] = std::uint8_t(hilbert_bits(xy & 15u, xy >> 4, 4, &state));
                next[s][xy] = std::uint8_t(state);
            }
    }
};

std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y) {
    static const HilbertNibbles table;
    std::uint32_t d = 0, state = 0;
    for (int shift = 12; shift >= 0; shift -= 4) {
        const std::uint32_t xy = ((x >> shift) & 15u) | (((y >> shift) & 15u) << 4);
        d |= std::uint32_t(table.index[state][xy]) << (2 * shift);
        state = table.next[state][xy];
    }
    return d;
}

// The range where every product of the exact predicates stays exact (see delaunay.hpp).
bool coordinate_in_range(double v) {
    const double m = std::fabs(v);
    return m == 0.0 || (m >= kDelaunayMinCoordinate && m <= kDelaunayMaxCoordinate);
}

// A coordinate below the range moved away from the data (direction -1: down, +1: up) onto 0
// or onto the smallest coordinate of the range.
double outward_into_range(double v, double direction) {
    if (v == 0.0 || std::fabs(v) >= kDelaunayMinCoordinate) return v;
    if ((v > 0.0) == (direction > 0.0)) return direction * kDelaunayMinCoordinate;
    return 0.0;
}

struct BoundaryEdge {
    int u, w;          // the edge u -> w as it runs in the cavity triangle (counter-clockwise)
    int outside;       // triangle beyond it, -1 at the frame
    int outside_slot;  // index j with triangles[outside].n[j] == the cavity triangle
};

class Builder {
public:
    explicit Builder(DelaunayTriangulation* dt) : dt_(*dt) {}

    void start_frame() {
        const int n = dt_.input_count;
        // n + 4 points whose hull is the 4 frame points: 2 (n + 4) - 6 triangles at most
        // (fewer with duplicates), reserved once: no doubling, no copies, no slack
        const std::size_t most = 2 * dt_.points.size() - 6;
        dt_.triangles.clear();
        dt_.triangles.reserve(most);
        mark_.reserve(most);
        // frame points n..n+3 counter-clockwise: (-,-) (+,-) (+,+) (-,+)
        dt_.triangles.push_back({{n, n + 1, n + 2}, {-1, 1, -1}});
        dt_.triangles.push_back({{n, n + 2, n + 3}, {-1, -1, 0}});
        mark_.assign(2, -1);
        starting_at_.assign(dt_.points.size(), -1);
        last_ = 0;
    }

    // The visibility walk from the last new triangle: across the first edge (in an order
    // rotated at every step: no cycling) that has q strictly on its far side. The edge the walk
    // came in through is never that edge (q is strictly on this side of it): not tested.
    int locate(int p) const {
        const Vec2d q = dt_.points[std::size_t(p)];
        const DelaunayTriangle* tris = dt_.triangles.data();
        const Vec2d* pts = dt_.points.data();
        static constexpr int kMod3[5] = {0, 1, 2, 0, 1};  // i % 3 for i < 5
        int t = last_, from = -1, first = 0;                // first: the step count % 3
        for (;;) {
            const DelaunayTriangle& tri = tris[t];
            int moved = -1;
            for (int k = 0; k < 3; ++k) {
                const int i = kMod3[first + k];
                if (tri.n[i] == from && from >= 0) continue;
                const Vec2d a = pts[tri.v[kMod3[i + 1]]], b = pts[tri.v[kMod3[i + 2]]];
                if (orient2d(a, b, q) < 0.0) {
                    moved = tri.n[i];
                    break;
                }
            }
            if (moved < 0) return t;
            from = t;
            t = moved;
            first = kMod3[first + 1];
        }
    }

    bool circle_contains(int t, int p) const {
        const DelaunayTriangle& tri = dt_.triangles[std::size_t(t)];
        return incircle(dt_.points[std::size_t(tri.v[0])], dt_.points[std::size_t(tri.v[1])],
                        dt_.points[std::size_t(tri.v[2])], dt_.points[std::size_t(p)]) > 0.0;
    }

    // False if the point's triangle does not hold it in its circumcircle (cannot happen with
    // exact predicates inside the coordinate range; reported rather than trusted).
    bool insert(int p) {
        const int start = locate(p);
        if (!circle_contains(start, p)) return false;
        collect_cavity(start, p);
        return fill_cavity(p);
    }

private:
    // The cavity: the connected triangles whose circumcircle strictly holds p, found from the
    // start triangle across their edges, and its boundary edges in the order found. One mark
    // per triangle: p inside the cavity, -(p + 2) tested and outside (no test twice).
    void collect_cavity(int start, int p) {
        cavity_.clear();
        boundary_.clear();
        cavity_.push_back(start);
        mark_[std::size_t(start)] = p;
        const int outside = -(p + 2);
        for (std::size_t k = 0; k < cavity_.size(); ++k) {
            const int t = cavity_[k];
            const DelaunayTriangle tri = dt_.triangles[std::size_t(t)];
            for (int i = 0; i < 3; ++i) {
                const int nb = tri.n[i];
                int slot = -1;
                if (nb >= 0) {
                    const int m = mark_[std::size_t(nb)];
                    if (m == p) continue;
                    if (m != outside && circle_contains(nb, p)) {
                        mark_[std::size_t(nb)] = p;
                        cavity_.push_back(nb);
                        continue;
                    }
                    mark_[std::size_t(nb)] = outside;
                    const int* o = dt_.triangles[std::size_t(nb)].n;
                    slot = o[0] == t ? 0 : (o[1] == t ? 1 : 2);
                }
                const int u = tri.v[i == 2 ? 0 : i + 1], w = tri.v[i == 0 ? 2 : i - 1];
                boundary_.push_back({u, w, nb, slot});
            }
        }
    }

    // Re-triangulate: one triangle (p, u, w) per boundary edge, in the cavity's slots first.
    // The boundary is one cycle: each vertex starts one boundary edge and ends one, so the new
    // triangle across w -> p is the one starting at w (a vertex-indexed table; a scan of the
    // boundary per edge was quadratic in the cavity size), and that one's edge p -> w is
    // across from this one. False if the cycle does not close (reported, not trusted).
    bool fill_cavity(int p) {
        for (std::size_t k = cavity_.size(); k < boundary_.size(); ++k) {
            cavity_.push_back(int(dt_.triangles.size()));
            dt_.triangles.push_back({{0, 0, 0}, {-1, -1, -1}});
            mark_.push_back(-1);
        }
        DelaunayTriangle* tris = dt_.triangles.data();
        for (std::size_t k = 0; k < boundary_.size(); ++k) {
            const BoundaryEdge& e = boundary_[k];
            const int created = cavity_[k];
            tris[created] = {{p, e.u, e.w}, {e.outside, -1, -1}};
            if (e.outside >= 0) tris[e.outside].n[e.outside_slot] = created;
            starting_at_[std::size_t(e.u)] = created;
        }
        for (std::size_t k = 0; k < boundary_.size(); ++k) {
            const int created = cavity_[k];
            const int w = boundary_[k].w;
            const int next = starting_at_[std::size_t(w)];
            if (next < 0 || tris[next].v[0] != p || tris[next].v[1] != w) return false;
            tris[created].n[1] = next;
            tris[next].n[2] = created;
        }
        for (std::size_t k = 0; k < boundary_.size(); ++k)
            if (tris[cavity_[k]].n[2] < 0) return false;
        last_ = cavity_[0];
        return true;
    }

    DelaunayTriangulation& dt_;
    std::vector<int> mark_, cavity_;
    std::vector<int> starting_at_;  // per point: the new triangle of its boundary edge
    std::vector<BoundaryEdge> boundary_;
    int last_ = 0;
};

}  // namespace

Status build_delaunay(const Vec2d* points, int count, DelaunayTriangulation& out) {
    return build_delaunay(points, count, out, Vec2d{0, 0}, Vec2d{-1, -1});
}

Status build_delaunay(const Vec2d* points, int count, DelaunayTriangulation& out, Vec2d cover_lo,
                      Vec2d cover_hi) {
    return build_delaunay(points, count, out, cover_lo, cover_hi, false);
}

namespace {

// The steps of build_delaunay (delaunay.hpp: "Algorithm"), in order.

struct Box {
    double lo_x, hi_x, lo_y, hi_y;
};

// Step 1: the arguments, the coordinate range and the points' bounding box.
Status check_points(const Vec2d* points, int count, Box* data) {
    if (count < 1 || points == nullptr)
        return Status::error(StatusCode::invalid_argument,
                             "build_delaunay: need at least 1 point (got %d)", count);
    if (count > (1 << 28))
        return Status::error(StatusCode::too_large, "build_delaunay: %d points is more than 2^28",
                             count);
    SHITSUKAN_TRY(check_memory_budget(budget_mul(std::uint64_t(count), kDelaunayBytesPerPoint),
                                      "build_delaunay: the triangulation of the points"));
    *data = {points[0].x, points[0].x, points[0].y, points[0].y};
    for (int i = 0; i < count; ++i) {
        if (!coordinate_in_range(points[i].x) || !coordinate_in_range(points[i].y))
            return Status::error(StatusCode::invalid_argument,
                                 "build_delaunay: point %d = (%g, %g): each coordinate must be 0 "
                                 "or of magnitude in [%g, %g] (exact predicates)",
                                 i, points[i].x, points[i].y, kDelaunayMinCoordinate,
                                 kDelaunayMaxCoordinate);
        data->lo_x = std::min(data->lo_x, points[i].x);
        data->hi_x = std::max(data->hi_x, points[i].x);
        data->lo_y = std::min(data->lo_y, points[i].y);
        data->hi_y = std::max(data->hi_y, points[i].y);
    }
    return Status::success();
}

// Step 2, the frame (Bowyer 1981's "supertriangle", here a square of 4 points): 10
// half-extents out from the centre of the points and of the box to cover, so frame points
// never fall near the data. Appended to out->points.
Status add_frame(Box data, Vec2d cover_lo, Vec2d cover_hi, DelaunayTriangulation* out) {
    Box all = data;
    if (cover_lo.x <= cover_hi.x && cover_lo.y <= cover_hi.y) {
        for (double c : {cover_lo.x, cover_lo.y, cover_hi.x, cover_hi.y})
            if (!(std::fabs(c) <= kDelaunayMaxCoordinate))
                return Status::error(StatusCode::invalid_argument,
                                     "build_delaunay: the box to cover reaches %g, beyond %g", c,
                                     kDelaunayMaxCoordinate);
        // coordinates below the range only need covering: move them outward onto 0 or the
        // smallest coordinate of the range (the box grows by at most 1e-50)
        cover_lo = {outward_into_range(cover_lo.x, -1.0), outward_into_range(cover_lo.y, -1.0)};
        cover_hi = {outward_into_range(cover_hi.x, 1.0), outward_into_range(cover_hi.y, 1.0)};
        all.lo_x = std::min(all.lo_x, cover_lo.x);
        all.hi_x = std::max(all.hi_x, cover_hi.x);
        all.lo_y = std::min(all.lo_y, cover_lo.y);
        all.hi_y = std::max(all.hi_y, cover_hi.y);
    }
    double cx = 0.5 * (all.lo_x + all.hi_x), cy = 0.5 * (all.lo_y + all.hi_y);
    double half = std::max(all.hi_x - all.lo_x, all.hi_y - all.lo_y) * 0.5;
    // Points far narrower than their coordinates ((0, 0.5) and (1e-17, 0.5)) would put the
    // frame within rounding of the data (0.5 + 5e-17 == 0.5): at least 2^-20 of the magnitude.
    half = std::max(half, std::ldexp(std::max(std::fabs(cx), std::fabs(cy)), -20));
    if (!(half > 0.0)) half = 1.0;
    double m = 10.0 * half;
    const double fx0 = outward_into_range(cx - m, -1.0), fx1 = outward_into_range(cx + m, 1.0);
    const double fy0 = outward_into_range(cy - m, -1.0), fy1 = outward_into_range(cy + m, 1.0);
    out->points.push_back({fx0, fy0});
    out->points.push_back({fx1, fy0});
    out->points.push_back({fx1, fy1});
    out->points.push_back({fx0, fy1});
    return Status::success();
}

struct HilbertKey {
    std::uint32_t h;  // hilbert_index on the 2^16 x 2^16 grid: below 2^32
    int i;
};

// The keys sorted by h, stably (equal h keep their order): LSD radix sort, 4 passes of 8 bits
// (a pass whose digit is the same for every key is skipped).
void radix_sort_by_h(std::vector<HilbertKey>* keys) {
    std::vector<HilbertKey> tmp(keys->size());
    for (int shift = 0; shift < 32; shift += 8) {
        std::size_t start[257] = {};
        for (const HilbertKey& k : *keys) ++start[((k.h >> shift) & 255u) + 1];
        if (start[((keys->front().h >> shift) & 255u) + 1] == keys->size()) continue;
        for (int d = 0; d < 256; ++d) start[d + 1] += start[d];
        for (const HilbertKey& k : *keys) tmp[start[(k.h >> shift) & 255u]++] = k;
        keys->swap(tmp);
    }
}

// Step 3, the insertion order: Hilbert index on a 2^16 grid over the points' box, then
// coordinates, then index (duplicates end adjacent, the smallest index first). A radix sort
// by Hilbert index, then each run of equal Hilbert index by coordinates and index: the same
// order as one comparison sort by all three (a strict total order), in a fraction of the time.
std::vector<HilbertKey> hilbert_order(const Vec2d* points, int count, Box data) {
    std::vector<HilbertKey> order(static_cast<std::size_t>(count));
    const double lo_x = data.lo_x, lo_y = data.lo_y;
    double sx = data.hi_x > lo_x ? 65535.0 / (data.hi_x - lo_x) : 0.0;
    double sy = data.hi_y > lo_y ? 65535.0 / (data.hi_y - lo_y) : 0.0;
    for (int i = 0; i < count; ++i) {
        auto gx = std::uint32_t((points[i].x - lo_x) * sx);
        auto gy = std::uint32_t((points[i].y - lo_y) * sy);
        order[std::size_t(i)] = {hilbert_index(std::min(gx, 65535u), std::min(gy, 65535u)), i};
    }
    radix_sort_by_h(&order);
    const auto by_point = [&](const HilbertKey& a, const HilbertKey& b) {
        const Vec2d& pa = points[a.i];
        const Vec2d& pb = points[b.i];
        if (pa.x != pb.x) return pa.x < pb.x;
        if (pa.y != pb.y) return pa.y < pb.y;
        return a.i < b.i;
    };
    for (std::size_t k = 0; k < order.size();) {
        std::size_t end = k + 1;
        while (end < order.size() && order[end].h == order[k].h) ++end;
        if (end - k > 1)
            std::sort(order.begin() + std::ptrdiff_t(k), order.begin() + std::ptrdiff_t(end),
                      by_point);
        k = end;
    }
    return order;
}

// Step 4, the incremental insertion (Bowyer 1981 / Watson 1981) in Hilbert numbering (point
// k = points[order[k].i]), so neighbouring points are neighbours in memory. A duplicate point
// is not inserted: it is recorded in duplicate_of.
// The order, coarse to fine: every 64th point of the Hilbert order first, then the other
// 16th, 4th and the rest, each round along the curve (the rounds of Amenta, Choi & Rote's
// biased randomized insertion order, 2003, made deterministic: chosen here). Each round then
// spans the whole data and the far frame is walled off after the first, so a point's cavity
// stays small (in one pass along the curve the triangles between the filled part and the
// frame made a lattice point's cavity 6.2 triangles, now 3.2; uniform points 5.2, now 3.8).
// Rounds of every k-th point keep a lattice's regular patterns: random rounds took 20 % more
// time at 1024 lattice sites for fewer instructions (mispredicted branches).
Status insert_in_order(const Vec2d* points, int count, const std::vector<HilbertKey>& order,
                       DelaunayTriangulation* out) {
    out->duplicate_of.assign(std::size_t(count), -1);
    for (std::size_t k = 0; k < order.size(); ++k) out->points[k] = points[order[k].i];
    for (std::size_t k = 1; k < order.size(); ++k) {
        if (!(out->points[k - 1] == out->points[k])) continue;  // sequential, not random reads
        const int i = order[k].i, first = order[k - 1].i;
        out->duplicate_of[std::size_t(i)] = out->duplicate_of[std::size_t(first)] >= 0
                                                ? out->duplicate_of[std::size_t(first)]
                                                : first;
    }
    Builder builder(out);
    builder.start_frame();
    for (const int step : {64, 16, 4, 1})
        for (int k = 0; k < count; k += step) {
            if (step < 64 && k % (4 * step) == 0) continue;  // inserted in an earlier round
            // a duplicate (the same point as the one before it along the curve, found above):
            // not inserted; tested in Hilbert numbering (duplicate_of is in input order, and
            // random reads of it cost 10 % of the time at 1e6 uniform points)
            if (k > 0 && out->points[std::size_t(k) - 1] == out->points[std::size_t(k)]) continue;
            if (!builder.insert(k)) {
                const int i = order[std::size_t(k)].i;
                return Status::error(StatusCode::degenerate,
                                     "build_delaunay: point %d = (%.17g, %.17g) could not be "
                                     "inserted (its triangle's circle does not hold it)",
                                     i, points[i].x, points[i].y);
            }
        }
    return Status::success();
}

// Step 5: the vertices numbered back to the input's indices (unless the caller keeps the
// Hilbert numbering), the insertion order and one triangle per point.
void finish_numbering(const Vec2d* points, int count, const std::vector<HilbertKey>& order,
                      bool keep_hilbert_numbering, DelaunayTriangulation* out) {
    if (!keep_hilbert_numbering) {
        std::copy(points, points + count, out->points.begin());
        for (DelaunayTriangle& t : out->triangles)
            for (int& v : t.v)
                if (v < count) v = order[std::size_t(v)].i;
    }
    out->insertion_order.resize(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) out->insertion_order[k] = order[k].i;
    out->point_triangle.assign(std::size_t(count) + 4, -1);
    for (std::size_t t = 0; t < out->triangles.size(); ++t)
        for (int v : out->triangles[t].v) out->point_triangle[std::size_t(v)] = int(t);
}

}  // namespace

Status build_delaunay(const Vec2d* points, int count, DelaunayTriangulation& out, Vec2d cover_lo,
                      Vec2d cover_hi, bool keep_hilbert_numbering) {
    Box data{};
    SHITSUKAN_TRY(check_points(points, count, &data));
    out.input_count = count;
    out.points.assign(points, points + count);
    SHITSUKAN_TRY(add_frame(data, cover_lo, cover_hi, &out));
    const std::vector<HilbertKey> order = hilbert_order(points, count, data);
    SHITSUKAN_TRY(insert_in_order(points, count, order, &out));
    finish_numbering(points, count, order, keep_hilbert_numbering, &out);
    return Status::success();
}

}  // namespace shitsukan
