// Progress of the long leather work: the scale pattern and the maps report how far
// they are through core/progress.hpp; the library itself never prints.
#include <doctest/doctest.h>

#include <vector>

#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/tileable.hpp"

using namespace shitsukan;

namespace {

void record(float fraction, void* user) { static_cast<std::vector<float>*>(user)->push_back(fraction); }

void check_monotone_to_one(const std::vector<float>& seen, std::size_t at_least,
                           std::size_t at_most) {
    REQUIRE(!seen.empty());
    for (std::size_t i = 1; i < seen.size(); ++i) CHECK(seen[i] >= seen[i - 1]);
    CHECK(seen.front() >= 0.0f);
    CHECK(seen.back() == 1.0f);
    CHECK(seen.size() >= at_least);
    CHECK(seen.size() <= at_most);
}

}  // namespace

TEST_CASE("leather progress: pattern, tileable pattern and maps report 0 .. 1, non-decreasing") {
    std::vector<float> seen;
    const Progress progress{record, &seen};
    ScalePattern pattern;
    REQUIRE(generate_scale_pattern(ScaleParams{}, pattern, nullptr, progress).ok());
    check_monotone_to_one(seen, 4, 4);

    seen.clear();
    TileParams tp;
    ScalePattern torus;
    REQUIRE(generate_tileable_pattern(tp, torus, nullptr, progress).ok());
    check_monotone_to_one(seen, 3, 3);

    seen.clear();
    LeatherMaps maps;
    REQUIRE(make_leather_maps(pattern, 300, 300, table1_section(Table1Section::convex),
                              ReliefOptions{}, maps, progress)
                .ok());
    check_monotone_to_one(seen, 100, 160);  // the labels, then ~100 row blocks
    CHECK(seen.front() == 0.1f);

    // Without a callback nothing is called and the result is the same.
    LeatherMaps quiet;
    REQUIRE(make_leather_maps(pattern, 300, 300, table1_section(Table1Section::convex),
                              ReliefOptions{}, quiet)
                .ok());
    CHECK(quiet.heights == maps.heights);
}
