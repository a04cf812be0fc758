// shitsukan/wrinkly/superposition.hpp — the superposed WR surface of fujimoto2000 §4.1.
//
//   R^inf(u,v) = P(u,v) + { sum_k W^k(u,v) H((F_U^k)^{-1}(u), (F_V^k)^{-1}(v)) } N(u,v)   (16)
//   W^k(u,v)   = (1 - delta(u,v)) · delta(u,v)^k                                        (19)
// with sum_k W^k = 1 (eq. 18), so the total height is still set by H; delta only moves weight
// between the steps: small delta = smooth "mountain ranges", large delta = rough (figs. 17-18).
// A truncated sum k = 0..K carries sum_k W^k = 1 - delta^(K+1), so summing eq. (19) to a level
// cap and stopping would lower every surface by the missing tail (by 42 % at delta = 0.75,
// K = 2). Here eq. (18) is kept on the finite sum instead: solving eqs. (17) and (18) over
// k = 0..K gives delta_0 = (1 - delta) / (1 - delta^(K+1)), i.e. the weights of eq. (19)
// divided by their sum. delta still only redistributes weight between the steps; a constant H
// comes back unchanged for every delta and K (tested).
//
// Manual
//   WrControlMesh mesh = make_control_mesh(8, 8);          // control_mesh.hpp
//   for (int r = 0; r < 8; ++r)
//       for (int c = 0; c < 8; ++c)
//           mesh.at(c, r).position = {c / 7.0f, r / 7.0f, 0.0f}, mesh.at(c, r).height = 0.05f;
//   WrSurface surface;
//   Status s = make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface);
//   if (!s) return s;
//   float u = 0.3f, v = 0.6f;
//   float w = superposition_weight(0.5f, 2);            // (1 - 0.5)·0.5^2 = 0.125
//   float sum = superposition_weight_sum(0.5f, 3);      // 1 - 0.5^4
//   float t = superposition_weight_truncated(0.5f, 2, 3);  // 0.125 / (1 - 0.5^4)
//   Vec3 r = superposed_point_direct(surface, u, v, 4); // eq. (16) summed to K = 4, no sampling
//   #include "shitsukan/wrinkly/control_mesh.hpp"
// superposed_point_direct shows the staircase artefact of fig. 19(b); the hierarchical
// sampling of §4.2 (hierarchical_sampling.hpp) removes it and is what the figures use.
#pragma once

#include "shitsukan/core/vec.hpp"
#include "shitsukan/wrinkly/wr_surface.hpp"

namespace shitsukan {

// eq. (19). delta in (0, 1), k >= 0.
float superposition_weight(float delta, int k);
// sum_{k=0..K} W^k = 1 - delta^(K+1) (the truncated eq. 18).
float superposition_weight_sum(float delta, int levels_k);
// The weight of step k in a sum that stops at K, with eq. (18) kept on that finite sum:
// W^k / (1 - delta^(K+1)); the K + 1 weights add up to 1. 0 <= k <= K.
float superposition_weight_truncated(float delta, int k, int levels_k);

// eq. (16) summed for k = 0..K without hierarchical sampling (the staircase form), with the
// truncated weights (eq. 18 on the finite sum: every attribute is divided by sum_k W^k).
WrAttributes superposed_attributes_direct(const WrSurface& s, float u, float v, int levels_k);
// The same from the bases located at the inverses, bu[k] = s.basis_u(s.inverse_u(u, k)) and
// bv[k] likewise for k = 0..levels_k, and delta = s.base_point(u, v).delta. Same bits.
WrAttributes superposed_attributes_direct(const WrSurface& s, float delta, const WrBasisAt* bu,
                                          const WrBasisAt* bv, int levels_k);
Vec3 superposed_point_direct(const WrSurface& s, float u, float v, int levels_k);

}  // namespace shitsukan
