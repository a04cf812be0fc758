// ports/cortex-m/semihosting.cpp — see semihosting.hpp.
#include "semihosting.hpp"

namespace shitsukan::port {

namespace {
constexpr int kSysWrite0 = 0x04;
constexpr int kSysExit = 0x18;
constexpr int kAdpStoppedApplicationExit = 0x20026;
constexpr int kAdpStoppedRunTimeErrorUnknown = 0x20023;

int semihosting_call(int operation, const void* argument) {
    register int r0 __asm__("r0") = operation;
    register const void* r1 __asm__("r1") = argument;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}
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
    // On AArch32 SYS_EXIT takes the reason itself in r1: ApplicationExit means success.
    (void)semihosting_call(kSysExit, reinterpret_cast<const void*>(
                                         code == 0 ? kAdpStoppedApplicationExit
                                                   : kAdpStoppedRunTimeErrorUnknown));
    for (;;) {
    }
}

}  // namespace shitsukan::port
