// small-device: yes (no allocation, no exceptions)
// fujimoto2000 §2.2.1(1), §2.2.2(1): div, in-shf, ex-shf simulated on a real coordinate.
#include "shitsukan/wrinkly/ist_procedure.hpp"

#include <cmath>

#include "shitsukan/core/assert.hpp"

namespace shitsukan {

namespace {

double edge(const IstAxis& axis, const double* edges, int i) {
    return edges != nullptr ? edges[i] : double(i) / double(axis.base_intervals);
}

double width(const IstAxis& axis, const double* edges, int b) {
    return edge(axis, edges, b + 1) - edge(axis, edges, b);
}

// Which end of a sub-interval a point on it belongs to: fujimoto2000 §2.3.1 (below eq. 9)
// says a sub-interval with ends u_a, u_b holds u_a <= u < u_b, and u = 1 the last one; the
// division of §2.2.1(1) 1) produces exactly such half-open parts, and eq. (7) / eq. (12) map
// the left end of a part (offset Δu = 0) to the left end of its image. The procedure computes
// the ends by rounding (x_b + g w_b / N, start + g part, ...), so a point that lies on an end
// u_b may be computed a few ulps short of it; it still belongs to the part starting at u_b.
// kEndSlack is how short (chosen here: 64 ulps of 1, far above the rounding of K <= 8
// steps and far below a sub-interval of B N^K <= 2^32: 2.3e-10).
constexpr double kEndSlack = 64.0 * 2.220446049250313e-16;

// The part [start + g part, start + (g + 1) part) holding u, g in 0 .. n - 1 (a point at the
// far end, u = 1, stays in the last part).
int part_holding(double u, double start, double part, int n) {
    const double q = (u - start) / part;
    int g = int(std::floor(q));
    if ((start + double(g + 1) * part) - u <= kEndSlack) ++g;  // on the end: the next part
    return g < 0 ? 0 : (g >= n ? n - 1 : g);
}

// The offset of u in its part, 0 for a point on the left end.
double offset_in(double u, double left) { return u - left > 0.0 ? u - left : 0.0; }

int base_holding(const IstAxis& axis, const double* edges, double u) {
    const int count = axis.base_intervals;
    if (edges == nullptr) return part_holding(u, 0.0, 1.0 / double(count), count);
    int b = 0;
    while (b + 1 < count && u >= edges[b + 1] - kEndSlack) ++b;  // [x_b, x_{b+1}); 1 the last
    return b;
}

// Destination of group g of base b: (base, slot); a move past a translation end is skipped.
void destination(const IstAxis& axis, int b, int g, int* to_base, int* to_slot) {
    if (axis.kind == IstKind::unit) {
        *to_base = b;
        *to_slot = g;
        return;
    }
    int to = b + axis.shuffle.offset[g];
    if (axis.ends == IstEnds::translation) {
        if (to < 0 || to >= axis.base_intervals) {
            *to_base = b;
            *to_slot = g;
            return;
        }
    } else {
        to %= axis.base_intervals;
        if (to < 0) to += axis.base_intervals;
    }
    *to_base = to;
    *to_slot = axis.shuffle.slot[g];
}

// The group that lands in slot t of base b, and where it came from (inverse of destination).
void source(const IstAxis& axis, int b, int t, int* from_base, int* group) {
    if (axis.kind == IstKind::unit) {
        *from_base = b;
        *group = t;
        return;
    }
    int g = 0;
    while (axis.shuffle.slot[g] != t) ++g;
    int from = b - axis.shuffle.offset[g];
    if (axis.ends == IstEnds::translation) {
        if (from < 0 || from >= axis.base_intervals) {  // the exchange was skipped
            *from_base = b;
            *group = t;
            return;
        }
    } else {
        from %= axis.base_intervals;
        if (from < 0) from += axis.base_intervals;
    }
    *from_base = from;
    *group = g;
}

}  // namespace

Status ist_check_edges(const IstAxis& axis, const double* edges) {
    if (edges == nullptr) return Status::success();
    if (!(edges[0] == 0.0) || !(edges[axis.base_intervals] == 1.0))
        return Status::error(StatusCode::invalid_argument,
                             "IST: base-interval edges must run from 0 to 1 (got %g .. %g)",
                             edges[0], edges[axis.base_intervals]);
    for (int i = 0; i < axis.base_intervals; ++i)
        if (!(edges[i + 1] > edges[i]))
            return Status::error(StatusCode::invalid_argument,
                                 "IST: base-interval edges must increase: x_%d = %g, x_%d = %g",
                                 i, edges[i], i + 1, edges[i + 1]);
    return Status::success();
}

void ist_procedure_start(const IstAxis& axis, const double* edges, double u, IstPoint* point) {
    SHITSUKAN_ASSERT(point != nullptr);
    if (!(u > 0.0)) u = 0.0;
    if (u > 1.0) u = 1.0;
    // Each base interval is the initial sub-interval (§2.1(1), §2.2.2(1)).
    point->base = base_holding(axis, edges, u);
    point->start = edge(axis, edges, point->base);
    point->end = edge(axis, edges, point->base + 1);
    point->u = u;
    point->step = 0;
}

void ist_divide_and_shuffle_internally(const IstAxis& axis, const double* edges,
                                       IstPoint* point) {
    SHITSUKAN_ASSERT(point != nullptr);
    const int n = axis.n;
    const double x_b = edge(axis, edges, point->base);
    const double w_b = width(axis, edges, point->base);
    // 1) div: the sub-interval [start, end) into N parts; g = the part holding u.
    const double part = (point->end - point->start) / double(n);
    const int g = part_holding(point->u, point->start, part, n);
    const double inside = offset_in(point->u, point->start + double(g) * part);
    // 2) in-shf: group g (the g-th part of every parent, in parent order) is placed g-th;
    //    the parent's part keeps the parent's rank: offset (start - x_b) / N in the group.
    const double new_start = x_b + double(g) * w_b / double(n) + (point->start - x_b) / double(n);
    point->start = new_start;
    point->end = new_start + part;
    point->u = new_start + inside;
    point->step += 1;
}

void ist_shuffle_externally(const IstAxis& axis, const double* edges, IstPoint* point) {
    SHITSUKAN_ASSERT(point != nullptr);
    if (axis.kind == IstKind::unit) return;
    const int n = axis.n;
    const int b = point->base;
    const double x_b = edge(axis, edges, b);
    const double w_b = width(axis, edges, b);
    // 3) ex-shf: the point sits in slot g of base b (the group placed there by in-shf).
    const double slot_width = w_b / double(n);
    const int g =
        part_holding(point->start + 0.5 * (point->end - point->start), x_b, slot_width, n);
    int to = 0, slot = 0;
    destination(axis, b, g, &to, &slot);
    const double x_to = edge(axis, edges, to);
    const double scale = width(axis, edges, to) / w_b;
    const double group_from = x_b + double(g) * slot_width;
    const double group_to = x_to + double(slot) * width(axis, edges, to) / double(n);
    point->u = group_to + (point->u - group_from) * scale;
    point->start = group_to + (point->start - group_from) * scale;
    point->end = group_to + (point->end - group_from) * scale;
    point->base = to;
}

double ist_procedure_forward(const IstAxis& axis, double u, const double* edges) {
    IstPoint point;
    ist_procedure_start(axis, edges, u, &point);
    for (int k = 1; k <= axis.iterations; ++k) {
        ist_divide_and_shuffle_internally(axis, edges, &point);
        ist_shuffle_externally(axis, edges, &point);
    }
    return point.u;
}

double ist_procedure_inverse(const IstAxis& axis, double u, const double* edges) {
    if (!(u > 0.0)) u = 0.0;
    if (u > 1.0) u = 1.0;
    const int n = axis.n;
    int b = base_holding(axis, edges, u);
    // N^{k-1} equal sub-intervals per base interval on u^{k-1}: start from N^{K-1}.
    double parents = 1.0;
    for (int k = 1; k < axis.iterations; ++k) parents *= double(n);
    for (int k = axis.iterations; k >= 1; --k) {
        // Undo 3) ex-shf: the slot holding u, the group that came there and its source.
        double x_b = edge(axis, edges, b);
        double w_b = width(axis, edges, b);
        int t = part_holding(u, x_b, w_b / double(n), n);
        int from = 0, g = 0;
        source(axis, b, t, &from, &g);
        double in_slot = offset_in(u, x_b + double(t) * w_b / double(n));
        double x_from = edge(axis, edges, from);
        double w_from = width(axis, edges, from);
        in_slot *= w_from / w_b;
        // Undo 2) in-shf: the rank of the part in group g is the rank of its parent.
        double part = w_from / (parents * double(n));
        double rank_d = std::floor(in_slot / part);
        if ((rank_d + 1.0) * part - in_slot <= kEndSlack) rank_d += 1.0;  // on the end
        if (rank_d < 0.0) rank_d = 0.0;
        if (rank_d > parents - 1.0) rank_d = parents - 1.0;
        double inside = offset_in(in_slot, rank_d * part);
        // Undo 1) div: part g of parent number rank_d.
        u = x_from + rank_d * (w_from / parents) + double(g) * part + inside;
        b = from;
        parents /= double(n);
    }
    return u;
}

}  // namespace shitsukan
