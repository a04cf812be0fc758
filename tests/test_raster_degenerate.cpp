// Tests for lib/shitsukan/raster/rasterizer.cpp and band.cpp: degenerate and bad input.
// Degenerate triangles are skipped and counted; bad buffers, indices, shaders and matrices
// give a Status with a clear message and draw nothing. (The sanitizer run checks that
// nothing is written outside the buffers.)
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "raster_test_scenes.hpp"
#include "shitsukan/raster/wireframe.hpp"

using namespace shitsukan;
using namespace raster_test;

namespace {

Rgb8 white(const Fragment&, void*) { return Rgb8{255, 255, 255}; }

struct Frame {
    RgbImage color{32, 32};
    FloatImage depth{32, 32};
    FrameBand band;
    Frame() {
        band = full_frame_band(color.view(), depth.view());
        clear_band(band, Rgb8{0, 0, 0});
    }
    int lit() const {
        int n = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) n += color.at(x, y).r != 0;
        return n;
    }
};

Camera camera32() { return perspective_camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45.0f, 32, 32); }

bool mentions(const Status& s, const char* text) {
    return std::string(s.message()).find(text) != std::string::npos;
}

}  // namespace

TEST_CASE("degeneracy is decided on exact products: a float-cancelling sliver is kept") {
    // Edges (1 + 2^-12, 1 + 2^-11, 0) and (1, 1 + 2^-12, 0): x·y' = 1 + 2^-11 + 2^-24 and
    // y·x' = 1 + 2^-11 round to the same float, so a float cross product is 0; the exact one is
    // 2^-24 (a sliver, not a degenerate triangle). Collinear corners, scaled far outside the
    // float products' range (1e-30, 1e25), stay degenerate.
    const float a = 1.0f + 0x1p-12f, b = 1.0f + 0x1p-11f;
    TriangleMesh m;
    m.positions = {{0, 0, 0},           {a, b, 0},           {1, a, 0},
                   {1e-30f, 1e-30f, 0}, {2e-30f, 2e-30f, 0}, {3e-30f, 3e-30f, 0},
                   {1e25f, 1e25f, 0},   {2e25f, 2e25f, 0},   {4e25f, 4e25f, 0}};
    m.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    CHECK(a * a - b * 1.0f == 0.0f);  // the float cross product's z cancels
    Frame f;
    RasterStats stats;
    DrawOptions opt;
    opt.cull = CullMode::none;
    CHECK(draw_mesh(camera32(), f.band, m.view(), opt, white, nullptr, &stats).ok());
    CHECK(stats.triangles_in == 3);
    CHECK(stats.triangles_rejected == 2);
}

TEST_CASE("a triangle is rejected exactly when its edges' cross product is zero (random slivers)") {
    // The rasterizer decides most triangles from the rounded products (rounded ones that differ
    // are exact ones that differ) and only the rest from exact ones; the reference here is the
    // cross product of the same float edges in double (products of floats are exact there, and
    // a difference of doubles is zero only when they are equal).
    TriangleMesh m;
    std::uint32_t state = 2024u;
    auto next = [&state](int range) {
        state = state * 1664525u + 1013904223u;
        return int(state >> 16) % range;
    };
    long degenerate = 0;
    for (int i = 0; i < 600; ++i) {
        const float unit = std::ldexp(1.0f, -next(30));  // edges from 1 down to 2^-29
        const Vec3 p{0.1f * float(next(9) - 4), 0.1f * float(next(9) - 4), 0.0f};
        const Vec3 e1 = Vec3{float(next(4097) - 2048), float(next(4097) - 2048),
                             float(next(5) - 2)} * unit;
        // e2 = 2^k·e1 (collinear), nudged by an ulp in one component or by nothing.
        Vec3 e2 = e1 * std::ldexp(1.0f, next(5) - 2);
        const int nudge = next(4);
        if (nudge == 1) e2.x = std::nextafter(e2.x, 1e30f);
        if (nudge == 2) e2.y = std::nextafter(e2.y, -1e30f);
        const std::uint32_t a = m.add_vertex(p), b = m.add_vertex(p + e1), c = m.add_vertex(p + e2);
        m.add_triangle(a, b, c);
        const Vec3 f1 = m.positions[b] - m.positions[a], f2 = m.positions[c] - m.positions[a];
        const double x1 = f1.x, y1 = f1.y, z1 = f1.z, x2 = f2.x, y2 = f2.y, z2 = f2.z;
        degenerate +=
            y1 * z2 - z1 * y2 == 0.0 && z1 * x2 - x1 * z2 == 0.0 && x1 * y2 - y1 * x2 == 0.0;
    }
    Frame f;
    RasterStats stats;
    DrawOptions opt;
    opt.cull = CullMode::none;
    CHECK(draw_mesh(camera32(), f.band, m.view(), opt, white, nullptr, &stats).ok());
    CHECK(degenerate > 100);
    CHECK(degenerate < 500);
    CHECK(stats.triangles_rejected == degenerate);
}

