// fuzz/fuzz_scale_pattern.cpp — generate_scale_pattern (both Voronoi stages, *(T junctions),
// the two-stage perturbation) on any parameters. Contract: a non-ok Status, or polygons that
// tile [0, W] x [0, H] (areas sum to W H within 1e-6 relative), straight cells that share
// every inner edge (no one-sided edge inside the rectangle: finding 7's cause) and a label
// image that the rasterizer accepts. Patterns above 64 x 64 seeds, or above 65536 seeds x
// 2^levels curve points, are skipped (time, not correctness: the library's own limit is 4096
// seeds per line). Small ones (<= 16 x 16 seeds, the block of tiles within the same point
// budget) also go through generate_tileable_pattern (the layout from one more byte): a non-ok
// Status or one tile's scales summing to W H.
#include <cmath>
#include <vector>

#include "fuzz_input.hpp"
#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/scale_labels.hpp"
#include "shitsukan/leather/tileable.hpp"

using namespace shitsukan;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    ScaleParams prm;
    prm.width = in.take<float>();
    prm.height = in.take<float>();
    prm.D = in.take<float>();
    prm.d = in.take<float>();
    prm.a = in.take<float>();
    prm.edge_ratio = in.take<float>();
    prm.perturbation.p = in.take<float>();
    prm.perturbation.levels = in.take<std::uint8_t>() % 12;
    prm.perturbation.decay = in.take<float>();
    prm.perturbation.safety = in.take<float>();
    prm.seed = in.take<std::uint32_t>();
    const int layout = in.take<std::uint8_t>() % 3;
    if (!(prm.width / prm.D <= 64.0f && prm.height / prm.D <= 64.0f)) return 0;
    // output size ~ scales x 2^levels points: keep a run under the 1 s timeout under ASan
    // (0.2 s natively for 1.2 million points; found as a timeout, not a defect)
    if (!(prm.width / prm.D * prm.height / prm.D * float(1 << prm.perturbation.levels) <= 65536.0f))
        return 0;
    ScalePattern pat;
    ScaleDivision steps;
    if (!generate_scale_pattern(prm, pat, &steps)) return 0;
    double area = 0.0;
    for (int f = 0; f < pat.polygon_count(); ++f) {
        int n;
        const Vec2* v = pat.polygon(f, &n);
        for (int k = 0; k < n; ++k) FUZZ_REQUIRE(std::isfinite(v[k].x) && std::isfinite(v[k].y));
        area += polygon_area(v, n);
    }
    const double want = double(prm.width) * double(prm.height);
    FUZZ_REQUIRE(std::fabs(area - want) <= 1e-6 * want);
    FUZZ_REQUIRE(outer_edges_on_box(steps.cells, {0, 0}, {double(prm.width), double(prm.height)}));
    std::vector<std::int32_t> labels(64 * 64);
    FUZZ_REQUIRE(rasterize_scale_labels(pat, 64, 64, labels.data()).ok());
    // the tileable block is 2m + 1 tiles a periodic axis, at least 6 cells of margin: at most
    // (3 n + 12) cells; the same point budget (found as a timeout)
    if (!(prm.width / prm.D <= 16.0f && prm.height / prm.D <= 16.0f)) return 0;
    if (!((3.0f * prm.width / prm.D + 12.0f) * (3.0f * prm.height / prm.D + 12.0f) *
              float(1 << prm.perturbation.levels) <=
          65536.0f))
        return 0;
    TileParams tp;
    tp.layout = TileLayout(layout);
    tp.scales = prm;
    ScalePattern torus;
    if (!generate_tileable_pattern(tp, torus)) return 0;
    double torus_area = 0.0;
    for (int f = 0; f < torus.polygon_count(); ++f) {
        int n;
        const Vec2* v = torus.polygon(f, &n);
        torus_area += polygon_area(v, n);
    }
    FUZZ_REQUIRE(std::fabs(torus_area - want) <= 1e-5 * want);
    return 0;
}
