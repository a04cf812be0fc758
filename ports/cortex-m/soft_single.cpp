// ports/cortex-m/soft_single.cpp — the Arm run-time ABI's float addition, multiplication and
// division for the FPU-less Cortex-M0 from soft_single.hpp (in place of libgcc's 2.0 KB; the
// same bits: make test-mcu runs tests/mcu/soft_double_check.cpp against libgcc on the device).
// Subtraction is the addition of the negated operand (soft_float_sub.cpp). Linked on Armv6-M
// only (mcu.mk); `used`: the compiler calls these after link-time optimisation has run.
#include <cstring>

#include "soft_single.hpp"

namespace {
namespace ss = shitsukan::port::soft_single;
ss::u32 bits(float f) {
    ss::u32 u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}
float from(ss::u32 u) {
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}
}  // namespace

extern "C" {
__attribute__((used)) float __aeabi_fadd(float a, float b) {
    return from(ss::add(bits(a), bits(b)));
}
__attribute__((used)) float __aeabi_fmul(float a, float b) {
    return from(ss::mul(bits(a), bits(b)));
}
__attribute__((used)) float __aeabi_fdiv(float a, float b) {
    return from(ss::div(bits(a), bits(b)));
}
}
