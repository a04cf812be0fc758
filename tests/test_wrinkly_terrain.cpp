// Tests for lib/shitsukan/wrinkly/terrain_mesh and terrain_maps: the shell from a height map,
// colour ramps, the periodic control mesh whose maps tile 2 x 2 without a seam.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "shitsukan/core/hash.hpp"
#include "shitsukan/wrinkly/terrain_maps.hpp"
#include "shitsukan/wrinkly/terrain_mesh.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "measured.hpp"
#include "tile_seams.hpp"

using namespace shitsukan;

namespace {

// A tileable height map: two waves and hashed bumps, all with period 1 in u and v.
std::vector<float> waves(int n) {
    std::vector<float> h(std::size_t(n * n));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double u = double(x) / n, v = double(y) / n, tau = 6.283185307179586;
            h[std::size_t(y * n + x)] = float(0.5 + 0.25 * std::sin(tau * u) * std::cos(tau * v) +
                                              0.2 * std::sin(tau * (2 * u + v)) +
                                              0.1 * hash_uniform(3, 0, x / 8, y / 8));
        }
    return h;
}

// The periodic terrain of the map: wrapped B-spline, cyclic fully-connected IST (N = 3).
struct Terrain {
    WrControlMesh mesh;
    WrSurface surface;
    WrIstAxis au, av;
    HierarchicalSampling hs;
};

// A rough tileable map: hashed values on an 8-pixel grid (homogeneous: no place is special).
std::vector<float> noise(int n) {
    std::vector<float> h(std::size_t(n * n));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) h[std::size_t(y * n + x)] = hash_uniform(5, 0, x / 4, y / 4);
    return h;
}

// The map rolled by (dx, dy) pixels: out(x, y) = in(x + dx, y + dy), wrapped.
std::vector<float> rolled(const std::vector<float>& in, int n, int dx, int dy) {
    std::vector<float> out(in.size());
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            out[std::size_t(y * n + x)] = in[std::size_t(((y + dy) % n) * n + (x + dx) % n)];
    return out;
}

void make_terrain(Terrain& t, bool periodic, int K, SampleInterpolation interpolation,
                  const std::vector<float>& map = waves(64), bool jitter = true) {
    TerrainMeshOptions o;
    o.points = 12;
    o.periodic = periodic;
    REQUIRE(parse_color_ramp("terrain", o.ramp));
    REQUIRE(control_mesh_from_height_map(map.data(), 64, 64, o, t.mesh));
    REQUIRE(make_wr_surface(t.mesh, SurfaceBasis::bspline, 3, t.surface));
    const IstEnds ends = periodic ? IstEnds::cyclic : IstEnds::translation;
    IstAxis iu, iv;
    REQUIRE(ist_fully_connected_axis(3, 1, t.surface.spans_u(), ends, iu));
    REQUIRE(ist_fully_connected_axis(3, 1, t.surface.spans_v(), ends, iv));
    REQUIRE(make_wr_ist_axis(iu, K, t.au));
    REQUIRE(make_wr_ist_axis(iv, K, t.av));
    REQUIRE(t.surface.set_axes(t.au.axis(), t.av.axis()));
    HierarchicalOptions ho;
    ho.levels = K;
    ho.interpolation = interpolation;
    ho.jitter_height = jitter ? 0.12f : 0.0f;  // §5's jitter (fig. 21's deviation)
    ho.jitter_color = jitter ? 0.035f : 0.0f;
    REQUIRE(sample_hierarchy(t.surface, ho, t.hs));
}

}  // namespace

