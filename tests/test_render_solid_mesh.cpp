// Tests for the reusable pieces the figures now call: solid/object_mapping, solid_material,
// okada1987_presets, geom/mesh_fit, render/solid_mesh, and leather/maps' one-call maps and
// mirrored tiling, render/leather_mesh.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "shitsukan/shitsukan.hpp"

using namespace shitsukan;

namespace {

const FractalLattice& okada_lattice() {
    static FractalLattice lattice;
    if (lattice.empty()) REQUIRE(lattice.build(okada1987_lattice_params()).ok());
    return lattice;
}

TriangleMesh unit_torus() {
    TriangleMesh mesh;
    REQUIRE(make_torus(0.64f, 0.28f, 24, 12, mesh).ok());
    REQUIRE(fit_mesh_to_cube(mesh, 0.92f).ok());
    return mesh;
}

}  // namespace

TEST_CASE("object_to_lattice: [-1, 1]^3 (y up) fills [2, 62]^3 of the R = 6 lattice, z = up") {
    const ObjectToLattice m = object_to_lattice_mapping(6);
    CHECK(m.centre == 32.0f);
    CHECK(m.scale == 30.0f);
    const Vec3 lo = object_to_lattice(Vec3{-1, -1, 1}, m), hi = object_to_lattice({1, 1, -1}, m);
    CHECK(lo.x == 2.0f);
    CHECK(lo.y == 2.0f);
    CHECK(lo.z == 2.0f);  // object y (up) -> lattice z
    CHECK(hi.x == 62.0f);
    CHECK(hi.y == 62.0f);
    CHECK(hi.z == 62.0f);
    const ObjectToLattice m8 = object_to_lattice_mapping(8);  // 257^3: the same margins
    CHECK(object_to_lattice(Vec3{1, 1, 1}, m8).x == 256.0f * 31.0f / 32.0f);
}

TEST_CASE("fit_mesh_to_cube: centred, longest side 2·extent, proportions kept, errors") {
    TriangleMesh box;
    REQUIRE(make_box({1, 2, 3}, {5, 4, 4}, box).ok());  // 4 x 2 x 1
    REQUIRE(fit_mesh_to_cube(box, 0.5f).ok());
    Vec3 lo{1e9f, 1e9f, 1e9f}, hi{-1e9f, -1e9f, -1e9f};
    for (const Vec3& p : box.positions) lo = vmin(lo, p), hi = vmax(hi, p);
    CHECK(lo.x == doctest::Approx(-0.5f));
    CHECK(hi.x == doctest::Approx(0.5f));
    CHECK(hi.y - lo.y == doctest::Approx(0.5f));
    CHECK(hi.z - lo.z == doctest::Approx(0.25f));
    CHECK(lo.y + hi.y == doctest::Approx(0.0f));
    TriangleMesh empty;
    CHECK(fit_mesh_to_cube(empty).code() == StatusCode::degenerate);
    CHECK(fit_mesh_to_cube(box, 0.0f).code() == StatusCode::invalid_argument);
    CHECK(fit_mesh_to_cube(box, NAN).code() == StatusCode::invalid_argument);
}

TEST_CASE("okada1987 presets: the figures' values, and valid materials") {
    const FractalParams p = okada1987_lattice_params();
    CHECK(p.R == 6);
    CHECK(p.beta == 0.9f);
    CHECK(p.seed == 1987u);
    const SolidMaterial marble = okada1987_marble(), wood = okada1987_wood();
    const SolidMaterial single = okada1989_marble();
    CHECK(validate_solid_material(marble).ok());
    CHECK(validate_solid_material(wood).ok());
    CHECK(validate_solid_material(single).ok());
    CHECK(marble.marble.count == 6);
    CHECK(marble.marble.k == 16.0f);
    CHECK(single.marble.count == 1);
    CHECK(single.marble.stripes[0].c == 32.0f);
    CHECK(wood.wood.k == 1.6f);
    CHECK(wood.wood.k2 == 1.2f);
    SolidMaterial bad = marble;
    const MarbleStripe flat{10.0f, 0.0f, 1.0f};  // w must be > 0
    bad.marble = MarbleParams{&flat, 1, 16.0f};
    CHECK_FALSE(validate_solid_material(bad).ok());
    bad = wood;
    bad.i_max.y = NAN;
    CHECK_FALSE(validate_solid_material(bad).ok());
}