TEST_CASE("zero-area, NaN and inf triangles are skipped and counted, the rest is drawn") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    TriangleMesh m;
    m.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0},     // 0-2 a good triangle
                   {-1, 0, 0}, {0, 0, 0},  {1, 0, 0},      // 3-5 collinear
                   {nan, 0, 0}, {inf, 1, 0}, {0, -inf, 0}, // 6-8 not finite
                   {0.5f, 0.5f, 0}};                       // 9
    m.indices = {3, 4, 5,   // zero area (collinear)
                 9, 9, 0,   // zero area (repeated vertex)
                 6, 1, 2,   // NaN
                 0, 7, 2,   // inf
                 0, 1, 8,   // -inf
                 0, 1, 2};  // good
    Frame f;
    RasterStats stats;
    DrawOptions opt;
    opt.cull = CullMode::none;
    Status s = draw_mesh(camera32(), f.band, m.view(), opt, white, nullptr, &stats);
    CHECK(s.ok());
    CHECK(stats.triangles_in == 6);
    CHECK(stats.triangles_rejected == 5);
    CHECK(stats.triangles_drawn == 1);
    CHECK(f.lit() > 50);
    CHECK(stats.fragments_shaded == f.lit());

    // Only degenerate triangles: nothing drawn at all.
    Frame g;
    TriangleMesh bad = m;
    bad.indices.resize(15);
    RasterStats st2;
    CHECK(draw_mesh(camera32(), g.band, bad.view(), opt, white, nullptr, &st2).ok());
    CHECK(g.lit() == 0);
    CHECK(st2.triangles_rejected == 5);
    CHECK(st2.fragments_shaded == 0);
}

TEST_CASE("a corner with w_clip == 0 (at the eye) is not divided by: rejected, not NaN") {
    // A valid camera at the origin looking down -z, and a projective (invertible) model
    // matrix taking the object origin to the homogeneous point (0, 0, 0, -1): the eye. Its
    // clip coordinates are (0, 0, z, 0) with no clipping-plane outcode, so only the w test
    // keeps it out of the fast path's divide. The other corners are ordinary points in front.
    Camera cam = perspective_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 32, 32);
    DrawOptions opt;
    opt.model = Mat4::identity();
    opt.model.m[3][2] = -1.0f;  // w_model = -z - 1
    opt.model.m[3][3] = -1.0f;
    opt.cull = CullMode::none;
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {-1, -1, -3}, {1, -1, -3}};
    m.indices = {0, 1, 2};
    Vec4 clip0 = cam.projection * (cam.view * (opt.model * Vec4{0, 0, 0, 1}));
    REQUIRE(clip0.w == 0.0f);
    REQUIRE(clip0.x == 0.0f);
    REQUIRE(clip0.y == 0.0f);
    Frame f;
    RasterStats stats;
    CHECK(draw_mesh(cam, f.band, m.view(), opt, white, nullptr, &stats).ok());
    CHECK(stats.triangles_rejected == 1);  // its plane passes through the eye: edge-on
    CHECK(stats.fragments_shaded == 0);
    CHECK(f.lit() == 0);
    // The wireframe drops the two edges ending at the eye and draws the third.
    WireEdge edges[3];
    int n = 0;
    REQUIRE(collect_edges(m.view(), edges, 3, n).ok());
    WireOptions w;
    w.model = opt.model;
    long pixels = 0;
    CHECK(draw_edges(cam, f.band, m.view(), edges, n, w, &pixels).ok());
    CHECK(pixels > 0);
    CHECK(pixels == f.lit());
}

