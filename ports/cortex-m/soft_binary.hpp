// ports/cortex-m/soft_binary.hpp — IEEE 754 addition, multiplication and division on the bits,
// with round-to-nearest-even, subnormals, infinities and NaNs, written once for both formats
// the FPU-less ports need: binary64 (soft_double.hpp) and binary32 (soft_single.hpp).
//
//   using D = shitsukan::port::soft_binary::Format<shitsukan::port::soft_binary::Binary64>;
//   const std::uint64_t three = shitsukan::port::soft_binary::add<D>(0x3ff0000000000000ull,
//                                                                    0x4000000000000000ull);
//   // three == 0x4008000000000000 (1 + 2 = 3)
//
// The method: the operands are widened to significands of kFractionBits + 4 bits (the leading
// 1, the fraction, then guard, round and a sticky bit), the exact result is formed (a sum
// with the shifted-out bits ORed into the sticky bit, the double-width product, the quotient
// by long division with the remainder as sticky bit) and rounded once by round_pack. Every
// operation is correctly rounded (IEEE 754 defines one result for each pair of operands), so
// these give libgcc's bits; a NaN result is the target's own (nan_result: what its libgcc
// returns). Checked against libgcc on the M0 and the RV32 (tests/mcu/soft_double_check.cpp).
#pragma once

#include <cstdint>

