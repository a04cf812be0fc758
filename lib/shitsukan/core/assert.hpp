// shitsukan/core/assert.hpp — checks for programmer bugs (never for user input).
//
// Manual
//   SHITSUKAN_ASSERT(i < n);   aborts with file:line and the expression when false.
// User input is never checked with this macro: public functions validate their arguments
// and return a Status (status.hpp). An assert firing means a bug inside shitsukan or a
// broken precondition that the caller was documented to guarantee (e.g. an index).
//
// Porting: define SHITSUKAN_ASSERT(expr) yourself before including any shitsukan header
// (e.g. to a breakpoint or an LED blink), or define SHITSUKAN_NO_ASSERT to compile it out.
#pragma once

namespace shitsukan::detail {
[[noreturn]] void assert_failed(const char* expr, const char* file, int line);
}

#ifndef SHITSUKAN_ASSERT
#ifdef SHITSUKAN_NO_ASSERT
#define SHITSUKAN_ASSERT(expr) ((void)0)
#else
#define SHITSUKAN_ASSERT(expr) \
    ((expr) ? (void)0 : ::shitsukan::detail::assert_failed(#expr, __FILE__, __LINE__))
#endif
#endif
