// ports/cortex-m/assert_handler.cpp — what SHITSUKAN_ASSERT and SHITSUKAN_REQUIRE_BUILT do on
// this port: write through semihosting with no stdio, then exit. The library's default on a
// small device (core/assert.cpp with SHITSUKAN_SMALL_DEVICE) is a silent __builtin_trap();
// a board might blink an LED and reset instead.
#include "assert_handler.hpp"

#include "semihosting.hpp"
#include "shitsukan/core/assert.hpp"

namespace shitsukan::port {

namespace {
void write_text(const char* s) {
    int n = 0;
    while (s[n]) ++n;
    semihosting_write(s, n);
}
void write_line_number(int line) {
    char buf[12];
    int n = 0;
    unsigned u = line < 0 ? 0u : unsigned(line);
    do {
        buf[sizeof buf - 1 - n++] = char('0' + u % 10u);
        u /= 10u;
    } while (u != 0);
    semihosting_write(buf + sizeof buf - n, n);
}

void on_check_failed(const CheckFailure& f) {
    if (f.kind == CheckFailure::assertion) {
        write_text("shitsukan: internal check failed: ");
        write_text(f.expression);
    } else {
        write_text("shitsukan: ");
        write_text(f.user);
        write_text(" used without a successful ");
        write_text(f.builder);
        write_text(": the Status it returned was ignored");
    }
    write_text(" (");
    write_text(f.file);
    write_text(":");
    write_line_number(f.line);
    write_text(")\n");
    semihosting_exit(3);
}
}  // namespace

void install_check_handler() { (void)set_check_failed_handler(&on_check_failed); }

}  // namespace shitsukan::port
