// shitsukan/image/colormap.hpp — colour maps: a value in [0, 1] -> Rgb8.
//
// Manual
//   float t = 0.75f;
//   Rgb8 c = colormap(ColorMap::perceptual, 0.25f);
//   Rgb8 g = colormap(ColorMap::gray, t);        // black .. white
//   Rgb8 d = colormap(ColorMap::diverging, t);   // blue .. light gray (t = 0.5) .. red
//   const char* name = colormap_name(ColorMap::perceptual);   // "perceptual"
// t is clamped to [0, 1]; NaN gives kColorMapNaN (magenta) so missing data stays visible.
// Each map is a few control colours chosen here, joined by straight lines in 8-bit sRGB:
//   perceptual  seven colours from dark violet through blue, teal and green to yellow, a
//               viridis-like ramp (not viridis' table): each control colour's CIE L* was
//               set to 10 + 80·i/6, so lightness rises evenly (1/255 of t never adds less
//               than 0.27 or more than 0.36 to L*) and the map prints well in gray.
//   diverging   blue (L* 38) -> light gray (L* 95) -> red (L* 39): equal-lightness ends,
//               for signed data centred on 0 (map the range symmetrically, e.g. [-m, m]).
//   gray        linear 0..255.
// No allocation; usable on a small device.
#pragma once

#include "shitsukan/image/image_view.hpp"

namespace shitsukan {

enum class ColorMap { gray, perceptual, diverging };

constexpr Rgb8 kColorMapNaN{255, 0, 255};

Rgb8 colormap(ColorMap map, float t);
const char* colormap_name(ColorMap map);

}  // namespace shitsukan