TEST_CASE("solid_density with k = 0: layers of impurity at G' = 0, rings of (sin(k2 r) + 1)/2") {
    const LatticeView v = okada_lattice().view();
    const SolidMaterial marble = okada1987_marble(0.0f);
    for (int j = 0; j < kOkada1987StripeCount; ++j) {
        const float c = kOkada1987Stripes[j].c;
        CHECK(solid_density(marble, v, Vec3{20.0f, 30.0f, c}) == 0.0f);  // inside a layer
        const Vec3 colour = solid_color(marble, v, Vec3{20.0f, 30.0f, c});
        CHECK(colour.x == kOkada1987Impurity.x);
    }
    // Halfway between the fourth and fifth stripes (35, 3.5 wide and 46): mostly limestone.
    CHECK(solid_density(marble, v, Vec3{20.0f, 30.0f, 40.5f}) > 0.5f);
    const SolidMaterial wood = okada1987_wood(0.0f);
    for (float r : {1.0f, 2.5f, 7.0f}) {
        const Vec3 p{kOkada1987WoodAxis.x + r, kOkada1987WoodAxis.y, 20.0f};
        CHECK(solid_density(wood, v, p) ==
              doctest::Approx((std::sin(kOkada1987WoodK2 * r) + 1.0f) / 2.0f).epsilon(1e-5));
    }
}

TEST_CASE("render_solid_texture: one call equals drawing band by band; colours in range") {
    const TriangleMesh mesh = unit_torus();
    const Camera cam = perspective_camera({1.6f, 2.5f, 2.8f}, {0, 0, 0}, {0, 1, 0}, 30.0f, 96, 80);
    const SolidMaterial marble = okada1987_marble();
    const Rgb8 bg{24, 26, 32};
    RgbImage one;
    REQUIRE(render_solid_texture(cam, mesh.view(), okada_lattice().view(), marble, one).ok());
    REQUIRE(one.width() == 96);
    REQUIRE(one.height() == 80);

    // The same frame in bands of 16 rows through draw_solid_textured_mesh.
    RgbImage bands(96, 80);
    for (int y0 = 0; y0 < 80; y0 += 16) {
        RgbImage c(96, 16);
        FloatImage d(96, 16);
        const FrameBand band = make_band(c.view(), d.view(), y0, 96, 80);
        clear_band(band, bg);
        REQUIRE(draw_solid_textured_mesh(cam, band, mesh.view(), DrawOptions{},
                                         okada_lattice().view(), marble)
                    .ok());
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 96; ++x) bands.at(x, y0 + y) = c.at(x, y);
    }
    int covered = 0, differ = 0, out_of_range = 0;
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 96; ++x) {
            const Rgb8 a = one.at(x, y), b = bands.at(x, y);
            differ += a.r != b.r || a.g != b.g || a.b != b.b;
            if (a.r == bg.r && a.g == bg.g && a.b == bg.b) continue;
            ++covered;
            // Lit colour = eq. (12) colour x (0.3 .. 1.0): never brighter than the limestone.
            out_of_range += a.r > 238 || a.g > 234 || a.b > 226;
        }
    CHECK(differ == 0);
    CHECK(covered > 96 * 80 / 5);
    CHECK(out_of_range == 0);
}

TEST_CASE("render_solid_texture refuses an unbuilt lattice and a bad material with a message") {
    const TriangleMesh mesh = unit_torus();
    const Camera cam = perspective_camera({1.6f, 2.5f, 2.8f}, {0, 0, 0}, {0, 1, 0}, 30.0f, 32, 32);
    RgbImage img;
    Status s = render_solid_texture(cam, mesh.view(), LatticeView{}, okada1987_marble(), img);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("lattice") != std::string::npos);
    SolidMaterial bad = okada1987_wood();
    bad.wood.k2 = -1.0f;
    s = render_solid_texture(cam, mesh.view(), okada_lattice().view(), bad, img);
    CHECK_FALSE(s.ok());
}

