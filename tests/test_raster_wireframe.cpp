// Tests for lib/shitsukan/raster/wireframe.cpp: unique edges, line pixels, near-plane
// clipping of lines, hidden lines, bands.
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "raster_test_scenes.hpp"
#include "shitsukan/raster/wireframe.hpp"

using namespace shitsukan;
using namespace raster_test;

namespace {

std::vector<WireEdge> edges_of(const MeshView& mesh) {
    std::vector<WireEdge> e(std::size_t(3 * mesh.triangle_count));
    int n = 0;
    CHECK(collect_edges(mesh, e.data(), int(e.size()), n).ok());
    e.resize(std::size_t(n));
    return e;
}

// World (x, y) on the z = 0 plane maps to screen (x, 32 - y): pixel units.
Camera pixel_camera() {
    return orthographic_camera({16, 16, 1}, {16, 16, 0}, {0, 1, 0}, 16.0f, 32, 32);
}

int count_color(const RgbImage& img, Rgb8 c) {
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) n += img.at(x, y) == c;
    return n;
}

}  // namespace

TEST_CASE("collect_edges: each shared edge once, also across duplicated corner vertices") {
    TriangleMesh box = box_mesh({-1, -1, -1}, {1, 1, 1});  // 24 vertices, 4 per face
    CHECK(edges_of(box.view()).size() == 12 + 6);  // 12 box edges + 6 face diagonals
    TriangleMesh sphere = sphere_mesh(1.0f, 12, 6);
    CHECK(edges_of(sphere.view()).size() == std::size_t(3 * sphere.triangle_count() / 2));
    TriangleMesh torus = torus_mesh(1.0f, 0.3f, 10, 6);
    CHECK(edges_of(torus.view()).size() == std::size_t(3 * torus.triangle_count() / 2));
    // An open mesh keeps its boundary edges: one triangle has three.
    TriangleMesh tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.indices = {0, 1, 2};
    CHECK(edges_of(tri.view()).size() == 3);
    // Too little room, bad indices.
    WireEdge two[2];
    int n = -1;
    CHECK(collect_edges(tri.view(), two, 2, n).code() == StatusCode::buffer_too_small);
    CHECK(n == 0);
    tri.indices = {0, 1, 5};
    WireEdge three[3];
    CHECK(!collect_edges(tri.view(), three, 3, n).ok());
}

TEST_CASE("collect_edges: 3·triangle_count beyond INT_MAX is refused before any index is read") {
    // Only one triangle's indices exist: a count that the arrays cannot back must be refused
    // from the counts alone (3 · 800 000 000 overflows int).
    const Vec3 positions[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::uint32_t indices[3] = {0, 1, 2};
    MeshView mesh;
    mesh.positions = positions;
    mesh.indices = indices;
    mesh.vertex_count = 3;
    mesh.triangle_count = 800000000;
    WireEdge room[16];
    int n = -1;
    Status s = collect_edges(mesh, room, 16, n);
    CHECK(s.code() == StatusCode::buffer_too_small);
    CHECK(std::strstr(s.message(), "need 2400000000") != nullptr);
    CHECK(n == 0);
    CHECK(collect_edges(mesh, room, -1, n).code() == StatusCode::invalid_argument);
    mesh.triangle_count = 1;  // the same arrays with the true count are fine
    CHECK(collect_edges(mesh, room, 16, n).ok());
    CHECK(n == 3);
}

TEST_CASE("a line lights one pixel per column at the centres in [start, end)") {
    Camera cam = pixel_camera();
    TriangleMesh seg;
    seg.positions = {{2.3f, 32 - 5.5f, 0}, {10.7f, 32 - 5.5f, 0},   // horizontal, row 5
                     {20.5f, 32 - 3.2f, 0}, {24.5f, 32 - 20.9f, 0}}; // steep: one per row
    WireEdge e[2] = {{0, 1}, {2, 3}};
    RgbImage color(32, 32);
    FloatImage depth(32, 32);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{0, 0, 0});
    WireOptions w;
    long pixels = 0;
    REQUIRE(draw_edges(cam, band, seg.view(), e, 2, w, &pixels).ok());
    for (int x = 0; x < 16; ++x) CHECK((color.at(x, 5) == w.color) == (x >= 2 && x <= 10));
    // Rows 3..20 (centres 3.5 .. 20.5 in [3.2, 20.9)): 18 pixels, one per row.
    int steep = 0;
    for (int y = 0; y < 32; ++y) {
        int in_row = 0;
        for (int x = 16; x < 32; ++x) in_row += color.at(x, y) == w.color;
        CHECK(in_row == (y >= 3 && y <= 20 ? 1 : 0));
        steep += in_row;
    }
    CHECK(pixels == 9 + steep);
}

