// Seamless tiling of the leather maps (tileable.hpp): each layout's maps tiled 2x2
// must be as continuous across the seams as inside the tile.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/scale_labels.hpp"
#include "shitsukan/leather/tileable.hpp"

using namespace shitsukan;

namespace {

// Steps between neighbouring pixels of one map, across the seams of its 2x2 tiling (column
// w-1 -> column 0 of the next tile, row h-1 -> row 0) and inside the tile.
struct Steps {
    std::vector<double> seam, inside;
};

double height_step(const LeatherMaps& m, int i0, int j0, int i1, int j1) {
    return std::fabs(double(m.at_height(i1, j1)) - double(m.at_height(i0, j0)));
}
double normal_step(const LeatherMaps& m, int i0, int j0, int i1, int j1) {
    return double(length(m.at_normal(i1, j1) - m.at_normal(i0, j0)));
}

template <class F>
Steps steps_along(const LeatherMaps& m, bool along_x, F step) {
    Steps s;
    const int w = m.width, h = m.height;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const int i1 = along_x ? (i + 1) % w : i, j1 = along_x ? j : (j + 1) % h;
            const bool seam = along_x ? i == w - 1 : j == h - 1;
            (seam ? s.seam : s.inside).push_back(step(m, i, j, i1, j1));
        }
    return s;
}

double mean(const std::vector<double>& v) {
    double t = 0.0;
    for (double x : v) t += x;
    return v.empty() ? 0.0 : t / double(v.size());
}
double quantile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    return v[std::size_t(q * double(v.size() - 1))];
}

LeatherMaps tile_maps(const ScalePattern& pattern, int size) {
    LeatherMaps maps;
    REQUIRE(make_leather_maps(pattern, size, size, table1_section(Table1Section::convex),
                              ReliefOptions{}, maps)
                .ok());
    return maps;
}

// The continuity criterion (stated tolerance): across the seam the 99th percentile of the
// steps between neighbouring pixels is at most 1.5 times the interior's 99th percentile and
// the largest step at most the interior's largest (plus 1 %). (The mean is not compared: a
// lattice's seam runs along a groove line on average, where steps are steeper by nature.)
struct Continuity {
    double mean_ratio, q99_ratio, max_ratio;
};
Continuity continuity(const Steps& s) {
    return {mean(s.seam) / mean(s.inside), quantile(s.seam, 0.99) / quantile(s.inside, 0.99),
            quantile(s.seam, 1.0) / quantile(s.inside, 1.0)};
}
void check_continuous(const Steps& s, const char* what) {
    const Continuity c = continuity(s);
    INFO(what << ": seam/inside mean " << c.mean_ratio << ", q99 " << c.q99_ratio << ", max "
              << c.max_ratio);
    CHECK(c.q99_ratio <= 1.5);
    CHECK(c.max_ratio <= 1.01);
}

// The torus pattern moved by half a tile along its periodic axes: its maps must be the
// original maps rolled by half the pixels (the seam then lies inside the tile). Returns the
// share of pixels whose height differs by more than 1e-3 of the largest height or whose
// normal differs by more than 1e-3.
double rolled_mismatch(const ScalePattern& torus, const LeatherMaps& maps) {
    ScalePattern moved = torus;
    const float dx = torus.wrap_x ? 0.5f * torus.width : 0.0f;
    const float dy = torus.wrap_y ? 0.5f * torus.height : 0.0f;
    for (Vec2& v : moved.vertices) v = Vec2{v.x + dx, v.y + dy};
    for (Vec2& c : moved.centroids) c = Vec2{c.x + dx, c.y + dy};
    const LeatherMaps m2 = tile_maps(moved, maps.width);
    const int w = maps.width, h = maps.height;
    const int si = torus.wrap_x ? w / 2 : 0, sj = torus.wrap_y ? h / 2 : 0;
    long bad = 0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const int i0 = (i - si + w) % w, j0 = (j - sj + h) % h;
            const double dh = std::fabs(double(m2.at_height(i, j)) - double(maps.at_height(i0, j0)));
            const double dn = double(length(m2.at_normal(i, j) - maps.at_normal(i0, j0)));
            bad += dh > 1e-3 * double(maps.max_height) || dn > 1e-3;
        }
    return double(bad) / double(w * h);
}

// Polygon edges lying along a tile border (both ends within 1e-6 of x = 0, W or y = 0, H on
// a periodic axis): a pattern cut at the border, not continued across it.
int edges_along_border(const ScalePattern& p, bool wx, bool wy) {
    int count = 0;
    auto on = [](float v, float period) {
        return std::fabs(v) < 1e-6f || std::fabs(v - period) < 1e-6f;
    };
    for (int f = 0; f < p.polygon_count(); ++f) {
        int n;
        const Vec2* v = p.polygon(f, &n);
        for (int k = 0; k < n; ++k) {
            const Vec2 a = v[k], b = v[(k + 1) % n];
            count += (wx && on(a.x, p.width) && on(b.x, p.width)) ||
                     (wy && on(a.y, p.height) && on(b.y, p.height));
        }
    }
    return count;
}

