// shitsukan/core/status.hpp — the result of a public call that takes user values.
//
// Manual
//   #include "shitsukan/core/memory_budget.hpp"
//   Status s = check_memory_budget(std::uint64_t(1) << 50, "a 1 PiB image");  // any public call
//   if (!s) std::fprintf(stderr, "%s\n", s.message());  // too_large: "... needs ... bytes ..."
//   Status bad = Status::error(StatusCode::invalid_argument, "beta must be >= 0 (got %g)", -1.0);
//   std::printf("%s: %s\n", status_code_name(bad.code()), bad.message());
//
//   Status::success()                              the ok value (message "ok")
//   Status::error(StatusCode::invalid_argument, "beta must be >= 0 (got %g)", beta)
//   s.ok(), bool(s), s.code(), s.message(), status_code_name(code)
//   char text[120]; s.format_message(text, sizeof text);   into your buffer (small devices)
//
// A Status is a small value: the code, the format (a string literal: it is kept, not
// copied) and the arguments (numbers, copies of short strings) in kArgumentBytes bytes:
// 80 with SHITSUKAN_SMALL_DEVICE defined (for the library and your code alike), so
// sizeof(Status) is 92 bytes on a 32-bit microcontroller; 184 on hosts, so sizeof(Status)
// stays 200 there and file paths fit (tests assert both). The message is formatted only when
// asked, by the library's own formatter (core/format_number.hpp), so it keeps its numbers on
// any C library (newlib-nano's printf drops %g) and never allocates.
//
// Formats follow printf: flags - + space 0 #, width and precision (digits or *), lengths
// hh h l ll z j t L, conversions d i u x X o c s p g G e E f F %. Numbers are kept exactly
// (a double that is an exact float in 4 bytes, an int64 that fits 32 bits in 4), so the
// message shows the same digits printf would. Strings are copied at error(): they share
// what the numbers leave of kArgumentBytes, fairly, and a cut one ends in "..."; a
// number that no longer fits (more than kArgumentBytes / 8 eight-byte numbers) prints "?".
//
// message() formats into one of kMessageSlots buffers of kMessageCapacity bytes per thread
// (per program on a small device, SHITSUKAN_SMALL_DEVICE), used in turn: the pointer stays
// valid until kMessageSlots more message() calls; copy the text to keep it longer, or use
// format_message(), which writes into your buffer and returns the full length.
//
// SHITSUKAN_STATUS_NO_ARGUMENTS, defined when compiling core/status.cpp (the switch for the
// smallest devices, e.g. an 8 KB Cortex-M0 firmware that checks every Status but never prints
// one): error() keeps the code and the format but no arguments, so the argument walk (2-3 KB
// of flash with the double conversions it needs; make footprint-mcu measures it) is not
// linked; message() is then the format with every conversion shown as '?' ("fractal lattice: R must
// be in [0, ?] (got ?)"). The codes and sizeof(Status) are the same either way.
//
// Status is [[nodiscard]]: every function returning one warns (an error under -Werror, as
// CI builds) when its result is dropped. Where ignoring it is really meant, say so with a
// (void) cast and a comment. An object used after its builder failed with the Status
// ignored aborts naming that builder (SHITSUKAN_REQUIRE_BUILT, assert.hpp).
//
// small-device: yes (no allocation, no exceptions)
#pragma once

#include <cstdint>

namespace shitsukan {

enum class StatusCode : std::uint8_t {
    ok = 0,
    invalid_argument,  // a value outside its documented range, NaN, inconsistent sizes
    out_of_range,      // a query outside the domain (e.g. a point outside the lattice)
    too_large,         // a memory or size request that cannot fit (the message gives bytes)
    buffer_too_small,  // a caller-provided buffer is smaller than required
    degenerate,        // geometry with no area/volume; nothing was produced
    io_error,          // a file could not be written or read
    not_supported,     // a valid request this build or function does not handle
};

const char* status_code_name(StatusCode code);

class [[nodiscard]] Status {
public:
#if defined(SHITSUKAN_SMALL_DEVICE)
    static constexpr int kArgumentBytes = 80;  // the kept arguments
#else
    static constexpr int kArgumentBytes = 184;
#endif
    static constexpr int kMessageCapacity = 200;  // message(): longer text is cut
    static constexpr int kMessageSlots = 4;       // message(): buffers used in turn

    Status() = default;  // ok
    static Status success() { return Status(); }
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    static Status
    error(StatusCode code, const char* format, ...);

    bool ok() const { return code_ == StatusCode::ok; }
    explicit operator bool() const { return ok(); }
    StatusCode code() const { return code_; }
    const char* message() const;
    // Writes the message (cut to capacity - 1 characters, NUL-terminated) and returns its
    // full length, like snprintf.
    int format_message(char* out, int capacity) const;

private:
    const char* format_ = nullptr;
    StatusCode code_ = StatusCode::ok;
    std::uint8_t used_ = 0;     // bytes of arguments_ in use
    std::uint32_t narrow_ = 0;  // bit i: the i-th kept argument is in its 4-byte form
    unsigned char arguments_[kArgumentBytes] = {};
};

// Propagate a failed Status to the caller: SHITSUKAN_TRY(write_png(...));
#define SHITSUKAN_TRY(expr)                          \
    do {                                             \
        ::shitsukan::Status shitsukan_s_ = (expr);   \
        if (!shitsukan_s_.ok()) return shitsukan_s_; \
    } while (0)

}  // namespace shitsukan
