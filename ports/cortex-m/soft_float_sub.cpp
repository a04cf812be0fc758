// ports/cortex-m/soft_float_sub.cpp — float and double subtraction for the FPU-less Cortex-M0
// as the addition of the negated operand: a - b = a + (-b).
//
// Why: Armv6-M's libgcc builds __aeabi_fsub and __aeabi_dsub from the same C soft-fp source
// as the additions, each a full copy (804 and 1,796 bytes of flash beside __aeabi_fadd's 772
// and __aeabi_dadd's 1,724). IEEE 754 defines subtraction as exactly that sum (2008, §5.4.1:
// x - y is x + (-y)), and negation only flips the sign bit, so the result is the same bits
// for every pair of operands (signed zeros and infinities included; only a NaN's sign may
// differ, and no result of the library is a NaN it prints). libgcc's own __aeabi_frsub and
// __aeabi_drsub are this same sign flip in front of the addition. `make test-mcu` checks the
// M0's transcript against the host's, byte for byte.
// Linked on Armv6-M only (mcu.mk): the Armv7-M cores add and subtract floats in hardware,
// and their libgcc's double subtraction is already an entry into the addition.
// `used`: the compiler calls these after link-time optimisation has run, which would otherwise
// drop them as unreferenced.
#include <cstdint>
#include <cstring>

extern "C" {
float __aeabi_fadd(float a, float b);
double __aeabi_dadd(double a, double b);
float __aeabi_fsub(float a, float b);
double __aeabi_dsub(double a, double b);
}

namespace {
float negated(float v) {
    std::uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    u ^= 0x80000000u;
    std::memcpy(&v, &u, sizeof v);
    return v;
}
double negated(double v) {
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    u ^= std::uint64_t(1) << 63;
    std::memcpy(&v, &u, sizeof v);
    return v;
}
}  // namespace

__attribute__((used)) float __aeabi_fsub(float a, float b) { return __aeabi_fadd(a, negated(b)); }
__attribute__((used)) double __aeabi_dsub(double a, double b) { return __aeabi_dadd(a, negated(b)); }
