// Tests for lib/shitsukan/bark/photograph_views: Table 3's mean and max in photograph-sized
// views of the trunk (the regions a view shows whole), on prescribed cracks and on the three
// species.
#include <doctest/doctest.h>
#include "measured.hpp"

#include <algorithm>
#include <vector>

#include "shitsukan/bark/bark.hpp"

using namespace shitsukan;

namespace {

// Blocks 8 columns x 8 rows (crack_regions' synthetic grid), except that the column boundary
// after column `merged` is left uncut: the two blocks beside it are one, 16 columns wide.
void cut_blocks(BarkCylinder& bark, int merged) {
    for (int c = 0; c < bark.params.N_R; ++c)
        for (int r = 0; r < bark.params.N_H; ++r)
            for (int dir = 0; dir < 3; ++dir) {
                const int s = bark.spring(c, r, dir);
                if (s < 0 || !bark.net.springs[std::size_t(s)].intact()) continue;
                const BarkSpring& sp = bark.net.springs[std::size_t(s)];
                const int r1 = bark.row_of(int(sp.i)), r2 = bark.row_of(int(sp.j));
                const bool across_rows = std::min(r1, r2) % 8 == 7 && r1 != r2;
                const bool across_columns = dir != 0 && c % 8 == 7 && c != merged;
                if (across_rows || across_columns) break_spring(bark.net, std::uint32_t(s), 0.0f);
            }
}

}  // namespace

TEST_CASE("a view counts the regions it shows whole: the wide block only where it fits") {
    CylinderParams p;  // 128 x 64
    BarkCylinder bark;
    REQUIRE(build_cylinder(p, bark).ok());
    cut_blocks(bark, /*merged=*/7);  // columns 0..15 in one block per row of blocks
    RegionReport rep;
    REQUIRE(measure_regions(bark, p.T, bark.net.W.data(), rep).ok());
    REQUIRE(rep.regions.size() == 120);  // 8 rows of 15 blocks
    const float cell = bark.a_h * (1 + hoop_strain(p, p.T));
    int wide = 0;
    for (const BarkRegion& r : rep.regions) {
        CHECK(r.columns == (r.first_column == 0 ? 16 : 8));
        CHECK(r.first_column % 8 == 0);
        wide += r.columns == 16;
    }
    CHECK(wide == 8);
    CHECK(rep.max_width == doctest::Approx(16 * cell).epsilon(1e-4));  // the whole section's
    // A view of 12 columns never holds a 16-column block: its largest is 8 columns wide.
    PhotographViews v;
    REQUIRE(measure_photograph_views(bark, rep, 12, v).ok());
    // Blocks 8k..8k+7 (k = 2..15) fit at the 5 positions 8k-4..8k: 70 positions show any.
    CHECK(v.views == 70);
    CHECK(v.max_width == doctest::Approx(8 * cell).epsilon(1e-4));
    CHECK(v.mean_width == doctest::Approx(8 * cell).epsilon(1e-4));
    // A view of 43 columns (a third of 128) holds the wide block at 43 - 16 + 1 = 28 of its
    // 128 positions: the expected largest is (28·16 + 100·8) / 128 columns.
    CHECK(photograph_view_columns(128) == 43);
    REQUIRE(measure_photograph_views(bark, rep, 43, v).ok());
    CHECK(v.max_width == doctest::Approx((28.0 * 16 + 100.0 * 8) / 128 * cell).epsilon(1e-4));
    CHECK(v.views == 128);
    CHECK(v.max_height == doctest::Approx(rep.max_height).epsilon(1e-5));  // all blocks alike
    CHECK(v.full_height_share == 0.0f);
    CHECK(measure_photograph_views(bark, rep, 0, v).code() == StatusCode::invalid_argument);
    CHECK(measure_photograph_views(bark, rep, 129, v).code() == StatusCode::invalid_argument);
    RegionReport empty;
    CHECK(measure_photograph_views(bark, empty, 43, v).code() == StatusCode::invalid_argument);
}

TEST_CASE("a region across the seam has its arc; bands around the trunk are never shown whole") {
    CylinderParams p;
    p.N_R = 32, p.N_H = 24;
    BarkCylinder bark;
    REQUIRE(build_cylinder(p, bark).ok());
    cut_blocks(bark, /*merged=*/31);  // the boundary at the seam uncut: columns 24..7 one block
    RegionReport rep;
    REQUIRE(measure_regions(bark, p.T, bark.net.W.data(), rep).ok());
    int across = 0;
    for (const BarkRegion& r : rep.regions)
        if (r.columns == 16) {
            CHECK(r.first_column == 24);
            ++across;
        }
    CHECK(across == 3);
    // Rows cut, no column boundary: every region closes around the trunk.
    BarkCylinder bands;
    REQUIRE(build_cylinder(p, bands).ok());
    for (int s = 0; s < int(bands.net.springs.size()); ++s) {
        const BarkSpring& sp = bands.net.springs[std::size_t(s)];
        const int r1 = bands.row_of(int(sp.i)), r2 = bands.row_of(int(sp.j));
        if (r1 != r2 && std::min(r1, r2) % 8 == 7) break_spring(bands.net, std::uint32_t(s), 0.0f);
    }
    REQUIRE(measure_regions(bands, p.T, bands.net.W.data(), rep).ok());
    REQUIRE(rep.wrapped == 3);
    for (const BarkRegion& r : rep.regions) CHECK(r.columns == p.N_R);
    PhotographViews v;
    REQUIRE(measure_photograph_views(bands, rep, p.N_R, v).ok());
    CHECK(v.views == 0);
    CHECK(v.max_width == 0.0f);
}
