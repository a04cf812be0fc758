// ports/cortex-m/startup.cpp — reset and fault vectors for an Armv7-M core (Cortex-M4F,
// Cortex-M7): copies .data from flash, clears .bss, turns on the FPU, runs static
// constructors, calls main, and reports its result through semihosting. The symbols come
// from mps2.ld; a real board keeps this file and changes the memory map in the linker script.
#include <cstdint>

#include "semihosting.hpp"

extern "C" {
extern std::uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
int main();
void __libc_init_array();
// -nostartfiles: no crti/crtn, so the hooks __libc_init_array calls are empty here.
void _init() {}
void _fini() {}

[[noreturn]] void Reset_Handler() {
    for (std::uint32_t *src = &_sidata, *dst = &_sdata; dst < &_edata;) *dst++ = *src++;
    for (std::uint32_t* dst = &_sbss; dst < &_ebss;) *dst++ = 0;
#if defined(__ARM_FP)
    // CPACR: full access to coprocessors 10 and 11 (the FPU) before any float instruction.
    volatile std::uint32_t* cpacr = reinterpret_cast<volatile std::uint32_t*>(0xE000ED88u);
    *cpacr = *cpacr | (0xFu << 20);
    __asm__ volatile("dsb\n isb" ::: "memory");
#endif
    __libc_init_array();
    shitsukan::port::semihosting_exit(main());
}

[[noreturn]] void Fault_Handler() {
    static const char text[] = "fault: hard fault or unexpected exception\n";
    shitsukan::port::semihosting_write(text, int(sizeof text - 1));
    shitsukan::port::semihosting_exit(2);
}

// The Armv7-M vector table: initial stack pointer, then the 15 system exceptions.
__attribute__((section(".isr_vector"), used)) void (*const g_vectors[16])() = {
    reinterpret_cast<void (*)()>(&_estack), Reset_Handler, Fault_Handler, Fault_Handler,
    Fault_Handler, Fault_Handler, Fault_Handler, nullptr, nullptr, nullptr, nullptr,
    Fault_Handler, Fault_Handler, nullptr, Fault_Handler, Fault_Handler};
}
