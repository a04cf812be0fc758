// shitsukan/leather/leather_looks.hpp — named looks of the reptile leather (tokai1994 §3) for
// artists: the crocodile's belly and back, each with its given values (the paper's figures)
// and chosen ones (colours, the back's layout and spacing), for `shitsukan leather --look`.
//
// Manual
//   const LeatherLook* look = find_leather_look("crocodile-belly");
//   if (look == nullptr) return Status::error(StatusCode::invalid_argument, "no such look");
//   ScaleParams prm;
//   prm.D = look->D, prm.d = look->d, prm.a = look->a, prm.perturbation.p = look->p;
//   BezierChain section = table1_section(look->section);   // relief.hpp, Table 1
//   return validate_section(section);
//   #include "shitsukan/leather/relief.hpp"
//   #include "shitsukan/leather/scale_division.hpp"
//
// layout: 0 the two-stage belly (figs. 4-7), 1 fig. 3's square lattice, 2 the triangular one.
// The colours are display values (sRGB 0..255): `crevice` where the height is lowest, `top` on
// the crowns of the scales; the albedo mixes them by the height (chosen: dirt and tanning dye
// gather in the grooves, the crowns wear light).
// Host or device: a constant table.
#pragma once

#include "shitsukan/core/vec.hpp"
#include "shitsukan/leather/relief.hpp"

namespace shitsukan {

struct LeatherLook {
    const char* name;
    int layout;
    Table1Section section;
    float D, d, a, p;
    Vec3 crevice, top;
    const char* given;
    const char* chosen;
};

const LeatherLook* find_leather_look(const char* name);  // null when there is none
const char* leather_look_names();                         // "crocodile-belly|crocodile-back"

}  // namespace shitsukan
