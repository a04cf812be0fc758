// Tests for lib/shitsukan/raster/rasterizer.cpp: coverage. The top-left fill rule must give
// every pixel of a tiling to exactly one triangle (shared edges, shared vertices, fans, edges
// through pixel centres), and a closed mesh must have no cracks from any direction.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "raster_test_scenes.hpp"
#include "shitsukan/geom/mesh_builders.hpp"

using namespace shitsukan;
using namespace raster_test;

namespace {

// A grid of cells over [-s, s]^2 in the plane z = 0 (wider than the screen), interior
// vertices moved by a deterministic jitter that puts a third of them exactly on pixel
// centres and a third exactly on pixel corners (the cases a fill rule must decide). Every
// third cell is a fan of four triangles around a centre vertex, the others two triangles
// with alternating diagonals. Counter-clockwise seen from +z.
TriangleMesh tiling_grid(int cells, float s, float pixel, std::uint64_t seed) {
    TriangleMesh m;
    Pcg32 rng(seed, 3u);
    auto snap = [&](float v) {
        int kind = int(rng.next_u32() % 3u);
        if (kind == 0) return (std::floor(v / pixel) + 0.5f) * pixel;  // a pixel centre
        if (kind == 1) return std::floor(v / pixel) * pixel;           // a pixel corner
        return v + (rng.uniform() - 0.5f) * pixel;                     // anywhere
    };
    float step = 2.0f * s / float(cells);
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            float x = -s + step * float(i), y = -s + step * float(j);
            if (i > 0 && i < cells && j > 0 && j < cells) {
                x = snap(x + (rng.uniform() - 0.5f) * 0.4f * step);
                y = snap(y + (rng.uniform() - 0.5f) * 0.4f * step);
            }
            m.add_vertex({x, y, 0}, {0, 0, 1});
        }
    auto id = [&](int i, int j) { return std::uint32_t(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            std::uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if ((i + j) % 3 == 0) {  // a fan around the cell's centre
                Vec3 centre = (m.positions[a] + m.positions[b] + m.positions[c] +
                               m.positions[d]) * 0.25f;
                std::uint32_t e = m.add_vertex({snap(centre.x), snap(centre.y), 0}, {0, 0, 1});
                m.add_triangle(a, b, e);
                m.add_triangle(b, c, e);
                m.add_triangle(c, d, e);
                m.add_triangle(d, a, e);
            } else if ((i + j) % 2 == 0) {
                m.add_triangle(a, b, c);
                m.add_triangle(a, c, d);
            } else {
                m.add_triangle(a, b, d);
                m.add_triangle(b, c, d);
            }
        }
    return m;
}

// Fibonacci points on the unit sphere: well-spread view directions.
Vec3 direction(int i, int n) {
    float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(n);
    float r = std::sqrt(1.0f - y * y);
    float phi = float(i) * 2.39996323f;  // the golden angle
    return {r * std::cos(phi), y, r * std::sin(phi)};
}

int count_not_one(Counts& c) {
    int bad = 0;
    for (int v : c.n) bad += v != 1;
    return bad;
}

}  // namespace

TEST_CASE("a grid of triangles tiling the screen covers every pixel exactly once (ortho)") {
    // 64 x 64 pixels over [-1, 1]^2: one pixel is 1/32 world unit.
    Camera cam = orthographic_camera({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 1.0f, 64, 64);
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        TriangleMesh grid = tiling_grid(9, 1.3f, 1.0f / 32.0f, seed);
        Counts c = coverage_per_triangle(cam, grid.view(), CullMode::back);
        CHECK(count_not_one(c) == 0);
        Counts none = coverage_per_triangle(cam, grid.view(), CullMode::none);
        CHECK(none.n == c.n);
        Counts front = coverage_per_triangle(cam, grid.view(), CullMode::front);
        int written = 0;
        for (int v : front.n) written += v;
        CHECK(written == 0);  // seen from +z, every triangle is front-facing
    }
}

TEST_CASE("a grid of triangles tiling the screen covers every pixel exactly once (perspective)") {
    Camera cam = perspective_camera({0.3f, -0.4f, 1.6f}, {0.1f, 0.1f, 0}, {0, 1, 0}, 50.0f, 80, 60);
    for (std::uint64_t seed = 5; seed <= 7; ++seed) {
        TriangleMesh grid = tiling_grid(16, 3.0f, 0.01f, seed);
        Counts c = coverage_per_triangle(cam, grid.view(), CullMode::back);
        CHECK(count_not_one(c) == 0);
    }
}

