// shitsukan/geom/mesh_fit.hpp — scale and move a mesh into a centred cube, so object-space
// textures (solid/object_mapping.hpp) and cameras can assume [-extent, extent]^3.
//
// Manual
//   TriangleMesh mesh;  Status s = make_torus(0.64f, 0.28f, 96, 48, mesh);  // or your own
//   if (s) s = fit_mesh_to_cube(mesh, 0.92f);   // longest side 2·0.92, centred at the origin
//   return s;
//   #include "shitsukan/geom/mesh_builders.hpp"
//
// One uniform scale (the proportions are kept) and one shift: the bounding box's centre
// goes to the origin and its longest side becomes 2·extent. Normals are unchanged (a uniform
// scale does not turn them). degenerate for an empty mesh or one whose box has no extent;
// invalid_argument for extent <= 0 or NaN, or a non-finite position.
// Host side (TriangleMesh).
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

Status fit_mesh_to_cube(TriangleMesh& mesh, float extent = 1.0f);

}  // namespace shitsukan
