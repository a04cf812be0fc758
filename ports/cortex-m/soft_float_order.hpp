// ports/cortex-m/soft_float_order.hpp — the IEEE order of two floats or two doubles from their
// bits, for the soft-float comparison routines of the Cortex-M0 (soft_float_compare.cpp) and
// the RV32 (../riscv/soft_float_compare.cpp).
//
// IEEE 754 orders every non-NaN value by its sign and magnitude, with +0 == -0; a NaN is
// unordered with everything (itself included). The bits, read as sign and magnitude, give
// that order as a signed integer key: the magnitude for a positive number, minus it for a
// negative one (both zeros become 0). Exact, so the same answers as libgcc's soft-fp
// comparisons (which are 1.3 KB on Armv6-M and 1.0 KB on RV32 against ~0.3 KB here).
#pragma once

#include <cstdint>
#include <cstring>

namespace shitsukan::port {

constexpr int kUnordered = 2;  // order(): one of the two is a NaN

// -1 (a < b), 0 (a == b), 1 (a > b) or kUnordered.
inline int order(float a, float b) {
    std::uint32_t ua, ub;
    std::memcpy(&ua, &a, sizeof ua);
    std::memcpy(&ub, &b, sizeof ub);
    const std::uint32_t ma = ua & 0x7fffffffu, mb = ub & 0x7fffffffu;
    if (ma > 0x7f800000u || mb > 0x7f800000u) return kUnordered;
    const std::int32_t ka = (ua >> 31) != 0 ? -std::int32_t(ma) : std::int32_t(ma);
    const std::int32_t kb = (ub >> 31) != 0 ? -std::int32_t(mb) : std::int32_t(mb);
    return (ka > kb) - (ka < kb);
}

inline int order(double a, double b) {
    std::uint64_t ua, ub;
    std::memcpy(&ua, &a, sizeof ua);
    std::memcpy(&ub, &b, sizeof ub);
    const std::uint64_t sign = std::uint64_t(1) << 63, inf = std::uint64_t(0x7ff) << 52;
    const std::uint64_t ma = ua & ~sign, mb = ub & ~sign;
    if (ma > inf || mb > inf) return kUnordered;
    const std::int64_t ka = (ua & sign) != 0 ? -std::int64_t(ma) : std::int64_t(ma);
    const std::int64_t kb = (ub & sign) != 0 ? -std::int64_t(mb) : std::int64_t(mb);
    return (ka > kb) - (ka < kb);
}

}  // namespace shitsukan::port
