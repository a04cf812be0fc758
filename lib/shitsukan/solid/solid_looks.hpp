// shitsukan/solid/solid_looks.hpp — named looks of the marble and wood solid textures for
// artists: each one the paper's given values (okada1987 §4.4: k, the lattice R and beta,
// eqs. (8)-(12)) with chosen colours and, where said, a chosen k or ring frequency.
//
// Manual
//   const SolidLook* look = find_solid_look("carrara");
//   if (look == nullptr) return Status::error(StatusCode::invalid_argument, "no such look");
//   SolidMaterial m = solid_look_material(*look);       // marble or wood, k, colours
//   Status s = validate_solid_material(m);
//   for (int i = 0; i < solid_look_count(); ++i) (void)solid_look(i).name;   // every look
//   return s;
//   #include "shitsukan/solid/solid_material.hpp"
//
// Every look keeps eq. (6)'s lattice defaults (okada1987_presets.hpp: R = 6, beta, seed 1987)
// and names, in `given`, what comes from the paper and, in `chosen`, what was picked here and
// why. Marbles use okada1989's one layer repeated (layer_period), so they tile with
// --tileable; woods use okada1987 §4.2's rings (eqs. (10), (11)), which never tile.
// The looks' colours are display values (sRGB 0..255), the albedo an engine reads as sRGB.
// solid_look_material must be given a look from the table (solid_look / find_solid_look).
// Host side (the looks' layers are held in a static table).
#pragma once

#include "shitsukan/core/vec.hpp"
#include "shitsukan/solid/solid_material.hpp"

namespace shitsukan {

struct SolidLook {
    const char* name;
    bool wood;
    float k;                 // eq. (9) / (11)
    float layer_period;      // marble: okada1989 eq. (8) layer every this (lattice units)
    float w, alpha;          // marble: the layer's flat top and skirt (okada1989 eq. (8))
    float k2;                // wood: eq. (10) ring frequency
    Vec3 i_min, i_max;       // eq. (12)
    const char* given;
    const char* chosen;
};

int solid_look_count();
const SolidLook& solid_look(int index);               // 0 <= index < solid_look_count()
const SolidLook* find_solid_look(const char* name);   // null when there is none
SolidMaterial solid_look_material(const SolidLook& look);
// "carrara|nero|..." of the marble looks (wood = false) or the wood looks.
const char* solid_look_names(bool wood);

}  // namespace shitsukan