TEST_CASE("huge but finite coordinates are clipped by the guard band, not overflowed") {
    // 1e5: far beyond the guard band (about 10 units at this distance); the guard-band cut
    // points are still precise in float, so the triangle covers the whole screen.
    TriangleMesh m;
    m.positions = {{-1e5f, -1e5f, 0}, {1e5f, -1e5f, 0}, {0, 1e5f, 0}};
    m.indices = {0, 1, 2};
    Frame f;
    RasterStats stats;
    CHECK(draw_mesh(camera32(), f.band, m.view(), DrawOptions{}, white, nullptr, &stats).ok());
    CHECK(f.lit() == 32 * 32);
    CHECK(stats.fragments_shaded == 32 * 32);
    // 1e30: float cannot place the cut points precisely any more (nor could a GPU), but
    // nothing overflows, nothing is written outside the band (sanitizer) and the status is ok.
    for (float big : {1e30f, 3e38f}) {
        m.positions = {{-big, -big, 0}, {big, -big, 0}, {0, big, 0}};
        Frame g;
        RasterStats st;
        CHECK(draw_mesh(camera32(), g.band, m.view(), DrawOptions{}, white, nullptr, &st).ok());
        CHECK(st.fragments_shaded == g.lit());
    }
}

TEST_CASE("an empty mesh draws nothing and is fine") {
    Frame f;
    MeshView empty;
    RasterStats stats;
    CHECK(draw_mesh(camera32(), f.band, empty, DrawOptions{}, white, nullptr, &stats).ok());
    CHECK(stats.triangles_in == 0);
    CHECK(f.lit() == 0);
}

