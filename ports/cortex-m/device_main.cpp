// ports/cortex-m/device_main.cpp — the transcript program on the device (semihosting).
#include "assert_handler.hpp"
#include "semihosting.hpp"
#include "transcript.hpp"

int main() {
    shitsukan::port::install_check_handler();
    return shitsukan::port::run_transcript(shitsukan::port::semihosting_write);
}
