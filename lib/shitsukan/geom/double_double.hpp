// shitsukan/geom/double_double.hpp — double-double numbers (about 106 significant bits) for the
// few geometric constructions that must not lose their digits to cancellation.
//
// Manual
//   // The intersection of two lines, to double-double precision in the middle steps:
//   double ax = 0.1, bx_ = 3.7, cx = 0.3, cy = 2.0, by = 0.9;
//   DoubleDouble bx = dd_diff(bx_, ax);             // exact: bx_ - ax as hi + lo
//   DoubleDouble d = dd_sub(dd_mul(bx, dd_from(cy)), dd_mul(dd_from(by), dd_from(cx)));
//   DoubleDouble num = dd_diff(1.0, 0.25);
//   double x = dd_round(dd_add(dd_from(ax), dd_div(num, d)));
//
// Why: the circumcentre of three sites one ulp apart, or the point where a bisector meets a
// clip line, is a ratio of determinants whose terms cancel almost completely; in doubles the
// denominator rounds to 0 (a NaN vertex) or the point lands far off. In double-double the
// coordinate differences are exact and each product keeps ~106 bits, so the result is
// correctly rounded but for a condition number beyond ~2^50.
//
// Algorithms: Dekker (1971) / Knuth TWO-SUM and Dekker's split TWO-PRODUCT (no FMA: the
// project compiles with -ffp-contract=off and wants the same bits on every compiler), and the
// usual double-double add / multiply / divide (Hida, Li & Bailey 2001). Valid while products
// stay below ~1e300 (the callers keep coordinates within 1e50). Header only, no allocation.
// small-device: yes
#pragma once

namespace shitsukan {

struct DoubleDouble {
    double hi = 0.0, lo = 0.0;  // value hi + lo, |lo| <= ulp(hi) / 2
};

namespace dd_detail {
inline DoubleDouble two_sum(double a, double b) {
    double s = a + b;
    double bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}
inline DoubleDouble fast_two_sum(double a, double b) {  // |a| >= |b| or a == 0
    double s = a + b;
    return {s, b - (s - a)};
}
inline void split(double a, double& hi, double& lo) {
    double c = 134217729.0 * a;  // 2^27 + 1
    hi = c - (c - a);
    lo = a - hi;
}
inline DoubleDouble two_product(double a, double b) {
    double p = a * b, ah, al, bh, bl;
    split(a, ah, al);
    split(b, bh, bl);
    return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}
}  // namespace dd_detail

inline DoubleDouble dd_from(double a) { return {a, 0.0}; }
inline double dd_round(DoubleDouble a) { return a.hi + a.lo; }
// a - b exactly (for finite doubles whose difference does not overflow)
inline DoubleDouble dd_diff(double a, double b) { return dd_detail::two_sum(a, -b); }

inline DoubleDouble dd_add(DoubleDouble a, DoubleDouble b) {
    DoubleDouble s = dd_detail::two_sum(a.hi, b.hi);
    DoubleDouble t = dd_detail::two_sum(a.lo, b.lo);
    s.lo += t.hi;
    s = dd_detail::fast_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return dd_detail::fast_two_sum(s.hi, s.lo);
}
inline DoubleDouble dd_neg(DoubleDouble a) { return {-a.hi, -a.lo}; }
inline DoubleDouble dd_sub(DoubleDouble a, DoubleDouble b) { return dd_add(a, dd_neg(b)); }
inline DoubleDouble dd_mul(DoubleDouble a, DoubleDouble b) {
    DoubleDouble p = dd_detail::two_product(a.hi, b.hi);
    p.lo += a.hi * b.lo + a.lo * b.hi;
    return dd_detail::fast_two_sum(p.hi, p.lo);
}
inline DoubleDouble dd_scale(DoubleDouble a, double power_of_two) {  // exact
    return {a.hi * power_of_two, a.lo * power_of_two};
}
// a / b (b != 0): three correction steps, error ~2^-104 relative.
inline DoubleDouble dd_div(DoubleDouble a, DoubleDouble b) {
    double q1 = a.hi / b.hi;
    DoubleDouble r = dd_sub(a, dd_mul(b, dd_from(q1)));
    double q2 = r.hi / b.hi;
    r = dd_sub(r, dd_mul(b, dd_from(q2)));
    double q3 = r.hi / b.hi;
    DoubleDouble q = dd_detail::fast_two_sum(q1, q2);
    return dd_add(q, dd_from(q3));
}

}  // namespace shitsukan
