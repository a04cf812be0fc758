// shitsukan/bark/spacing_estimate.hpp — the crack-spacing estimate hirota1998 §3.2 refers to
// (RECONSTRUCTED: the paper cites ref. 12 and gives no formula).
//
// Manual
//   float a_h = 0.286f, k = 2.0e7f, k_sh = 3.0e5f, kappa2 = 1.015f, eps_final = 0.1f;
//   float L = crack_spacing_estimate(a_h, std::sqrt(k / k_sh), kappa2 - 1, eps_final);
//   // largest crack spacing [cm]; +inf when the final strain never reaches the threshold
//
// §3.2: "for a two-layer model the spacing of the cracks can be estimated, and the parameters
// were determined from that estimate. ... The simulated spacing comes out smaller than the
// measured one because the estimate gives only the maximum spacing." The classical shear-lag
// result for a chain of surface springs k (node spacing s) on shear springs k_sh over a
// substrate stretched by eps_f: a fragment of length L between two cracks is most strained
// in its middle, eps_f·(1 - 1/cosh(L / (2 lambda))), lambda = s·sqrt(k/k_sh). A fragment
// splits when that reaches the critical strain eps_c, so no fragment is longer than
//     L_max = 2 lambda·arccosh(1 / (1 - eps_c/eps_f))     (none at all if eps_c >= eps_f)
// and the final fragments lie in (L_max/2, L_max].
#pragma once

namespace shitsukan {

// s: node spacing along the chain [cm]; stiffness_ratio_sqrt = sqrt(k/k_sh); eps_c: critical
// strain; eps_f: the substrate's final strain along the chain.
float crack_spacing_estimate(float s, float stiffness_ratio_sqrt, float eps_c, float eps_f);

// The shear-lag decay length lambda = s·sqrt(k/k_sh).
inline float shear_lag_length(float s, float stiffness_ratio_sqrt) {
    return s * stiffness_ratio_sqrt;
}

}  // namespace shitsukan