double pattern_area(const ScalePattern& p) {
    double a = 0.0;
    for (int f = 0; f < p.polygon_count(); ++f) {
        int n;
        const Vec2* v = p.polygon(f, &n);
        a += polygon_area(v, n);
    }
    return a;
}

}  // namespace

TEST_CASE("tileable: every layout's height and normal maps tile 2x2 with no seam") {
    for (TileLayout layout :
         {TileLayout::belly, TileLayout::square_lattice, TileLayout::triangular_lattice}) {
        TileParams tp;
        tp.layout = layout;
        tp.scales.D = layout == TileLayout::belly ? 0.1f : 0.125f;
        tp.scales.a = layout == TileLayout::belly ? 0.25f : 0.3f;
        ScalePattern torus;
        TileReport rep;
        REQUIRE(generate_tileable_pattern(tp, torus, &rep).ok());
        CAPTURE(int(layout));
        CHECK(torus.wrap_y);
        CHECK(torus.wrap_x);  // every layout, the belly too
        // one tile's scales tile the torus: their areas sum to W·H ...
        CHECK(std::fabs(pattern_area(torus) - 1.0) < 1e-5);
        CHECK(rep.polygons == torus.polygon_count());
        CHECK(rep.perturbation.realised_rms > 0.5 * rep.perturbation.requested_rms);
        // ... and their cover leaves no pixel without a scale (no gap at the seams)
        ScalePattern cover;
        REQUIRE(torus_cover(torus, cover).ok());
        std::vector<std::int32_t> labels(256 * 256);
        REQUIRE(rasterize_scale_labels(cover, 256, 256, labels.data()).ok());
        CHECK(std::count(labels.begin(), labels.end(), -1) == 0);

        // no scale is cut at the tile border: it continues on the other side
        CHECK(edges_along_border(torus, torus.wrap_x, torus.wrap_y) == 0);

        const LeatherMaps maps = tile_maps(torus, 256);
        // the maps half a tile further on are these maps rolled: the seam is like the inside
        CHECK(rolled_mismatch(torus, maps) < 1e-3);
        check_continuous(steps_along(maps, false, height_step), "height across y seams");
        check_continuous(steps_along(maps, false, normal_step), "normal across y seams");
        check_continuous(steps_along(maps, true, height_step), "height across x seams");
        check_continuous(steps_along(maps, true, normal_step), "normal across x seams");
    }
}

TEST_CASE("tileable: the lattice closes the tile; the same pattern twice; the plain one seams") {
    TileParams tp;
    tp.layout = TileLayout::square_lattice;
    tp.scales.D = 0.3f;  // 1 / 0.3 is not whole: 3 columns of 1/3
    ScalePattern a, b;
    TileReport rep;
    REQUIRE(generate_tileable_pattern(tp, a, &rep).ok());
    CHECK(rep.columns == 3);
    CHECK(rep.rows == 3);
    CHECK(rep.Dx == doctest::Approx(1.0 / 3.0));
    CHECK(a.polygon_count() == 9);
    REQUIRE(generate_tileable_pattern(tp, b).ok());
    CHECK(a.vertices == b.vertices);  // deterministic
    tp.layout = TileLayout::triangular_lattice;
    tp.scales.D = 0.125f;
    REQUIRE(generate_tileable_pattern(tp, a, &rep).ok());
    CHECK(rep.rows % 2 == 0);
    CHECK(rep.Dy == doctest::Approx(rep.Dx * std::sqrt(3.0) / 2.0).epsilon(0.1));

    // The check can fail: the plain (non-tileable) belly is cut at every tile border (scales
    // end along the border: half scales meet half scales of other rows when tiled).
    ScaleParams plain;
    ScalePattern p;
    REQUIRE(generate_scale_pattern(plain, p).ok());
    CHECK(edges_along_border(p, false, true) > 10);
    // Bad parameters are refused as for the plain pattern.
    tp.scales.D = 0.0f;
    CHECK(generate_tileable_pattern(tp, a).code() == StatusCode::invalid_argument);
}

TEST_CASE("tileable: tiles of few, big scales get a wider block (the margin is in cells)") {
    // Found by a parameter sweep: belly, D = 0.33 (3 rows a tile), a = 0.5, seed 7. With one
    // tile of margin, processing 4's shrinking near the block's straight border reached the
    // kept tile and the copies across the seam bent differently (areas summed to 1.00017).
    TileParams tp;
    tp.scales.D = tp.scales.d = 0.33f;
    tp.scales.a = 0.5f;
    tp.scales.seed = 7;
    for (float p : {0.001f, 0.015f, 0.05f}) {
        tp.scales.perturbation.p = p;
        ScalePattern torus;
        REQUIRE(generate_tileable_pattern(tp, torus).ok());
        CHECK(std::fabs(pattern_area(torus) - 1.0) < 1e-6);
        CHECK(edges_along_border(torus, false, true) == 0);
    }
}
