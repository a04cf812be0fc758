// ports/riscv/soft_float_sub.cpp — float and double subtraction for RV32IMAC (no F or D
// extension) as the addition of the negated operand: a - b = a + (-b).
//
// Why: libgcc builds __subsf3 and __subdf3 from the same C soft-fp source as the additions,
// each a full copy (884 and 1,652 bytes of flash beside __addsf3's 818 and __adddf3's 1,590).
// IEEE 754 defines subtraction as exactly that sum (2008, §5.4.1: x - y is x + (-y)), and
// negation only flips the sign bit, so the result is the same bits for every pair of operands
// (signed zeros and infinities included; only a NaN's sign may differ, and no result of the
// library is a NaN it prints). `make test-mcu` checks the RV32 transcript against the
// host's, byte for byte. (ports/cortex-m/soft_float_sub.cpp is the same for the Cortex-M0.)
// `used`: the compiler calls these after link-time optimisation has run, which would otherwise
// drop them as unreferenced.
#include <cstdint>
#include <cstring>

extern "C" {
float __addsf3(float a, float b);
double __adddf3(double a, double b);
float __subsf3(float a, float b);
double __subdf3(double a, double b);
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

__attribute__((used)) float __subsf3(float a, float b) { return __addsf3(a, negated(b)); }
__attribute__((used)) double __subdf3(double a, double b) { return __adddf3(a, negated(b)); }
