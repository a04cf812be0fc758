// ports/cortex-m/soft_double.hpp — IEEE 754 binary64 addition, multiplication and division on
// the bits, with round-to-nearest-even, subnormals, infinities and NaNs, for the FPU-less
// Cortex-M0 and RV32IMAC (soft_double.cpp, for both), and the conversions they need.
//
// Why: libgcc's soft-fp double routines are 4.7 KB of flash on Armv6-M (__aeabi_dadd 1,724,
// __aeabi_dmul 1,416, __aeabi_ddiv 1,592 bytes) and 4.0 KB on RV32, more than the library's
// whole marble shader; these are about a quarter of that. The operations are soft_binary.hpp's
// at binary64 (56-bit widened significands: the leading 1 at bit 55, then 52 fraction bits,
// then guard, round and a sticky bit), correctly rounded, so libgcc's bits. Checked against
// the host's FPU on random and edge operands and against libgcc on the devices
// (tests/mcu/soft_double_check.cpp).
#pragma once

#include <cstdint>

#include "soft_binary.hpp"

namespace shitsukan::port::soft_double {

using u64 = std::uint64_t;
using u32 = std::uint32_t;

using Format = soft_binary::Format<soft_binary::Binary64>;
constexpr u64 kSign = Format::kSign;
constexpr u64 kInf = Format::kInf;
constexpr u64 kHidden = Format::kHidden;
constexpr u64 kFraction = Format::kFraction;
constexpr u64 kLead = Format::kLead;  // the leading 1 of a widened significand (bit 55)
constexpr u64 kNaN = Format::kNaN;    // an invalid operation's NaN: libgcc's on both targets

inline bool is_nan(u64 x) { return soft_binary::is_nan<Format>(x); }
inline u64 round_pack(u64 sign, int e, u64 m) { return soft_binary::round_pack<Format>(sign, e, m); }
inline u64 add(u64 a, u64 b) { return soft_binary::add<Format>(a, b); }
inline u64 mul(u64 a, u64 b) { return soft_binary::mul<Format>(a, b); }
inline u64 div(u64 a, u64 b) { return soft_binary::div<Format>(a, b); }

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

}  // namespace shitsukan::port::soft_double
