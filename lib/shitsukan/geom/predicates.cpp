// small-device: yes (no allocation; every frame under 2.5 KB of stack, see predicates.hpp)
#include "shitsukan/geom/predicates.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "shitsukan/geom/double_double.hpp"

namespace shitsukan {
namespace detail {

// An expansion is an array of doubles, increasing magnitude, non-overlapping; its value is
// the exact sum. Shewchuk 1997 §2: TWO-SUM, TWO-PRODUCT (Dekker split), and the linear-time
// merge FAST-EXPANSION-SUM and SCALE-EXPANSION, both eliminating zero components.

constexpr double kEpsilon = 1.1102230246251565e-16;  // 2^-53
constexpr double kSplitter = 134217729.0;            // 2^27 + 1

inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    double bv = x - a;
    double av = x - bv;
    y = (a - av) + (b - bv);
}

inline void fast_two_sum(double a, double b, double& x, double& y) {  // |a| >= |b|
    x = a + b;
    y = b - (x - a);
}

inline void split(double a, double& hi, double& lo) {
    double c = kSplitter * a;
    hi = c - (c - a);
    lo = a - hi;
}

inline void two_product(double a, double b, double& x, double& y) {
    x = a * b;
    double ahi, alo, bhi, blo;
    split(a, ahi, alo);
    split(b, bhi, blo);
    double err1 = x - ahi * bhi;
    double err2 = err1 - alo * bhi;
    double err3 = err2 - ahi * blo;
    y = alo * blo - err3;
}

inline void two_diff(double a, double b, double& x, double& y) { two_sum(a, -b, x, y); }

// h = e + f (h has room for elen + flen components); returns the length of h.
int fast_expansion_sum(int elen, const double* e, int flen, const double* f, double* h) {
    int ei = 0, fi = 0, hi = 0;
    double q, qnew, hh;
    double enow = e[0], fnow = f[0];
    auto take_e = [&](double& out) {
        out = enow;
        ++ei;
        if (ei < elen) enow = e[ei];
    };
    auto take_f = [&](double& out) {
        out = fnow;
        ++fi;
        if (fi < flen) fnow = f[fi];
    };
    if ((fnow > enow) == (fnow > -enow))
        take_e(q);
    else
        take_f(q);
    if (ei < elen && fi < flen) {
        double next;
        if ((fnow > enow) == (fnow > -enow))
            take_e(next);
        else
            take_f(next);
        fast_two_sum(next, q, qnew, hh);
        q = qnew;
        if (hh != 0.0) h[hi++] = hh;
        while (ei < elen && fi < flen) {
            if ((fnow > enow) == (fnow > -enow))
                take_e(next);
            else
                take_f(next);
            two_sum(q, next, qnew, hh);
            q = qnew;
            if (hh != 0.0) h[hi++] = hh;
        }
    }
    while (ei < elen) {
        double next;
        take_e(next);
        two_sum(q, next, qnew, hh);
        q = qnew;
        if (hh != 0.0) h[hi++] = hh;
    }
    while (fi < flen) {
        double next;
        take_f(next);
        two_sum(q, next, qnew, hh);
        q = qnew;
        if (hh != 0.0) h[hi++] = hh;
    }
    if (q != 0.0 || hi == 0) h[hi++] = q;
    return hi;
}

// h = e * b (room for 2 * elen components).
int scale_expansion(int elen, const double* e, double b, double* h) {
    double q, hh, p1, p0, sum;
    int hi = 0;
    two_product(e[0], b, q, hh);
    if (hh != 0.0) h[hi++] = hh;
    for (int i = 1; i < elen; ++i) {
        two_product(e[i], b, p1, p0);
        two_sum(q, p0, sum, hh);
        if (hh != 0.0) h[hi++] = hh;
        fast_two_sum(p1, sum, q, hh);
        if (hh != 0.0) h[hi++] = hh;
    }
    if (q != 0.0 || hi == 0) h[hi++] = q;
    return hi;
}

// h = e * f for short expansions (room for 2 * elen * flen); tmp needs 2 * elen, acc as h.
int multiply_expansions(int elen, const double* e, int flen, const double* f, double* h,
                        double* tmp, double* acc) {
    int hlen = scale_expansion(elen, e, f[0], h);
    for (int j = 1; j < flen; ++j) {
        int tlen = scale_expansion(elen, e, f[j], tmp);
        int alen = fast_expansion_sum(hlen, h, tlen, tmp, acc);
        for (int i = 0; i < alen; ++i) h[i] = acc[i];
        hlen = alen;
    }
    return hlen;
}

inline double expansion_sign_value(int len, const double* e) { return e[len - 1]; }

}  // namespace detail

