// shitsukan/bark/connection_area.hpp — hirota1998 §5.1, Fig. 9: connection areas and the
// spring constants that follow from them.
//
// Manual
//   // two triangles sharing spring 1 (nodes 1-2): a unit square cut along its diagonal
//   std::vector<ConnectionTriangle> tris = {
//       {{0, 1, 2}, {0, 1, 2}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},   // corners, node ids, springs
//       {{1, 3, 2}, {3, 4, 1}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}};
//   int n_nodes = 4, n_springs = 5;
//   std::vector<float> area(static_cast<std::size_t>(n_nodes)), face(static_cast<std::size_t>(n_springs));
//   Status s = connection_areas(tris.data(), int(tris.size()), n_nodes, n_springs,
//                               area.data(), face.data());
//   float E = 1.07e9f, G = 4.8e8f, D = 0.55f, l0 = 1.0f;  int i = 1;
//   float k    = spring_constant(E, face[1] * D, l0);      // k = E·S/l0, S = |C1-P-C2|·H
//   float k_sh = shear_spring_constant(G, area[std::size_t(i)], D);  // k_sh = G·A/h
//   return s;
//
// The paper (§5.1): the element of node N1 is bounded by the closed curve through the
// midpoints P of its springs and the centroids C of the triangles it forms with its
// neighbours. The part shared with one neighbour (C1-P-C2) times the element height H is that
// spring's connection area; the shear spring's connection area is the area the curve
// encloses. Per triangle that is: each edge gets the distance from its midpoint to the
// centroid, each corner a third of the area (the quadrilateral corner-P-C-P is one third of
// any triangle). A boundary edge has one triangle (C1-P only) and a boundary node a partial
// element, so the free top and bottom of the cylinder get their physically reduced values,
// and the cylinder and an irregular mesh share one code path.
//
// Spring constants (chosen here: the standard bar-in-tension and block-in-shear formulas;
// the paper only says the constants follow from the connection areas): k = E·S/l0 for a spring
// of rest length l0 and connection area S; k_sh = G·A/h for a shear spring of area A between
// layers whose mid-planes are h apart (h = D, the layer thickness: equal layers).
//
// Corners are given per triangle (not per node), so a periodic mesh passes each triangle with
// its seam-corrected corners.
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct ConnectionTriangle {
    std::uint32_t node[3];    // corner nodes
    std::uint32_t spring[3];  // spring[k] joins node[k] and node[(k + 1) % 3]
    Vec3 corner[3];           // corner positions (2D meshes leave z = 0)
};

// area[i] = sum over triangles at i of area/3; face[s] = sum over triangles at s of the
// distance from the midpoint of s to the triangle's centroid. Both arrays are overwritten.
Status connection_areas(const ConnectionTriangle* triangles, int triangle_count, int node_count,
                        int spring_count, float* area, float* face);

inline float spring_constant(float E, float connection_area, float l0) {
    return E * connection_area / l0;  // a bar in tension: F = (E·S/l0)·elongation
}
inline float shear_spring_constant(float G, float connection_area, float h) {
    return G * connection_area / h;  // a block in simple shear: F = (G·A/h)·slip
}

}  // namespace shitsukan
