// Tests for core/memory_budget.hpp: the per-request byte budget.
#include <cstring>

#include <doctest/doctest.h>
#include "shitsukan/core/memory_budget.hpp"

using namespace shitsukan;

TEST_CASE("check_memory_budget: ok within, too_large over, with the byte counts") {
    set_memory_budget(0);
    CHECK(memory_budget() == kDefaultMemoryBudget);
    CHECK(check_memory_budget(kDefaultMemoryBudget, "x").ok());
    Status s = check_memory_budget(kDefaultMemoryBudget + 1, "voronoi_cells: 1e7 sites");
    REQUIRE_FALSE(s.ok());
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::strstr(s.message(), "voronoi_cells: 1e7 sites") != nullptr);
    CHECK(std::strstr(s.message(), "4294967297") != nullptr);
    CHECK(std::strstr(s.message(), "4294967296") != nullptr);

    set_memory_budget(1000);
    CHECK(check_memory_budget(1000, "a").ok());
    CHECK(check_memory_budget(1001, "a").code() == StatusCode::too_large);
    set_memory_budget(0);
    CHECK(memory_budget() == kDefaultMemoryBudget);
}

TEST_CASE("budget_mul and budget_add saturate instead of wrapping") {
    CHECK(budget_mul(1u << 20, 1u << 20) == (std::uint64_t(1) << 40));
    CHECK(budget_mul(UINT64_MAX / 2, 3) == UINT64_MAX);
    CHECK(budget_mul(0, UINT64_MAX) == 0);
    CHECK(budget_add(UINT64_MAX - 1, 1) == UINT64_MAX);
    CHECK(budget_add(UINT64_MAX, 1) == UINT64_MAX);
    CHECK_FALSE(check_memory_budget(budget_mul(UINT64_MAX / 2, 3), "overflow").ok());
}
