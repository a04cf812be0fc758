// paper_figures/okada1987/okada_common.cpp — the shared lattice, choices, scenes and shader.
#include "okada1987/okada_common.hpp"

#include <chrono>
#include <cmath>
#include <mutex>

#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/geom/mesh_fit.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/render/solid_mesh.hpp"

namespace shitsukan::okada {

using figures::fmt;

namespace {
double g_build_seconds = 0.0;
}  // namespace

SolidMaterial solid_material(Material m, float k) {
    if (m == Material::marble) return okada1987_marble(k);
    if (m == Material::marble_single) return okada1989_marble(k);
    return okada1987_wood(k);
}

const FractalLattice& shared_lattice() {
    // Built once, under std::call_once: figures run in parallel (the driver's --jobs).
    static FractalLattice lattice;
    static std::once_flag built;
    std::call_once(built, [] {
        const FractalParams p = okada1987_lattice_params();
        auto t0 = std::chrono::steady_clock::now();
        Status s = lattice.build(p);
        g_build_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        SHITSUKAN_ASSERT(s.ok());  // fixed, valid parameters: a failure is a bug
    });
    return lattice;
}

double shared_lattice_build_seconds() {
    (void)shared_lattice();
    return g_build_seconds;
}

void record_lattice(figures::FigureContext& ctx) {
    ctx.given("lattice", "65^3 (R = 6), one lattice for every figure",
              "okada1987 §4.4, okada1989 §4-4");
    ctx.given("noise g", "N(0, 1), amplitude exp(-(n-1)·beta)", "okada1987 eqs. (1)-(5)");
    ctx.given("lattice type", "Type I (the whole 65^3 array in memory)", "okada1989 §4-4");
    ctx.chosen("beta", fmt("%g (the library's default)", double(kBeta)),
               "not printed; finest level at e^-4.5 = 1 % of the first: smooth folds at k = 16 "
               "(0.5 broke the k = 16 marble into fine noise)");
    ctx.chosen("eq. (2) reading", "L^(n) = e^-(n-1)·beta, so L^(1) = 1 (as eq. (5))",
               "eq. (2) also reads L^(n) = L^(n-1)·e^-beta from L^(0) = 1, i.e. L^(1) = e^-beta: "
               "that reading scales D by e^-beta = 0.41, so its k = 16 is k = 6.5 here");
    ctx.chosen("seed", fmt("%u (coordinate hash, Types I/II/III agree)", kSeed),
               "any seed; hash noise so okada1989's three types give the same lattice");
    ctx.chosen("corner values", "0 (all eight)", "not given; D then has mean 0 everywhere");
    ctx.chosen("object -> lattice", "(32 + 30x, 32 - 30z, 32 + 30y), object in [-1, 1]^3, y up",
               "objects fill [2, 62]^3 of the lattice; texture z = object up");
    ctx.chosen("texture units", "one lattice spacing: P, c_j, w_j, r and the shift k·D(P)",
               "the paper does not say in which unit k applies; in lattice units k = 16 folds "
               "the layers and k = 1.6 bends rings 5.2 units apart");
}

void record_material(figures::FigureContext& ctx, Material m, float k) {
    if (m == Material::marble_single)
        ctx.given("k", fmt("%g", double(k)), "okada1989 §4-4 (marble 16)");
    else if (m == Material::marble)
        ctx.given("k", fmt("%g", double(k)), "okada1987 §4.4 (marble 16; fig. 12a 0..30)");
    else
        ctx.given("k", fmt("%g", double(k)), "okada1987 §4.4 (wood 1.6; fig. 12b 0..6)");
    record_material(ctx, m);
}

void record_material(figures::FigureContext& ctx, Material m) {
    if (m == Material::marble_single) {
        ctx.given("G", "one layer: trapezoid with exponential skirts, u = (0, 0, 1)",
                  "okada1989 eqs. (8), (9)");
        ctx.chosen(
            "layers (lattice units)",
            fmt("the one layer of eq. (8), w %g, alpha %g, repeated every %g along z "
                "(c = %g + %g j)",
                double(kSingleStripe.w), double(kSingleStripe.alpha), double(kSingleLayerPeriod),
                double(kSingleStripe.c), double(kSingleLayerPeriod)),
            "eq. (8) is 'the function representing one layer' of 'layered, striped "
            "marble' (§4-2); a single layer through the middle (c 32, w 3, alpha 0.5) "
            "covered 4-12 % of each object: one crack in a white object");
        ctx.chosen("G'", "1 - min(G, 1)", "as okada1987: I_max = limestone, I_min = impurity");
        ctx.chosen("I_max (limestone)", "(238, 234, 226)", "warm white");
        ctx.chosen("I_min (impurity)", "(62, 74, 80)", "dark grey-green");
    } else if (m == Material::marble) {
        ctx.given("G", "sum of trapezoids with exponential skirts, u = (0, 0, 1)",
                  "okada1987 eqs. (8), (9)");
        std::string s;
        for (int j = 0; j < kStripeCount; ++j)
            s += fmt("%s(c %g, w %g, alpha %g)", j ? ", " : "", double(kStripes[j].c),
                     double(kStripes[j].w), double(kStripes[j].alpha));
        ctx.chosen("stripes (lattice units)", s, "not given; uneven layers, sharp and soft skirts");
        ctx.chosen("G'", "1 - min(G, 1)",
                   "eq. (12): I_max = limestone, I_min = impurity, and G = 1 inside a layer");
        ctx.chosen("I_max (limestone)", "(238, 234, 226)", "warm white");
        ctx.chosen("I_min (impurity)", "(62, 74, 80)", "dark grey-green veins");
    } else {
        ctx.given("G", "sin(k2·r), radial u (eq. 11)", "okada1987 eqs. (10), (11)");
        ctx.chosen("k2", fmt("%g (rings every %.1f lattice units)", double(kWoodK2),
                             2.0 * 3.14159265 / double(kWoodK2)),
                   "not given; about 10 rings across an object");
        ctx.chosen("axis (x0, y0)",
                   fmt("(%g, %g) lattice", double(kWoodAxis.x), double(kWoodAxis.y)),
                   "off the objects' centre, as a board cut beside the pith");
        ctx.chosen("G'", "(sin + 1)/2", "sin lies in [-1, 1], eq. (12) needs [0, 1]; linear map");
        ctx.chosen("r = 0", "u = 0 (no shift)", "radial direction undefined on the axis");
        ctx.chosen("I_max (winter wood)", "(128, 72, 34)", "dark late wood");
        ctx.chosen("I_min (summer wood)", "(226, 184, 128)", "light early wood");
    }
    ctx.chosen("shading", "colour·(0.3 + 0.7·max(0, n·l)), l = (0.3, 0.8, 0.55) normalised",
               "the paper does not describe its shading");
}

void record_camera(figures::FigureContext& ctx, const std::string& description) {
    ctx.chosen("camera", description, "not given; three faces / the cut visible");
}

float density(Material m, float k, Vec3 lp) {
    return solid_density(solid_material(m, k), shared_lattice().view(), lp);  // eqs. (6)-(11)
}

Vec3 material_color(Material m, float g) {
    return solid_density_color(solid_material(m, 0.0f), g);  // eq. (12)
}

void add_piece(Scene* scene, const TriangleMesh& mesh, const Mat4& model) {
    Piece p;
    p.mesh = mesh;
    p.model = model;
    scene->pieces.push_back(std::move(p));
}

namespace {

// The library's shader (render/solid_mesh.hpp), counting the density shares the notes report.
struct SolidShader {
    SolidTextureShader inner;
    DensityShares* shares;  // counted when not null
    Rgb8 operator()(const Fragment& f) const {
        if (shares) {
            const Vec3 lp = shitsukan::object_to_lattice(f.object_position, inner.shading.mapping);
            const float g = solid_density(inner.material, inner.lattice, lp);
            ++shares->pixels;
            if (g < 0.5f)
                ++shares->vein;
            else if (g < 0.9f)
                ++shares->skirt;
        }
        return inner(f);
    }
};

// A Catmull-Rom profile (r, y) through the control points, in double (okada1987 §4.4: the
// spline is the one computation in 8-byte reals).
Status spline_profile(const Vec2d* control, int count, int samples, std::vector<Vec2d>* out) {
    return sample_spline(control, count, samples, *out);
}

}  // namespace

Status render_scene(const Scene& scene, Material m, float k, int size, RgbImage* out,
                    DensityShares* shares) {
    out->resize(size, size, kBackground);
    FloatImage depth(size, size);
    const FrameBand band = full_frame_band(out->view(), depth.view());
    clear_band(band, kBackground);
    const Camera camera = perspective_camera(scene.eye, scene.target, Vec3{0, 1, 0},
                                             scene.fov_degrees, size, size);
    SolidShader shader{SolidTextureShader{shared_lattice().view(), solid_material(m, k), SolidShading{}},
                       shares};
    for (const Piece& piece : scene.pieces) {
        DrawOptions opt;
        opt.model = piece.model;
        opt.cull = CullMode::back;
        SHITSUKAN_TRY(draw_mesh(camera, band, piece.mesh.view(), opt, shader));
    }
    return Status::success();
}

std::string scene_camera_text(const Scene& s) {
    return fmt("perspective, eye (%g, %g, %g), target (%g, %g, %g), fov %g deg", double(s.eye.x),
               double(s.eye.y), double(s.eye.z), double(s.target.x), double(s.target.y),
               double(s.target.z), double(s.fov_degrees));
}

Status build_scene(const std::string& name, bool quick, Scene* out) {
    *out = Scene();
    const int seg = quick ? 32 : 96;  // revolution / sphere resolution
    TriangleMesh mesh;
    if (name == "cube") {
        SHITSUKAN_TRY(make_box({-0.9f, -0.9f, -0.9f}, {0.9f, 0.9f, 0.9f}, mesh));
        add_piece(out, mesh);
        out->eye = {3.6f, 3.0f, 4.6f};
    } else if (name == "slices") {
        // The cube cut into five slabs across x, spread apart: each slab keeps its object
        // coordinates (the texture) and is only moved by its model matrix.
        const float x0 = -0.9f, thickness = 0.3f, pitch = 0.375f, spread = 0.32f;
        for (int i = 0; i < 5; ++i) {
            float a = x0 + pitch * float(i);
            SHITSUKAN_TRY(make_box({a, -0.9f, -0.9f}, {a + thickness, 0.9f, 0.9f}, mesh));
            add_piece(out, mesh, Mat4::translate({spread * (float(i) - 2.0f), 0.0f, 0.0f}));
        }
        out->eye = {5.2f, 3.2f, 5.2f};
    } else if (name == "cut_sphere") {
        SHITSUKAN_TRY(make_sphere_without_octant(0.9f, quick ? 12 : 40, mesh));
        add_piece(out, mesh);
        out->eye = {2.7f, 2.3f, 3.1f};
    } else if (name == "pot") {
        const Vec2d control[] = {{0.0, -1.0},  {0.50, -1.0}, {0.78, -0.7}, {0.92, -0.25},
                                 {0.80, 0.20}, {0.50, 0.55}, {0.40, 0.80}, {0.50, 1.0}};
        std::vector<Vec2d> profile;
        SHITSUKAN_TRY(spline_profile(control, 8, quick ? 6 : 16, &profile));
        // The lip and the inside: step in by the wall thickness and go down into the pot.
        profile.push_back({0.42, 1.0});
        profile.push_back({0.32, 0.80});
        profile.push_back({0.40, 0.55});
        profile.push_back({0.0, 0.45});
        SHITSUKAN_TRY(make_revolution(profile.data(), int(profile.size()), seg, mesh));
        SHITSUKAN_TRY(fit_mesh_to_cube(mesh, 0.92f));
        add_piece(out, mesh);
        out->eye = {2.5f, 2.5f, 3.4f};
    } else if (name == "nagoya") {
        // Chosen: the word in two rows, NAG over OYA, cut from one block of the stone. In one
        // row the word filled 10 % of the frame and each letter (9 lattice units tall) held
        // about one marble layer or two wood rings, so neither material read; in two rows each
        // letter is 20 units tall (two to three layers, four rings) and the word fills the
        // frame. The texture stays one continuous solid (one object -> lattice map).
        SHITSUKAN_TRY(make_block_text("NAG", 1.0f, 0.45f, mesh));
        TriangleMesh second;
        SHITSUKAN_TRY(make_block_text("OYA", 1.0f, 0.45f, second));
        SHITSUKAN_TRY(append(mesh, second, Mat4::translate({0.0f, -1.25f, 0.0f})));
        SHITSUKAN_TRY(fit_mesh_to_cube(mesh, 0.92f));
        add_piece(out, mesh);
        out->eye = {0.9f, 1.5f, 5.2f};
        out->target = {0.0f, -0.02f, 0.0f};
        out->fov_degrees = 23.0f;
    } else if (name == "cup") {
        const Vec2d profile[] = {{0.0, -0.9},  {0.52, -0.9}, {0.58, -0.84}, {0.62, 0.2},
                                 {0.66, 0.88}, {0.66, 0.92}, {0.60, 0.92},  {0.56, 0.2},
                                 {0.50, -0.78}, {0.0, -0.78}};
        SHITSUKAN_TRY(make_revolution(profile, 10, seg, mesh));
        TriangleMesh handle;
        SHITSUKAN_TRY(make_torus(0.3f, 0.07f, seg / 2, quick ? 8 : 24, handle));
        // The handle: a ring in the xy plane, its inner half hidden in the wall.
        SHITSUKAN_TRY(append(mesh, handle,
                             Mat4::translate({0.66f, 0.05f, 0.0f}) * Mat4::rotate_x(1.5707963f)));
        SHITSUKAN_TRY(fit_mesh_to_cube(mesh, 0.92f));
        add_piece(out, mesh);
        out->eye = {1.9f, 2.4f, 4.2f};
    } else if (name == "ashtray") {
        const Vec2d profile[] = {{0.0, -0.3},  {0.90, -0.3}, {0.98, -0.22}, {1.0, 0.05},
                                 {0.96, 0.12}, {0.74, 0.12}, {0.66, 0.02},  {0.58, -0.14},
                                 {0.0, -0.14}};
        SHITSUKAN_TRY(make_revolution(profile, 9, seg, mesh));
        SHITSUKAN_TRY(fit_mesh_to_cube(mesh, 0.92f));
        add_piece(out, mesh);
        out->eye = {1.5f, 2.5f, 2.7f};
    } else if (name == "torus") {
        SHITSUKAN_TRY(make_torus(0.64f, 0.28f, seg, quick ? 16 : 48, mesh));
        SHITSUKAN_TRY(fit_mesh_to_cube(mesh, 0.92f));
        add_piece(out, mesh);
        out->eye = {1.6f, 2.5f, 2.8f};
    } else {
        return Status::error(StatusCode::invalid_argument, "okada: unknown scene %s", name.c_str());
    }
    return Status::success();
}

Status object_figure(figures::FigureContext& ctx, const std::string& scene_name, Material m) {
    const float k = m == Material::wood ? kWoodK : kMarbleK;
    Scene scene;
    SHITSUKAN_TRY(build_scene(scene_name, ctx.quick(), &scene));
    record_lattice(ctx);
    record_material(ctx, m, k);
    record_camera(ctx, scene_camera_text(scene));
    ctx.given("image", "512 x 512, RGB 8 bit",
              ctx.paper() == "okada1989" ? "okada1989 §4-4" : "okada1987 §4.4");
    RgbImage img;
    DensityShares shares;
    SHITSUKAN_TRY(render_scene(scene, m, k, ctx.quick() ? 128 : 512, &img, &shares));
    long covered = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const Rgb8 c = img.view().at(x, y);
            covered += !(c.r == kBackground.r && c.g == kBackground.g && c.b == kBackground.b);
        }
    ctx.note(fmt("The object covers %.1f %% of the frame.",
                 100.0 * double(covered) / (double(img.width()) * double(img.height()))));
    if (m != Material::wood && shares.pixels > 0)
        ctx.note(fmt(
            "Measured over the object's drawn fragments: %.1f %% in the vein colour (G' < 0.5, "
            "nearer I_min than I_max), %.1f %% in the pale skirt (0.5 <= G' < 0.9), "
            "%.1f %% limestone.",
            100.0 * double(shares.vein) / double(shares.pixels),
            100.0 * double(shares.skirt) / double(shares.pixels),
            100.0 * double(shares.pixels - shares.vein - shares.skirt) / double(shares.pixels)));
    return ctx.save_png(img.view());
}

}  // namespace shitsukan::okada