using namespace detail;

double orient2d_exact(Vec2d a, Vec2d b, Vec2d c) {
    // det = (ax - cx)(by - cy) - (ay - cy)(bx - cx), with the differences kept exact.
    double acx[2], acy[2], bcx[2], bcy[2];
    two_diff(a.x, c.x, acx[1], acx[0]);
    two_diff(a.y, c.y, acy[1], acy[0]);
    two_diff(b.x, c.x, bcx[1], bcx[0]);
    two_diff(b.y, c.y, bcy[1], bcy[0]);
    double left[8], right[8], tmp[4], acc[8], det[16];
    int llen = multiply_expansions(2, acx, 2, bcy, left, tmp, acc);
    int rlen = multiply_expansions(2, acy, 2, bcx, right, tmp, acc);
    for (int i = 0; i < rlen; ++i) right[i] = -right[i];
    int dlen = fast_expansion_sum(llen, left, rlen, right, det);
    return expansion_sign_value(dlen, det);
}

namespace {

// The exact in-circle determinant as a sum of products of four doubles, accumulated in a
// fixed-point integer (chosen here instead of Shewchuk's full expansion product, whose
// worst-case arrays need 37.8 KB of stack, over check-small's 4 KB budget).
// Each coordinate difference is exact as two doubles (two_diff), so
//   det = sum over k of (dx_k^2 + dy_k^2) (dx_i dy_j - dx_j dy_i),  (i, j, k) cyclic,
// expands into 3 * 2 * 2 * 16 = 192 products of four doubles m 2^e (m an integer < 2^53).
// Each product is an integer of at most 212 bits, added at bit (e - e_min) to one of two
// accumulators of kSumLimbs 32-bit limbs (the positive products and the negative ones; their
// difference's sign is the determinant's). Inside the coordinate range (delaunay.hpp: 0 or
// magnitude in [1e-50, 1e50]) every exponent e of a difference component lies in
// [-219, 114], so the placements span at most 4 * 333 + 212 + 8 = 1552 bits; 2048 are kept.
// 32-bit limbs and 64-bit products only: no __int128 on a Cortex-M.
constexpr int kSumLimbs = 64;  // 2048 bits, 256 bytes
constexpr int kProductLimbs = 8;

struct Factor {  // a double as m 2^e (m < 2^53), sign apart
    std::uint64_t m;
    int e;
    bool negative;
};

Factor factor_of(double x) {  // from the bits: x = m 2^e exactly (subnormals included)
    std::uint64_t bits;
    std::memcpy(&bits, &x, 8);
    const int field = int((bits >> 52) & 0x7ff);
    const std::uint64_t fraction = bits & 0x000fffffffffffffULL;
    const bool negative = (bits >> 63) != 0;
    if (field == 0) return {fraction, -1074, negative};
    return {fraction | (std::uint64_t(1) << 52), field - 1075, negative};
}

// p (len limbs, room for kProductLimbs) *= m, m < 2^53; returns the new length
int multiply_limbs(std::uint32_t* p, int len, std::uint64_t m) {
    const std::uint64_t m_lo = m & 0xffffffffu, m_hi = m >> 32;
    std::uint32_t out[kProductLimbs + 2] = {};
    std::uint64_t carry = 0;
    for (int i = 0; i < len; ++i) {  // p m_lo
        const std::uint64_t t = std::uint64_t(p[i]) * m_lo + carry;
        out[i] = std::uint32_t(t);
        carry = t >> 32;
    }
    out[len] = std::uint32_t(carry);
    carry = 0;
    for (int i = 0; i < len; ++i) {  // + p m_hi 2^32
        const std::uint64_t t = std::uint64_t(p[i]) * m_hi + out[i + 1] + carry;
        out[i + 1] = std::uint32_t(t);
        carry = t >> 32;
    }
    out[len + 1] = std::uint32_t(carry);
    int n = std::min(len + 2, kProductLimbs);
    while (n > 1 && out[n - 1] == 0) --n;
    for (int i = 0; i < n; ++i) p[i] = out[i];
    return n;
}

// sum += p 2^shift (p: len limbs; sum: kSumLimbs limbs, non-negative; the carry stops early)
void add_shifted(std::uint32_t* sum, const std::uint32_t* p, int len, int shift) {
    const int word = shift / 32, bit = shift % 32;
    std::uint64_t carry = 0;
    int i = word;
    for (int k = 0; k <= len && i < kSumLimbs; ++k, ++i) {
        const std::uint32_t lo = k < len ? p[k] << bit : 0u;
        const std::uint32_t hi = (bit && k > 0) ? p[k - 1] >> (32 - bit) : 0u;
        const std::uint64_t t = std::uint64_t(sum[i]) + (lo | hi) + carry;
        sum[i] = std::uint32_t(t);
        carry = t >> 32;
    }
    for (; carry != 0 && i < kSumLimbs; ++i) {
        const std::uint64_t t = std::uint64_t(sum[i]) + carry;
        sum[i] = std::uint32_t(t);
        carry = t >> 32;
    }
}

struct LiftedCross {  // the four factors of one product and its sign
    const double* f[4];
    bool negative;
};

// The 12 products of expansions: lift_k part (u u) times cross part (+p q or -q p).
int lifted_cross_terms(const double* const* dx, const double* const* dy, LiftedCross* terms) {
    int n = 0;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        for (int u = 0; u < 2; ++u) {
            const double* c = u == 0 ? dx[k] : dy[k];
            terms[n++] = {{c, c, dx[i], dy[j]}, false};
            terms[n++] = {{c, c, dx[j], dy[i]}, true};
        }
    }
    return n;
}