TEST_CASE("a tiling clipped by the near plane and the guard band still covers once") {
    // A jittered grid laid on the floor y = 0, reaching far behind the eye (z up to +20) and
    // far to the sides: many triangles cross the near plane or the guard band, and their
    // cut points must match along shared edges.
    // The eye 0.02 above the floor, closer than the near plane (0.05): the near plane cuts
    // the floor inside the view, at the bottom of the picture.
    Camera cam = perspective_camera({0, 0.02f, 0}, {0.2f, -0.15f, -1}, {0, 1, 0}, 70.0f, 72, 54);
    Mat4 lay_flat = Mat4::rotate_x(-kPi / 2);  // (x, y, 0) -> (x, 0, -y)
    for (std::uint64_t seed = 11; seed <= 12; ++seed) {
        TriangleMesh grid = tiling_grid(24, 20.0f, 0.01f, seed);
        Counts c = coverage_per_triangle(cam, grid.view(), CullMode::back, lay_flat);
        // Down a column: sky, the floor, then (below the near plane's cut line) nothing
        // again. The floor must be one unbroken run: a crack would split it.
        int twice = 0, holes = 0, covered = 0, bottom_empty = 0;
        for (int x = 0; x < c.width; ++x) {
            int runs = 0;
            for (int y = 0; y < c.height; ++y) {
                int n = c.at(x, y);
                twice += n > 1;
                covered += n > 0;
                if (n > 0 && (y == 0 || c.at(x, y - 1) == 0)) ++runs;
            }
            holes += runs > 1;
            bottom_empty += c.at(x, c.height - 1) == 0;
        }
        RgbImage color(72, 54);
        FloatImage depth(72, 54);
        RasterStats stats;
        DrawOptions opt;
        opt.model = lay_flat;
        auto any = [](const Fragment&) { return Rgb8{1, 1, 1}; };
        clear_band(full_frame_band(color.view(), depth.view()), Rgb8{});
        REQUIRE(draw_mesh(cam, full_frame_band(color.view(), depth.view()), grid.view(), opt, any,
                          &stats).ok());
        CHECK(stats.triangles_clipped >= 2);
        CHECK(twice == 0);
        CHECK(holes == 0);
        CHECK(covered > 72 * 54 / 4);
        CHECK(bottom_empty == 72);  // the part of the floor nearer than the near plane is cut
    }
}

TEST_CASE("a closed mesh seen from many directions: no cracks, front layer written once") {
    TriangleMesh meshes[3] = {box_mesh({-0.8f, -0.6f, -0.7f}, {0.7f, 0.9f, 0.5f}),
                              sphere_mesh(1.0f, 20, 10), torus_mesh(0.9f, 0.4f, 24, 12)};
    const bool convex[3] = {true, true, false};
    const int kDirections = 12;
    for (int m = 0; m < 3; ++m) {
        MeshView mesh = meshes[m].view();
        int mismatched = 0, layered = 0, shaded_not_front = 0;
        long covered = 0;
        for (int d = 0; d < kDirections; ++d) {
            Vec3 eye = direction(d, kDirections) * 3.5f;
            Camera cam = perspective_camera(eye, {0.05f, 0.02f, 0}, {0, 1, 0}, 45.0f, 64, 64);
            Counts front = coverage_per_triangle(cam, mesh, CullMode::back);
            Counts back = coverage_per_triangle(cam, mesh, CullMode::front);
            // Every ray that enters a closed surface leaves it: as many front-facing as
            // back-facing triangles cover each pixel. A crack breaks the balance.
            for (std::size_t i = 0; i < front.n.size(); ++i) {
                mismatched += front.n[i] != back.n[i];
                if (convex[m]) layered += front.n[i] > 1;
                covered += front.n[i] > 0;
            }
            if (convex[m]) {
                // One draw call with early z: the shader runs exactly once per covered pixel.
                Counts shaded(64, 64);
                RgbImage color(64, 64);
                FloatImage depth(64, 64);
                FrameBand band = full_frame_band(color.view(), depth.view());
                clear_band(band, Rgb8{0, 0, 0});
                auto count = [&](const Fragment& f) {
                    ++shaded.at(f.x, f.y);
                    return Rgb8{1, 1, 1};
                };
                DrawOptions opt;
                REQUIRE(draw_mesh(cam, band, mesh, opt, count).ok());
                for (std::size_t i = 0; i < front.n.size(); ++i)
                    shaded_not_front += shaded.n[i] != front.n[i];
            }
        }
        INFO("mesh " << m);
        CHECK(mismatched == 0);
        CHECK(layered == 0);
        CHECK(shaded_not_front == 0);
        CHECK(covered > 64 * 64);  // the object is actually on screen
    }
}

TEST_CASE("the mesh builders' closed solids have no cracks from any direction") {
    TriangleMesh meshes[4];
    REQUIRE(make_uv_sphere(1.0f, 24, 12, meshes[0]).ok());
    REQUIRE(make_torus(0.9f, 0.35f, 24, 12, meshes[1]).ok());
    REQUIRE(make_cylinder(0.6f, -0.8f, 0.9f, 20, true, meshes[2]).ok());
    REQUIRE(make_sphere_without_octant(1.0f, 8, meshes[3]).ok());
    const int kDirections = 8;
    for (int m = 0; m < 4; ++m) {
        int mismatched = 0;
        long covered = 0;
        for (int d = 0; d < kDirections; ++d) {
            Vec3 eye = direction(d + 3, kDirections + 6) * 3.5f;
            Camera cam = perspective_camera(eye, {0.03f, 0.01f, 0}, {0, 1, 0}, 45.0f, 56, 56);
            Counts front = coverage_per_triangle(cam, meshes[m].view(), CullMode::back);
            Counts back = coverage_per_triangle(cam, meshes[m].view(), CullMode::front);
            for (std::size_t i = 0; i < front.n.size(); ++i) {
                mismatched += front.n[i] != back.n[i];
                covered += front.n[i] > 0;
            }
        }
        INFO("builder mesh " << m);
        CHECK(mismatched == 0);
        CHECK(covered > 56 * 56);
    }
}

