// ports/cortex-m/signed_divide.cpp — the Arm run-time ABI's signed division for the
// Cortex-M0 (__divsi3, __aeabi_idiv, __aeabi_idivmod) through libgcc's unsigned one
// (signed_divide.hpp): the same quotients and remainders in 0.1 KB of flash, in place of
// libgcc's 460-byte unrolled signed copy. A division by zero (undefined in C++) gives 0 here.
// Checked against libgcc on the device by tests/mcu/soft_double_check.cpp. Linked on Armv6-M
// only (mcu.mk); `used`: the compiler calls these after link-time optimisation has run.
#include "signed_divide.hpp"

using shitsukan::port::signed_quotient;
using shitsukan::port::signed_remainder;

extern "C" {
__attribute__((used)) int __divsi3(int a, int b) { return signed_quotient(a, b); }
__attribute__((used)) int __aeabi_idiv(int a, int b) { return signed_quotient(a, b); }
// The quotient in r0 and the remainder in r1: a 64-bit return value, low word first.
__attribute__((used)) unsigned long long __aeabi_idivmod(int a, int b) {
    const std::int32_t q = signed_quotient(a, b);
    return (static_cast<unsigned long long>(std::uint32_t(signed_remainder(a, b, q))) << 32) |
           std::uint32_t(q);
}
}
