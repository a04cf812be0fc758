// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/status.hpp"

#include <cstdarg>
#include <cstdio>

namespace shitsukan {

const char* status_code_name(StatusCode code) {
    switch (code) {
        case StatusCode::ok:
            return "ok";
        case StatusCode::invalid_argument:
            return "invalid argument";
        case StatusCode::out_of_range:
            return "out of range";
        case StatusCode::too_large:
            return "too large";
        case StatusCode::buffer_too_small:
            return "buffer too small";
        case StatusCode::degenerate:
            return "degenerate";
        case StatusCode::io_error:
            return "i/o error";
        case StatusCode::not_supported:
            return "not supported";
    }
    return "unknown status";
}

Status Status::error(StatusCode code, const char* format, ...) {
    Status s;
    s.code_ = code == StatusCode::ok ? StatusCode::invalid_argument : code;
    va_list args;
    va_start(args, format);
    std::vsnprintf(s.message_, sizeof s.message_, format, args);
    va_end(args);
    return s;
}

}  // namespace shitsukan