TEST_CASE("a non-convex closed mesh (torus): early z keeps the nearest fragment per pixel") {
    // For a convex mesh each pixel's front layer is shaded exactly once (test above). A torus
    // has pixels with two front-facing layers, so what holds in general is checked instead,
    // against every triangle drawn on its own (a fragment's depth depends only on the pixel
    // and the triangle, so the single draw must reproduce those very bits):
    //   - per pixel, the shaded fragments of the single draw come in strictly decreasing
    //     depth (early z: a fragment is shaded only when nearer than all before it), each is
    //     one of that pixel's per-triangle fragments, and the last one is the nearest of
    //     them: final depth == min depth, final colour from a triangle reaching it;
    //   - a pixel is shaded at least once iff a front-facing triangle covers it, and at most
    //     as many times as front-facing triangles cover it.
    TriangleMesh torus = torus_mesh(0.9f, 0.4f, 24, 12);
    const MeshView mesh = torus.view();
    const int N = 64;
    const Vec3 eyes[3] = {{0.3f, 1.4f, 3.2f}, {-2.5f, 0.9f, 2.0f}, {0.2f, 3.3f, 0.6f}};
    long layered = 0, multiply_shaded = 0, covered = 0;
    int wrong_order = 0, unknown_fragment = 0, not_nearest = 0, wrong_count = 0;
    for (const Vec3& eye : eyes) {
        Camera cam = perspective_camera(eye, {0.05f, 0.02f, 0}, {0, 1, 0}, 45.0f, N, N);
        // Every triangle on its own (back faces culled, as below): (triangle, depth) per pixel.
        std::vector<std::vector<std::pair<int, float>>> alone(std::size_t(N * N));
        {
            RgbImage color(N, N);
            FloatImage depth(N, N, INFINITY);
            FrameBand band = full_frame_band(color.view(), depth.view());
            std::vector<int> touched;
            int current = 0;  // f.triangle counts within `one` below: always 0
            auto record = [&](const Fragment& f) {
                alone[std::size_t(f.y * N + f.x)].push_back({current, f.depth});
                touched.push_back(f.y * N + f.x);
                return Rgb8{1, 1, 1};
            };
            for (int t = 0; t < mesh.triangle_count; ++t) {
                MeshView one = mesh;
                one.indices = mesh.indices + 3 * t;
                one.triangle_count = 1;
                current = t;
                Status s = draw_mesh(cam, band, one, DrawOptions{}, record);
                REQUIRE(s.ok());
                for (int i : touched) depth.data()[i] = INFINITY;
                touched.clear();
            }
        }
        // The same triangles in one draw call.
        std::vector<std::vector<std::pair<int, float>>> shaded(std::size_t(N * N));
        RgbImage color(N, N);
        FloatImage depth(N, N);
        FrameBand band = full_frame_band(color.view(), depth.view());
        clear_band(band, Rgb8{0, 0, 0});
        auto record = [&](const Fragment& f) {
            shaded[std::size_t(f.y * N + f.x)].push_back({f.triangle, f.depth});
            return Rgb8{1, 1, 1};
        };
        REQUIRE(draw_mesh(cam, band, mesh, DrawOptions{}, record).ok());
        for (int i = 0; i < N * N; ++i) {
            const auto& a = alone[std::size_t(i)];
            const auto& s = shaded[std::size_t(i)];
            layered += a.size() > 1;
            multiply_shaded += s.size() > 1;
            covered += !a.empty();
            wrong_count += s.empty() != a.empty() || s.size() > a.size();
            for (std::size_t k = 1; k < s.size(); ++k)
                wrong_order += !(s[k].second < s[k - 1].second);
            if (s.empty()) continue;
            float nearest = INFINITY;
            for (const auto& p : a) nearest = std::min(nearest, p.second);
            not_nearest += s.back().second != nearest || depth.data()[i] != nearest;
            for (const auto& p : s) {
                bool found = false;
                for (const auto& q : a)
                    found = found || (q.first == p.first && q.second == p.second);
                unknown_fragment += !found;
            }
        }
    }
    CHECK(covered > N * N);          // the torus is on screen in every view
    CHECK(layered > 100);            // and has pixels with two front-facing layers
    CHECK(multiply_shaded > 0);      // where early z cannot avoid a second shading
    CHECK(wrong_count == 0);
    CHECK(wrong_order == 0);
    CHECK(not_nearest == 0);
    CHECK(unknown_fragment == 0);
}
