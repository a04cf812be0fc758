// shitsukan/wrinkly/ist_procedure.hpp — the unit-IST and the connected IST as a procedure on a
// real coordinate: the division and the moves of fujimoto2000 §2.2.1(1) and §2.2.2(1)
// simulated step by step, the way ref. 13 implemented the original IST (§2.3 intro).
//
// Manual
//   IstAxis axis;
//   Status s = ist_fully_connected_axis(5, 3, 5, IstEnds::cyclic, axis);    // ist_axis.hpp
//   if (!s) return s;
//   double v = ist_procedure_forward(axis, 0.37);          // equals ist_forward_double
//   double u = ist_procedure_inverse(axis, v);
//   // unequal base intervals (fig 6 draws base 6 wider): edges x_0 = 0 < .. < x_B = 1
//   const double edges[6] = {0, 0.15, 0.3, 0.7, 0.85, 1};
//   double w = ist_procedure_forward(axis, 0.37, edges);
//
//   // one iteration at a time (figures draw u^k and u^{k.5}):
//   IstPoint p;  ist_procedure_start(axis, edges, 0.37, &p);
//   for (int k = 1; k <= axis.iterations; ++k) {
//       ist_divide_and_shuffle_internally(axis, edges, &p);   // u^{k-1} -> u^{(k-1).5}
//       ist_shuffle_externally(axis, edges, &p);              // u^{(k-1).5} -> u^k
//   }
//
// The point carries the sub-interval of the current axis that holds it ([start, end), the
// paper's rule below eq. (9); u = 1 stays in the last one). A point on an end belongs to the
// part that starts there; since the procedure computes the ends by rounding, a point within
// 64 ulps of 1 (1.4e-14) short of an end is read as on it (the formulas, exact, read such a
// point in the part before; the two agree at every end of the grid, as computed by eq. 9,
// for B N^K up to 2^32). One iteration:
//   1) div      the sub-interval is cut into N equal parts; g = the part holding u.
//   2) in-shf   the parts at position g of all parents of the base interval form group g,
//               in parent order, placed g-th: the part of a parent starting at a moves to
//               x_b + g w_b / N + (a - x_b) / N.
//   3) ex-shf   group g moves to base b + offset[g] (wrapped on a cyclic axis, not moved
//               past an end of a translation axis), slot slot[g]; a group keeps its place in
//               the slot and is scaled by w_to / w_from when base widths differ.
// Double precision: the procedure is the reference the formulas are tested against.
// The axis must be valid (ist_validate) and the edges increasing (ist_check_edges).
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/wrinkly/ist_axis.hpp"

namespace shitsukan {

struct IstPoint {
    double u = 0.0;      // the coordinate on the current axis
    double start = 0.0;  // the sub-interval [start, end) that holds it
    double end = 0.0;
    int base = 0;        // the base interval that holds it
    int step = 0;        // iterations done
};

// edges: B + 1 increasing values from 0 to 1, or nullptr for B equal base intervals.
Status ist_check_edges(const IstAxis& axis, const double* edges);

void ist_procedure_start(const IstAxis& axis, const double* edges, double u, IstPoint* point);
void ist_divide_and_shuffle_internally(const IstAxis& axis, const double* edges,
                                       IstPoint* point);
void ist_shuffle_externally(const IstAxis& axis, const double* edges, IstPoint* point);

double ist_procedure_forward(const IstAxis& axis, double u, const double* edges = nullptr);
// Undoes the iterations k = K..1 (ex-shf, then in-shf: every base interval of u^{k-1} holds
// N^{k-1} equal sub-intervals, so the parent of a part is found by its place in the group).
double ist_procedure_inverse(const IstAxis& axis, double u, const double* edges = nullptr);

}  // namespace shitsukan