TEST_CASE("leather maps in one call; mirrored tiling is continuous and 2W-periodic") {
    ScaleParams prm;  // the fig. 7 crocodile pattern
    ScalePattern pattern;
    REQUIRE(generate_scale_pattern(prm, pattern).ok());
    LeatherMaps maps;
    REQUIRE(make_leather_maps(pattern, 96, 96, table1_section(Table1Section::convex),
                              ReliefOptions{}, maps)
                .ok());
    CHECK(maps.max_height > 0.0f);
    CHECK(make_leather_maps(pattern, 0, 96, table1_section(Table1Section::convex), ReliefOptions{},
                            maps)
              .code() == StatusCode::invalid_argument);
    REQUIRE(make_leather_maps(pattern, 96, 96, table1_section(Table1Section::convex),
                              ReliefOptions{}, maps)
                .ok());
    const float W = maps.pattern_width, H = maps.pattern_height;
    int bad = 0;
    for (int i = 0; i < 20; ++i) {
        const Vec2 t{W * (0.05f + 0.045f * float(i)), H * (0.97f - 0.04f * float(i))};
        // Inside the pattern the tiling is the map itself.
        const Vec3 n = mirrored_normal_at(maps, t), n0 = normal_at(maps, t);
        bad += n.x != n0.x || n.y != n0.y || n.z != n0.z;
        // Period 2W in x, 2H in y.
        bad += std::fabs(mirrored_height_at(maps, t + Vec2{2 * W, -2 * H}) - height_at(maps, t)) >
               1e-5f * maps.max_height + 1e-7f;
        // The mirror image across x = W: same height, normal x negated.
        const Vec2 m{2 * W - t.x, t.y};
        bad += std::fabs(mirrored_height_at(maps, m) - height_at(maps, t)) >
               1e-4f * maps.max_height + 1e-7f;
        bad += std::fabs(mirrored_normal_at(maps, m).x + n0.x) > 1e-4f;
    }
    CHECK(bad == 0);
}

TEST_CASE("render/leather_mesh: bumps change the shading, gamma, tangents must match the mesh") {
    CHECK(to_display_gamma(Vec3{0.0f, 1.0f, 2.0f}).r == 0);
    CHECK(to_display_gamma(Vec3{0.0f, 1.0f, 2.0f}).g == 255);
    CHECK(to_display_gamma(Vec3{0.0f, 1.0f, 2.0f}).b == 255);  // clamped
    CHECK(int(to_display_gamma(Vec3{0.5f, 0.5f, 0.5f}).r) == 186);  // 255·0.5^(1/2.2)

    ScalePattern pattern;
    REQUIRE(generate_scale_pattern(ScaleParams{}, pattern).ok());
    LeatherMaps maps;
    REQUIRE(make_leather_maps(pattern, 128, 128, table1_section(Table1Section::convex),
                              ReliefOptions{}, maps)
                .ok());
    TriangleMesh box;
    REQUIRE(make_box({-0.8f, -0.8f, -0.8f}, {0.8f, 0.8f, 0.8f}, box).ok());
    TextureTangents tangents;
    REQUIRE(compute_texture_tangents(box.view(), tangents).ok());
    const Camera cam = perspective_camera({2.5f, 2.0f, 3.0f}, {0, 0, 0}, {0, 1, 0}, 35.0f, 64, 64);

    auto render = [&](bool bumps, RgbImage* img) {
        img->resize(64, 64);
        FloatImage depth(64, 64);
        const FrameBand band = full_frame_band(img->view(), depth.view());
        clear_band(band, Rgb8{0, 0, 0});
        if (bumps)
            return draw_leather_mesh(cam, band, box.view(), DrawOptions{}, maps, tangents);
        LeatherShader flat;  // no maps: the same material unbumped
        flat.eye = cam.eye;
        return draw_mesh(cam, band, box.view(), DrawOptions{}, flat);
    };
    RgbImage bumped, flat;
    REQUIRE(render(true, &bumped).ok());
    REQUIRE(render(false, &flat).ok());
    int covered = 0, differ = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Rgb8 a = bumped.at(x, y), b = flat.at(x, y);
            if (b.r == 0 && b.g == 0 && b.b == 0) continue;
            ++covered;
            differ += a.r != b.r || a.g != b.g || a.b != b.b;
        }
    CHECK(covered > 64 * 64 / 4);
    CHECK(differ > covered / 3);  // the scales' slopes show on most pixels

    TriangleMesh other;
    REQUIRE(make_torus(0.6f, 0.2f, 8, 6, other).ok());
    RgbImage img(64, 64);
    FloatImage depth(64, 64);
    const FrameBand band = full_frame_band(img.view(), depth.view());
    const Status s = draw_leather_mesh(cam, band, other.view(), DrawOptions{}, maps, tangents);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("compute_texture_tangents") != std::string::npos);
}
