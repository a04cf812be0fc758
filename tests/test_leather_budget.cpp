// The byte budget (core/memory_budget.hpp) before the leather module's large
// allocations: the scale pattern, the tileable block and the maps refuse at once, with the
// byte count, instead of dying of std::bad_alloc.
#include <doctest/doctest.h>

#include <cstring>
#include <string>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/tileable.hpp"

using namespace shitsukan;

namespace {
struct BudgetGuard {  // restores the default even when a check fails
    explicit BudgetGuard(std::uint64_t bytes) { set_memory_budget(bytes); }
    ~BudgetGuard() { set_memory_budget(0); }
};
}  // namespace

TEST_CASE("leather budget: the estimate follows the scale count, a small budget refuses") {
    ScaleParams prm;
    prm.D = 0.02f;
    prm.d = prm.D;
    ScalePattern pattern;
    REQUIRE(generate_scale_pattern(prm, pattern).ok());
    const double per_scale = 1024.0 + 128.0 * double(1 << prm.perturbation.levels);
    const double estimated_scales = double(scale_pattern_bytes(prm)) / per_scale;
    CHECK(estimated_scales >= pattern.polygon_count());
    CHECK(estimated_scales <= 1.5 * pattern.polygon_count());
    prm.d = 0.0f;  // every stage-1 polygon spans both halves: twice the columns a row
    CHECK(scale_pattern_bytes(prm) > scale_pattern_bytes(ScaleParams{}) * 3);
    ScaleParams huge;
    huge.D = 1e-3f;
    huge.perturbation.levels = kMaxPerturbationLevels;
    CHECK(scale_pattern_bytes(huge) > (std::uint64_t(64) << 30));  // refused by the default

    BudgetGuard guard(1u << 20);  // 1 MiB
    ScalePattern p;
    Status s = generate_scale_pattern(prm, p);
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::string(s.message()).find("bytes") != std::string::npos);
    ScaleDivision steps;
    CHECK(divide_scales(prm, steps).code() == StatusCode::too_large);
    TileParams tp;
    CHECK(generate_tileable_pattern(tp, p).code() == StatusCode::too_large);
    LeatherMaps maps;
    s = make_leather_maps(pattern, 1024, 1024, table1_section(Table1Section::convex),
                          ReliefOptions{}, maps);
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::string(s.message()).find("leather maps") != std::string::npos);
    CHECK(maps.heights.empty());  // refused before allocating
    // small work still fits
    CHECK(make_leather_maps(pattern, 64, 64, table1_section(Table1Section::convex),
                            ReliefOptions{}, maps)
              .ok());
}