// The approximate value of (pos - neg) 2^e_min (its sign is exact).
double accumulator_value(const std::uint32_t* pos, const std::uint32_t* neg, int e_min) {
    int top = kSumLimbs - 1;
    while (top >= 0 && pos[top] == neg[top]) --top;
    if (top < 0) return 0.0;
    const bool negative = neg[top] > pos[top];
    const std::uint32_t* big = negative ? neg : pos;
    const std::uint32_t* small = negative ? pos : neg;
    std::uint32_t diff[3] = {};  // the top limbs of big - small (borrow from below ignored:
    std::int64_t borrow = 0;     // it moves the value by less than 2^-64 of it)
    for (int i = std::max(0, top - 2), k = 0; i <= top; ++i, ++k) {
        const std::int64_t t = std::int64_t(big[i]) - small[i] - borrow;
        borrow = t < 0 ? 1 : 0;
        diff[k] = std::uint32_t(t + (borrow << 32));
    }
    double v = 0.0;
    for (int i = std::max(0, top - 2), k = 0; i <= top; ++i, ++k)
        v += std::ldexp(double(diff[k]), 32 * i + e_min);
    return negative ? -v : v;
}

struct ExactSum {
    std::uint32_t pos[kSumLimbs], neg[kSumLimbs];
    int e_min;
};

