// ports/cortex-m/semihosting.hpp — semihosting (Arm: bkpt 0xAB; RISC-V: ebreak): text to
// the debugger's or QEMU's console and the program's exit, with no UART driver. A real board
// without a debugger attached replaces these two functions (e.g. with a UART write and a
// reset loop).
#pragma once

namespace shitsukan::port {

void semihosting_write(const char* text, int length);  // SYS_WRITE0, in chunks
[[noreturn]] void semihosting_exit(int code);          // SYS_EXIT: 0 ok, else failure

}  // namespace shitsukan::port
