// Tests for the memory budget (core/memory_budget.hpp) in solid/: the Type I
// lattice (build, load_lattice: its own budget and the global one) and the Type II list.
#include <cstdio>
#include <cstring>

#include <doctest/doctest.h>
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/solid/lattice_type2.hpp"

using namespace shitsukan;

namespace {
struct BudgetGuard {
    explicit BudgetGuard(std::uint64_t bytes) { set_memory_budget(bytes); }
    ~BudgetGuard() { set_memory_budget(0); }
};
}  // namespace

TEST_CASE("Type I lattice: the global memory budget applies besides the lattice's own") {
    FractalParams p;
    p.R = 5;  // 33^3 floats = 143748 bytes
    FractalLattice lat;
    REQUIRE(lat.build(p).ok());
    REQUIRE(save_lattice("build/budget_lattice.shl", lat).ok());
    {
        BudgetGuard guard(100000);
        FractalLattice small;
        Status s = small.build(p);  // fits kDefaultLatticeBudget, not the global budget
        CHECK(s.code() == StatusCode::too_large);
        CHECK(std::strstr(s.message(), "143748") != nullptr);
        CHECK(small.empty());
        s = load_lattice("build/budget_lattice.shl", small);
        CHECK(s.code() == StatusCode::too_large);
        p.R = 4;  // 17^3 floats = 19652 bytes
        CHECK(small.build(p).ok());
    }
    FractalLattice back;
    CHECK(load_lattice("build/budget_lattice.shl", back).ok());
    CHECK(load_lattice("build/budget_lattice.shl", back, 1000).code() == StatusCode::too_large);
    std::remove("build/budget_lattice.shl");
}

TEST_CASE("Type II lattice: the list of computed nodes stops at the memory budget") {
    FractalParams p;
    p.R = 8;
    p.noise = NoiseSource::sequential;  // the list can never be cleared
    TypeIILattice lat;
    REQUIRE(lat.init(p).ok());
    BudgetGuard guard(256 * 1024);
    Status s;
    float v = 0;
    int queries = 0;
    for (int z = 0; z <= 256 && s.ok(); z += 3)
        for (int y = 0; y <= 256 && s.ok(); y += 3)
            for (int x = 0; x <= 256 && s.ok(); x += 3) {
                s = lat.node_value_checked(x, y, z, v);
                if (s) ++queries;
            }
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::strstr(s.message(), "Type II lattice") != nullptr);
    CHECK(queries > 100);
    CHECK(lat.container_bytes() <= 256 * 1024);
}