// The 16 products of one term's four two-component factors, from factor `level` on, with the
// partial product p 2^e of the factors before it (prefixes shared: 28 multiplications, not 64).
void add_products(const double* const* f, int level, const std::uint32_t* p, int len, int e,
                  bool negative, ExactSum* sum) {
    for (int c = 0; c < 2; ++c) {
        const double x = f[level][c];
        if (x == 0.0) continue;
        const Factor q = factor_of(x);
        std::uint32_t next[kProductLimbs];
        for (int i = 0; i < len; ++i) next[i] = p[i];
        const int next_len = multiply_limbs(next, len, q.m);
        const bool sign = negative != q.negative;
        if (level == 3)
            add_shifted(sign ? sum->neg : sum->pos, next, next_len, e + q.e - sum->e_min);
        else
            add_products(f, level + 1, next, next_len, e + q.e, sign, sum);
    }
}

}  // namespace

double incircle_exact(Vec2d a, Vec2d b, Vec2d c, Vec2d d) {
    double adx[2], ady[2], bdx[2], bdy[2], cdx[2], cdy[2];
    two_diff(a.x, d.x, adx[1], adx[0]);
    two_diff(a.y, d.y, ady[1], ady[0]);
    two_diff(b.x, d.x, bdx[1], bdx[0]);
    two_diff(b.y, d.y, bdy[1], bdy[0]);
    two_diff(c.x, d.x, cdx[1], cdx[0]);
    two_diff(c.y, d.y, cdy[1], cdy[0]);
    const double* dx[3] = {adx, bdx, cdx};
    const double* dy[3] = {ady, bdy, cdy};
    LiftedCross terms[12];
    const int n = lifted_cross_terms(dx, dy, terms);
    // the lowest and highest placement of the 192 products (bounds: per factor, the smallest
    // and largest exponent of its non-zero components)
    int e_min = 1 << 30, e_max = -(1 << 30);
    for (int t = 0; t < n; ++t) {
        int lo = 0, hi = 0;
        bool zero = false;
        for (int f = 0; f < 4; ++f) {
            const double* x = terms[t].f[f];
            if (x[0] == 0.0 && x[1] == 0.0) zero = true;
            if (zero) break;
            const int e0 = x[0] == 0.0 ? factor_of(x[1]).e : factor_of(x[0]).e;
            const int e1 = x[1] == 0.0 ? e0 : factor_of(x[1]).e;
            lo += std::min(e0, e1);
            hi += std::max(e0, e1);
        }
        if (zero) continue;
        e_min = std::min(e_min, lo);
        e_max = std::max(e_max, hi);
    }
    if (e_min > e_max) return 0.0;  // every product is 0
    if (e_max - e_min + 212 + 9 > 32 * kSumLimbs) {
        // outside the coordinate range: the sign is not guaranteed (as predicates.hpp says);
        // the floating-point value of the determinant
        double det = 0.0;
        for (int t = 0; t < n; ++t)
            det += (terms[t].negative ? -1.0 : 1.0) * terms[t].f[0][1] * terms[t].f[1][1] *
                   terms[t].f[2][1] * terms[t].f[3][1];
        return det;
    }
    // every product exactly, the positive and the negative ones apart
    ExactSum sum{};
    sum.e_min = e_min;
    const std::uint32_t one[1] = {1};
    for (int t = 0; t < n; ++t) add_products(terms[t].f, 0, one, 1, 0, terms[t].negative, &sum);
    return accumulator_value(sum.pos, sum.neg, e_min);
}

