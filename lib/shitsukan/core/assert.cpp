// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/assert.hpp"

#if !defined(SHITSUKAN_SMALL_DEVICE)
#include <cstdio>
#include <cstdlib>
#endif

namespace shitsukan {

namespace {
CheckFailedHandler installed_handler = nullptr;

#if !defined(SHITSUKAN_SMALL_DEVICE)
void print_failure(const CheckFailure& f) {
    if (f.kind == CheckFailure::assertion)
        std::fprintf(stderr, "shitsukan: internal check failed: %s (%s:%d)\n", f.expression, f.file,
                     f.line);
    else
        std::fprintf(stderr,
                     "shitsukan: %s used without a successful %s: the Status it returned was "
                     "ignored (print s.message() to see why it refused) (%s:%d)\n",
                     f.user, f.builder, f.file, f.line);
}
#endif

[[noreturn]] void fail(const CheckFailure& f) {
    if (installed_handler != nullptr) installed_handler(f);
#if defined(SHITSUKAN_SMALL_DEVICE)
    __builtin_trap();  // no stdio on a small device: a port installs a handler to say more
#else
    if (installed_handler == nullptr) print_failure(f);
    std::abort();
#endif
}
}  // namespace

CheckFailedHandler set_check_failed_handler(CheckFailedHandler handler) {
    CheckFailedHandler previous = installed_handler;
    installed_handler = handler;
    return previous;
}

}  // namespace shitsukan

#if defined(__GNUC__)
#define SHITSUKAN_WEAK __attribute__((weak))
#else
#define SHITSUKAN_WEAK
#endif

namespace shitsukan::detail {

// Weak: a port that links its own definitions replaces these.
SHITSUKAN_WEAK void assert_failed(const char* expr, const char* file, int line) {
    fail(CheckFailure{CheckFailure::assertion, expr, nullptr, nullptr, file, line});
}

SHITSUKAN_WEAK void unchecked_status(const char* builder, const char* user, const char* file,
                                     int line) {
    fail(CheckFailure{CheckFailure::unchecked_status, nullptr, builder, user, file, line});
}

}  // namespace shitsukan::detail
