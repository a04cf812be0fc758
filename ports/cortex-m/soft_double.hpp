// ports/cortex-m/soft_double.hpp — IEEE 754 binary64 addition, multiplication and division on
// the bits, with round-to-nearest-even, subnormals, infinities and NaNs, for the FPU-less
// Cortex-M0 and RV32IMAC (soft_double.cpp, for both).
//
// Why: libgcc's soft-fp double routines are 4.7 KB of flash on Armv6-M (__aeabi_dadd 1,724,
// __aeabi_dmul 1,416, __aeabi_ddiv 1,592 bytes) and 4.0 KB on RV32, more than the library's
// whole marble shader; these are about a quarter of that. Every operation is correctly rounded
// (IEEE 754 defines one result for each pair of operands), so they give libgcc's bits: the
// operands are widened to 56-bit significands (the leading 1 at bit 55, then 52 fraction bits,
// then guard, round and a sticky bit), the exact result is formed (a sum with the shifted-out
// bits ORed into the sticky bit, the 106-bit product, the quotient by long division with the
// remainder as sticky bit) and rounded once by round_pack. A NaN result is the target's own
// (kNaN and nan_result, below: what its libgcc returns). Checked against the host's FPU on random and edge
// operands and against libgcc on the devices (tests/mcu/soft_double_check.cpp).
#pragma once

#include <cstdint>

