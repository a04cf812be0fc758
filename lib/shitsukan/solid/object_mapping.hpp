// shitsukan/solid/object_mapping.hpp — object space -> lattice coordinates, so a solid texture
// can be put on any mesh (okada1987 §4: the texture is a function of the object's own
// coordinates, the lattice a box of 2^R cells around it).
//
// Manual
//   FractalLattice lattice;                                 // lattice_store.hpp
//   Status s = lattice.build(FractalParams{});
//   if (!s) return s;
//   Vec3 object_position{0.2f, -0.5f, 0.7f};                // e.g. a Fragment's object_position
//   ObjectToLattice map = object_to_lattice_mapping(6);     // R = 6: (32 + 30x, 32 - 30z, 32 + 30y)
//   Vec3 p = object_to_lattice(object_position, map);
//   float d = turbulence(lattice.view(), p);
//   #include "shitsukan/solid/lattice_store.hpp"
//   #include "shitsukan/solid/turbulence.hpp"
//
// The object is expected inside [-1, 1]^3 with y up (fit_mesh_to_cube, geom/mesh_fit.hpp,
// puts any mesh there). The mapping is P = (c + s·x, c - s·z, c + s·y): the texture's z
// axis (marble's layer normal, wood's axis) is the object's up axis, and the right-handed
// frame is kept. object_to_lattice_mapping(R) centres the object (c = 2^(R-1)) and leaves a
// margin of 1/16 of the lattice on each side (s = 2^(R-1)·15/16: 30 at R = 6, chosen here as
// in the okada1987 figures: the objects fill [2, 62]^3 of [0, 64]^3, so D(P) never needs a
// point outside the lattice). All texture lengths (P, c_j, w_j, r, the shift k·D) are then in
// lattice spacings.
// small-device: yes (inline)
#pragma once

#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct ObjectToLattice {
    float centre = 32.0f;  // lattice coordinate of the object's origin (on all three axes)
    float scale = 30.0f;   // lattice spacings per object unit
};

// The mapping for a lattice of depth R: the object's [-1, 1]^3 fills [2^R/32, 2^R·31/32]^3.
inline ObjectToLattice object_to_lattice_mapping(int R) {
    const float half = R > 0 ? float(1 << (R - 1)) : 0.5f;
    return ObjectToLattice{half, half * (15.0f / 16.0f)};
}

// P = (c + s·x, c - s·z, c + s·y).
inline Vec3 object_to_lattice(Vec3 p, const ObjectToLattice& m = ObjectToLattice{}) {
    return Vec3{m.centre + m.scale * p.x, m.centre - m.scale * p.z, m.centre + m.scale * p.y};
}

}  // namespace shitsukan
