// ports/cortex-m/soft_float_sub.cpp — float and double subtraction for the FPU-less cores (the
// Cortex-M0 and RV32IMAC; soft_float_abi.hpp names the entry points) as the addition of the
// negated operand: a - b = a + (-b).
//
// Why: libgcc builds the subtractions from the same C soft-fp source as the additions, each a
// full copy (Armv6-M: __aeabi_fsub 804 and __aeabi_dsub 1,796 bytes of flash beside
// __aeabi_fadd's 772 and __aeabi_dadd's 1,724; RV32: __subsf3 884 and __subdf3 1,652 beside
// 818 and 1,590). IEEE 754 defines subtraction as exactly that sum (2008, §5.4.1: x - y is
// x + (-y)), and negation only flips the sign bit, so the result is the same bits for every
// pair of operands (signed zeros and infinities included; only a NaN's sign may differ, and no
// result of the library is a NaN it prints). libgcc's own __aeabi_frsub and __aeabi_drsub are
// this same sign flip in front of the addition. `make test-mcu` checks the M0's and the RV32's
// transcripts against the host's, byte for byte.
// Linked on Armv6-M and RV32 only (mcu.mk): the Armv7-M cores add and subtract floats in
// hardware, and their libgcc's double subtraction is already an entry into the addition.
// `used`: the compiler calls these after link-time optimisation has run, which would otherwise
// drop them as unreferenced.
#include "soft_float_abi.hpp"

extern "C" {
float SOFT_FADD(float a, float b);
double SOFT_DADD(double a, double b);
float SOFT_FSUB(float a, float b);
double SOFT_DSUB(double a, double b);
}

namespace port = shitsukan::port;

__attribute__((used)) float SOFT_FSUB(float a, float b) {
    return SOFT_FADD(a, port::float_from_bits(port::float_bits(b) ^ 0x80000000u));
}
__attribute__((used)) double SOFT_DSUB(double a, double b) {
    return SOFT_DADD(a, port::double_from_bits(port::double_bits(b) ^ (std::uint64_t(1) << 63)));
}
