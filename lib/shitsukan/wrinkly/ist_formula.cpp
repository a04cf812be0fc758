// small-device: yes (no allocation, no exceptions)
// fujimoto2000 eqs. (9), (10), (14): the IST on a real coordinate.
#include "shitsukan/wrinkly/ist_formula.hpp"

#include <cmath>
#include <limits>

#include "shitsukan/core/assert.hpp"

namespace shitsukan {

namespace {

// Eq. (9) forwards: the left end of sub-interval `index` of base `base`, plus `offset`
// sub-intervals. Every rounding step is monotone, so the left ends are non-decreasing in
// (base, index); split() below is written against exactly these values.
template <class Real>
Real left_end(const IstAxis& axis, int base, std::uint64_t index, std::uint64_t count) {
    return (Real(base) + Real(index) / Real(count)) / Real(axis.base_intervals);
}

// A distance, in sub-intervals, beyond which a point's sub-interval (and base) is sure without
// comparing against the computed left ends: eight times the few ulps of B N^K by which
// u B N^K and the left ends of eq. (9) can be off (each a handful of roundings, each at most
// half an ulp of a value below B). Nearer to an end, split() and join() compare exactly.
template <class Real>
Real far_from_ends(const IstAxis& axis, std::uint64_t count) {
    return Real(8) * std::numeric_limits<Real>::epsilon() * Real(axis.base_intervals) *
           Real(count);
}

template <class Real>
Real join(const IstAxis& axis, int base, std::uint64_t index, Real offset, std::uint64_t count) {
    // Where Real cannot resolve B N^K sub-intervals (B N^K > 2^53 in double; fuzz_ist found
    // N = 3, K = 33, B = 4) the last left ends round up to 1; a point below 1 stays below 1.
    if (offset > Real(0) && Real(1) - offset > far_from_ends<Real>(axis, count)) {
        // Fast path, the same value as below: rounding is monotone, so a <= v, and a gap of
        // (1 - offset) / (B N^K) far above the few ulps the three expressions can be off keeps
        // v below the right end z; only v < 1 is left to see.
        const Real v =
            (Real(base) + (Real(index) + offset) / Real(count)) / Real(axis.base_intervals);
        if (v < Real(1)) return v;
    }
    const Real below_one = std::nextafter(Real(1), Real(0));
    const Real a0 = left_end<Real>(axis, base, index, count);
    const Real a = a0 < Real(1) ? a0 : below_one;
    if (!(offset > Real(0))) return a;  // a left end maps to a left end, exactly
    const Real v = (Real(base) + (Real(index) + offset) / Real(count)) / Real(axis.base_intervals);
    // The right end: the next sub-interval's left end (base + 1 after the last one).
    const Real z = index + 1 < count ? left_end<Real>(axis, base, index + 1, count)
                                     : Real(base + 1) / Real(axis.base_intervals);
    if (offset >= Real(1)) return z;  // u = 1: the right end of the last sub-interval
    // Rounding must not carry a point out of its sub-interval [a, z): the inverse would then
    // read it as the neighbour's and send it anywhere on the axis.
    if (v >= z) return z > a ? std::nextafter(z, a) : a;
    return v < a ? a : v;
}

// Eq. (9) read backwards: base b, sub-interval index and the offset inside it (in units of
// one sub-interval). The last sub-interval keeps u = 1 (offset 1).
// The sub-interval is the last one whose computed left end (left_end above) is <= u, so that
// split(join(b, i, 0)) == (b, i, 0) exactly; the plain floor of u B N^K missed this on about
// 20 % of the left ends (u B rounded just below b, or (t - b) N^K just below i), and the
// inverse then returned the image of the neighbouring sub-interval.
template <class Real>
void split(const IstAxis& axis, Real u, std::uint64_t count, int* base, std::uint64_t* index,
           Real* offset) {
    if (!(u > Real(0))) u = Real(0);  // also NaN
    const int nb = axis.base_intervals;
    if (u >= Real(1)) {
        *base = nb - 1;
        *index = count - 1;
        *offset = Real(1);
        return;
    }
    Real t = u * Real(nb);
    int b = int(t);
    if (b >= nb) b = nb - 1;
    // Far from every end the floors are the answer (far_from_ends); near one, compare with
    // the computed left ends, as join() computes them.
    const Real far = far_from_ends<Real>(axis, count);
    const Real far_b = Real(8) * std::numeric_limits<Real>::epsilon() * Real(nb);
    const bool base_sure = t - Real(b) > far_b && Real(b + 1) - t > far_b;
    if (!base_sure) {
        while (b > 0 && Real(b) / Real(nb) > u) --b;  // the base's left end b / B, as join()
        while (b + 1 < nb && Real(b + 1) / Real(nb) <= u) ++b;
    }
    Real s = (t - Real(b)) * Real(count);
    std::uint64_t i = s > Real(0) ? std::uint64_t(s) : 0;
    if (i >= count) i = count - 1;
    if (!(base_sure && s - Real(i) > far && Real(i + 1) - s > far)) {
        // The floor is off by at most one where Real resolves the left ends (B N^K within the
        // header's bounds); beyond them left ends coincide and a few steps are all that is owed.
        for (int step = 0; step < 4 && i > 0 && left_end<Real>(axis, b, i, count) > u; ++step)
            --i;
        for (int step = 0;
             step < 4 && i + 1 < count && left_end<Real>(axis, b, i + 1, count) <= u; ++step)
            ++i;
    }
    const Real a = left_end<Real>(axis, b, i, count);
    Real f = (u - a) * Real(nb) * Real(count);  // u - a is exact (Sterbenz) near a
    if (!(f > Real(0))) f = Real(0);
    if (f >= Real(1)) f = std::nextafter(Real(1), Real(0));  // u < 1 stays inside [a, z)
    *base = b;
    *index = i;
    *offset = f;
}

// The digit part of eq. (10) on the integer index, without a digit array: the digits are
// peeled off from alpha_K (index % N) and appended, so alpha_K becomes the most significant.
std::uint64_t reverse_digits(std::uint64_t index, int n, int k) {
    std::uint64_t reversed = 0;
    for (int i = 0; i < k; ++i) {
        reversed = reversed * std::uint64_t(n) + index % std::uint64_t(n);
        index /= std::uint64_t(n);
    }
    return reversed;
}

// eq. (12) on the index: digits reversed and complemented (N - 1 - alpha), base moved by
// sum (alpha_j - M), wrapped on the cyclic axis.
std::uint64_t fully_connected_digits(std::uint64_t index, int n, int k, int base_intervals,
                                     int* base) {
    const int m = (n - 1) / 2;
    std::uint64_t result = 0;
    long shift = 0;
    for (int i = 0; i < k; ++i) {
        int digit = int(index % std::uint64_t(n));
        index /= std::uint64_t(n);
        shift += digit - m;
        result = result * std::uint64_t(n) + std::uint64_t(n - 1 - digit);
    }
    long b = (long(*base) + shift) % base_intervals;
    *base = int(b < 0 ? b + base_intervals : b);
    return result;
}

template <class Real>
Real transform(const IstAxis& axis, Real u, bool inverse) {
    const std::uint64_t count = ist_sub_interval_count(axis);
    int base = 0;
    std::uint64_t index = 0;
    Real offset = 0;
    split(axis, u, count, &base, &index, &offset);
    if (axis.kind == IstKind::unit) {
        index = reverse_digits(index, axis.n, axis.iterations);  // eq. (10), its own inverse
    } else if (axis.kind == IstKind::fully_connected && axis.ends == IstEnds::cyclic) {
        index = fully_connected_digits(index, axis.n, axis.iterations, axis.base_intervals,
                                       &base);  // eq. (14), its own inverse (eq. 13)
    } else {
        IstDigits alpha, result;
        ist_digits_from_index(axis, base, index, &alpha);
        if (inverse)
            ist_digits_inverse_by_steps(axis, alpha, &result);
        else
            ist_digits_forward_by_steps(axis, alpha, &result);
        base = result.base;
        index = ist_digits_index(axis, result);
    }
    return join(axis, base, index, offset, count);
}

Status check_u(float u) {
    if (!(u >= 0.0f && u <= 1.0f))
        return Status::error(StatusCode::out_of_range, "IST: u must be in [0, 1] (got %g)",
                             double(u));
    return Status::success();
}

}  // namespace

float ist_forward(const IstAxis& axis, float u) { return transform<float>(axis, u, false); }
float ist_inverse(const IstAxis& axis, float u) { return transform<float>(axis, u, true); }
double ist_forward_double(const IstAxis& axis, double u) {
    return transform<double>(axis, u, false);
}
double ist_inverse_double(const IstAxis& axis, double u) {
    return transform<double>(axis, u, true);
}

Status ist_forward_checked(const IstAxis& axis, float u, float& out) {
    SHITSUKAN_TRY(ist_validate(axis));
    SHITSUKAN_TRY(check_u(u));
    out = ist_forward(axis, u);
    return Status::success();
}

Status ist_inverse_checked(const IstAxis& axis, float u, float& out) {
    SHITSUKAN_TRY(ist_validate(axis));
    SHITSUKAN_TRY(check_u(u));
    out = ist_inverse(axis, u);
    return Status::success();
}

void ist_locate(const IstAxis& axis, double u, IstLocation* out) {
    SHITSUKAN_ASSERT(out != nullptr);
    const std::uint64_t count = ist_sub_interval_count(axis);
    int base = 0;
    std::uint64_t index = 0;
    double offset = 0;
    split(axis, u, count, &base, &index, &offset);
    ist_digits_from_index(axis, base, index, &out->alpha);
    out->offset = offset;
}

double ist_position(const IstAxis& axis, const IstLocation& location) {
    const std::uint64_t count = ist_sub_interval_count(axis);
    return join(axis, location.alpha.base, ist_digits_index(axis, location.alpha),
                location.offset, count);
}

}  // namespace shitsukan
