// fuzz/fuzz_maps.cpp — height and normal maps on any values, chosen by the first byte:
// 0 height_map_normals (any heights, up to 16 x 16, any strength, wrap or not);
// 1 make_leather_maps (a small scale pattern of tokai1994 §3.1, then any map size, a Table 1
//   section or any Bezier chain, any relief options; the memory budget is 16 MiB).
// Contracts:
//   normals: ok => every normal finite and of unit length with z > 0; not ok only for a
//     non-finite height (invalid_argument) or a slope past a float (out_of_range): heights
//     within +-1e30 and a strength within 1e6 must succeed.
//   leather: ok => width·height finite heights, max_height their largest, unit normals; sizes
//     outside 1..16384 refused.
#include <cmath>
#include <vector>

#include "fuzz_input.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/image/normal_map.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/scale_division.hpp"

using namespace shitsukan;

namespace {

bool unit(Vec3 n) {
    const double l = std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
    return std::isfinite(l) && std::fabs(l - 1.0) < 1e-4;
}

void fuzz_normals(fuzz::Input& in) {
    const int w = 1 + in.take<std::uint8_t>() % 16, h = 1 + in.take<std::uint8_t>() % 16;
    std::vector<float> heights(std::size_t(w) * std::size_t(h));
    bool tame = true;
    for (float& v : heights) {
        v = in.value();
        tame = tame && std::fabs(v) <= 1e30f;
    }
    HeightNormalOptions o;
    o.strength = in.value();
    o.wrap = in.take<std::uint8_t>() & 1;
    tame = tame && std::fabs(o.strength) <= 1e6f;
    std::vector<Vec3> n(heights.size());
    const Status s = height_map_normals(heights.data(), w, h, o, n.data());
    if (!s) {
        FUZZ_REQUIRE(!tame);
        FUZZ_REQUIRE(s.code() == StatusCode::invalid_argument ||
                     s.code() == StatusCode::out_of_range);
        return;
    }
    for (const Vec3& v : n) FUZZ_REQUIRE(unit(v) && v.z > 0.0f);
}

void fuzz_leather(fuzz::Input& in) {
    ScaleParams prm;
    const float spacing[4] = {0.2f, 0.25f, 1.0f / 3.0f, 0.5f};
    prm.D = prm.d = spacing[in.take<std::uint8_t>() % 4];
    prm.perturbation.levels = in.take<std::uint8_t>() % 4;
    prm.seed = in.take<std::uint32_t>();
    ScalePattern pattern;
    if (!generate_scale_pattern(prm, pattern)) return;
    int w = in.take<std::uint8_t>() % 48, h = in.take<std::uint8_t>() % 48;
    if ((in.take<std::uint8_t>() & 15) == 15) w = in.take<std::int16_t>(), h = 1;  // any width
    BezierChain section = table1_section(Table1Section(in.take<std::uint8_t>() % 3));
    if (in.take<std::uint8_t>() & 1) {  // any chain
        section.count = int(in.take<std::uint8_t>() % 6);
        for (CubicBezier2& seg : section.segments)
            for (Vec2& p : seg.p) p = {in.value(), in.value()};
    }
    ReliefOptions o;
    if (in.take<std::uint8_t>() & 1) {
        o.edge_r = in.value();
        o.height_scale = in.value();
    }
    o.normal_rule = (in.take<std::uint8_t>() & 1) ? ReliefNormal::height_gradient : ReliefNormal::eq4;
    LeatherMaps maps;
    if (!make_leather_maps(pattern, w, h, section, o, maps)) return;
    FUZZ_REQUIRE(w >= 1 && w <= 16384 && h >= 1 && h <= 16384);
    FUZZ_REQUIRE(maps.width == w && maps.height == h);
    const std::size_t n = std::size_t(w) * std::size_t(h);
    FUZZ_REQUIRE(maps.heights.size() == n && maps.normals.size() == n);
    float top = 0.0f;
    for (std::size_t i = 0; i < n; ++i) {
        FUZZ_REQUIRE(std::isfinite(maps.heights[i]));
        FUZZ_REQUIRE(unit(maps.normals[i]));
        if (i == 0 || maps.heights[i] > top) top = maps.heights[i];
    }
    FUZZ_REQUIRE(std::isfinite(maps.max_height) && maps.max_height >= top);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    set_memory_budget(std::uint64_t(16) << 20);
    fuzz::Input in(data, size);
    if (in.take<std::uint8_t>() & 1)
        fuzz_leather(in);
    else
        fuzz_normals(in);
    return 0;
}
