// ports/cortex-m/device_main.cpp — the transcript program on the device (semihosting).
#include "semihosting.hpp"
#include "transcript.hpp"

int main() { return shitsukan::port::run_transcript(shitsukan::port::semihosting_write); }
