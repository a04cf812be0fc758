// ports/cortex-m/soft_float_compare.cpp — the Arm run-time ABI's float and double comparisons
// (__aeabi_fcmpeq ... __aeabi_dcmpun: 1 when the relation holds, else 0, and 0 for every
// relation but "unordered" when a NaN is involved) for the FPU-less Cortex-M0, from the IEEE
// order of the bits (soft_float_order.hpp). Exact; replaces libgcc's soft-fp comparisons and
// their flag-setting wrappers (1,386 bytes of flash in the marble firmware). Linked on Armv6-M
// only (mcu.mk); `used`: the compiler calls these after link-time optimisation has run.
#include "soft_float_order.hpp"

using shitsukan::port::kUnordered;
using shitsukan::port::order;

#define SHITSUKAN_AEABI_COMPARE(name, type, test)                  \
    extern "C" __attribute__((used)) int name(type a, type b) {    \
        const int o = order(a, b);                                 \
        return (test) ? 1 : 0;                                     \
    }

SHITSUKAN_AEABI_COMPARE(__aeabi_fcmpeq, float, o == 0)
SHITSUKAN_AEABI_COMPARE(__aeabi_fcmplt, float, o == -1)
SHITSUKAN_AEABI_COMPARE(__aeabi_fcmple, float, o == -1 || o == 0)
SHITSUKAN_AEABI_COMPARE(__aeabi_fcmpgt, float, o == 1)
SHITSUKAN_AEABI_COMPARE(__aeabi_fcmpge, float, o == 1 || o == 0)
SHITSUKAN_AEABI_COMPARE(__aeabi_fcmpun, float, o == kUnordered)
SHITSUKAN_AEABI_COMPARE(__aeabi_dcmpeq, double, o == 0)
SHITSUKAN_AEABI_COMPARE(__aeabi_dcmplt, double, o == -1)
SHITSUKAN_AEABI_COMPARE(__aeabi_dcmple, double, o == -1 || o == 0)
SHITSUKAN_AEABI_COMPARE(__aeabi_dcmpgt, double, o == 1)
SHITSUKAN_AEABI_COMPARE(__aeabi_dcmpge, double, o == 1 || o == 0)
SHITSUKAN_AEABI_COMPARE(__aeabi_dcmpun, double, o == kUnordered)
