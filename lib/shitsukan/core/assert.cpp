// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/assert.hpp"

#include <cstdio>
#include <cstdlib>

namespace shitsukan::detail {

void assert_failed(const char* expr, const char* file, int line) {
    std::fprintf(stderr, "shitsukan: internal check failed: %s (%s:%d)\n", expr, file, line);
    std::abort();
}

void unchecked_status(const char* builder, const char* user, const char* file, int line) {
    std::fprintf(stderr,
                 "shitsukan: %s used without a successful %s: the Status it returned was "
                 "ignored (print s.message() to see why it refused) (%s:%d)\n",
                 user, builder, file, line);
    std::abort();
}

}  // namespace shitsukan::detail
