// small-device: yes (no allocation, no exceptions)
// fujimoto2000 §2.3, appendix A: the IST on digit strings.
#include "shitsukan/wrinkly/ist_digits.hpp"

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/format_number.hpp"

namespace shitsukan {

namespace {

int wrap(int b, int count) {
    int r = b % count;
    return r < 0 ? r + count : r;
}

bool has_external_shuffle(const IstAxis& axis) { return axis.kind != IstKind::unit; }

}  // namespace

void ist_digits_from_index(const IstAxis& axis, int base, std::uint64_t index, IstDigits* out) {
    SHITSUKAN_ASSERT(out != nullptr);
    const std::uint64_t n = std::uint64_t(axis.n);
    out->base = base;
    out->count = axis.iterations;
    for (int i = axis.iterations; i >= 1; --i) {  // alpha_K is the least significant digit
        out->digit[i] = std::uint8_t(index % n);
        index /= n;
    }
}

std::uint64_t ist_digits_index(const IstAxis& axis, const IstDigits& alpha) {
    std::uint64_t index = 0;
    for (int i = 1; i <= alpha.count; ++i) index = index * std::uint64_t(axis.n) + alpha.digit[i];
    return index;
}

// eq. (22)/(25): the k-th digit (the parts at the same position g = alpha_k in their parents
// form group g) is carried to the front; the digits in between move one place down.
void ist_internal_shuffle(const IstAxis& axis, int k, IstDigits* alpha) {
    (void)axis;
    SHITSUKAN_ASSERT(alpha != nullptr && k >= 1 && k <= alpha->count);
    std::uint8_t g = alpha->digit[k];
    for (int i = k; i > 1; --i) alpha->digit[i] = alpha->digit[i - 1];
    alpha->digit[1] = g;
}

void ist_internal_shuffle_inverse(const IstAxis& axis, int k, IstDigits* alpha) {
    (void)axis;
    SHITSUKAN_ASSERT(alpha != nullptr && k >= 1 && k <= alpha->count);
    std::uint8_t g = alpha->digit[1];
    for (int i = 1; i < k; ++i) alpha->digit[i] = alpha->digit[i + 1];
    alpha->digit[k] = g;
}

// eq. (26), any table: group g = alpha_1 moves to base alpha_0 + offset[g], slot slot[g].
// On a translation axis a move past an end is not performed (fig 9); the table is an
// exchange there, so the partner's move is skipped too and nothing collides.
void ist_external_shuffle(const IstAxis& axis, IstDigits* alpha) {
    SHITSUKAN_ASSERT(alpha != nullptr && alpha->count >= 1);
    if (!has_external_shuffle(axis)) return;
    int g = alpha->digit[1];
    int to = alpha->base + axis.shuffle.offset[g];
    if (axis.ends == IstEnds::translation) {
        if (to < 0 || to >= axis.base_intervals) return;
    } else {
        to = wrap(to, axis.base_intervals);
    }
    alpha->base = to;
    alpha->digit[1] = axis.shuffle.slot[g];
}

void ist_external_shuffle_inverse(const IstAxis& axis, IstDigits* alpha) {
    SHITSUKAN_ASSERT(alpha != nullptr && alpha->count >= 1);
    if (!has_external_shuffle(axis)) return;
    int t = alpha->digit[1];
    int g = 0;
    while (axis.shuffle.slot[g] != t) ++g;  // the group that lands in slot t
    int from = alpha->base - axis.shuffle.offset[g];
    if (axis.ends == IstEnds::translation) {
        if (from < 0 || from >= axis.base_intervals) return;  // its partner stayed: so did it
    } else {
        from = wrap(from, axis.base_intervals);
    }
    alpha->base = from;
    alpha->digit[1] = std::uint8_t(g);
}

// eq. (23) / (28): D^K(D^{K-1}(...D^1(alpha^0)))
void ist_digits_forward_by_steps(const IstAxis& axis, const IstDigits& in, IstDigits* out) {
    SHITSUKAN_ASSERT(out != nullptr && in.count == axis.iterations);
    *out = in;
    for (int k = 1; k <= axis.iterations; ++k) {
        ist_internal_shuffle(axis, k, out);
        ist_external_shuffle(axis, out);
    }
}

void ist_digits_inverse_by_steps(const IstAxis& axis, const IstDigits& in, IstDigits* out) {
    SHITSUKAN_ASSERT(out != nullptr && in.count == axis.iterations);
    *out = in;
    for (int k = axis.iterations; k >= 1; --k) {
        ist_external_shuffle_inverse(axis, out);
        ist_internal_shuffle_inverse(axis, k, out);
    }
}

// eq. (7): alpha^K = alpha^0_K alpha^0_{K-1} .. alpha^0_1
void ist_scale_reverse_unit(const IstDigits& in, IstDigits* out) {
    SHITSUKAN_ASSERT(out != nullptr && out != &in);
    out->base = in.base;
    out->count = in.count;
    for (int i = 1; i <= in.count; ++i) out->digit[i] = in.digit[in.count - i + 1];
}

// eq. (12): alpha^K_0 = alpha^0_0 + sum_{j=1..K} (alpha^0_j - M);
//           alpha^K_i = N - 1 - alpha^0_{K-i+1}
void ist_scale_reverse_fully_connected(int n, const IstDigits& in, IstDigits* out) {
    SHITSUKAN_ASSERT(out != nullptr && out != &in && n % 2 == 1);
    const int m = (n - 1) / 2;
    int base = in.base;
    for (int j = 1; j <= in.count; ++j) base += int(in.digit[j]) - m;
    out->base = base;
    out->count = in.count;
    for (int i = 1; i <= in.count; ++i)
        out->digit[i] = std::uint8_t(n - 1 - in.digit[in.count - i + 1]);
}

void ist_digits_forward(const IstAxis& axis, const IstDigits& in, IstDigits* out) {
    SHITSUKAN_ASSERT(out != nullptr && in.count == axis.iterations);
    IstDigits result;
    if (axis.kind == IstKind::unit) {
        ist_scale_reverse_unit(in, &result);
    } else if (axis.kind == IstKind::fully_connected && axis.ends == IstEnds::cyclic) {
        ist_scale_reverse_fully_connected(axis.n, in, &result);
        result.base = wrap(result.base, axis.base_intervals);  // §2.3.2 footnote: cyclic axis
    } else {
        ist_digits_forward_by_steps(axis, in, &result);
    }
    *out = result;
}

void ist_digits_inverse(const IstAxis& axis, const IstDigits& in, IstDigits* out) {
    SHITSUKAN_ASSERT(out != nullptr && in.count == axis.iterations);
    if (axis.kind == IstKind::unit ||
        (axis.kind == IstKind::fully_connected && axis.ends == IstEnds::cyclic)) {
        ist_digits_forward(axis, in, out);  // eqs. (8), (13): the formulas are involutions
        return;
    }
    IstDigits result;
    ist_digits_inverse_by_steps(axis, in, &result);
    *out = result;
}

Status ist_digits_check(const IstAxis& axis, const IstDigits& alpha) {
    SHITSUKAN_TRY(ist_validate(axis));
    if (alpha.count != axis.iterations)
        return Status::error(StatusCode::invalid_argument,
                             "IST: digit string has %d digits, the axis has K = %d", alpha.count,
                             axis.iterations);
    if (alpha.base < 0 || alpha.base >= axis.base_intervals)
        return Status::error(StatusCode::out_of_range,
                             "IST: base-interval number %d outside 0..%d", alpha.base,
                             axis.base_intervals - 1);
    for (int i = 1; i <= alpha.count; ++i)
        if (alpha.digit[i] >= axis.n)
            return Status::error(StatusCode::out_of_range,
                                 "IST: digit alpha_%d = %d is not a base-%d digit", i,
                                 alpha.digit[i], axis.n);
    return Status::success();
}

Status ist_digits_forward_checked(const IstAxis& axis, const IstDigits& in, IstDigits& out) {
    SHITSUKAN_TRY(ist_digits_check(axis, in));
    ist_digits_forward(axis, in, &out);
    return Status::success();
}

Status ist_digits_inverse_checked(const IstAxis& axis, const IstDigits& in, IstDigits& out) {
    SHITSUKAN_TRY(ist_digits_check(axis, in));
    ist_digits_inverse(axis, in, &out);
    return Status::success();
}

const char* ist_digits_format(const IstDigits& alpha, int base_label, char* buf, int size) {
    if (buf == nullptr || size <= 0) return "";  // nothing fits, not even the terminator
    static const char kDigitChars[] = "0123456789abcdefghijklmnopqrstuv";  // N <= kIstMaxN
    // The string may come from a user (not checked): a label sum that would overflow an int,
    // a digit that is not base-32 ('?') or more digits than the array holds are all printable.
    // The label in decimal (core/format_number: no stdio in a firmware), then the point.
    const long long label = static_cast<long long>(alpha.base) + base_label;
    const std::uint64_t magnitude =
        label < 0 ? 0ull - static_cast<std::uint64_t>(label) : static_cast<std::uint64_t>(label);
    NumberFormat decimal;
    decimal.conversion = 'd';
    int used = format_integer(buf, size, magnitude, label < 0, decimal);
    if (used > size - 1) used = size - 1;
    if (used < size - 1) buf[used++] = '.';
    const int count = alpha.count < kIstMaxIterations ? alpha.count : kIstMaxIterations;
    for (int i = 1; i <= count && used < size - 1; ++i)
        buf[used++] = alpha.digit[i] < kIstMaxN ? kDigitChars[alpha.digit[i]] : '?';
    if (used > size - 1) used = size - 1;
    buf[used] = '\0';
    return buf;
}

}  // namespace shitsukan