namespace shitsukan::port::soft_double {

using u64 = std::uint64_t;
using u32 = std::uint32_t;

constexpr u64 kSign = u64(1) << 63;
constexpr u64 kInf = u64(0x7ff) << 52;
constexpr u64 kHidden = u64(1) << 52;
constexpr u64 kFraction = kHidden - 1;
constexpr u64 kLead = u64(1) << 55;  // the leading 1 of a widened significand

// The NaN of an invalid operation (inf - inf, 0·inf, 0/0, inf/inf): libgcc's on both targets.
constexpr u64 kNaN = u64(0x7ff8) << 48;

inline bool is_nan(u64 x) { return (x & ~kSign) > kInf; }

// Rounds m·2^(e - 1078) to the nearest double, ties to even, with sign: m has its leading 1 at
// bit 55 (or, with e == 1, is a subnormal's smaller significand); its bit 0 is sticky.
inline u64 round_pack(u64 sign, int e, u64 m) {
    if (e >= 0x7ff) return sign | kInf;
    if (e <= 0) {  // below the normal range: to the subnormal's position, keeping a sticky bit
        const int shift = 1 - e;
        m = shift < 64 ? (m >> shift) | u64((m << (64 - shift)) != 0) : u64(m != 0);
        e = 1;
    }
    const u32 low = u32(m & 7u);
    m >>= 3;
    if (low > 4 || (low == 4 && (m & 1u) != 0)) ++m;  // a carry moves into the exponent
    return sign | ((u64(e - 1) << 52) + m);  // m < 2^52 (no leading 1): subnormal, e - 1 = 0
}

// The widened significand (leading 1 at bit 55 after normalising a subnormal) and exponent of
// a finite nonzero magnitude.
inline u64 unpack(u64 magnitude, int* e) {
    int exponent = int(magnitude >> 52);
    u64 f = magnitude & kFraction;
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

// The NaN an operation with a NaN operand returns: libgcc's choice on each target.
inline u64 nan_result(u64 a, u64 b) {
#if defined(__arm__)
    // Arm: the operand's NaN, payload and sign kept, made quiet; of two NaNs the first,
    // unless only the second is signalling (soft-fp's _FP_CHOOSENAN for Arm)
    const u64 quiet = u64(1) << 51;
    if (is_nan(a) && is_nan(b))
        return (b & quiet) == 0 && (a & quiet) != 0 ? b | quiet : a | quiet;
    return (is_nan(a) ? a : b) | quiet;
#else
    // RISC-V: the canonical quiet NaN for every NaN result (the ISA's rule)
    (void)a;
    (void)b;
    return kNaN;
#endif
}

// n rounded to the nearest double, ties to even (what double(n) does).
inline u64 from_unsigned(u64 n) {
    if (n == 0) return 0;
    int top = 63;  // the leading 1
    while ((n >> top) == 0) --top;
    // to the leading 1 at bit 55, the bits shifted out ORed into the sticky bit 0
    const u64 m = top <= 55 ? n << (55 - top)
                            : (n >> (top - 55)) | u64((n << (64 - (top - 55))) != 0);
    return round_pack(0, top + 1023, m);
}

// The float with bits f as a double (exact: what double(f) does).
inline u64 from_float(u32 f) {
    const u64 sign = u64(f & 0x80000000u) << 32;
    int exponent = int((f >> 23) & 0xffu);
    u64 fraction = f & 0x7fffffu;
    if (exponent == 0xff) {
        // a NaN keeps its sign and payload, made quiet (libgcc's, measured, on both targets)
        const u64 x = sign | kInf | (fraction << 29);
        return fraction == 0 ? x : x | (u64(1) << 51);
    }
    if (exponent == 0) {  // a subnormal float is a normal double
        if (fraction == 0) return sign;
        exponent = 1;
        while ((fraction & 0x800000u) == 0) {
            fraction <<= 1;
            --exponent;
        }
        fraction &= 0x7fffffu;
    }
    return sign | (u64(exponent - 127 + 1023) << 52) | (fraction << 29);
}

// The binary128 number with words high (sign, 15-bit exponent, 48 fraction bits) and low (64
// fraction bits) rounded once to a double, ties to even.
inline u64 from_quad(u64 high, u64 low) {
    const u64 sign = high & kSign;
    const int exponent = int((high >> 48) & 0x7fffu);
    high &= (u64(1) << 48) - 1;
    if (exponent == 0x7fff)  // a NaN: the canonical one (libgcc's, measured)
        return high == 0 && low == 0 ? sign | kInf : kNaN;
    if (exponent == 0 && high == 0 && low == 0) return sign;
    // the leading 1 (none for a binary128 subnormal: far below the doubles, it rounds to 0)
    // at bit 55, 55 fraction bits, the other 57 ORed into the sticky bit
    const u64 m = (exponent == 0 ? 0 : kLead) | (high << 7) | (low >> 57) |
                  u64((low & ((u64(1) << 57) - 1)) != 0);
    return round_pack(sign, exponent - 16383 + 1023, m);
}

inline u64 add(u64 a, u64 b) {
    if (is_nan(a) || is_nan(b)) return nan_result(a, b);
    u64 ma = a & ~kSign, mb = b & ~kSign;
    if (ma == kInf) return mb == kInf && ((a ^ b) & kSign) != 0 ? kNaN : a;  // inf - inf
    if (mb == kInf) return b;
    if (ma < mb) {  // |a| >= |b| from here on
        const u64 t = a;
        a = b;
        b = t;
        ma = a & ~kSign;
        mb = b & ~kSign;
    }
    if (mb == 0) return ma == 0 ? (a & b) : a;  // -0 + -0 = -0, +0 + -0 = +0
    int ea, eb;
    const u64 fa = unpack(ma, &ea);
    u64 fb = unpack(mb, &eb);
    const int d = ea - eb;
    if (d > 0) fb = d < 64 ? (fb >> d) | u64((fb << (64 - d)) != 0) : 1u;
    u64 m;
    if (((a ^ b) & kSign) != 0) {
        m = fa - fb;
        if (m == 0) return 0;  // x - x = +0
        while (m < kLead) {    // cancellation: normalise (a subnormal result stops at e = 1)
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

inline u64 mul(u64 a, u64 b) {
    if (is_nan(a) || is_nan(b)) return nan_result(a, b);
    const u64 sign = (a ^ b) & kSign, ma = a & ~kSign, mb = b & ~kSign;
    if (ma == kInf || mb == kInf) return ma == 0 || mb == 0 ? kNaN : sign | kInf;
    if (ma == 0 || mb == 0) return sign;
    int ea, eb;
    const u64 fa = unpack(ma, &ea) >> 3, fb = unpack(mb, &eb) >> 3;  // 53 bits each
    // the 106-bit product from four 32 x 32 -> 64 products
    const u64 a0 = u32(fa), a1 = fa >> 32, b0 = u32(fb), b1 = fb >> 32;
    const u64 ll = a0 * b0, lh = a0 * b1, hl = a1 * b0, hh = a1 * b1;
    const u64 mid = (ll >> 32) + u32(lh) + u32(hl);
    const u64 lo = (mid << 32) | u32(ll), hi = hh + (lh >> 32) + (hl >> 32) + (mid >> 32);
    // product in [2^104, 2^106): its top 56 bits (from bit 49) with the rest as sticky
    u64 m = (hi << 15) | (lo >> 49) | u64((lo & ((u64(1) << 49) - 1)) != 0);
    int e = ea + eb - 1023;
    if (m >= (kLead << 1)) {
        m = (m >> 1) | (m & 1u);
        ++e;
    }
    return round_pack(sign, e, m);
}

inline u64 div(u64 a, u64 b) {
    if (is_nan(a) || is_nan(b)) return nan_result(a, b);
    const u64 sign = (a ^ b) & kSign, ma = a & ~kSign, mb = b & ~kSign;
    if (ma == kInf) return mb == kInf ? kNaN : sign | kInf;
    if (mb == kInf) return sign;
    if (mb == 0) return ma == 0 ? kNaN : sign | kInf;
    if (ma == 0) return sign;
    int ea, eb;
    u64 fa = unpack(ma, &ea) >> 3;
    const u64 fb = unpack(mb, &eb) >> 3;
    int e = ea - eb + 1023;
    if (fa < fb) {  // the quotient of the significands in [1, 2)
        fa <<= 1;
        --e;
    }
    u64 q = 0;  // 56 quotient bits by long division: leading 1 at bit 55
    for (int i = 0; i < 56; ++i) {
        q <<= 1;
        if (fa >= fb) {
            fa -= fb;
            q |= 1u;
        }
        fa <<= 1;
    }
    return round_pack(sign, e, q | u64(fa != 0));
}

}  // namespace shitsukan::port::soft_double
