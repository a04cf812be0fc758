// ports/cortex-m/signed_divide.hpp — C++'s signed 32-bit division and remainder (quotient
// truncated toward zero, remainder with the dividend's sign) through the unsigned division,
// for the Cortex-M0, which has no divide instruction (signed_divide.cpp).
#pragma once

#include <cstdint>

extern "C" unsigned __aeabi_uidiv(unsigned n, unsigned d);  // libgcc's unsigned division

namespace shitsukan::port {

inline std::uint32_t magnitude(std::int32_t v) {
    return v < 0 ? 0u - std::uint32_t(v) : std::uint32_t(v);
}

// a / b for b != 0 (INT32_MIN / -1 wraps to INT32_MIN, as the hardware dividers do).
inline std::int32_t signed_quotient(std::int32_t a, std::int32_t b) {
    const std::uint32_t q = __aeabi_uidiv(magnitude(a), magnitude(b));
    return std::int32_t((a < 0) != (b < 0) ? 0u - q : q);
}

// a - (a / b)·b, in unsigned arithmetic (no overflow).
inline std::int32_t signed_remainder(std::int32_t a, std::int32_t b, std::int32_t q) {
    return std::int32_t(std::uint32_t(a) - std::uint32_t(q) * std::uint32_t(b));
}

}  // namespace shitsukan::port
