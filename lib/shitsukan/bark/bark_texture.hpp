// shitsukan/bark/bark_texture.hpp — hirota1998's cracked bark as a seamless texture: a height
// map from the plates and Fig. 4's crack widths, an albedo with a tone per plate, periodic
// around and along the trunk.
//
// Manual
//   CylinderParams p;  p.N_R = 16;  p.N_H = 14;  p.species = species_preset(Species::pine);
//   BarkCylinder bark;  CrackRun run;  RegionReport regions;
//   Status s = build_cylinder(p, true, bark);        // periodic along the axis as well
//   if (s) s = grow_and_crack(bark, CrackRunOptions{}, run);
//   if (s) s = measure_regions(bark, p.T, bark.net.W.data(), regions);
//   BarkTextureOptions o;  o.width = o.height = 64;  o.colors = bark_texture_colors(Species::pine);
//   BarkTexture tex;
//   if (s) s = make_bark_texture(bark, p.T, bark.net.W.data(), &regions, o, tex);
//   // tex.height[y·64 + x] in cm (0 = crack floor), tex.albedo: sRGB bytes, tex.period_u/_z
//   return s;
//   #include "shitsukan/bark/crack_events.hpp"
//   #include "shitsukan/bark/crack_regions.hpp"
//
// The texture covers one period of the grown bark at time t: u in [0, C(t)) around the trunk
// (the cylinder's own period) and z in [0, H(t)) along it, which needs the lattice built
// periodic along the axis (build_cylinder(params, true, ...); chosen here: a real trunk has
// no cut ends, and a texture must tile; the free edges of §3's cylinder would leave a band of
// uncracked bark at the top and bottom, crack_regions.hpp kSectionEndRows). Pixel (x, y) is
// the point u = (x + 1/2)·C/width, z = H - (y + 1/2)·H/height (row 0 at the top, z up), so
// the map tiles in both directions by construction; any width and height >= 8 work (powers of
// two are what engines want), the aspect C : H is the caller's to match (tex.period_u/_z).
//
// Height (chosen here; the paper draws cracks flat, Fig. 4): the surface layer of thickness D
// (§3.1, the layer's thickness) is the plate; a crack is a groove through it down to the inner
// layer (height 0). Each broken spring's crack is Fig. 4's: centred on the face C1-M-C2, width
// w = l - l0 at the midpoint M. Along the face the width goes linearly from M to the
// centroids, where it is the mean of the cracks meeting there, or 0 where the crack ends (a
// crack tip closes; so a chain of cracks is one groove of smoothly varying width). Weak
// springs (crack_regions.hpp: a crack opened by sliding) are cracks of width 0. Across a
// crack, at distance e from its edge, the plate's edge is rounded over a bevel b:
//     f(e) = 0 (e <= 0),  top·(1 - (1 - e/b)^2) (0 < e < b),  top (e >= b),
// and each pixel takes the exact mean of f over its footprint across the crack (a box of one
// pixel's width, px = max(C/width, H/height)): the integral of f is closed-form, so crack
// edges are anti-aliased at any size, a crack narrower than a pixel still darkens its pixels
// by its share. Where several cracks reach a pixel the lowest value counts. Each plate (a
// region of crack_regions.hpp, else the node's own) has its own top = D·(1 + relief·(g - 1/2))
// and tone 1 + tone·(g' - 1/2) (g, g' hashed from the region's first node; chosen here so
// neighbouring plates read apart in light and colour). A pixel belongs to the plate of the
// nearest node (the node's element is the hexagon the faces bound, Fig. 9).
// Albedo: lerp(crack colour, plate colour·tone, f / top) in sRGB bytes.
// Errors: bark not periodic along the axis, W null, sizes outside [8, 16384], a bevel or
// relief out of range -> invalid_argument; the maps over the memory budget -> too_large.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/bark/bark_params.hpp"
#include "shitsukan/bark/crack_regions.hpp"
#include "shitsukan/bark/cylinder_lattice.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct BarkTextureColors {
    Vec3 plate{0.59f, 0.50f, 0.41f};  // sRGB in [0, 1]
    Vec3 crack{0.11f, 0.08f, 0.05f};
};

// Per species (chosen here, from the look of each bark: camphor grey-brown, Chinese tallow
// grey, pine red-brown plates; the paper prints only grey-scale renderings).
BarkTextureColors bark_texture_colors(Species species);

struct BarkTextureOptions {
    int width = 1024, height = 1024;
    // Rounded plate edge, relative to D (chosen here: 0.25, a quarter of the layer thickness;
    // 0.14 cm for D = 0.55 cm, a few pixels of a 1024 map of a 37 cm trunk).
    float bevel = 0.25f;
    float relief = 0.2f;  // spread of the plate tops, relative to D (chosen here)
    float tone = 0.24f;   // spread of the plate tones (chosen here: the crack map's 0.88-1.12)
    BarkTextureColors colors;
    std::uint32_t seed = 1998;  // the plates' hashed tops and tones
};

struct BarkTexture {
    int width = 0, height = 0;
    float period_u = 0, period_z = 0;   // cm covered: C(t) around, H(t) along
    float max_height = 0;               // cm: the highest plate top (the 16-bit map's 1)
    float cm_per_pixel = 0;             // max(C/width, H/height): the footprint used
    std::vector<float> height_cm;       // row-major, row 0 at the top (z = H)
    std::vector<std::uint8_t> albedo;   // 3 bytes (sRGB) per pixel
    int cracks = 0, plates = 0;         // crack faces drawn (broken + weak), plates toned
    float mean_crack_width = 0;         // cm, over the broken springs (Fig. 4's l - l0)
};

Status make_bark_texture(const BarkCylinder& bark, float t, const Vec3* W,
                         const RegionReport* regions, const BarkTextureOptions& options,
                         BarkTexture& out);

// The filtered profile (exposed for tests): the mean over [x - px/2, x + px/2] of the profile
// across a crack of half-width r, bevel b and top `top`, x the distance from its centre line.
float bark_crack_profile(float x, float r, float b, float top, float px);

}  // namespace shitsukan
