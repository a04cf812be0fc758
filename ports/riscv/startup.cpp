// ports/riscv/startup.cpp — reset code for an RV32 core in machine mode (QEMU `virt` with
// -bios none starts here): sets the stack and global pointers, copies .data from flash,
// clears .bss, runs static constructors, calls main and reports its result through
// semihosting. The symbols come from virt.ld; a real board keeps this file and changes the
// memory map in its linker script. No FPU to turn on: rv32imac computes floats in software.
#include <cstdint>

#include "semihosting.hpp"

extern "C" {
extern std::uint32_t _sidata, _sdata, _edata, _sbss, _ebss;
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();
int main();

// used: referenced only from the asm entry below (which -flto does not see)
[[noreturn]] __attribute__((used)) void reset_handler() {
    for (std::uint32_t *src = &_sidata, *dst = &_sdata; dst < &_edata;) *dst++ = *src++;
    for (std::uint32_t* dst = &_sbss; dst < &_ebss;) *dst++ = 0;
    for (void (**f)() = __init_array_start; f < __init_array_end; ++f) (*f)();
    shitsukan::port::semihosting_exit(main());
}

// The entry: gp first (relaxed loads of small data go through it), then sp; any trap
// (an illegal instruction, a misaligned access) ends the run through trap_handler.
__asm__(R"(
    .section .text.start, "ax"
    .globl _start
_start:
    .option push
    .option norelax
    la gp, __global_pointer$
    .option pop
    la sp, _estack
    la t0, trap_handler
    .option push
    .option arch, +zicsr
    csrw mtvec, t0
    .option pop
    j reset_handler
    .text
)");

[[noreturn]] void trap_handler() __attribute__((aligned(4), used));
void trap_handler() {
    static const char text[] = "fault: trap (illegal instruction, misaligned or bad access)\n";
    shitsukan::port::semihosting_write(text, int(sizeof text - 1));
    shitsukan::port::semihosting_exit(2);
}
}
