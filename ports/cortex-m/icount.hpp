// ports/cortex-m/icount.hpp — instructions executed on the device, as QEMU counts them when run
// with `-icount shift=0` (one instruction = 1 ns of virtual time), for bench_main.cpp:
//   Cortex-M4F / M7 (MPS2)   CMSDK APB timer 0, 25 MHz: one tick = 40 instructions
//   Cortex-M0 (micro:bit)    nRF51 TIMER0, 16 MHz, 32-bit: one tick = 62.5 instructions
//   RV32 (virt)              the minstret / minstreth counters: one count per instruction
// On a real board these read cycles, not instructions (and the MPS2/nRF51 addresses are those
// boards' only).
#pragma once

#include <cstdint>

namespace shitsukan::port {

#if defined(__riscv)
inline std::uint64_t read_instret() {
    std::uint32_t hi, lo, hi2;
    do {
        __asm__ volatile(".option push\n .option arch, +zicsr\n csrr %0, minstreth\n"
                         " csrr %1, minstret\n csrr %2, minstreth\n .option pop"
                         : "=r"(hi), "=r"(lo), "=r"(hi2));
    } while (hi != hi2);
    return (std::uint64_t(hi) << 32) | lo;
}
inline std::uint64_t g_icount_start = 0;
inline void icount_start() { g_icount_start = read_instret(); }
inline std::uint64_t icount_since_start() { return read_instret() - g_icount_start; }
#elif defined(BOARD_MICROBIT)
inline volatile std::uint32_t* nrf51_timer0(std::uint32_t offset) {
    return reinterpret_cast<volatile std::uint32_t*>(0x40008000u + offset);
}
inline void icount_start() {
    *nrf51_timer0(0x004) = 1;  // TASKS_STOP
    *nrf51_timer0(0x504) = 0;  // MODE: timer
    *nrf51_timer0(0x508) = 3;  // BITMODE: 32 bits
    *nrf51_timer0(0x510) = 0;  // PRESCALER: 16 MHz
    *nrf51_timer0(0x00C) = 1;  // TASKS_CLEAR
    *nrf51_timer0(0x000) = 1;  // TASKS_START
}
inline std::uint64_t icount_since_start() {
    *nrf51_timer0(0x040) = 1;  // TASKS_CAPTURE[0] -> CC[0]
    return std::uint64_t(*nrf51_timer0(0x540)) * 125u / 2u;  // 1 GHz / 16 MHz = 62.5
}
#else
inline volatile std::uint32_t* cmsdk_timer0(std::uint32_t offset) {
    return reinterpret_cast<volatile std::uint32_t*>(0x40000000u + offset);
}
inline void icount_start() {
    *cmsdk_timer0(0x0) = 0;            // CTRL: stop
    *cmsdk_timer0(0x8) = 0xffffffffu;  // RELOAD
    *cmsdk_timer0(0x4) = 0xffffffffu;  // VALUE (counts down)
    *cmsdk_timer0(0x0) = 1;            // CTRL: enable
}
inline std::uint64_t icount_since_start() {
    return std::uint64_t(0xffffffffu - *cmsdk_timer0(0x4)) * 40u;  // 1 GHz / 25 MHz
}
#endif

}  // namespace shitsukan::port
