// Tests for lib/shitsukan/render/solid_bake: a texel of the bake is the solid colour of the
// surface point behind it, uncovered texels are dilated from the chart, a slice pixel is the
// colour at its lattice point, progress is reported, bad input is refused.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/geom/mesh_fit.hpp"
#include "shitsukan/render/solid_bake.hpp"
#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"

using namespace shitsukan;

namespace {
void count_progress(float fraction, void* user) {
    auto* v = static_cast<std::vector<float>*>(user);
    v->push_back(fraction);
}
Rgb8 bytes(Vec3 c) {
    auto b = [](float v) { return std::uint8_t(v <= 0 ? 0 : v >= 255 ? 255 : int(v + 0.5f)); };
    return Rgb8{b(c.x), b(c.y), b(c.z)};
}
}  // namespace

TEST_CASE("bake_solid_texture: texels are the colour of the surface point behind them") {
    FractalLattice lattice;
    REQUIRE(lattice.build(okada1987_lattice_params()).ok());
    const SolidMaterial m = okada1987_marble();
    // A square in the plane y = 0.2 whose uv covers the left half of the map, u in [0, 0.5].
    TriangleMesh quad;
    quad.add_vertex({-1, 0.2f, -1}, {0, 1, 0}, {0, 0});
    quad.add_vertex({1, 0.2f, -1}, {0, 1, 0}, {0.5f, 0});
    quad.add_vertex({1, 0.2f, 1}, {0, 1, 0}, {0.5f, 1});
    quad.add_vertex({-1, 0.2f, 1}, {0, 1, 0}, {0, 1});
    quad.add_triangle(0, 1, 2);
    quad.add_triangle(0, 2, 3);
    const ObjectToLattice map = object_to_lattice_mapping(6);
    const int W = 64, H = 32;
    RgbImage tex;
    std::vector<float> seen;
    REQUIRE(bake_solid_texture(quad.view(), lattice.view(), m, map, W, H, tex, Rgb8{1, 2, 3}, 2,
                               Progress{count_progress, &seen})
                .ok());
    CHECK(tex.width() == W);
    int wrong = 0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W / 2; ++i) {
            const float u = (float(i) + 0.5f) / float(W), v = 1.0f - (float(j) + 0.5f) / float(H);
            const Vec3 object{-1.0f + 4.0f * u, 0.2f, -1.0f + 2.0f * v};
            const Rgb8 want = bytes(solid_color(m, lattice.view(), object_to_lattice(object, map)));
            const Rgb8 got = tex.at(i, j);
            wrong += std::abs(int(got.r) - int(want.r)) > 1 || std::abs(int(got.g) - int(want.g)) > 1;
        }
    CHECK(wrong == 0);
    // two rings of dilation, then the background
    CHECK(tex.at(W / 2, 5) == tex.at(W / 2 - 1, 5));
    CHECK(tex.at(W / 2 + 1, 5) == tex.at(W / 2 - 1, 5));
    CHECK(tex.at(W / 2 + 2, 5) == Rgb8{1, 2, 3});
    REQUIRE(!seen.empty());
    CHECK(seen.back() == 1.0f);
    for (std::size_t k = 1; k < seen.size(); ++k) CHECK(seen[k] >= seen[k - 1]);

    TriangleMesh no_uv = quad;
    no_uv.uvs.clear();
    Status s = bake_solid_texture(no_uv.view(), lattice.view(), m, map, W, H, tex);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(bake_solid_texture(quad.view(), lattice.view(), m, map, 0, H, tex).code() ==
          StatusCode::invalid_argument);
    CHECK(bake_solid_texture(quad.view(), LatticeView{}, m, map, W, H, tex).code() ==
          StatusCode::invalid_argument);
}

TEST_CASE("render_solid_slice: pixels are the colours at their lattice points; densities too") {
    FractalLattice lattice;
    REQUIRE(lattice.build(okada1987_lattice_params()).ok());
    const SolidMaterial m = okada1987_wood();
    SolidSlice slice;  // y = 32, x right, z up, 64 units
    RgbImage img;
    FloatImage g;
    REQUIRE(render_solid_slice(lattice.view(), m, slice, 32, 16, img, &g).ok());
    const int i = 7, j = 3;  // image row 3 from the top = v index 12 from the bottom
    const Vec3 p{(float(i) + 0.5f) * 2.0f, 32.0f, (float(16 - 1 - j) + 0.5f) * 4.0f};
    CHECK(g.at(i, j) == solid_density(m, lattice.view(), p));
    CHECK(img.at(i, j) == bytes(solid_color(m, lattice.view(), p)));
    slice.extent = 0.0f;
    CHECK(render_solid_slice(lattice.view(), m, slice, 32, 16, img).code() ==
          StatusCode::invalid_argument);
}