namespace {

// e = p - q for two products taken exactly (4 components at most).
int two_products_diff(double a, double b, double c, double d, double* e) {
    double p[2], q[2];
    two_product(a, b, p[1], p[0]);
    two_product(c, d, q[1], q[0]);
    q[0] = -q[0];
    q[1] = -q[1];
    return fast_expansion_sum(2, p, 2, q, e);
}

// lift * cross with lift = x^2 + y^2, exactly (x, y doubles; cross an expansion of <= 4).
int lifted_term(double x, double y, const double* cross_e, int cl, double* out) {
    double xc[8], xxc[16], yc[8], yyc[16];
    int l1 = scale_expansion(cl, cross_e, x, xc);
    int l2 = scale_expansion(l1, xc, x, xxc);
    int l3 = scale_expansion(cl, cross_e, y, yc);
    int l4 = scale_expansion(l3, yc, y, yyc);
    return fast_expansion_sum(l2, xxc, l4, yyc, out);
}

// The in-circle determinant exactly; when the six coordinate differences are exact in doubles
// (two_diff leaves no tail: nearby points, Sterbenz), Shewchuk's stage B alone is exact and
// ~10x cheaper than the general expansion (what lattices, whose determinants are exactly 0,
// spend their time on). Only the sign and zero-ness of the result are specified.
// The stage between the filter and the expansions: the in-circle determinant from the exact
// coordinate differences in double-double (double_double.hpp). Its error is at most ~20 u^2
// times the permanent (u = 2^-53: exact products, then 3 u^2 per accurate addition and 7 u^2
// per product, Joldes, Muller & Popescu 2017); 32 u^2 is required (chosen here with margin).
// It decides the near-cocircular sets of a rounded lattice (whose determinant is ~1e-16 of the
// permanent, far below the filter's 1e-15) at a fraction of the expansions' cost; an exact
// zero still goes on to the expansions. The value returned has the exact sign.
bool incircle_double_double(double adx, double ady, double bdx, double bdy, double cdx,
                            double cdy, double* det) {
    const double permanent =
        (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * (adx * adx + ady * ady) +
        (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * (bdx * bdx + bdy * bdy) +
        (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * (cdx * cdx + cdy * cdy);
    // inside this range no partial result or error term leaves the normal doubles
    if (!(permanent >= 1e-240 && permanent <= 1e240)) return false;
    using dd_detail::two_product;
    const DoubleDouble bc = dd_sub(two_product(bdx, cdy), two_product(cdx, bdy));
    const DoubleDouble ca = dd_sub(two_product(cdx, ady), two_product(adx, cdy));
    const DoubleDouble ab = dd_sub(two_product(adx, bdy), two_product(bdx, ady));
    const DoubleDouble alift = dd_add(two_product(adx, adx), two_product(ady, ady));
    const DoubleDouble blift = dd_add(two_product(bdx, bdx), two_product(bdy, bdy));
    const DoubleDouble clift = dd_add(two_product(cdx, cdx), two_product(cdy, cdy));
    const DoubleDouble sum =
        dd_add(dd_add(dd_mul(alift, bc), dd_mul(blift, ca)), dd_mul(clift, ab));
    const double bound = 32.0 * kEpsilon * kEpsilon * permanent * 1.01;  // 1.01: its rounding
    if (!(std::fabs(sum.hi) - std::fabs(sum.lo) > bound)) return false;
    *det = sum.hi;
    return true;
}

// The same stage when some coordinate difference is not exact in doubles (points far apart
// in magnitude: 0.005 and 0.035 of a rounded lattice near the origin): the differences are
// exact as double-doubles (hi + lo), and every product is a double-double product (7 u^2,
// Joldes, Muller & Popescu 2017, against the exact products of the stage above). The error
// then stays below ~33 u^2 times the permanent (cross terms 10 u^2, lifts 10 u^2, their
// product 7 u^2, the two sums 3 u^2 each); 64 u^2 is required (chosen here: twice that). It
// decides the near-cocircular sets with inexact differences (a rounded 100 x 100 lattice: 206
// per Voronoi division, all non-zero) at ~1/30 of the fixed-point sum's cost; an exact zero,
// or anything it cannot prove, goes on to incircle_exact.
bool incircle_double_double_inexact(const DoubleDouble* x, const DoubleDouble* y, double* det) {
    const double permanent =
        (std::fabs(x[1].hi * y[2].hi) + std::fabs(x[2].hi * y[1].hi)) *
            (x[0].hi * x[0].hi + y[0].hi * y[0].hi) +
        (std::fabs(x[2].hi * y[0].hi) + std::fabs(x[0].hi * y[2].hi)) *
            (x[1].hi * x[1].hi + y[1].hi * y[1].hi) +
        (std::fabs(x[0].hi * y[1].hi) + std::fabs(x[1].hi * y[0].hi)) *
            (x[2].hi * x[2].hi + y[2].hi * y[2].hi);
    if (!(permanent >= 1e-240 && permanent <= 1e240)) return false;
    DoubleDouble sum;
    for (int k = 0; k < 3; ++k) {  // lift_k (dx_i dy_j - dx_j dy_i), (i, j, k) cyclic
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const DoubleDouble cross = dd_sub(dd_mul(x[i], y[j]), dd_mul(x[j], y[i]));
        const DoubleDouble lift = dd_add(dd_mul(x[k], x[k]), dd_mul(y[k], y[k]));
        const DoubleDouble term = dd_mul(lift, cross);
        sum = k == 0 ? term : dd_add(sum, term);
    }
    const double bound = 64.0 * kEpsilon * kEpsilon * permanent * 1.01;  // 1.01: its rounding
    if (!(std::fabs(sum.hi) - std::fabs(sum.lo) > bound)) return false;
    *det = sum.hi;
    return true;
}

double incircle_exact_differences(Vec2d a, Vec2d b, Vec2d c, Vec2d d) {
    double adx, bdx, cdx, ady, bdy, cdy, t[6];
    two_diff(a.x, d.x, adx, t[0]);
    two_diff(b.x, d.x, bdx, t[1]);
    two_diff(c.x, d.x, cdx, t[2]);
    two_diff(a.y, d.y, ady, t[3]);
    two_diff(b.y, d.y, bdy, t[4]);
    two_diff(c.y, d.y, cdy, t[5]);
    if (t[0] != 0.0 || t[1] != 0.0 || t[2] != 0.0 || t[3] != 0.0 || t[4] != 0.0 || t[5] != 0.0) {
        const DoubleDouble x[3] = {{adx, t[0]}, {bdx, t[1]}, {cdx, t[2]}};
        const DoubleDouble y[3] = {{ady, t[3]}, {bdy, t[4]}, {cdy, t[5]}};
        double estimate;
        if (incircle_double_double_inexact(x, y, &estimate)) return estimate;
        return incircle_exact(a, b, c, d);
    }
    double estimate;
    if (incircle_double_double(adx, ady, bdx, bdy, cdx, cdy, &estimate)) return estimate;
    double bc[4], ca[4], ab[4], adet[32], bdet[32], cdet[32], abdet[64], fin[96];
    int bcl = two_products_diff(bdx, cdy, cdx, bdy, bc);
    int cal = two_products_diff(cdx, ady, adx, cdy, ca);
    int abl = two_products_diff(adx, bdy, bdx, ady, ab);
    int al = lifted_term(adx, ady, bc, bcl, adet);
    int bl = lifted_term(bdx, bdy, ca, cal, bdet);
    int cl = lifted_term(cdx, cdy, ab, abl, cdet);
    int abl2 = fast_expansion_sum(al, adet, bl, bdet, abdet);
    int fl = fast_expansion_sum(abl2, abdet, cl, cdet, fin);
    return expansion_sign_value(fl, fin);
}

// Two equal pairs of different values (p q r s in any order).
inline bool two_pairs(double p, double q, double r, double s) {
    if (p == q) return r == s && r != p;
    if (p == r) return q == s && q != p;
    if (p == s) return q == r && q != p;
    return false;
}

// The cheap exact path for the cocircular case of a square lattice: when the x coordinates
// are two equal pairs and so are the y coordinates, the four points are the corners of an
// axis-parallel rectangle (or two doubled points), exactly cocircular: the determinant is 0,
// decided by comparisons (every square of a lattice, before: Shewchuk's stage B or the full
// exact sum, 35-43 % of a lattice's Delaunay time).
inline bool axis_parallel_rectangle(Vec2d a, Vec2d b, Vec2d c, Vec2d d) {
    return two_pairs(a.x, b.x, c.x, d.x) && two_pairs(a.y, b.y, c.y, d.y);
}

// p + q == r + s exactly (the sums compared as expansions: no rounding).
bool equal_sums(double p, double q, double r, double s) {
    double e[2], f[2], h[4];
    two_sum(p, q, e[1], e[0]);
    two_sum(-r, -s, f[1], f[0]);
    const int n = fast_expansion_sum(2, e, 2, f, h);
    return expansion_sign_value(n, h) == 0.0;
}

// q - p == s - r exactly (two_diff's pair is unique for a given exact difference).
bool equal_differences(double p, double q, double r, double s) {
    double d1, t1, d2, t2;
    two_diff(q, p, d1, t1);
    two_diff(s, r, d2, t2);
    return d1 == d2 && t1 == t2;
}

// The chords PQ and RS share their perpendicular bisector, and it is a line the doubles
// reflect in exactly: vertical or horizontal chords (x == const or y == const), or chords
// along a diagonal (q - p = (t, t) or (t, -t)). The four points are then symmetric about that
// line: Q mirrors P and S mirrors R, so the circle through any three (centred on the line)
// holds the fourth (or all four are collinear): the in-circle determinant is exactly 0.
bool mirrored_chords(Vec2d p, Vec2d q, Vec2d r, Vec2d s) {
    if (p.x == q.x && r.x == s.x) return equal_sums(p.y, q.y, r.y, s.y);
    if (p.y == q.y && r.y == s.y) return equal_sums(p.x, q.x, r.x, s.x);
    // diagonal chords: the doubles first (cheap), then exactly
    const double qpx = q.x - p.x, qpy = q.y - p.y, srx = s.x - r.x, sry = s.y - r.y;
    if (qpx == qpy && srx == sry) {
        if (!equal_differences(p.x, q.x, p.y, q.y) || !equal_differences(r.x, s.x, r.y, s.y))
            return false;
        // the bisector x + y = m: p.x + p.y + q.x + q.y == r.x + r.y + s.x + s.y, exactly
        double e[2], f[2], g[2], k[2], ef[4], gk[4], h[8];
        two_sum(p.x, p.y, e[1], e[0]);
        two_sum(q.x, q.y, f[1], f[0]);
        two_sum(-r.x, -r.y, g[1], g[0]);
        two_sum(-s.x, -s.y, k[1], k[0]);
        const int n = fast_expansion_sum(fast_expansion_sum(2, e, 2, f, ef), ef,
                                         fast_expansion_sum(2, g, 2, k, gk), gk, h);
        return expansion_sign_value(n, h) == 0.0;
    }
    if (qpx == -qpy && srx == -sry) {
        if (!equal_differences(p.x, q.x, q.y, p.y) || !equal_differences(r.x, s.x, s.y, r.y))
            return false;
        // the bisector x - y = m
        double e[2], f[2], g[2], k[2], ef[4], gk[4], h[8];
        two_sum(p.x, -p.y, e[1], e[0]);
        two_sum(q.x, -q.y, f[1], f[0]);
        two_sum(-r.x, r.y, g[1], g[0]);
        two_sum(-s.x, s.y, k[1], k[0]);
        const int n = fast_expansion_sum(fast_expansion_sum(2, e, 2, f, ef), ef,
                                         fast_expansion_sum(2, g, 2, k, gk), gk, h);
        return expansion_sign_value(n, h) == 0.0;
    }
    return false;
}

// The other cocircular sets of a square lattice: two mirrored chords (isosceles trapezoids
// whose axis is horizontal, vertical or diagonal; 99.5 % of the exact zeros the rectangle
// test leaves on a 100 x 100 lattice, which before cost the full expansions). Only a proof of
// 0 returns true; anything else goes on to the exact stages.
bool mirrored_lattice_chords(Vec2d a, Vec2d b, Vec2d c, Vec2d d) {
    return mirrored_chords(a, b, c, d) || mirrored_chords(a, c, b, d) ||
           mirrored_chords(a, d, b, c);
}

}  // namespace

double incircle_unfiltered(Vec2d a, Vec2d b, Vec2d c, Vec2d d) {
    if (axis_parallel_rectangle(a, b, c, d)) return 0.0;
    if (mirrored_lattice_chords(a, b, c, d)) return 0.0;
    return incircle_exact_differences(a, b, c, d);
}

}  // namespace shitsukan
