// shitsukan/solid/color_lookup.hpp — okada1987 §4.3 eq. (12): from texture density G' to
// R, G, B intensities.
//
// Manual
//   float g_prime = 0.4f;                   // the texture value G' in [0, 1]
//   Vec3 rgb = lookup_color(g_prime, Vec3{40, 45, 60}, Vec3{235, 232, 225});   // I_min, I_max
//
// I = (1 - G')·I_min + G'·I_max per channel. For marble I_max is the limestone colour and
// I_min the impurity's; for wood I_max and I_min are the winter and summer wood (§4.3).
// G' is clamped to [0, 1] first (marble's sum of stripes can exceed 1 where skirts
// overlap; chosen here). Units of I are the caller's (0..255 in the figures).
// small-device: yes (inline)
#pragma once

#include "shitsukan/core/vec.hpp"

namespace shitsukan {

inline Vec3 lookup_color(float g_prime, Vec3 i_min, Vec3 i_max) {
    float g = g_prime > 0.0f ? (g_prime < 1.0f ? g_prime : 1.0f) : 0.0f;  // also NaN -> 0
    return i_min * (1.0f - g) + i_max * g;  // eq. (12)
}

}  // namespace shitsukan
