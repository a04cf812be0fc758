// tests/consumer/status_no_arguments.cpp — core/status.cpp built with
// SHITSUKAN_STATUS_NO_ARGUMENTS (the footprint firmwares' switch, ports/cortex-m/mcu.mk): a
// Status keeps its code and its format, every conversion prints as '?', and a success is still
// "ok". Built on the host with the switch and run by `make check-api` (tools/check_api.sh);
// exits 1 (printing what differs) otherwise.
#include <cstdio>
#include <cstring>

#include "shitsukan/core/status.hpp"

using shitsukan::Status;
using shitsukan::StatusCode;

static int check(const char* what, const char* got, const char* want) {
    if (std::strcmp(got, want) == 0) return 0;
    std::printf("status_no_arguments: %s: got \"%s\", want \"%s\"\n", what, got, want);
    return 1;
}

int main() {
    int fail = 0;
    const Status s = Status::error(StatusCode::out_of_range,
                                   "fractal lattice: R must be in [0, %d] (got %d), beta %g, %s",
                                   24, 99, 0.9, "a name");
    if (s.code() != StatusCode::out_of_range || s.ok()) {
        std::printf("status_no_arguments: the code was not kept\n");
        fail = 1;
    }
    fail |= check("message", s.message(),
                  "fractal lattice: R must be in [0, ?] (got ?), beta ?, ?");
    fail |= check("percent", Status::error(StatusCode::degenerate, "100%% of %s", "it").message(),
                  "100% of ?");
    fail |= check("success", Status::success().message(), "ok");
    if (fail == 0) std::printf("status_no_arguments: code and format kept, arguments as '?'\n");
    return fail;
}
