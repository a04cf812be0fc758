// small-device: yes (no allocation, no exceptions)
// fujimoto2000 eqs. (9), (10), (14): the IST on a real coordinate.
#include "shitsukan/wrinkly/ist_formula.hpp"

#include "shitsukan/core/assert.hpp"

namespace shitsukan {

namespace {

// Eq. (9) read backwards: base b, sub-interval index and the offset inside it (in units of
// one sub-interval). The last sub-interval keeps u = 1 (offset 1).
template <class Real>
void split(const IstAxis& axis, Real u, std::uint64_t count, int* base, std::uint64_t* index,
           Real* offset) {
    if (!(u > Real(0))) u = Real(0);  // also NaN
    if (u > Real(1)) u = Real(1);
    Real t = u * Real(axis.base_intervals);
    int b = int(t);
    if (b >= axis.base_intervals) b = axis.base_intervals - 1;
    Real s = (t - Real(b)) * Real(count);
    std::uint64_t i = std::uint64_t(s);
    if (i >= count) i = count - 1;
    *base = b;
    *index = i;
    *offset = s - Real(i);
}

template <class Real>
Real join(const IstAxis& axis, int base, std::uint64_t index, Real offset, std::uint64_t count) {
    return (Real(base) + (Real(index) + offset) / Real(count)) / Real(axis.base_intervals);
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

Status ist_forward_checked(const IstAxis& axis, float u, float* out) {
    SHITSUKAN_ASSERT(out != nullptr);
    SHITSUKAN_TRY(ist_validate(axis));
    SHITSUKAN_TRY(check_u(u));
    *out = ist_forward(axis, u);
    return Status::success();
}

Status ist_inverse_checked(const IstAxis& axis, float u, float* out) {
    SHITSUKAN_ASSERT(out != nullptr);
    SHITSUKAN_TRY(ist_validate(axis));
    SHITSUKAN_TRY(check_u(u));
    *out = ist_inverse(axis, u);
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
