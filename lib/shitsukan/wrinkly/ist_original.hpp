// shitsukan/wrinkly/ist_original.hpp — the original Iterated Shuffle Transformation of
// fujimoto2000 §2.1 (ref. 13): every base interval i has its own crossing number M_i
// (交差区間数), simulated step by step on a real coordinate.
//
// Manual
//   const int crossing[5] = {1, 1, 2, 1, 1};        // fig 2: M_i = 2 for the centre only
//   IstOriginal ist;
//   ist.base_intervals = 5;  ist.crossing = crossing;  ist.iterations = 1;
//   if (Status bad = ist_original_check(ist); !bad) return bad;  // the offending value
//   double v = ist_original_forward(ist, 0.37);     // u^0 -> u^K, eq. (1)
//   double u = ist_original_inverse(ist, v);
//   double user_u = 0.5;
//   Status s = ist_original_forward_checked(ist, user_u, v);    // checks ist and u too
//   return s;
//
// One iteration (§2.1(1)), on the sub-interval [start, end) that holds u in base interval i:
//   1) it is divided into 2 M_i + 1 equal parts;
//   2) part g goes to base interval i + g - M_i: "symmetrically to itself and the M_i
//      neighbours on each side".
// Where a part lands, chosen here (the paper shows it only in figs 1, 2): base interval j
// receives, from each source i, the group of the parts g = j - i + M_i of every sub-interval
// of i (in their order on the axis), and lays the groups out ordered by source from left to
// right. With a constant M this is exactly the fully-connected IST (the group from j + t - M
// in slot t, eq. 26), as §2.1(2) states; the tests check it at every sub-interval.
// With unequal M_i the parts dealt into j no longer add up to j's width (fig 2: base 6 with
// M = 2 gives fifths, its neighbours give thirds): chosen here, base intervals keep their
// place and width, and the groups arriving in j are scaled together to fill it, keeping their
// relative widths ("with unequal M_i the pieces have unequal widths").
// Translation axis (fig 9, §2.2.2(1)): a part whose base interval would lie past an end stays
// home and takes the place of the missing source (the fully-connected exchange left undone).
// Cyclic axis: base intervals wrap.
// Ranges: 1 <= B <= kIstMaxBase, 0 <= M_i <= 15, 0 <= K <= kIstMaxIterations; double
// precision resolves the sub-intervals while prod (2 M + 1) stays below about 2^45, and
// ist_original_check refuses K, M and edges whose finest sub-interval would be narrower than
// 2^-45 (there the inverse would divide 0 by 0). forward() returns values in [0, 1), and 1
// only for u = 1 (the paper's rule: u = 1 belongs to the last sub-interval).
// Round trips: a sub-interval of u^0 with parts g_1..g_K (a mixed-radix fraction I / D of its
// base) has the left end x_b + w_b I / D; forward and inverse map left ends to left ends
// exactly, so inverse(forward(u)) == u there (u = 0 included), and keep every other point
// inside its image sub-interval (the offset inside is kept as a fraction, so the round trip
// is good to a few ulps times the ratio of the two sub-intervals' widths: ulps with equal
// bases and constant M). ist_original_check refuses axes whose finest sub-interval on u^0
// or on u^K would be narrower than 2^-45. Cost: O(K^2 (2M + 1)) at most, forward or inverse.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/wrinkly/ist_axis.hpp"
#include "shitsukan/wrinkly/ist_procedure.hpp"

namespace shitsukan {

constexpr int kIstMaxCrossing = 15;  // 2 M + 1 <= 31 < kIstMaxN

struct IstOriginal {
    int base_intervals = 1;
    const int* crossing = nullptr;   // M_i, i = 0..B-1; nullptr: every M_i = crossing_all
    int crossing_all = 1;
    const double* edges = nullptr;   // B + 1 edges from 0 to 1; nullptr: equal widths
    int iterations = 0;              // K
    IstEnds ends = IstEnds::cyclic;
};

Status ist_original_check(const IstOriginal& ist);
int ist_original_crossing(const IstOriginal& ist, int base);  // M_i

// The point's base interval and sub-interval on u^0: the base interval itself.
void ist_original_start(const IstOriginal& ist, double u, IstPoint* point);
// One iteration u^{k-1} -> u^k: 1) divide into 2 M_i + 1, 2) deal the part symmetrically.
// If part != nullptr it receives g, the index of the part that held the point.
void ist_original_step(const IstOriginal& ist, IstPoint* point, int* part = nullptr);

double ist_original_forward(const IstOriginal& ist, double u);
// Undoes the iterations K..1: the sub-interval of u^K holding the point is located group by
// group (outermost first), its parts read back onto u^0.
double ist_original_inverse(const IstOriginal& ist, double u);

// For user input: check the description (ist_original_check) and u in [0, 1] first, and
// return the status instead of clamping u or asserting on a bad M_i.
Status ist_original_forward_checked(const IstOriginal& ist, double u, double& out);
Status ist_original_inverse_checked(const IstOriginal& ist, double u, double& out);

}  // namespace shitsukan
