// ports/cortex-m/soft_single.hpp — IEEE 754 binary32 addition, multiplication and division on
// the bits, round-to-nearest-even with subnormals, infinities and NaNs: soft_binary.hpp's
// operations at float width (27-bit significands: the leading 1 at bit 26, 23 fraction bits,
// guard, round, sticky), for RV32IMAC (../riscv/soft_single.cpp), in place of libgcc's
// soft-fp float routines (2.0 KB of flash). Correctly rounded, so libgcc's bits; checked against
// the host's FPU and against libgcc on the M0 and the RV32 (tests/mcu/soft_double_check.cpp).
// The M0 keeps libgcc's: these cost it 25 % more instructions on the float-heavy paths.
#pragma once

#include <cstdint>

#include "soft_binary.hpp"

namespace shitsukan::port::soft_single {

using u32 = std::uint32_t;
using u64 = std::uint64_t;

using Format = soft_binary::Format<soft_binary::Binary32>;
constexpr u32 kSign = Format::kSign;
constexpr u32 kInf = Format::kInf;
constexpr u32 kNaN = Format::kNaN;  // an invalid operation's NaN: libgcc's on both targets

inline bool is_nan(u32 x) { return soft_binary::is_nan<Format>(x); }
inline u32 add(u32 a, u32 b) { return soft_binary::add<Format>(a, b); }
inline u32 mul(u32 a, u32 b) { return soft_binary::mul<Format>(a, b); }
inline u32 div(u32 a, u32 b) { return soft_binary::div<Format>(a, b); }

}  // namespace shitsukan::port::soft_single
