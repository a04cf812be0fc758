// ports/cortex-m/assert_handler.cpp — this port's replacement for core/assert.cpp: the two
// handlers SHITSUKAN_ASSERT and SHITSUKAN_REQUIRE_BUILT call, written through semihosting
// with no stdio (core/assert.cpp's fprintf + abort pull about 4.7 KB of newlib into a
// firmware). A port links its own file like this one instead of core/assert.cpp.
#include "semihosting.hpp"
#include "shitsukan/core/assert.hpp"

namespace shitsukan::detail {

namespace {
void write_text(const char* s) {
    int n = 0;
    while (s[n]) ++n;
    port::semihosting_write(s, n);
}
void write_line_number(int line) {
    char buf[12];
    int n = 0;
    unsigned u = line < 0 ? 0u : unsigned(line);
    do {
        buf[sizeof buf - 1 - n++] = char('0' + u % 10u);
        u /= 10u;
    } while (u != 0);
    port::semihosting_write(buf + sizeof buf - n, n);
}
}  // namespace

void assert_failed(const char* expr, const char* file, int line) {
    write_text("shitsukan: internal check failed: ");
    write_text(expr);
    write_text(" (");
    write_text(file);
    write_text(":");
    write_line_number(line);
    write_text(")\n");
    port::semihosting_exit(3);
}

void unchecked_status(const char* builder, const char* user, const char* file, int line) {
    write_text("shitsukan: ");
    write_text(user);
    write_text(" used without a successful ");
    write_text(builder);
    write_text(": the Status it returned was ignored (");
    write_text(file);
    write_text(":");
    write_line_number(line);
    write_text(")\n");
    port::semihosting_exit(3);
}

}  // namespace shitsukan::detail