TEST_CASE("lines crossing the near plane are clipped, lines behind the eye vanish") {
    Camera cam = perspective_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 48, 48);
    TriangleMesh m;
    m.positions = {{0.2f, -0.3f, 5}, {0.2f, -0.3f, -5},   // from behind the eye to the front
                   {-1, 0, 2}, {1, 0.5f, 3}};             // wholly behind
    WireEdge e[2] = {{0, 1}, {2, 3}};
    RgbImage color(48, 48);
    FloatImage depth(48, 48);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{0, 0, 0});
    long pixels = 0;
    REQUIRE(draw_edges(cam, band, m.view(), e, 2, WireOptions{}, &pixels).ok());
    CHECK(pixels > 5);
    // The visible part runs from the lower right corner region towards the vanishing point
    // (the screen centre) and never above or left of it.
    Vec3 vanish = project(cam, {0.2f, -0.3f, -1e4f});
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x)
            if (color.at(x, y).r) {
                CHECK(x >= int(vanish.x) - 1);
                CHECK(y >= int(vanish.y) - 1);
            }
}

TEST_CASE("hidden lines: edges behind a surface are not drawn; bands == full frame") {
    Camera cam = perspective_camera({0.5f, 1.0f, 3.5f}, {0, 0, 0}, {0, 1, 0}, 40.0f, 72, 56);
    TriangleMesh sphere = sphere_mesh(1.0f, 16, 8);
    std::vector<WireEdge> edges = edges_of(sphere.view());
    auto fill_shader = [](const Fragment&) { return Rgb8{20, 20, 20}; };
    auto render = [&](const FrameBand& band, bool hidden, long* pixels) {
        clear_band(band, Rgb8{0, 0, 0});
        DrawOptions opt;
        CHECK(draw_mesh(cam, band, sphere.view(), opt, fill_shader).ok());
        WireOptions w;
        w.depth_test = hidden;
        CHECK(draw_edges(cam, band, sphere.view(), edges.data(), int(edges.size()), w, pixels)
                  .ok());
    };
    RgbImage all(72, 56), hidden(72, 56);
    FloatImage depth(72, 56);
    long n_all = 0, n_hidden = 0;
    render(full_frame_band(all.view(), depth.view()), false, &n_all);
    render(full_frame_band(hidden.view(), depth.view()), true, &n_hidden);
    // About half of a sphere's edges are on the back.
    CHECK(n_hidden < n_all * 3 / 4);
    CHECK(n_hidden > n_all / 4);

    // Bands of 5 rows stack into the hidden-line frame.
    RgbImage stacked(72, 56);
    RgbImage band_color(72, 5);
    FloatImage band_depth(72, 5);
    long n_bands = 0;
    for (int y0 = 0; y0 < 56; y0 += 5) {
        int h = std::min(5, 56 - y0);
        FrameBand band = make_band(band_color.view().subview(0, 0, 72, h),
                                   band_depth.view().subview(0, 0, 72, h), y0, 72, 56);
        render(band, true, &n_bands);
        for (int y = 0; y < h; ++y)
            std::memcpy(stacked.view().row(y0 + y), band.color.row(y), sizeof(Rgb8) * 72);
    }
    CHECK(std::memcmp(stacked.data(), hidden.data(), sizeof(Rgb8) * 72 * 56) == 0);
    CHECK(n_bands == n_hidden);
    // Edges meeting at a vertex may share its pixel; otherwise a pixel is drawn once.
    int lit = count_color(hidden, Rgb8{255, 255, 255});
    CHECK(lit <= n_hidden);
    CHECK(lit > n_hidden * 2 / 3);
}

TEST_CASE("view_distance inverts the window depth of both camera kinds") {
    Camera persp = perspective_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 50.0f, 64, 64, 0.1f, 50.0f);
    Camera ortho = orthographic_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 2.0f, 64, 64, 0.1f, 50.0f);
    for (float z : {4.5f, 2.0f, 0.0f, -7.0f, -30.0f}) {
        float d = 5.0f - z;  // distance along the view axis
        CHECK(view_distance(persp, project(persp, {0.3f, -0.2f, z}).z) ==
              doctest::Approx(d).epsilon(1e-3));
        CHECK(view_distance(ortho, project(ortho, {0.3f, -0.2f, z}).z) ==
              doctest::Approx(d).epsilon(1e-4));
    }
}
