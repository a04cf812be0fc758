// shitsukan/bark/layer_schedule.hpp — hirota1998 §4.1, Figs. 6-7: where the four layers are
// at time t (one function, used by the simulation and by the plot).
//
// Manual
//   LayerSchedule s;  s.R_in0 = 30;  s.D = 0.55f;  s.delta_R = 0.1f;  s.T = 100;
//   LayerRadii r = layer_radii(s, 2.5f * s.T);        // r.surface, r.middle1, ...
//   LayerRadii before = layer_radii(s, 3 * s.T, true); // the limit t -> 3T from below
//
// The paper (§4.1): four layers, from outside: the surface (cracks and peels), middle (1)
// (exposed when the surface peels), middle (2) (new cork whose thickness grows with time) and
// the inner layer (the cork cambium and everything inside). The wood's growth is the inner
// layer itself expanding radially, by delta_R per period T; "one cycle is the period T in
// which middle (2) grows to the thickness of middle (1)"; at each cycle middle (2) takes the
// role of middle (1) and middle (1) that of the surface, so every layer moves outward (Fig. 7).
// Reconstructed (linear in time; chosen here), with tau = t/T, k = floor(tau), f = tau - k:
//     r_in(t) = R_in0 + delta_R·tau          the inner layer's outer boundary
//     d2(t)   = D·f                          the thickness of middle (2)
//     middle (2) node at r_in + d2/2, middle (1) at r_in + d2 + D/2, surface at r_in + d2 + 3D/2
// (nodes at the layers' mid-planes; the inner layer's node at r_in - D/2). Through a role
// change at t = kT every layer's node radius is continuous: middle (1) at kT- is the surface at
// kT+, middle (2) at kT- (thickness D) is middle (1) at kT+. The outer layers therefore move
// out by delta_R + D per cycle: new cork pushes the old outward.
#pragma once

namespace shitsukan {

struct LayerSchedule {
    float R_in0 = 30.0f;    // inner layer's outer radius at t = 0 [cm]
    float D = 0.55f;        // thickness of a full layer [cm]
    float delta_R = 0.1f;   // growth of the inner layer's radius per cycle [cm]
    float T = 100.0f;       // one cycle [s]
};

struct LayerRadii {
    int cycle = 0;               // k = floor(t/T) (the cycle t lies in)
    float fraction = 0;          // t/T - k
    float inner_boundary = 0;    // r_in
    float inner = 0;             // node radius of the inner layer, r_in - D/2
    float middle2 = 0;           // node radius of middle (2)
    float middle2_thickness = 0; // d2 = D·fraction
    float middle1 = 0;           // node radius of middle (1)
    float surface = 0;           // node radius of the surface
};

// before_role_change: at t = kT exactly, the limit from below (cycle k - 1, fraction 1).
LayerRadii layer_radii(const LayerSchedule& s, float t, bool before_role_change = false);

}  // namespace shitsukan
