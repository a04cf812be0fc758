// ports/cortex-m/soft_single.hpp — IEEE 754 binary32 addition, multiplication and division on
// the bits, round-to-nearest-even with subnormals, infinities and NaNs: soft_double.hpp's
// method at float width (27-bit significands: the leading 1 at bit 26, 23 fraction bits,
// guard, round, sticky), for RV32IMAC (../riscv/soft_single.cpp), in place of libgcc's
// soft-fp float routines (2.0 KB of flash). Correctly rounded, so libgcc's bits; checked against
// the host's FPU and against libgcc on the M0 and the RV32 (tests/mcu/soft_double_check.cpp).
// The M0 keeps libgcc's: these cost it 25 % more instructions on the float-heavy paths.
#pragma once

#include <cstdint>

namespace shitsukan::port::soft_single {

using u32 = std::uint32_t;
using u64 = std::uint64_t;

constexpr u32 kSign = 0x80000000u;
constexpr u32 kInf = 0x7f800000u;
constexpr u32 kHidden = 0x00800000u;
constexpr u32 kFraction = kHidden - 1;
constexpr u32 kLead = u32(1) << 26;
constexpr u32 kNaN = 0x7fc00000u;  // an invalid operation's NaN: libgcc's on both targets

inline bool is_nan(u32 x) { return (x & ~kSign) > kInf; }

inline u32 nan_result(u32 a, u32 b) {  // soft_double.hpp's rule at float width
#if defined(__arm__)
    const u32 quiet = u32(1) << 22;
    if (is_nan(a) && is_nan(b))
        return (b & quiet) == 0 && (a & quiet) != 0 ? b | quiet : a | quiet;
    return (is_nan(a) ? a : b) | quiet;
#else
    (void)a;
    (void)b;
    return kNaN;
#endif
}

// Rounds m·2^(e - 153) to the nearest float, ties to even, with sign (m: leading 1 at bit 26,
// or with e == 1 a subnormal's smaller significand; bit 0 sticky).
inline u32 round_pack(u32 sign, int e, u32 m) {
    if (e >= 0xff) return sign | kInf;
    if (e <= 0) {
        const int shift = 1 - e;
        m = shift < 32 ? (m >> shift) | u32((m << (32 - shift)) != 0) : u32(m != 0);
        e = 1;
    }
    const u32 low = m & 7u;
    m >>= 3;
    if (low > 4 || (low == 4 && (m & 1u) != 0)) ++m;
    return sign | ((u32(e - 1) << 23) + m);
}

inline u32 unpack(u32 magnitude, int* e) {
    int exponent = int(magnitude >> 23);
    u32 f = magnitude & kFraction;
    if (exponent != 0) {
        f |= kHidden;
    } else {
        exponent = 1;
        while ((f & kHidden) == 0) {
            f <<= 1;
            --exponent;
        }
    }
    *e = exponent;
    return f << 3;
}

inline u32 add(u32 a, u32 b) {
    if (is_nan(a) || is_nan(b)) return nan_result(a, b);
    u32 ma = a & ~kSign, mb = b & ~kSign;
    if (ma == kInf) return mb == kInf && ((a ^ b) & kSign) != 0 ? kNaN : a;
    if (mb == kInf) return b;
    if (ma < mb) {
        const u32 t = a;
        a = b;
        b = t;
        ma = a & ~kSign;
        mb = b & ~kSign;
    }
    if (mb == 0) return ma == 0 ? (a & b) : a;
    int ea, eb;
    const u32 fa = unpack(ma, &ea);
    u32 fb = unpack(mb, &eb);
    const int d = ea - eb;
    if (d > 0) fb = d < 32 ? (fb >> d) | u32((fb << (32 - d)) != 0) : 1u;
    u32 m;
    if (((a ^ b) & kSign) != 0) {
        m = fa - fb;
        if (m == 0) return 0;
        while (m < kLead) {
            m <<= 1;
            --ea;
        }
    } else {
        m = fa + fb;
        if (m >= (kLead << 1)) {
            m = (m >> 1) | (m & 1u);
            ++ea;
        }
    }
    return round_pack(a & kSign, ea, m);
}

inline u32 mul(u32 a, u32 b) {
    if (is_nan(a) || is_nan(b)) return nan_result(a, b);
    const u32 sign = (a ^ b) & kSign, ma = a & ~kSign, mb = b & ~kSign;
    if (ma == kInf || mb == kInf) return ma == 0 || mb == 0 ? kNaN : sign | kInf;
    if (ma == 0 || mb == 0) return sign;
    int ea, eb;
    const u32 fa = unpack(ma, &ea) >> 3, fb = unpack(mb, &eb) >> 3;  // 24 bits each
    const u64 p = u64(fa) * fb;  // in [2^46, 2^48): the top 27 bits from bit 20, sticky below
    u32 m = u32(p >> 20) | u32((p & 0xfffffu) != 0);
    int e = ea + eb - 127;
    if (m >= (kLead << 1)) {
        m = (m >> 1) | (m & 1u);
        ++e;
    }
    return round_pack(sign, e, m);
}

inline u32 div(u32 a, u32 b) {
    if (is_nan(a) || is_nan(b)) return nan_result(a, b);
    const u32 sign = (a ^ b) & kSign, ma = a & ~kSign, mb = b & ~kSign;
    if (ma == kInf) return mb == kInf ? kNaN : sign | kInf;
    if (mb == kInf) return sign;
    if (mb == 0) return ma == 0 ? kNaN : sign | kInf;
    if (ma == 0) return sign;
    int ea, eb;
    u32 fa = unpack(ma, &ea) >> 3;
    const u32 fb = unpack(mb, &eb) >> 3;
    int e = ea - eb + 127;
    if (fa < fb) {
        fa <<= 1;
        --e;
    }
    u32 q = 0;  // 27 quotient bits by long division: leading 1 at bit 26
    for (int i = 0; i < 27; ++i) {
        q <<= 1;
        if (fa >= fb) {
            fa -= fb;
            q |= 1u;
        }
        fa <<= 1;
    }
    return round_pack(sign, e, q | u32(fa != 0));
}

}  // namespace shitsukan::port::soft_single
