// shitsukan/wrinkly/ist_formula.hpp — the IST on a real coordinate u in [0, 1] by the scale
// reverse formulas: fujimoto2000 eqs. (9), (10) (unit-IST) and (14) (fully-connected IST),
// and the digit algorithm for a general connected IST (§2.3.2, last paragraph).
//
// Manual
//   IstAxis axis;
//   Status s = ist_unit_axis(3, 2, axis);        // N = 3, K = 2
//   if (!s) return s;
//   float v = ist_forward(axis, 0.25f);          // u^K = F(u^0)
//   float u = ist_inverse(axis, v);              // u^0 = F^-1(u^K), as eq. (15) needs
//
// Eq. (9): u = (alpha_0 + Δ + sum_i alpha_i N^-i) / B, 0 <= Δ < N^-K (here u is scaled so that
// the B base intervals, each of length 1 in the paper, fill [0, 1]). The transformation
// replaces the digits and keeps Δ (eq. 10): continuous inside a sub-interval, a jump between
// sub-intervals. Ends, the paper's rule: a sub-interval [u_a, u_b) holds u_a but not u_b,
// and u = 1 belongs to the last sub-interval (Δ = N^-K there), so F(1) is the right end of
// the image of the last sub-interval.
//
// Round trips: the left end of sub-interval i of base b is computed as
// (b + i / N^K) / B (ist_position with offset 0); forward and inverse map left ends to left
// ends exactly, so inverse(forward(u)) == u there, u = 0 included, wherever the Real resolves
// the left ends (double: B N^K up to about 2^50; float: B N^K up to about 2^22). Any other u
// stays inside its image sub-interval, so the round trip is off by a few ulps at most.
//
// ist_forward / ist_inverse take a valid axis (ist_validate) and never fail: u below 0 or NaN
// is read as 0, above 1 as 1. float resolves about 2^24 sub-intervals (N^K); beyond that use
// the double versions. The *_checked versions return invalid_argument / out_of_range for a
// bad axis or a u outside [0, 1]. ist_locate / ist_position expose the split of eq. (9).
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/wrinkly/ist_axis.hpp"
#include "shitsukan/wrinkly/ist_digits.hpp"

namespace shitsukan {

float ist_forward(const IstAxis& axis, float u);
float ist_inverse(const IstAxis& axis, float u);
double ist_forward_double(const IstAxis& axis, double u);
double ist_inverse_double(const IstAxis& axis, double u);

Status ist_forward_checked(const IstAxis& axis, float u, float& out);
Status ist_inverse_checked(const IstAxis& axis, float u, float& out);

// Eq. (9) split: u -> sub-interval alpha (base and K digits) and the offset Δ inside it,
// given as a fraction of the sub-interval: offset = Δ N^K in [0, 1] (1 only for u = 1).
struct IstLocation {
    IstDigits alpha;
    double offset = 0.0;
};
void ist_locate(const IstAxis& axis, double u, IstLocation* out);
double ist_position(const IstAxis& axis, const IstLocation& location);  // eq. (9) back

}  // namespace shitsukan