TEST_CASE("bake_solid_texture: a 16 px gutter leaves no empty texel near a uv sphere's islands") {
    TriangleMesh mesh;
    REQUIRE(make_uv_sphere(1.0f, 24, 12, mesh));
    REQUIRE(fit_mesh_to_cube(mesh, 0.92f));
    FractalLattice lattice;
    REQUIRE(lattice.build(okada1987_lattice_params()));
    const int size = 256;
    const Rgb8 magenta{255, 0, 255}, cyan{0, 255, 255};
    RgbImage a, b, gutter, old_default;
    const ObjectToLattice mapping = object_to_lattice_mapping(6);
    // covered texels: the same colour whatever the background, with no dilation
    REQUIRE(bake_solid_texture(mesh.view(), lattice.view(), okada1987_marble(), mapping, size,
                               size, a, magenta, 0));
    REQUIRE(bake_solid_texture(mesh.view(), lattice.view(), okada1987_marble(), mapping, size,
                               size, b, cyan, 0));
    REQUIRE(bake_solid_texture(mesh.view(), lattice.view(), okada1987_marble(), mapping, size,
                               size, gutter, magenta, 16));
    REQUIRE(bake_solid_texture(mesh.view(), lattice.view(), okada1987_marble(), mapping, size,
                               size, old_default, magenta, 4));
    std::vector<int> covered(std::size_t(size * size));
    for (int i = 0; i < size * size; ++i) covered[std::size_t(i)] = a.data()[i] == b.data()[i];
    int near = 0, empty_near = 0, empty_old = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            bool close = false;  // within 16 texels (square ring) of a covered one
            for (int dy = -16; dy <= 16 && !close; ++dy)
                for (int dx = -16; dx <= 16 && !close; ++dx) {
                    const int u = x + dx, v = y + dy;
                    close = u >= 0 && v >= 0 && u < size && v < size &&
                            covered[std::size_t(v * size + u)];
                }
            if (!close) continue;
            ++near;
            empty_near += gutter.at(x, y) == magenta;
            empty_old += old_default.at(x, y) == magenta;
        }
    MESSAGE(near << " texels within 16 px of an island; empty with a 4 px gutter: " << empty_old
                 << ", with 16 px: " << empty_near);
    CHECK(empty_near == 0);
    CHECK(empty_old > 0);  // the pole cells the old default left empty
}

TEST_CASE("bake_solid_texture: the densities G' as floats, the colours unchanged, no 8-bit steps") {
    TriangleMesh mesh;
    REQUIRE(make_uv_sphere(1.0f, 24, 12, mesh));
    REQUIRE(fit_mesh_to_cube(mesh, 0.92f));
    FractalLattice lattice;
    REQUIRE(lattice.build(okada1987_lattice_params()));
    const int size = 128;
    const Rgb8 magenta{255, 0, 255};
    const ObjectToLattice mapping = object_to_lattice_mapping(6);
    const SolidMaterial marble = okada1987_marble();
    RgbImage plain, with, bare;
    FloatImage density, bare_density;
    REQUIRE(bake_solid_texture(mesh.view(), lattice.view(), marble, mapping, size, size, plain,
                               magenta, 8));
    REQUIRE(bake_solid_texture(mesh.view(), lattice.view(), marble, mapping, size, size, with,
                               density, magenta, 8));
    REQUIRE(bake_solid_texture(mesh.view(), lattice.view(), marble, mapping, size, size, bare,
                               bare_density, magenta, 0));
    REQUIRE(density.width() == size);
    REQUIRE(density.height() == size);
    std::vector<float> levels;
    int covered = 0, colour_mismatch = 0, outside = 0, differs = 0;
    double sum = 0.0;
    for (int i = 0; i < size * size; ++i) {
        differs += !(plain.data()[i] == with.data()[i]);
        const float g = density.data()[i];
        outside += !(g >= 0.0f && g <= 1.0f);
        if (bare.data()[i] == magenta) continue;  // not under a triangle
        ++covered;
        sum += double(bare_density.data()[i]);
        // eq. (12) of the float density gives the texel's colour
        colour_mismatch += !(bytes(solid_density_color(marble, bare_density.data()[i])) ==
                             bare.data()[i]);
        levels.push_back(bare_density.data()[i]);
    }
    std::sort(levels.begin(), levels.end());
    const long distinct = long(std::unique(levels.begin(), levels.end()) - levels.begin());
    // beyond the rings: the covered texels' mean
    int mean_fill = 0, beyond = 0;
    const float mean = float(sum / double(covered));
    for (int i = 0; i < size * size; ++i)
        if (bare.data()[i] == magenta) ++beyond, mean_fill += bare_density.data()[i] == mean;
    MESSAGE(covered << " covered texels, " << distinct << " distinct densities (8-bit: <= 256)");
    CHECK(differs == 0);
    CHECK(outside == 0);
    CHECK(colour_mismatch == 0);
    CHECK(distinct > 1000);
    CHECK(beyond > 0);
    CHECK(mean_fill == beyond);
}