TEST_CASE("bad buffers, meshes, shaders and matrices: a clear Status, nothing drawn") {
    TriangleMesh good;
    good.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    good.indices = {0, 1, 2};
    Camera cam = camera32();

    SUBCASE("zero-size image") {
        RgbImage color(0, 0);
        FloatImage depth(0, 0);
        FrameBand band = full_frame_band(color.view(), depth.view());
        clear_band(band, Rgb8{1, 2, 3});  // harmless on an empty band
        Status s = draw_mesh(cam, band, good.view(), DrawOptions{}, white, nullptr);
        CHECK(s.code() == StatusCode::invalid_argument);
        CHECK(mentions(s, "empty"));
    }
    SUBCASE("colour and depth sizes differ") {
        RgbImage color(32, 32);
        FloatImage depth(32, 16);
        FrameBand band = make_band(color.view(), depth.view(), 0, 32, 32);
        Status s = draw_mesh(cam, band, good.view(), DrawOptions{}, white, nullptr);
        CHECK(!s.ok());
        CHECK(mentions(s, "32 x 16"));
    }
    SUBCASE("band rows outside the frame, band narrower than the frame, frame != camera") {
        RgbImage color(32, 8);
        FloatImage depth(32, 8);
        Status s = draw_mesh(cam, make_band(color.view(), depth.view(), 28, 32, 32), good.view(),
                             DrawOptions{}, white, nullptr);
        CHECK(!s.ok());
        CHECK(mentions(s, "[28, 36)"));
        s = draw_mesh(cam, make_band(color.view(), depth.view(), -1, 32, 32), good.view(),
                      DrawOptions{}, white, nullptr);
        CHECK(!s.ok());
        RgbImage narrow(16, 8);
        FloatImage narrow_depth(16, 8);
        s = draw_mesh(cam, make_band(narrow.view(), narrow_depth.view(), 0, 32, 32), good.view(),
                      DrawOptions{}, white, nullptr);
        CHECK(!s.ok());
        CHECK(mentions(s, "16 pixels wide"));
        s = draw_mesh(cam, make_band(color.view(), depth.view(), 0, 32, 64), good.view(),
                      DrawOptions{}, white, nullptr);
        CHECK(!s.ok());
        CHECK(mentions(s, "camera"));
    }
    SUBCASE("a band starting near INT_MAX: refused, no int overflow in the row check") {
        RgbImage color(32, 8);
        FloatImage depth(32, 8);
        const int y0 = std::numeric_limits<int>::max() - 2;
        FrameBand band = make_band(color.view(), depth.view(), y0, 32, 32);
        Status s = validate_band(cam, band);
        CHECK(s.code() == StatusCode::invalid_argument);
        CHECK(mentions(s, "outside the frame rows"));
        CHECK(mentions(s, "2147483653)"));  // y0 + 8, printed without wrapping
        CHECK(!draw_mesh(cam, band, good.view(), DrawOptions{}, white, nullptr).ok());
    }
    SUBCASE("a stride below the width (or negative) is refused, by draw_edges too") {
        // Room for exactly 32 x 32 pixels: a short stride would write past it otherwise.
        Frame f;
        TriangleMesh m = good;
        WireEdge edges[3];
        int n = 0;
        REQUIRE(collect_edges(m.view(), edges, 3, n).ok());
        for (int stride : {31, 16, 0, -32}) {
            for (int which = 0; which < 2; ++which) {
                FrameBand band = f.band;
                (which == 0 ? band.color.stride : band.depth.stride) = stride;
                std::string view = which == 0 ? "colour" : "depth";
                INFO("stride " << stride << " on the " << view << " view");
                Status s = validate_band(cam, band);
                CHECK(s.code() == StatusCode::invalid_argument);
                CHECK(mentions(s, "stride"));
                CHECK(!draw_mesh(cam, band, m.view(), DrawOptions{}, white, nullptr).ok());
                CHECK(!draw_edges(cam, band, m.view(), edges, n, WireOptions{}).ok());
            }
        }
        CHECK(f.lit() == 0);
        CHECK(validate_band(cam, f.band).ok());
    }
    SUBCASE("out-of-range index: refused before anything is drawn") {
        TriangleMesh m = good;
        m.indices = {0, 1, 2, 0, 1, 7};
        Frame f;
        Status s = draw_mesh(cam, f.band, m.view(), DrawOptions{}, white, nullptr);
        CHECK(s.code() == StatusCode::invalid_argument);
        CHECK(mentions(s, "triangle 1 corner 2 has index 7"));
        CHECK(f.lit() == 0);
    }
    SUBCASE("missing arrays and negative counts") {
        MeshView v = good.view();
        v.indices = nullptr;
        Frame f;
        CHECK(!draw_mesh(cam, f.band, v, DrawOptions{}, white, nullptr).ok());
        v = good.view();
        v.triangle_count = -1;
        CHECK(!draw_mesh(cam, f.band, v, DrawOptions{}, white, nullptr).ok());
        v = good.view();
        v.positions = nullptr;
        CHECK(!draw_mesh(cam, f.band, v, DrawOptions{}, white, nullptr).ok());
    }
    SUBCASE("null shader, singular or NaN model, NaN camera, zero-size camera") {
        Frame f;
        Status s = draw_mesh(cam, f.band, good.view(), DrawOptions{}, nullptr, nullptr);
        CHECK(mentions(s, "shader"));
        DrawOptions opt;
        opt.model = Mat4::scale({1, 0, 1});
        s = draw_mesh(cam, f.band, good.view(), opt, white, nullptr);
        CHECK(mentions(s, "singular"));
        opt.model.m[0][0] = NAN;
        CHECK(!draw_mesh(cam, f.band, good.view(), opt, white, nullptr).ok());
        Camera bad = cam;
        bad.view.m[1][1] = INFINITY;
        CHECK(mentions(draw_mesh(bad, f.band, good.view(), DrawOptions{}, white, nullptr),
                       "NaN/inf"));
        bad = cam;
        bad.width = 0;
        CHECK(!draw_mesh(bad, f.band, good.view(), DrawOptions{}, white, nullptr).ok());
        CHECK(f.lit() == 0);
    }
}

