// shitsukan/solid/pixel_shift.hpp — okada1989 §4-1 eq. (7): the pixel shift method.
//
// Manual
//   Vec3 p{10, 20, 30}, u{0, 0, 1};          // the point, the shift direction
//   float k = 16.0f, d = 0.3f;               // the strength, the turbulence D(P)
//   Vec3 q = pixel_shift(p, k, d, u);        // P' = P + k·D(P)·u
//   auto G = [](Vec3 x) { return std::sin(x.z); };   // any original texture
//   float texture = G(q);                    // what the point P shows
//
// Forward vs. backward. okada1987 §3.2 words the turbulence as a forward map: the value
// G(P) of the original function "is observed at" P' = F(P, D(P)). A renderer cannot use
// that directly: it asks "what colour is at this surface point?", and a forward map
// scatters values to wherever P' lands (leaving some points with no value, others with
// several). okada1989 §4-1 states the backward (gather) form: the point P shows G(P') with
// P' = P + k·D(P)·u. That is evaluable per pixel and is what this library implements. For
// smooth D and small k the two differ only by the sign of k to first order
// (examples/11_turbulence_line.cpp draws both along a line).
// u: a direction, normally a unit vector: (0, 0, 1) for marble (okada1987 eq. (9)), the
// radial direction from the wood axis (eq. (11)). k: the contribution of the turbulence
// (okada1987: marble 16, wood 1.6).
// small-device: yes (inline)
#pragma once

#include "shitsukan/core/vec.hpp"

namespace shitsukan {

// okada1989 eq. (7): P' = F(P, D(P)) = P + k·D(P)·u.
inline Vec3 pixel_shift(Vec3 p, float k, float d, Vec3 u) { return p + u * (k * d); }

}  // namespace shitsukan
