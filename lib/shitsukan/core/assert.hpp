// shitsukan/core/assert.hpp — checks for programmer bugs (never for user input).
//
// Manual
//   int i = 0, n = 3;
//   SHITSUKAN_ASSERT(i < n);   // aborts with file:line and the expression when false
// User input is never checked with this macro: public functions validate their arguments
// and return a Status (status.hpp). An assert firing means a bug inside shitsukan or a
// broken precondition that the caller was documented to guarantee (e.g. an index).
//
//
//   SHITSUKAN_REQUIRE_BUILT(expr, "FractalLattice::build()", "FractalLattice::view()");
// is the one check that fires on a caller's mistake rather than a bug: an object is used
// although the call that builds it returned an error Status that was not checked (Status is
// [[nodiscard]], so this only happens when the result was cast to void or stored and
// ignored). It aborts naming that call, not with "internal check failed":
//   shitsukan: FractalLattice::view() used without a successful FractalLattice::build():
//   the Status it returned was ignored (print s.message() to see why it refused)
//
// Porting: the default handlers (core/assert.cpp) print with fprintf(stderr) and abort()
// on a host; built with SHITSUKAN_SMALL_DEVICE they print nothing and stop with
// __builtin_trap() (no stdio: fprintf + abort measured 4.7 KB on a Cortex-M4F). Replace them
// in one of three ways:
//   set_check_failed_handler(&my_handler);  at start-up; my_handler(const CheckFailure&)
//       gets the kind, expression or builder/user, file and line; if it returns, the
//       default stop (abort / trap) follows.
//   link your own shitsukan::detail::assert_failed / unchecked_status: the library's are
//       weak symbols, yours win.
//   define SHITSUKAN_ASSERT(expr) yourself before including any shitsukan header (e.g. to a
//       breakpoint), or SHITSUKAN_NO_ASSERT to compile the checks out (both macros follow
//       these two switches).
// ports/cortex-m/README.md shows the first on a Cortex-M (semihosting output).
#pragma once

namespace shitsukan {

// What failed, for a handler installed with set_check_failed_handler.
struct CheckFailure {
    enum Kind { assertion, unchecked_status } kind;
    const char* expression;  // assertion: the expression that was false
    const char* builder;     // unchecked_status: the call whose Status was ignored
    const char* user;        // unchecked_status: the call that needed it
    const char* file;
    int line;
};
using CheckFailedHandler = void (*)(const CheckFailure& failure);

// Installs handler (null: the default) and returns the previous one.
CheckFailedHandler set_check_failed_handler(CheckFailedHandler handler);

}  // namespace shitsukan

namespace shitsukan::detail {
[[noreturn]] void assert_failed(const char* expr, const char* file, int line);
[[noreturn]] void unchecked_status(const char* builder, const char* user, const char* file,
                                   int line);
}  // namespace shitsukan::detail

#ifndef SHITSUKAN_ASSERT
#ifdef SHITSUKAN_NO_ASSERT
#define SHITSUKAN_ASSERT(expr) ((void)0)
#else
#define SHITSUKAN_ASSERT(expr) \
    ((expr) ? (void)0 : ::shitsukan::detail::assert_failed(#expr, __FILE__, __LINE__))
#endif
#endif

#ifndef SHITSUKAN_REQUIRE_BUILT
#ifdef SHITSUKAN_NO_ASSERT
#define SHITSUKAN_REQUIRE_BUILT(expr, builder, user) ((void)0)
#else
#define SHITSUKAN_REQUIRE_BUILT(expr, builder, user) \
    ((expr) ? (void)0 : ::shitsukan::detail::unchecked_status(builder, user, __FILE__, __LINE__))
#endif
#endif