TEST_CASE("colour ramps: names, stops, refusals") {
    ColorRamp r;
    REQUIRE(parse_color_ramp("0:0,0,0;0.5:1,0,0;1:1,1,1", r));
    CHECK(r.count == 3);
    CHECK(color_ramp_at(r, 0.25f).x == doctest::Approx(0.5f));
    CHECK(color_ramp_at(r, 0.75f).y == doctest::Approx(0.5f));
    CHECK(color_ramp_at(r, -1.0f).x == 0.0f);
    CHECK(color_ramp_at(r, 2.0f).z == 1.0f);
    for (const char* name : {"terrain", "grey", "sand"}) CHECK(parse_color_ramp(name, r));
    for (const char* bad : {"", "heat", "0:1,1", "0.5:0,0,0;0.2:1,1,1", "0:2,0,0", "0:0,0,0,1"}) {
        const Status s = parse_color_ramp(bad, r);
        CHECK(!s);
        CHECK(std::string(s.message()).find("colour ramp") != std::string::npos);
    }
}

TEST_CASE("terrain mesh from a height map: open and periodic layouts") {
    std::vector<float> flat(32 * 16, 0.4f);
    TerrainMeshOptions o;
    o.points = 8;
    o.height_scale = 2.0f;
    WrControlMesh m;
    REQUIRE(control_mesh_from_height_map(flat.data(), 32, 16, o, m));
    CHECK(m.cols == 8);
    CHECK(m.rows == 8);
    for (const WrControlPoint& q : m.points) CHECK(q.height == doctest::Approx(0.8f));
    CHECK(m.at(7, 0).position.x == doctest::Approx(3.0f));
    o.periodic = true;
    REQUIRE(control_mesh_from_height_map(flat.data(), 32, 16, o, m));
    CHECK(m.cols == 11);  // 8 + degree 3
    // the wrapped points are the first ones moved by one period (extent 6)
    for (int r = 0; r < 3; ++r) {
        CHECK(m.at(8, r).position.x == doctest::Approx(m.at(0, r).position.x + 6.0f));
        CHECK(m.at(8, r).height == m.at(0, r).height);
        CHECK(m.at(r, 8).position.z == doctest::Approx(m.at(r, 0).position.z - 6.0f));
    }
    // a non-finite pixel, a bad option: named
    flat[5] = NAN;
    Status s = control_mesh_from_height_map(flat.data(), 32, 16, o, m);
    CHECK(!s);
    CHECK(std::string(s.message()).find("(5, 0)") != std::string::npos);
    flat[5] = 0.0f;
    o.points = 2;
    CHECK(!control_mesh_from_height_map(flat.data(), 32, 16, o, m));
}

TEST_CASE("a wrapped control mesh gives a B-spline surface that repeats") {
    Terrain t;
    make_terrain(t, true, 2, SampleInterpolation::linear);
    CHECK(t.surface.spans_u() == 12);
    for (float v : {0.1f, 0.5f, 0.83f}) {
        const BasePoint a = t.surface.base_point(0.0f, v), b = t.surface.base_point(1.0f, v);
        CHECK(b.position.x - a.position.x == doctest::Approx(6.0f).epsilon(1e-4));
        CHECK(b.position.z == doctest::Approx(a.position.z).epsilon(1e-4));
        CHECK(t.surface.attributes(0.0f, v).height ==
              doctest::Approx(t.surface.attributes(1.0f, v).height).epsilon(1e-5));
    }
}

