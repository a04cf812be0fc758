// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/format_number.hpp"

#include <cstring>

namespace shitsukan {

namespace {

// ---- exact arithmetic: a natural number in 32-bit words, least significant first ----
// A double is m * 2^e with m < 2^53 and -1074 <= e <= 971; scaled to 1 <= N / D < 10 the
// larger of N and D stays below 2^1140 (36 words), so 38 words suffice.
constexpr int kWords = 38;

struct BigNat {
    std::uint32_t w[kWords];
    int n;  // words in use; w[n-1] != 0 unless n == 0
};

void big_set(BigNat& a, std::uint64_t v) {
    a.n = 0;
    while (v != 0) {
        a.w[a.n++] = std::uint32_t(v);
        v >>= 32;
    }
}

void big_mul_small(BigNat& a, std::uint32_t k) {
    std::uint64_t carry = 0;
    for (int i = 0; i < a.n; ++i) {
        std::uint64_t t = std::uint64_t(a.w[i]) * k + carry;
        a.w[i] = std::uint32_t(t);
        carry = t >> 32;
    }
    if (carry != 0 && a.n < kWords) a.w[a.n++] = std::uint32_t(carry);
}

void big_mul_pow10(BigNat& a, int k) {
    for (; k >= 9; k -= 9) big_mul_small(a, 1000000000u);
    static const std::uint32_t small[9] = {1,      10,      100,      1000,     10000,
                                           100000, 1000000, 10000000, 100000000};
    if (k > 0) big_mul_small(a, small[k]);
}

void big_shift_left(BigNat& a, int bits) {
    if (a.n == 0) return;
    int words = bits / 32, rest = bits % 32;
    int n = a.n + words + 1;
    if (n > kWords) n = kWords;  // cannot happen for doubles (see kWords)
    for (int i = n - 1; i >= 0; --i) {
        int j = i - words;
        std::uint32_t hi = j >= 0 && j < a.n ? a.w[j] : 0u;
        std::uint32_t lo = j - 1 >= 0 && j - 1 < a.n ? a.w[j - 1] : 0u;
        a.w[i] = rest == 0 ? hi : (hi << rest) | (lo >> (32 - rest));
    }
    a.n = n;
    while (a.n > 0 && a.w[a.n - 1] == 0) --a.n;
}

int big_compare(const BigNat& a, const BigNat& b) {
    if (a.n != b.n) return a.n < b.n ? -1 : 1;
    for (int i = a.n - 1; i >= 0; --i)
        if (a.w[i] != b.w[i]) return a.w[i] < b.w[i] ? -1 : 1;
    return 0;
}

void big_sub(BigNat& a, const BigNat& b) {  // a -= b, a >= b
    std::int64_t borrow = 0;
    for (int i = 0; i < a.n; ++i) {
        std::int64_t t = std::int64_t(a.w[i]) - (i < b.n ? std::int64_t(b.w[i]) : 0) - borrow;
        borrow = t < 0 ? 1 : 0;
        a.w[i] = std::uint32_t(t + (borrow << 32));
    }
    while (a.n > 0 && a.w[a.n - 1] == 0) --a.n;
}

void big_add(BigNat& a, const BigNat& b) {  // a += b
    std::uint64_t carry = 0;
    int n = a.n > b.n ? a.n : b.n;
    for (int i = 0; i < n; ++i) {
        std::uint64_t t = std::uint64_t(i < a.n ? a.w[i] : 0u) + (i < b.n ? b.w[i] : 0u) + carry;
        a.w[i] = std::uint32_t(t);
        carry = t >> 32;
    }
    a.n = n;
    if (carry != 0 && a.n < kWords) a.w[a.n++] = std::uint32_t(carry);
}

// floor(a / b) for a < 10 b; a becomes the remainder.
int big_divide_digit(BigNat& a, const BigNat& b) {
    int d = 0;
    while (big_compare(a, b) >= 0) {
        big_sub(a, b);
        ++d;
    }
    return d;
}

// floor(log10(2^bits)) for |bits| < 2^13, never more than floor(log10(v)) for v >= 2^bits.
int floor_log10_pow2(int bits) { return (bits * 78913) >> 18; }

int bit_length(std::uint64_t m) {
    int n = 0;
    while (m != 0) {
        ++n;
        m >>= 1;
    }
    return n;
}

// ---- decimal digits of a finite positive double, correctly rounded ----
// The precision for %e and %f is capped at kMaxPrecision; the digits of a %f of 1e308 need
// 309 + kMaxPrecision characters.
constexpr int kMaxPrecision = 40;
constexpr int kMaxDigits = 309 + kMaxPrecision + 2;

struct Digits {
    char d[kMaxDigits];  // '0'..'9'
    int count;           // digits in d (0 when the value rounds to zero)
    int exponent;        // value = d[0].d[1]d[2]... * 10^exponent
};

// Rounds m * 2^e (m > 0) to `significant` digits, or, if `fixed`, to the digit of 10^-places.
// Ties go to the even digit, on the exact binary value.
void exact_digits(std::uint64_t m, int e, bool fixed, int places_or_digits, Digits& out) {
    BigNat num, den;
    big_set(num, m);
    big_set(den, 1);
    if (e >= 0)
        big_shift_left(num, e);
    else
        big_shift_left(den, -e);
    int k = floor_log10_pow2(bit_length(m) - 1 + e);
    if (k >= 0)
        big_mul_pow10(den, k);
    else
        big_mul_pow10(num, -k);
    BigNat ten_den = den;
    big_mul_small(ten_den, 10);
    while (big_compare(num, ten_den) >= 0) {  // the estimate was one low
        ++k;
        den = ten_den;
        ten_den = den;
        big_mul_small(ten_den, 10);
    }
    int count = fixed ? k + 1 + places_or_digits : places_or_digits;
    if (count > kMaxDigits) count = kMaxDigits;
    out.exponent = k;
    if (count < 0) {  // below half a unit of the last place: zero
        out.count = 0;
        return;
    }
    for (int i = 0; i < count; ++i) {
        out.d[i] = char('0' + big_divide_digit(num, den));
        if (i + 1 < count) big_mul_small(num, 10);
    }
    // Round on what is left: count digits taken, num / den the rest (for count == 0 the
    // rest is the whole value over 10^(k+1), compared as num vs 5 den).
    BigNat twice = num;
    int c;
    if (count == 0) {
        BigNat five_den = den;
        big_mul_small(five_den, 5);
        c = big_compare(num, five_den);
    } else {
        big_mul_small(twice, 2);
        c = big_compare(twice, den);
    }
    bool up = c > 0 || (c == 0 && count > 0 && (out.d[count - 1] - '0') % 2 == 1);
    out.count = count;
    if (!up) return;
    int i = count - 1;
    while (i >= 0 && out.d[i] == '9') out.d[i--] = '0';
    if (i >= 0) {
        ++out.d[i];
    } else {  // 99..9 -> 100..0: one more power of ten
        if (count > 0)
            out.d[0] = '1';
        else {
            out.d[0] = '1';
            out.count = 1;
        }
        ++out.exponent;
        if (fixed && out.count < kMaxDigits && count > 0) out.d[out.count++] = '0';
    }
}

// ---- output ----
struct Sink {
    char* out;  // null: count only
    int capacity;
    int length = 0;
    void put(char c) {
        if (out != nullptr && length + 1 < capacity) out[length] = c;
        ++length;
    }
    void finish() {
        if (out == nullptr || capacity <= 0) return;
        out[length < capacity ? length : capacity - 1] = '\0';
    }
};

// The digit of 10^position, from digits d (zero outside them).
char digit_at(const Digits& g, int position) {
    int i = g.exponent - position;
    return i >= 0 && i < g.count ? g.d[i] : '0';
}

void emit_fixed(Sink& s, const Digits& g, int places, bool point) {
    int top = g.exponent > 0 ? g.exponent : 0;
    for (int p = top; p >= -places; --p) {
        s.put(digit_at(g, p));
        if (p == 0 && (places > 0 || point)) s.put('.');
    }
}

void emit_exponent_digits(Sink& s, int exponent, bool upper) {
    s.put(upper ? 'E' : 'e');
    s.put(exponent < 0 ? '-' : '+');
    unsigned u = unsigned(exponent < 0 ? -exponent : exponent);
    char buf[4];
    int n = 0;
    do {
        buf[n++] = char('0' + u % 10u);
        u /= 10u;
    } while (u != 0);
    if (n < 2) buf[n++] = '0';
    while (n > 0) s.put(buf[--n]);
}

void emit_scientific(Sink& s, const Digits& g, int places, bool point, bool upper) {
    s.put(g.count > 0 ? g.d[0] : '0');
    if (places > 0 || point) s.put('.');
    for (int i = 1; i <= places; ++i) s.put(i < g.count ? g.d[i] : '0');
    emit_exponent_digits(s, g.count > 0 ? g.exponent : 0, upper);
}

// %g: P significant digits, fixed when -4 <= X < P, trailing zeros dropped unless '#'.
void emit_general(Sink& s, Digits& g, int precision, bool alternate, bool upper) {
    int x = g.count > 0 ? g.exponent : 0;
    int keep = precision;  // significant digits shown
    if (!alternate) {
        int last = g.count < precision ? g.count : precision;
        while (last > 1 && g.d[last - 1] == '0') --last;
        keep = g.count == 0 ? 1 : last;
    }
    if (x >= -4 && x < precision) {
        int places = keep - 1 - x;
        if (places < 0) places = 0;
        if (alternate) places = precision - 1 - x;
        emit_fixed(s, g, places, alternate);
    } else {
        emit_scientific(s, g, alternate ? precision - 1 : keep - 1, alternate, upper);
    }
}

struct Decomposed {
    bool negative, infinite, nan;
    std::uint64_t mantissa;  // 0 for zero
    int exponent;
};

Decomposed decompose(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    Decomposed r{};
    r.negative = (bits >> 63) != 0;
    int field = int((bits >> 52) & 0x7ff);
    std::uint64_t frac = bits & ((std::uint64_t(1) << 52) - 1);
    if (field == 0x7ff) {
        r.infinite = frac == 0;
        r.nan = frac != 0;
        return r;
    }
    r.mantissa = field == 0 ? frac : frac | (std::uint64_t(1) << 52);
    r.exponent = field == 0 ? -1074 : field - 1075;
    return r;
}

void emit_padded(Sink& s, const NumberFormat& f, const char* prefix, int prefix_len, int body_len,
                 bool zero_pad, void (*body)(Sink&, const void*), const void* ctx) {
    int pad = f.width - prefix_len - body_len;
    if (!f.left && !zero_pad)
        for (int i = 0; i < pad; ++i) s.put(' ');
    for (int i = 0; i < prefix_len; ++i) s.put(prefix[i]);
    if (!f.left && zero_pad)
        for (int i = 0; i < pad; ++i) s.put('0');
    body(s, ctx);
    if (f.left)
        for (int i = 0; i < pad; ++i) s.put(' ');
}

struct DoubleBody {
    const NumberFormat* f;
    Digits* g;
    int precision;
    const char* special;  // "inf" / "nan" or null
};

void double_body(Sink& s, const void* p) {
    const DoubleBody& b = *static_cast<const DoubleBody*>(p);
    if (b.special != nullptr) {
        bool upper = b.f->conversion >= 'A' && b.f->conversion <= 'Z';
        for (const char* c = b.special; *c; ++c) s.put(upper ? char(*c - 'a' + 'A') : *c);
        return;
    }
    char conv = b.f->conversion;
    bool upper = conv == 'E' || conv == 'G';
    if (conv == 'f' || conv == 'F')
        emit_fixed(s, *b.g, b.precision, b.f->alternate);
    else if (conv == 'e' || conv == 'E')
        emit_scientific(s, *b.g, b.precision, b.f->alternate, upper);
    else
        emit_general(s, *b.g, b.precision, b.f->alternate, upper);
}

int sign_prefix(char* prefix, bool negative, const NumberFormat& f) {
    if (negative)
        prefix[0] = '-';
    else if (f.plus)
        prefix[0] = '+';
    else if (f.space)
        prefix[0] = ' ';
    else
        return 0;
    return 1;
}

}  // namespace

int format_double(char* out, int capacity, double value, const NumberFormat& f) {
    Decomposed v = decompose(value);
    Digits g;
    g.count = 0;
    g.exponent = 0;
    char conv = f.conversion;
    bool fixed = conv == 'f' || conv == 'F';
    bool general = !fixed && conv != 'e' && conv != 'E';
    int precision = f.precision < 0 ? 6 : f.precision;
    if (precision > kMaxPrecision) precision = kMaxPrecision;
    if (general && precision == 0) precision = 1;
    DoubleBody body{&f, &g, precision, nullptr};
    if (v.nan)
        body.special = "nan";
    else if (v.infinite)
        body.special = "inf";
    else if (v.mantissa != 0)
        exact_digits(v.mantissa, v.exponent, fixed,
                     fixed ? precision : precision + (general ? 0 : 1), g);
    char prefix[1];
    int prefix_len = sign_prefix(prefix, v.negative, f);
    Sink counter{nullptr, 0};
    double_body(counter, &body);
    Sink s{out, capacity};
    emit_padded(s, f, prefix, prefix_len, counter.length, f.zero && body.special == nullptr,
                double_body, &body);
    s.finish();
    return s.length;
}

namespace {
struct IntegerBody {
    const char* digits;  // most significant first
    int count;
    int zeros;  // leading zeros from the precision
};
void integer_body(Sink& s, const void* p) {
    const IntegerBody& b = *static_cast<const IntegerBody*>(p);
    for (int i = 0; i < b.zeros; ++i) s.put('0');
    for (int i = 0; i < b.count; ++i) s.put(b.digits[i]);
}
}  // namespace

int format_integer(char* out, int capacity, std::uint64_t magnitude, bool negative,
                   const NumberFormat& f) {
    char conv = f.conversion;
    unsigned base = conv == 'x' || conv == 'X' ? 16u : conv == 'o' ? 8u : 10u;
    const char* glyphs = conv == 'X' ? "0123456789ABCDEF" : "0123456789abcdef";
    char buf[24];
    int n = 0;
    for (std::uint64_t u = magnitude; u != 0; u /= base)
        buf[sizeof buf - 1 - n++] = glyphs[u % base];
    int precision = f.precision < 0 ? 1 : f.precision;
    IntegerBody body{buf + sizeof buf - n, n, precision > n ? precision - n : 0};
    char prefix[2];
    int prefix_len = 0;
    bool is_signed = conv == 'd' || conv == 'i';
    if (is_signed) prefix_len = sign_prefix(prefix, negative, f);
    if (f.alternate && magnitude != 0 && base == 16u) {
        prefix[0] = '0';
        prefix[1] = conv;
        prefix_len = 2;
    }
    if (f.alternate && base == 8u && body.zeros == 0) body.zeros = 1;
    Sink s{out, capacity};
    emit_padded(s, f, prefix, prefix_len, body.zeros + body.count, f.zero && f.precision < 0,
                integer_body, &body);
    s.finish();
    return s.length;
}

namespace {

std::uint64_t to_u64(const BigNat& a) {
    std::uint64_t v = 0;
    for (int i = a.n - 1; i >= 0; --i) v = (v << 32) | a.w[i];
    return v;
}

// The same four operations on 64-bit numbers (when they fit) and on BigNat.
void nat_mul10(std::uint64_t& a) { a *= 10u; }
void nat_mul10(BigNat& a) { big_mul_small(a, 10); }
int nat_compare_sum(std::uint64_t a, std::uint64_t b, std::uint64_t c) {  // a + b vs c
    return a + b < c ? -1 : a + b > c ? 1 : 0;
}
int nat_compare_sum(const BigNat& a, const BigNat& b, const BigNat& c) {
    BigNat sum;
    sum.n = a.n;
    std::memcpy(sum.w, a.w, sizeof(std::uint32_t) * std::size_t(a.n));
    big_add(sum, b);
    return big_compare(sum, c);
}
int nat_compare(std::uint64_t a, std::uint64_t b) { return a < b ? -1 : a > b ? 1 : 0; }
int nat_compare(const BigNat& a, const BigNat& b) { return big_compare(a, b); }
int nat_divide_digit(std::uint64_t& r, std::uint64_t s) {
    int d = int(r / s);
    r -= std::uint64_t(d) * s;
    return d;
}
int nat_divide_digit(BigNat& r, const BigNat& s) { return big_divide_digit(r, s); }

// Digits of r / s until the number so far lies inside v's rounding interval (m- below,
// m+ above, scaled like r), ties between the two last candidates to the even digit.
template <class Nat>
void shortest_digits(Nat r, const Nat& s, Nat mplus, Nat mminus, bool even, Digits& g) {
    for (;;) {
        int d = nat_divide_digit(r, s);
        int cl = nat_compare(r, mminus), ch = nat_compare_sum(r, mplus, s);
        bool low_ok = cl < 0 || (cl == 0 && even);
        bool high_ok = ch > 0 || (ch == 0 && even);
        if (low_ok || high_ok || g.count + 1 >= 17) {
            if (high_ok && !low_ok) {
                ++d;
            } else if (high_ok && low_ok) {
                int c = nat_compare_sum(r, r, s);  // 2r vs s
                if (c > 0 || (c == 0 && d % 2 == 1)) ++d;
            }
            g.d[g.count++] = char('0' + d);  // d <= 9: a 10 would have stopped earlier
            return;
        }
        g.d[g.count++] = char('0' + d);
        nat_mul10(r);
        nat_mul10(mplus);
        nat_mul10(mminus);
    }
}

// The float m·2^e (24-bit m, e >= -149) scaled for free-format digits: r / s = v / 10^k
// with 1 <= that and (r + m+) / s < 10 (<= with even), m+ and m- the gaps to the neighbouring
// floats (halved, scaled like r). Done on 64-bit numbers where every step fits (typical
// coordinates, about 1e-9 .. 1e9, with 10·s < 2^63 so the digits fit too): the same integers
// as scaled_big, far faster; false where it does not fit.
bool scaled_u64(std::uint64_t m, int e, bool even, bool unequal_gaps, std::uint64_t* r,
                std::uint64_t* s, std::uint64_t* mplus, std::uint64_t* mminus, int* k) {
    static const std::uint64_t pow10[20] = {1u,
                                            10u,
                                            100u,
                                            1000u,
                                            10000u,
                                            100000u,
                                            1000000u,
                                            10000000u,
                                            100000000u,
                                            1000000000u,
                                            10000000000u,
                                            100000000000u,
                                            1000000000000u,
                                            10000000000000u,
                                            100000000000000u,
                                            1000000000000000u,
                                            10000000000000000u,
                                            100000000000000000u,
                                            1000000000000000000u,
                                            10000000000000000000u};
    const std::uint64_t max = ~std::uint64_t(0);
    const int g = unequal_gaps ? 2 : 1;
    *r = m << g, *s = std::uint64_t(1) << g, *mplus = unequal_gaps ? 2u : 1u, *mminus = 1u;
    if (e >= 0) {
        if (e > 63 - 26) return false;  // r < 2^26 before the shift
        *r <<= e, *mplus <<= e, *mminus <<= e;
    } else {
        if (-e > 63 - 3) return false;  // s <= 4 before the shift
        *s <<= -e;
    }
    *k = floor_log10_pow2(bit_length(m) - 1 + e);
    if (*k >= 0) {
        if (*k > 19 || *s > max / pow10[*k]) return false;
        *s *= pow10[*k];
    } else {
        if (-*k > 19 || *r > max / pow10[-*k]) return false;  // r is the largest of the three
        *r *= pow10[-*k], *mplus *= pow10[-*k], *mminus *= pow10[-*k];
    }
    for (;;) {
        if (*r > max - *mplus || *s > max / 10u) return false;
        const std::uint64_t high = *r + *mplus, ten = *s * 10u;
        if (!(high > ten || (high == ten && even))) break;
        *s = ten;
        ++*k;
    }
    return *s <= ((std::uint64_t(1) << 63) - 1u) / 10u;  // 10·s < 2^63: the digits' 64-bit path
}

// The same scaling on BigNat (any float), then the digits (on 64 bits where they fit).
void scaled_big_digits(std::uint64_t m, int e, bool even, bool unequal_gaps, Digits& g) {
    BigNat r, sden, mplus, mminus;
    big_set(r, m);
    big_set(sden, 1);
    big_set(mplus, 1);
    big_set(mminus, 1);
    big_shift_left(r, unequal_gaps ? 2 : 1);
    big_shift_left(sden, unequal_gaps ? 2 : 1);
    if (unequal_gaps) big_shift_left(mplus, 1);
    if (e >= 0) {
        big_shift_left(r, e);
        big_shift_left(mplus, e);
        big_shift_left(mminus, e);
    } else {
        big_shift_left(sden, -e);
    }
    int k = floor_log10_pow2(bit_length(m) - 1 + e);
    if (k >= 0) {
        big_mul_pow10(sden, k);
    } else {
        big_mul_pow10(r, -k);
        big_mul_pow10(mplus, -k);
        big_mul_pow10(mminus, -k);
    }
    // Now r / sden = v / 10^k with 1 <= that; raise k until the high end is <= 1 * 10^(k+1)
    // i.e. digits start at 10^k: want (r + m+) / sden < 10 (<= with even).
    for (;;) {
        BigNat high = r;
        big_add(high, mplus);
        BigNat ten = sden;
        big_mul_small(ten, 10);
        int c = big_compare(high, ten);
        if (c > 0 || (c == 0 && even)) {
            sden = ten;
            ++k;
        } else {
            break;
        }
    }
    g.exponent = k;
    BigNat ten_s = sden;
    big_mul_small(ten_s, 10);
    if (ten_s.n <= 2 && (ten_s.n < 2 || ten_s.w[1] < 0x80000000u))
        shortest_digits(to_u64(r), to_u64(sden), to_u64(mplus), to_u64(mminus), even, g);
    else
        shortest_digits(r, sden, mplus, mminus, even, g);
}

}  // namespace

// Steele & White's free-format digits (as in Burger & Dybvig): generate digits of v until
// the number so far lies strictly inside v's rounding interval (or on its boundary when the
// mantissa is even: round-to-even reads the boundary back to v).
int format_float_round_trip(char* out, int capacity, float value) {
    Decomposed v = decompose(double(value));
    Sink s{out, capacity};
    if (v.nan || v.infinite) {
        if (v.infinite && v.negative) s.put('-');
        for (const char* c = v.nan ? "nan" : "inf"; *c; ++c) s.put(*c);
        s.finish();
        return s.length;
    }
    if (v.negative) s.put('-');
    Digits g;
    g.count = 0;
    g.exponent = 0;
    if (v.mantissa != 0) {
        // The float's own mantissa and exponent (24 bits, e >= -149).
        std::uint64_t m = v.mantissa;
        int e = v.exponent;
        while (m >= (1u << 24) || e < -149) {  // exact: a float has no bits there
            m >>= 1;
            ++e;
        }
        while (m < (1u << 23) && e > -149) {
            m <<= 1;
            --e;
        }
        bool even = (m & 1u) == 0;
        bool unequal_gaps = m == (1u << 23) && e > -149;  // the gap below is half the gap above
        std::uint64_t r, sden, mplus, mminus;
        int k = 0;
        if (scaled_u64(m, e, even, unequal_gaps, &r, &sden, &mplus, &mminus, &k)) {
            g.exponent = k;
            shortest_digits(r, sden, mplus, mminus, even, g);
        } else {
            scaled_big_digits(m, e, even, unequal_gaps, g);
        }
    }
    // Chosen here: plain notation for 1e-5 <= |v| < 1e9 (no exponent in OBJ files for
    // ordinary coordinates), exponent notation outside, as %g prints it.
    int x = g.exponent;
    if (g.count == 0 || (x >= -5 && x < 9)) {
        int places = g.count - 1 - x;
        emit_fixed(s, g, places > 0 ? places : 0, false);
    } else {
        emit_scientific(s, g, g.count - 1, false, false);
    }
    s.finish();
    return s.length;
}

}  // namespace shitsukan
