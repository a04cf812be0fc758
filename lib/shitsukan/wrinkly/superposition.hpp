// shitsukan/wrinkly/superposition.hpp — the superposed WR surface of fujimoto2000 §4.1.
//
//   R^inf(u,v) = P(u,v) + { sum_k W^k(u,v) H((F_U^k)^{-1}(u), (F_V^k)^{-1}(v)) } N(u,v)   (16)
//   W^k(u,v)   = (1 - delta(u,v)) · delta(u,v)^k                                        (19)
// with sum_k W^k = 1 (eq. 18), so the total height is still set by H; delta only moves weight
// between the steps: small delta = smooth "mountain ranges", large delta = rough (figs. 17-18).
// A truncated sum k = 0..K carries sum_k W^k = 1 - delta^(K+1).
//
// Manual
//   float w = superposition_weight(0.5f, 2);            // (1 - 0.5)·0.5^2 = 0.125
//   float s = superposition_weight_sum(0.5f, 3);        // 1 - 0.5^4
//   Vec3 r = superposed_point_direct(surface, u, v, 4); // eq. (16) summed to K = 4, no sampling
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

// eq. (16) summed for k = 0..K without hierarchical sampling (the staircase form).
WrAttributes superposed_attributes_direct(const WrSurface& s, float u, float v, int levels_k);
Vec3 superposed_point_direct(const WrSurface& s, float u, float v, int levels_k);

}  // namespace shitsukan