TEST_CASE("periodic terrain maps: the tile's seam is an interior column of the same terrain") {
    // Rolling the input map by half a period (6 of the 12 control points, 32 of 64 pixels)
    // rolls the output by half a map: the columns and rows at the tile's edge are then the
    // middle ones of the other map, value for value. The cyclic IST is the same in every base
    // interval and the cyclic interpolation the same at every sample, so nothing marks u = 0.
    const std::vector<float> map = waves(64), half = rolled(map, 64, 32, 32);
    for (SampleInterpolation mode : {SampleInterpolation::linear, SampleInterpolation::hermite})
        for (WrSurfaceForm form : {WrSurfaceForm::superposed, WrSurfaceForm::wr}) {
            Terrain a, b;
            make_terrain(a, true, 3, mode, map, false);
            make_terrain(b, true, 3, mode, half, false);
            TerrainMapOptions o;
            o.width = o.height = 128;
            o.form = form;
            o.levels = 3;
            o.periodic = true;
            TerrainMaps ma, mb;
            REQUIRE(make_terrain_maps(a.surface, &a.hs, o, ma));
            REQUIRE(make_terrain_maps(b.surface, &b.hs, o, mb));
            double worst = 0;
            for (int y = 0; y < 128; ++y)
                for (int x = 0; x < 128; ++x)
                    worst = std::fmax(worst, std::fabs(mb.heights[std::size_t(y * 128 + x)] -
                                                       ma.heights[std::size_t(((y + 64) % 128) * 128 +
                                                                               (x + 64) % 128)]));
            INFO("form " << int(form) << " mode " << int(mode) << ": worst " << worst);
            MEASURED("terrain half-period roll, form " << int(form) << " mode " << int(mode)
                                                      << ": largest difference " << worst
                                                      << " of a range " << (ma.hi - ma.lo));
            CHECK(worst < 1e-4 * (ma.hi - ma.lo));
        }
}

TEST_CASE("periodic terrain maps tile 2 x 2: seams are ordinary columns and rows") {
    // §5's jitter on a homogeneous rough shell: the seam measured against the interior
    for (WrSurfaceForm form : {WrSurfaceForm::superposed, WrSurfaceForm::wr}) {
        Terrain t;
        make_terrain(t, true, 3, SampleInterpolation::linear, noise(64), true);
        TerrainMapOptions o;
        o.width = o.height = 128;
        o.form = form;
        o.levels = 3;
        o.periodic = true;
        TerrainMaps maps;
        REQUIRE(make_terrain_maps(t.surface, &t.hs, o, maps));
        CHECK(maps.hi > maps.lo);
        for (bool rows : {false, true}) {
            const test::SeamMeasure m = test::measure_seams(maps.heights.data(), 128, 128, rows);
            INFO("form " << int(form) << " rows " << rows << ": seam " << m.seam_value << " / "
                         << m.seam_gradient << ", median " << m.median_value << " / "
                         << m.median_gradient << ", max " << m.max_value << " / "
                         << m.max_gradient);
            MEASURED("terrain " << (form == WrSurfaceForm::wr ? "WR" : "superposed") << " 2x2 "
                                << (rows ? "rows" : "columns") << ": seam value jump "
                                << m.seam_value << " (interior median " << m.median_value
                                << ", max " << m.max_value << "), second difference "
                                << m.seam_gradient << " (median " << m.median_gradient
                                << ", max " << m.max_gradient << ")");
            CHECK(m.seam_value <= m.max_value);
            CHECK(m.seam_gradient <= m.max_gradient);
            CHECK(m.seam_value <= 3.0 * m.median_value);
            CHECK(m.seam_gradient <= 3.0 * m.median_gradient);
        }
    }
}

TEST_CASE("the open surface's superposed map is the library's eq. (20) at the pixels") {
    Terrain t;
    make_terrain(t, false, 2, SampleInterpolation::linear);
    TerrainMapOptions o;
    o.width = o.height = 16;
    o.form = WrSurfaceForm::superposed;
    TerrainMaps maps;
    REQUIRE(make_terrain_maps(t.surface, &t.hs, o, maps));
    const float u = 3.5f / 16.0f, v = 9.5f / 16.0f;
    CHECK(maps.heights[9 * 16 + 3] == superposed_sampled(t.surface, t.hs, u, v).attributes.height);
    o.form = WrSurfaceForm::plain;
    REQUIRE(make_terrain_maps(t.surface, nullptr, o, maps));
    CHECK(maps.heights[9 * 16 + 3] == t.surface.attributes(u, v).height);
    o.form = WrSurfaceForm::superposed;
    CHECK(!make_terrain_maps(t.surface, nullptr, o, maps));  // needs the sampling
    o.width = 0;
    CHECK(!make_terrain_maps(t.surface, &t.hs, o, maps));
}
