// ports/cortex-m/soft_float_abi.hpp — the names the compiler calls for soft-float arithmetic on
// the two FPU-less cores, so one source defines them for both: the Arm run-time ABI's
// (__aeabi_fadd, ...) on the Cortex-M0 (Armv6-M), libgcc's generic ones (__addsf3, ...) on
// RV32IMAC; and the bits of a float or double as an integer and back (memcpy: no aliasing).
// Used by soft_float_sub.cpp, soft_double.cpp and ../riscv/soft_single.cpp.
#pragma once

#include <cstdint>
#include <cstring>

#if defined(__riscv)
#define SOFT_FADD __addsf3
#define SOFT_FSUB __subsf3
#define SOFT_DADD __adddf3
#define SOFT_DSUB __subdf3
#define SOFT_DMUL __muldf3
#define SOFT_DDIV __divdf3
#define SOFT_F2D __extendsfdf2
#else
#define SOFT_FADD __aeabi_fadd
#define SOFT_FSUB __aeabi_fsub
#define SOFT_DADD __aeabi_dadd
#define SOFT_DSUB __aeabi_dsub
#define SOFT_DMUL __aeabi_dmul
#define SOFT_DDIV __aeabi_ddiv
#define SOFT_F2D __aeabi_f2d
#endif

namespace shitsukan {
namespace port {

inline std::uint32_t float_bits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}
inline float float_from_bits(std::uint32_t u) {
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}
inline std::uint64_t double_bits(double d) {
    std::uint64_t u;
    std::memcpy(&u, &d, sizeof u);
    return u;
}
inline double double_from_bits(std::uint64_t u) {
    double d;
    std::memcpy(&d, &u, sizeof d);
    return d;
}

}  // namespace port
}  // namespace shitsukan
