// ports/cortex-m/assert_handler.hpp — this port's check-failure handler (semihosting text,
// then exit code 3), installed with shitsukan::set_check_failed_handler.
//
//   int main() { shitsukan::port::install_check_handler(); ... }
#pragma once

namespace shitsukan::port {
void install_check_handler();
}
