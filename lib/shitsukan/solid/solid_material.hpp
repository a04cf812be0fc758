// shitsukan/solid/solid_material.hpp — a solid texture as one value: marble (okada1987 §4.1)
// or wood (§4.2) with its k and the two colours of eq. (12); density and colour at a point.
//
// Manual
//   FractalLattice lattice;                                // lattice_store.hpp
//   Status s = lattice.build(okada1987_lattice_params());
//   SolidMaterial m = okada1987_marble();                  // okada1987_presets.hpp
//   if (s) s = validate_solid_material(m);
//   if (!s) return s;
//   Vec3 p{32.0f, 20.0f, 40.5f};                           // in lattice units
//   float g  = solid_density(m, lattice.view(), p);        // G' in [0, 1]
//   Vec3 rgb = solid_color(m, lattice.view(), p);          // eq. (12), 0..255 as I_min/I_max
//   #include "shitsukan/solid/lattice_store.hpp"
//   #include "shitsukan/solid/okada1987_presets.hpp"
//
// Density G' (the input of eq. (12)), with D = turbulence(lattice, p) (eq. (6)):
//   marble  G' = 1 - min(G(P + k·D·(0, 0, 1)), 1): G = 1 inside a layer of impurity, so the
//           layers take I_min and the limestone between them I_max (chosen here: eq. (12)
//           says which colour is which, not how G maps to G'). With layer_period > 0 the first
//           stripe is ONE layer (okada1989 eq. (8): "the function of one layer") repeated every
//           layer_period along z through the stone; the two repeats nearest to the displaced z
//           are summed (the others add less than e^-8).
//   wood    G' = (sin(k2·r') + 1)/2, r' the radius of the point displaced along u (eq. (11)),
//           so each ring period holds one I_max and one I_min band (wood_unit_range).
// The stripes pointed to by `marble.stripes` must outlive the material.
// small-device: yes (no allocation)
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/marble.hpp"
#include "shitsukan/solid/wood.hpp"

namespace shitsukan {

enum class SolidPattern : std::uint8_t { marble, wood };

struct SolidMaterial {
    SolidPattern pattern = SolidPattern::marble;
    MarbleParams marble;        // used when pattern == marble (stripes, count, k)
    float layer_period = 0;     // > 0: marble.stripes[0] repeated every layer_period along z
    WoodParams wood;            // used when pattern == wood (axis, k2, k)
    Vec3 i_min{0, 0, 0};        // eq. (12): colour at G' = 0
    Vec3 i_max{255, 255, 255};  // eq. (12): colour at G' = 1
};

Status validate_solid_material(const SolidMaterial& material);

// G' in [0, 1] at lattice point p (see above). The lattice must be built (asserted).
float solid_density(const SolidMaterial& material, const LatticeView& lattice, Vec3 p);
// The same for a known D(P) = d (e.g. from TypeIIILattice::turbulence, with no lattice table).
float solid_density_at(const SolidMaterial& material, Vec3 p, float d);
// eq. (12) for a density: (1 - G')·I_min + G'·I_max.
Vec3 solid_density_color(const SolidMaterial& material, float density);
// Both: the colour of the texture at lattice point p.
Vec3 solid_color(const SolidMaterial& material, const LatticeView& lattice, Vec3 p);

}  // namespace shitsukan