namespace shitsukan::port::soft_binary {

struct Binary64 {
    using Bits = std::uint64_t;
    static constexpr int kWidth = 64, kFractionBits = 52, kMaxExponent = 0x7ff, kBias = 1023;
};
struct Binary32 {
    using Bits = std::uint32_t;
    static constexpr int kWidth = 32, kFractionBits = 23, kMaxExponent = 0xff, kBias = 127;
};

// A format's bit patterns.
template <class Base>
struct Format : Base {
    using Bits = typename Base::Bits;
    static constexpr Bits kSign = Bits(1) << (Base::kWidth - 1);
    static constexpr Bits kInf = Bits(Base::kMaxExponent) << Base::kFractionBits;
    static constexpr Bits kHidden = Bits(1) << Base::kFractionBits;
    static constexpr Bits kFraction = kHidden - 1;
    static constexpr Bits kLead = Bits(1) << (Base::kFractionBits + 3);  // widened leading 1
    static constexpr Bits kQuiet = Bits(1) << (Base::kFractionBits - 1);
    // The NaN of an invalid operation (inf - inf, 0·inf, 0/0, inf/inf): libgcc's on both targets.
    static constexpr Bits kNaN = kInf | kQuiet;
};

template <class F>
inline bool is_nan(typename F::Bits x) {
    return (x & ~F::kSign) > F::kInf;
}

// Rounds m·2^(e - bias - kFractionBits - 3) to the nearest value of the format, ties to even,
// with sign: m has its leading 1 at kLead (or, with e == 1, is a subnormal's smaller
// significand); its bit 0 is sticky.
template <class F>
inline typename F::Bits round_pack(typename F::Bits sign, int e, typename F::Bits m) {
    using Bits = typename F::Bits;
    if (e >= F::kMaxExponent) return sign | F::kInf;
    if (e <= 0) {  // below the normal range: to the subnormal's position, keeping a sticky bit
        const int shift = 1 - e;
        m = shift < F::kWidth ? (m >> shift) | Bits((m << (F::kWidth - shift)) != 0)
                              : Bits(m != 0);
        e = 1;
    }
    const std::uint32_t low = std::uint32_t(m & 7u);
    m >>= 3;
    if (low > 4 || (low == 4 && (m & 1u) != 0)) ++m;  // a carry moves into the exponent
    // m below kHidden (no leading 1): a subnormal, e - 1 = 0
    return sign | ((Bits(e - 1) << F::kFractionBits) + m);
}

// The widened significand (leading 1 at kLead after normalising a subnormal) and exponent of
// a finite nonzero magnitude.
template <class F>
inline typename F::Bits unpack(typename F::Bits magnitude, int* e) {
    int exponent = int(magnitude >> F::kFractionBits);
    typename F::Bits f = magnitude & F::kFraction;
    if (exponent != 0) {
        f |= F::kHidden;
    } else {
        exponent = 1;
        while ((f & F::kHidden) == 0) {
            f <<= 1;
            --exponent;
        }
    }
    *e = exponent;
    return f << 3;
}

// The NaN an operation with a NaN operand returns: libgcc's choice on each target.
template <class F>
inline typename F::Bits nan_result(typename F::Bits a, typename F::Bits b) {
#if defined(__arm__)
    // Arm: the operand's NaN, payload and sign kept, made quiet; of two NaNs the first,
    // unless only the second is signalling (soft-fp's _FP_CHOOSENAN for Arm)
    if (is_nan<F>(a) && is_nan<F>(b))
        return (b & F::kQuiet) == 0 && (a & F::kQuiet) != 0 ? b | F::kQuiet : a | F::kQuiet;
    return (is_nan<F>(a) ? a : b) | F::kQuiet;
#else
    // RISC-V: the canonical quiet NaN for every NaN result (the ISA's rule)
    (void)a;
    (void)b;
    return F::kNaN;
#endif
}

template <class F>
inline typename F::Bits add(typename F::Bits a, typename F::Bits b) {
    using Bits = typename F::Bits;
    if (is_nan<F>(a) || is_nan<F>(b)) return nan_result<F>(a, b);
    Bits ma = a & ~F::kSign, mb = b & ~F::kSign;
    if (ma == F::kInf) return mb == F::kInf && ((a ^ b) & F::kSign) != 0 ? F::kNaN : a;
    if (mb == F::kInf) return b;
    if (ma < mb) {  // |a| >= |b| from here on
        const Bits t = a;
        a = b;
        b = t;
        ma = a & ~F::kSign;
        mb = b & ~F::kSign;
    }
    if (mb == 0) return ma == 0 ? (a & b) : a;  // -0 + -0 = -0, +0 + -0 = +0
    int ea, eb;
    const Bits fa = unpack<F>(ma, &ea);
    Bits fb = unpack<F>(mb, &eb);
    const int d = ea - eb;
    if (d > 0) fb = d < F::kWidth ? (fb >> d) | Bits((fb << (F::kWidth - d)) != 0) : Bits(1);
    Bits m;
    if (((a ^ b) & F::kSign) != 0) {
        m = fa - fb;
        if (m == 0) return 0;  // x - x = +0
        while (m < F::kLead) {  // cancellation: normalise (a subnormal result stops at e = 1)
            m <<= 1;
            --ea;
        }
    } else {
        m = fa + fb;
        if (m >= (F::kLead << 1)) {
            m = (m >> 1) | (m & 1u);
            ++ea;
        }
    }
    return round_pack<F>(a & F::kSign, ea, m);
}

// The product of two significands of kFractionBits + 1 bits, in [2^(2·kFractionBits),
// 2^(2·kFractionBits + 2)): its top bits from bit kFractionBits - 3 on, the rest ORed into
// the sticky bit 0.
template <class F>
inline typename F::Bits significand_product(typename F::Bits fa, typename F::Bits fb) {
    using Bits = typename F::Bits;
    constexpr int kCut = F::kFractionBits - 3;
    if constexpr (F::kWidth == 64) {
        // the 106-bit product from four 32 x 32 -> 64 products
        const Bits a0 = std::uint32_t(fa), a1 = fa >> 32, b0 = std::uint32_t(fb), b1 = fb >> 32;
        const Bits ll = a0 * b0, lh = a0 * b1, hl = a1 * b0, hh = a1 * b1;
        const Bits mid = (ll >> 32) + std::uint32_t(lh) + std::uint32_t(hl);
        const Bits lo = (mid << 32) | std::uint32_t(ll);
        const Bits hi = hh + (lh >> 32) + (hl >> 32) + (mid >> 32);
        return (hi << (64 - kCut)) | (lo >> kCut) | Bits((lo & ((Bits(1) << kCut) - 1)) != 0);
    } else {
        const std::uint64_t p = std::uint64_t(fa) * fb;
        return Bits(p >> kCut) | Bits((p & ((std::uint64_t(1) << kCut) - 1)) != 0);
    }
}

template <class F>
inline typename F::Bits mul(typename F::Bits a, typename F::Bits b) {
    using Bits = typename F::Bits;
    if (is_nan<F>(a) || is_nan<F>(b)) return nan_result<F>(a, b);
    const Bits sign = (a ^ b) & F::kSign, ma = a & ~F::kSign, mb = b & ~F::kSign;
    if (ma == F::kInf || mb == F::kInf) return ma == 0 || mb == 0 ? F::kNaN : sign | F::kInf;
    if (ma == 0 || mb == 0) return sign;
    int ea, eb;
    const Bits fa = unpack<F>(ma, &ea) >> 3, fb = unpack<F>(mb, &eb) >> 3;
    Bits m = significand_product<F>(fa, fb);
    int e = ea + eb - F::kBias;
    if (m >= (F::kLead << 1)) {
        m = (m >> 1) | (m & 1u);
        ++e;
    }
    return round_pack<F>(sign, e, m);
}

template <class F>
inline typename F::Bits div(typename F::Bits a, typename F::Bits b) {
    using Bits = typename F::Bits;
    if (is_nan<F>(a) || is_nan<F>(b)) return nan_result<F>(a, b);
    const Bits sign = (a ^ b) & F::kSign, ma = a & ~F::kSign, mb = b & ~F::kSign;
    if (ma == F::kInf) return mb == F::kInf ? F::kNaN : sign | F::kInf;
    if (mb == F::kInf) return sign;
    if (mb == 0) return ma == 0 ? F::kNaN : sign | F::kInf;
    if (ma == 0) return sign;
    int ea, eb;
    Bits fa = unpack<F>(ma, &ea) >> 3;
    const Bits fb = unpack<F>(mb, &eb) >> 3;
    int e = ea - eb + F::kBias;
    if (fa < fb) {  // the quotient of the significands in [1, 2)
        fa <<= 1;
        --e;
    }
    Bits q = 0;  // kFractionBits + 4 quotient bits by long division: leading 1 at kLead
    for (int i = 0; i < F::kFractionBits + 4; ++i) {
        q <<= 1;
        if (fa >= fb) {
            fa -= fb;
            q |= 1u;
        }
        fa <<= 1;
    }
    return round_pack<F>(sign, e, q | Bits(fa != 0));
}

}  // namespace shitsukan::port::soft_binary
