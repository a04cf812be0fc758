// ports/cortex-m/semihosting.cpp — see semihosting.hpp. One source for both kinds of core:
// only the trap differs. Arm: `bkpt 0xab`, operation in r0, argument in r1. RISC-V: an
// `ebreak` between `slli x0, x0, 0x1f` and `srai x0, x0, 7` (all three uncompressed, on one
// page), operation in a0, argument in a1; the operations and their numbers are Arm's.
#include "semihosting.hpp"

namespace shitsukan::port {

namespace {
constexpr int kSysWrite0 = 0x04;
constexpr int kSysExit = 0x18;
constexpr int kAdpStoppedApplicationExit = 0x20026;
constexpr int kAdpStoppedRunTimeErrorUnknown = 0x20023;

#if defined(__riscv)
__attribute__((noinline)) int semihosting_call(int operation, const void* argument) {
    register int a0 __asm__("a0") = operation;
    register const void* a1 __asm__("a1") = argument;
    __asm__ volatile(
        ".option push\n .option norvc\n .balign 16\n"
        "slli x0, x0, 0x1f\n ebreak\n srai x0, x0, 7\n"
        ".option pop"
        : "+r"(a0)
        : "r"(a1)
        : "memory");
    return a0;
}
#else
int semihosting_call(int operation, const void* argument) {
    register int r0 __asm__("r0") = operation;
    register const void* r1 __asm__("r1") = argument;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}
#endif
}  // namespace

void semihosting_write(const char* text, int length) {
    char chunk[129];
    while (length > 0) {
        const int n = length < 128 ? length : 128;
        for (int i = 0; i < n; ++i) chunk[i] = text[i];
        chunk[n] = 0;
        (void)semihosting_call(kSysWrite0, chunk);
        text += n;
        length -= n;
    }
}

void semihosting_exit(int code) {
    // On a 32-bit core SYS_EXIT takes the reason itself in its argument register:
    // ApplicationExit means success.
    (void)semihosting_call(kSysExit, reinterpret_cast<const void*>(
                                         code == 0 ? kAdpStoppedApplicationExit
                                                   : kAdpStoppedRunTimeErrorUnknown));
    for (;;) {
    }
}

}  // namespace shitsukan::port
