// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/memory_budget.hpp"

namespace shitsukan {

namespace {
std::uint64_t g_budget = kDefaultMemoryBudget;  // plain: no 64-bit atomics on a Cortex-M
}

std::uint64_t memory_budget() { return g_budget; }

void set_memory_budget(std::uint64_t bytes) {
    g_budget = bytes == 0 ? kDefaultMemoryBudget : bytes;
}

Status check_memory_budget(std::uint64_t bytes, const char* what) {
    const std::uint64_t budget = memory_budget();
    if (bytes <= budget) return Status::success();
    return Status::error(StatusCode::too_large,
                         "%s needs %llu bytes, over the memory budget of %llu bytes "
                         "(set_memory_budget)",
                         what ? what : "a request", static_cast<unsigned long long>(bytes),
                         static_cast<unsigned long long>(budget));
}

}  // namespace shitsukan
