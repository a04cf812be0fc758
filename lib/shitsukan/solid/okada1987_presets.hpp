// shitsukan/solid/okada1987_presets.hpp — the values the okada1987 / okada1989 figures use
// where the papers print none: the lattice's beta and seed, marble's six stripes, the wood's
// axis and ring frequency, and the colours of eq. (12). One place, so marble on your own mesh
// looks like the figures.
//
// Manual
//   FractalLattice lattice;
//   Status s = lattice.build(okada1987_lattice_params());      // 65^3, beta 0.9, seed 1987
//   if (!s) return s;
//   TypeIIILattice small;                       // no table; eq. (2) computed by the compiler
//   s = small.init(okada1987_lattice_params(), kOkada1987Amplitudes);
//   if (!s) return s;
//   SolidMaterial marble = okada1987_marble();                  // k = 16, six stripes
//   SolidMaterial wood   = okada1987_wood();                    // k = 1.6
//   SolidMaterial single = okada1989_marble();                  // one layer through the middle
//   Vec3 p{0.1f, 0.2f, -0.3f};                                  // a point of the object
//   Vec3 rgb = solid_color(marble, lattice.view(), object_to_lattice(p));
//   #include "shitsukan/solid/lattice_store.hpp"
//   #include "shitsukan/solid/lattice_type3.hpp"
//   #include "shitsukan/solid/object_mapping.hpp"
//
// Given by the papers: R = 6 (the 65^3 lattice), k = 16 for marble, k = 1.6 for wood
// (okada1987 §4.4), the forms of G (eqs. (8), (10)). Chosen here (the papers print none),
// in lattice units along the texture's z (the object's up axis with object_to_lattice):
//   beta 0.9      the finest level at e^-4.5 = 1 % of the first: smooth folds at k = 16
//                 (0.5 broke the k = 16 marble into fine noise)
//   seed 1987     with hash noise, so Types I, II and III give the same lattice
//   stripes       six layers of impurity, uneven spacing and widths, sharp and soft skirts:
//                 (c, w, alpha) = (8, 1.2, 0.9) (17, 2.5, 0.6) (26, 0.8, 1.5) (35, 3.5, 0.5)
//                 (46, 1.5, 0.8) (55, 2, 0.7)
//   okada1989     one layer (c 32, w 1.2, alpha 1) repeated every 12 units along z: the
//                 "layered, striped marble" of okada1989 §4-2 (kOkada1989LayerPeriod below)
//   marble colour I_max limestone (238, 234, 226) warm white, I_min impurity (62, 74, 80)
//   wood          axis (x0, y0) = (6, 14), off the objects' centre as a board cut beside the
//                 pith; k2 = 1.2 (rings every 2·pi/k2 = 5.2 units, about 10 across an object);
//                 I_max winter (late) wood (128, 72, 34), I_min summer wood (226, 184, 128)
// Colours are 0..255 (the figures' 8-bit frames).
// small-device: yes (no allocation)
#pragma once

#include <cstdint>

#include "shitsukan/core/vec.hpp"
#include "shitsukan/solid/fractal_params.hpp"
#include "shitsukan/solid/marble.hpp"
#include "shitsukan/solid/solid_material.hpp"

namespace shitsukan {

constexpr int kOkada1987R = 6;
constexpr float kOkada1987Beta = FractalParams{}.beta;  // the library's default, one reason
// eq. (2)'s amplitudes for kOkada1987Beta, computed by the compiler (fractal_params.hpp): for
// TypeIIILattice::init(okada1987_lattice_params(), kOkada1987Amplitudes) on a small device.
inline constexpr LevelAmplitudes kOkada1987Amplitudes = level_amplitudes(kOkada1987Beta);
constexpr std::uint32_t kOkada1987Seed = 1987u;
constexpr float kOkada1987MarbleK = 16.0f;  // okada1987 §4.4
constexpr float kOkada1987WoodK = 1.6f;     // okada1987 §4.4
constexpr float kOkada1987WoodK2 = 1.2f;
const Vec2 kOkada1987WoodAxis{6.0f, 14.0f};
constexpr int kOkada1987StripeCount = 6;
extern const MarbleStripe kOkada1987Stripes[kOkada1987StripeCount];
// okada1989: eq. (8) is the function of ONE layer; its striped marble is that layer repeated
// through the stone every kOkada1989LayerPeriod along z (chosen reading: one layer through the
// middle covered only 4-12 % of each object and read as a white object with one crack).
extern const MarbleStripe kOkada1989Stripe;
constexpr float kOkada1989LayerPeriod = 12.0f;
const Vec3 kOkada1987Limestone{238.0f, 234.0f, 226.0f};   // marble I_max
const Vec3 kOkada1987Impurity{62.0f, 74.0f, 80.0f};       // marble I_min
const Vec3 kOkada1987WinterWood{128.0f, 72.0f, 34.0f};    // wood I_max (late wood, dark)
const Vec3 kOkada1987SummerWood{226.0f, 184.0f, 128.0f};  // wood I_min (early wood, light)

// R = 6, beta 0.9, seed 1987, hash noise, corners 0.
FractalParams okada1987_lattice_params();
// okada1987's marble: the six stripes, limestone and impurity colours.
SolidMaterial okada1987_marble(float k = kOkada1987MarbleK);
// okada1989's marble: its single layer (okada1989 eq. (8)) repeated every
// kOkada1989LayerPeriod, the same colours.
SolidMaterial okada1989_marble(float k = kOkada1987MarbleK);
// The wood of both papers: the radial sine about the chosen axis, winter and summer wood.
SolidMaterial okada1987_wood(float k = kOkada1987WoodK);

}  // namespace shitsukan
