// paper_figures/okada1987/okada_common.hpp — what every okada1987 / okada1989 figure shares:
// the one 65^3 lattice, the chosen stripes, colours, camera and object -> lattice mapping,
// and the solid-texture shader run by the rasterizer.
//
// Manual
//   const FractalLattice& lattice = okada::shared_lattice();   // built once per process
//   okada::record_lattice(ctx);  okada::record_material(ctx, okada::Material::marble, 16.0f);
//   okada::Scene scene;  okada::add_piece(&scene, mesh);       // meshes in [-1, 1]^3
//   RgbImage img;  okada::render_scene(scene, okada::Material::wood, 1.6f, 512, &img);
//
// Every value the papers leave open is chosen once, in the library
// (shitsukan/solid/okada1987_presets.hpp; docs/DESIGN.md: given vs. chosen), and recorded here:
//   lattice    R = 6 (given), beta = kBeta, seed = kSeed, corners 0, hash noise (so the
//              Type I array equals Types II/III, okada1989 Table "types").
//   mapping    object space [-1, 1]^3 (y up) -> lattice (32 + 30x, 32 - 30z, 32 + 30y): the
//              texture's z axis (marble's layer normal, wood's axis) is the object's up
//              axis, the objects fill [2, 62]^3 of [0, 64]^3, so D(P) never leaves the
//              lattice (even the wood's displaced point is not looked up again). All texture
//              lengths (P, c_j, w_j, r, the shift k·D) are in lattice spacings.
//   marble     six stripes (kStripes, lattice units), G' = 1 - min(G, 1) so that G' = 1
//              (I_max) is limestone and the stripes take the impurity colour I_min.
//   okada1989  one layer kSingleStripe (w 1.2, alpha 1) repeated every 12 along z,
//              same G' and colours.
//   wood       axis through lattice (x0, y0) = kWoodAxis, k2 = kWoodK2 (rings every
//              2·pi/k2 = 5.2 lattice units), G' = (sin + 1)/2; I_max winter (late) wood.
//   shading    Lambert, light from the upper front (slightly right), 0.3 + 0.7·max(0, n·l).
#pragma once

#include <string>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/solid/object_mapping.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"
#include "shitsukan/solid/solid.hpp"

namespace shitsukan::okada {

// marble: okada1987's sum of stripes (eq. (8)); marble_single: okada1989's single stripe
// (its eq. (8)); wood: the radial sine of both papers (eq. (10)).
enum class Material { marble, marble_single, wood };

// The library's presets under the figures' short names.
constexpr float kBeta = kOkada1987Beta;
constexpr std::uint32_t kSeed = kOkada1987Seed;
constexpr float kMarbleK = kOkada1987MarbleK;  // okada1987 §4.4
constexpr float kWoodK = kOkada1987WoodK;      // okada1987 §4.4
constexpr float kLatticeCentre = ObjectToLattice{}.centre;
constexpr float kLatticeScale = ObjectToLattice{}.scale;
constexpr float kWoodK2 = kOkada1987WoodK2;
const Vec2 kWoodAxis = kOkada1987WoodAxis;
inline const auto& kStripes = kOkada1987Stripes;
inline const MarbleStripe& kSingleStripe = kOkada1989Stripe;  // okada1989: one layer
constexpr float kSingleLayerPeriod = kOkada1989LayerPeriod;     // repeated every 12 units
constexpr int kStripeCount = kOkada1987StripeCount;
const Vec3 kMarbleLimestone = kOkada1987Limestone;  // I_max
const Vec3 kMarbleImpurity = kOkada1987Impurity;    // I_min
const Vec3 kWoodWinter = kOkada1987WinterWood;      // I_max (late wood, dark)
const Vec3 kWoodSummer = kOkada1987SummerWood;      // I_min (early wood, light)
const Rgb8 kBackground{24, 26, 32};

// The library's SolidMaterial for a figure material and k.
SolidMaterial solid_material(Material m, float k);

// The one lattice of every figure (okada1987 §4.4: "the same fractal lattice for all").
const FractalLattice& shared_lattice();
double shared_lattice_build_seconds();  // wall time of the one build in this process

void record_lattice(figures::FigureContext& ctx);
// k (given) and then everything record_material(ctx, m) records.
void record_material(figures::FigureContext& ctx, Material m, float k);
// The original function G, its stripes or rings, G' and the colours I_min / I_max (not k).
void record_material(figures::FigureContext& ctx, Material m);
void record_camera(figures::FigureContext& ctx, const std::string& description);

// Object space -> lattice coordinates (see the top of this file; the library's mapping).
inline Vec3 object_to_lattice(Vec3 p) { return shitsukan::object_to_lattice(p); }

// The texture density G' in [0, 1] at a lattice point (pixel shift + eq. (12)'s input).
float density(Material m, float k, Vec3 lattice_point);
// Density -> colour by eq. (12) with the material's I_min / I_max.
Vec3 material_color(Material m, float density);

struct Piece {
    TriangleMesh mesh;
    Mat4 model = Mat4::identity();  // object -> world; the texture uses object space
};

struct Scene {
    std::vector<Piece> pieces;
    Vec3 eye{3.4f, 2.6f, 4.2f};
    Vec3 target{0.0f, 0.0f, 0.0f};
    float fov_degrees = 30.0f;
};

void add_piece(Scene* scene, const TriangleMesh& mesh, const Mat4& model = Mat4::identity());

// Shares of the drawn pixels by texture density G' (marble: vein < 0.5 <= skirt < 0.9).
struct DensityShares {
    long pixels = 0, vein = 0, skirt = 0;
};

// Renders the scene into a size x size image with the solid texture (counting the density
// shares of the drawn fragments into `shares` when given).
Status render_scene(const Scene& scene, Material m, float k, int size, RgbImage* out,
                    DensityShares* shares = nullptr);

// The okada1987 objects (object space inside [-1, 1]^3): "cube", "slices", "cut_sphere",
// "pot", "nagoya"; okada1989: "cup", "ashtray", "torus". Returns the scene with its camera.
Status build_scene(const std::string& name, bool quick, Scene* out);
std::string scene_camera_text(const Scene& scene);

// fig. 12: a 4 x 4 grid of cubes with k = k_step·i, i = 0..15, labelled, (4·tile)^2 pixels.
Status render_k_grid(Material m, float k_step, int tile, RgbImage* out);

// Renders and saves one object figure (fig10..15, okada1989 fig08..10), recording all values.
Status object_figure(figures::FigureContext& ctx, const std::string& scene_name, Material m);

}  // namespace shitsukan::okada
