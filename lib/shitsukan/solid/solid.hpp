// shitsukan/solid/solid.hpp — okada1987, "Rendering Texture of Inhomogeneous Material Using
// Three-Dimensional Random Fractal" (Okada, Yokoi, Toriwaki, Hori, IPSJ Trans. 28(11), 1987) and
// okada1989, the pixel shift method (Okada, Yokoi, Toriwaki, c. 1989): the files in the order to
// read them beside the papers, and everything in one include.
//
//   okada1987 §2.1, fig. 1      quadtree_lattice.hpp   the 2D random fractal lattice (the idea)
//   okada1987 §2.2, eq. (5)     fractal_params.hpp     R, beta, seed: the lattice's parameters
//   okada1987 eqs. (1)-(4)      fractal_node.hpp       one recursion level's three rules, once
//   okada1987 §2.2, Type I      fractal_lattice.hpp    the whole 65^3 lattice in one array
//   okada1987 §4.4              lattice_store.hpp      an owning lattice; saved and loaded as
//                                                      the paper kept it on file
//   okada1989 §3-2, §3-3        lattice_type2.hpp,     Types II (ancestors in a list) and III
//                               lattice_type3.hpp      (hashed nodes, no table)
//   okada1987 eq. (6)           turbulence.hpp         D(P): trilinear interpolation
//   okada1989 §4-1, eq. (7)     pixel_shift.hpp        P shows G(P + k·D(P)·u): the backward map
//   okada1987 §4.1, eqs. (8)-(9) marble.hpp            layers with exponential skirts
//   okada1987 §4.2, eqs. (10)-(11) wood.hpp            a radial sine displaced along the radius
//   okada1987 §4.3, eq. (12)    color_lookup.hpp       density -> colour
//   okada1987 §4                object_mapping.hpp,    a material on any object: object ->
//                               solid_material.hpp,    lattice, marble or wood with its colours,
//                               okada1987_presets.hpp  and the values the figures chose
//
// Manual (a marble colour at a point of an object):
//   FractalLattice lattice;
//   Status s = lattice.build(okada1987_lattice_params());
//   Vec3 p{0.1f, 0.2f, -0.3f};                 // a point of the object, in [-1, 1]^3
//   Vec3 rgb = s ? solid_color(okada1987_marble(), lattice.view(), object_to_lattice(p)) : Vec3{};
//   return s;
#pragma once
#include "shitsukan/solid/quadtree_lattice.hpp"
#include "shitsukan/solid/fractal_params.hpp"
#include "shitsukan/solid/fractal_node.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/solid/lattice_type2.hpp"
#include "shitsukan/solid/lattice_type3.hpp"
#include "shitsukan/solid/turbulence.hpp"
#include "shitsukan/solid/pixel_shift.hpp"
#include "shitsukan/solid/marble.hpp"
#include "shitsukan/solid/wood.hpp"
#include "shitsukan/solid/color_lookup.hpp"
#include "shitsukan/solid/object_mapping.hpp"
#include "shitsukan/solid/solid_material.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"
