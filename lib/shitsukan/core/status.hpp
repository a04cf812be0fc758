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
//
// No exceptions, no allocation: the message is formatted (printf rules) into a fixed
// buffer of Status::kMessageCapacity bytes inside the object and truncated if longer.
// Return it by value; it is a plain struct a microcontroller port can keep.
// Status is [[nodiscard]]: every function returning one warns (an error under -Werror, as
// CI builds) when its result is dropped. Where ignoring it is really meant, say so with a
// (void) cast and a comment. An object used after its builder failed with the Status
// ignored aborts naming that builder (SHITSUKAN_REQUIRE_BUILT, assert.hpp).
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
    static constexpr int kMessageCapacity = 200;

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
    const char* message() const { return code_ == StatusCode::ok ? "ok" : message_; }

private:
    StatusCode code_ = StatusCode::ok;
    char message_[kMessageCapacity] = {0};
};

// Propagate a failed Status to the caller: SHITSUKAN_TRY(write_png(...));
#define SHITSUKAN_TRY(expr)                          \
    do {                                             \
        ::shitsukan::Status shitsukan_s_ = (expr);   \
        if (!shitsukan_s_.ok()) return shitsukan_s_; \
    } while (0)

}  // namespace shitsukan
