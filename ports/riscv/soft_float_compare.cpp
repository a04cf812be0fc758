// ports/riscv/soft_float_compare.cpp — libgcc's float and double comparison routines for
// RV32IMAC without F or D (the values libgcc documents: __eq: 0 iff equal; __lt, __le: < 0,
// 0, > 0 as a < b, a == b, a > b, and > 0 when unordered; __gt, __ge: the same with < 0 when
// unordered; __unord: nonzero iff a NaN is involved), from the IEEE order of the bits
// (../cortex-m/soft_float_order.hpp). Exact; replaces libgcc's soft-fp comparisons (994 bytes
// of flash in the marble firmware). `used`: the compiler calls these after link-time
// optimisation has run.
#include "soft_float_order.hpp"

using shitsukan::port::kUnordered;
using shitsukan::port::order;

#define SHITSUKAN_LIBGCC_COMPARE(name, type, if_unordered, result)   \
    extern "C" __attribute__((used)) int name(type a, type b) {      \
        const int o = order(a, b);                                   \
        return o == kUnordered ? (if_unordered) : (result);          \
    }

SHITSUKAN_LIBGCC_COMPARE(__eqsf2, float, 1, o)
SHITSUKAN_LIBGCC_COMPARE(__nesf2, float, 1, o)
SHITSUKAN_LIBGCC_COMPARE(__ltsf2, float, 1, o)
SHITSUKAN_LIBGCC_COMPARE(__lesf2, float, 1, o)
SHITSUKAN_LIBGCC_COMPARE(__gtsf2, float, -1, o)
SHITSUKAN_LIBGCC_COMPARE(__gesf2, float, -1, o)
SHITSUKAN_LIBGCC_COMPARE(__unordsf2, float, 1, 0)
SHITSUKAN_LIBGCC_COMPARE(__eqdf2, double, 1, o)
SHITSUKAN_LIBGCC_COMPARE(__nedf2, double, 1, o)
SHITSUKAN_LIBGCC_COMPARE(__ltdf2, double, 1, o)
SHITSUKAN_LIBGCC_COMPARE(__ledf2, double, 1, o)
SHITSUKAN_LIBGCC_COMPARE(__gtdf2, double, -1, o)
SHITSUKAN_LIBGCC_COMPARE(__gedf2, double, -1, o)
SHITSUKAN_LIBGCC_COMPARE(__unorddf2, double, 1, 0)
