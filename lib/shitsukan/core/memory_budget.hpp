// shitsukan/core/memory_budget.hpp — one byte budget, checked before every large allocation.
//
// Manual
//   std::uint64_t n = 1000;  // before allocating n sites' worth of cells:
//   Status s = check_memory_budget(n * 433, "voronoi_cells: cells of the sites");
//   if (!s) return s;              // too_large, message names what, bytes needed and budget
//   set_memory_budget(64u << 20);  // a caller of your own: at most 64 MiB per request
//   std::uint64_t b = memory_budget();
//   set_memory_budget(0);          // back to the default
//
// Inputs inside a function's accepted ranges can still ask for more memory than the machine
// has (1e7 Voronoi sites, a 1e5 x 1e5 image); instead of dying of std::bad_alloc after tens of
// seconds, every allocation that grows with user input is first checked against this budget
// and refused at once with a too_large Status giving the byte count.
// The budget is per request (one allocation or one call's working set), not a running total.
// Default (chosen here): 4 GiB, above every figure's and CLI default's need (the largest,
// fujimoto2000 table01, stays under 1 GiB) and below this project's 24 GiB test machine.
// The setting is one process-wide value: set it once at start-up, before starting threads
// (reads from several threads are fine; a write while others read is a data race).
// small-device: yes (no allocation, no exceptions)
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"

namespace shitsukan {

constexpr std::uint64_t kDefaultMemoryBudget = std::uint64_t(4) << 30;  // 4 GiB, chosen here

// The current per-request budget in bytes.
std::uint64_t memory_budget();
// Set the per-request budget (0 restores the default).
void set_memory_budget(std::uint64_t bytes);

// ok when `bytes` fits the budget; otherwise too_large: "<what> needs N bytes, over the
// memory budget of B bytes (set_memory_budget)".
Status check_memory_budget(std::uint64_t bytes, const char* what);

// Saturating helpers for computing a request's size without overflow (UINT64_MAX on overflow,
// which no budget accepts).
constexpr std::uint64_t budget_mul(std::uint64_t a, std::uint64_t b) {
    return (a != 0 && b > UINT64_MAX / a) ? UINT64_MAX : a * b;
}
constexpr std::uint64_t budget_add(std::uint64_t a, std::uint64_t b) {
    return (b > UINT64_MAX - a) ? UINT64_MAX : a + b;
}

}  // namespace shitsukan