TEST_CASE("triangles behind the eye or off screen draw nothing") {
    TriangleMesh m;
    m.positions = {{-1, -1, 5}, {1, -1, 5}, {0, 1, 5},          // behind the eye (z = 3)
                   {10, -1, 0}, {12, -1, 0}, {11, 1, 0}};       // right of the screen
    m.indices = {0, 1, 2, 3, 4, 5};
    Frame f;
    RasterStats stats;
    DrawOptions opt;
    opt.cull = CullMode::none;
    CHECK(draw_mesh(camera32(), f.band, m.view(), opt, white, nullptr, &stats).ok());
    CHECK(f.lit() == 0);
    CHECK(stats.triangles_drawn == 0);
    CHECK(stats.triangles_rejected == 0);
}

TEST_CASE("shader forms: function + user pointer, functor, captureless two-argument lambda") {
    TriangleMesh m;
    m.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2};
    Frame a, b, c;
    int calls = 0;
    auto functor = [&](const Fragment&) {
        ++calls;
        return Rgb8{255, 0, 0};
    };
    auto two_args = [](const Fragment&, void* user) {
        ++*static_cast<int*>(user);
        return Rgb8{255, 0, 0};
    };
    int calls2 = 0;
    CHECK(draw_mesh(camera32(), a.band, m.view(), DrawOptions{}, white, nullptr).ok());
    CHECK(draw_mesh(camera32(), b.band, m.view(), DrawOptions{}, functor).ok());
    CHECK(draw_mesh(camera32(), c.band, m.view(), DrawOptions{}, two_args, &calls2).ok());
    CHECK(calls == a.lit());
    CHECK(calls2 == a.lit());
    CHECK(b.lit() == a.lit());
    CHECK(c.lit() == a.lit());
}

TEST_CASE("fuzz_raster finding: a projective model sending corners to w ~ 0 draws no NaN") {
    // fuzz/corpus/fuzz_raster/finding_projective_model_nan_world: a bottom row of
    // (-1.6e-23, -1.6e-23, 9.4e-38, 1.5e-36) passed validate_model (finite, invertible) and
    // the shader got NaN world positions (x / w overflowed). Such triangles are now rejected.
    // The same defect on a readable matrix: w = x + 1 (invertible, det 1) and a corner at
    // x = -0.99999994, y = 1e32, whose world y = y / 5.96e-8 overflows to inf.
    Camera cam = perspective_camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 60.0f, 32, 32);
    DrawOptions opt;
    opt.model = Mat4::identity();
    opt.model.m[3][0] = 1.0f;
    opt.cull = CullMode::none;
    Mat4 normal_matrix;
    REQUIRE(validate_model(opt.model, normal_matrix).ok());   // projective models are allowed
    TriangleMesh m;
    m.positions = {{-0.99999994f, 1e32f, 0}, {0, 0, 0}, {0.5f, 0, 0}};
    m.indices = {0, 1, 2};
    Frame f;
    RasterStats stats;
    long nan_fragments = 0;
    auto shader = [](const Fragment& fr, void* user) -> Rgb8 {
        if (!is_finite(fr.world_position)) ++*static_cast<long*>(user);
        return Rgb8{255, 255, 255};
    };
    CHECK(draw_mesh(cam, f.band, m.view(), opt, shader, &nan_fragments, &stats).ok());
    CHECK(nan_fragments == 0);
    CHECK(stats.triangles_rejected == 1);
}
