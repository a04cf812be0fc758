// shitsukan/render/bark_crack_map.hpp — hirota1998 Figs. 4-5: the unrolled bark at time t as a
// picture: plates (the lattice triangles) and every crack as Fig. 4's ribbon (bark/
// crack_drawing.hpp), wrapped around the seam. The hirota1998 figures and `shitsukan bark`
// draw their maps with it.
//
// Manual
//   #include "shitsukan/bark/crack_events.hpp"   // build_cylinder, grow_and_crack
//   CylinderParams p;  p.N_R = 16;  p.N_H = 12;  p.species = species_preset(Species::camphor);
//   BarkCylinder bark;  CrackRun run;
//   Status s = build_cylinder(p, bark);
//   if (s) s = grow_and_crack(bark, CrackRunOptions{}, run);
//   if (!s) return s;
//   int w = 0, h = 0;
//   if (!(s = crack_map_size(bark, p.T, 24.0f, w, h))) return s;   // checked, budgeted
//   RgbImage map(200, 120, Rgb8{250, 250, 248});
//   RasterCanvas canvas(map.view());
//   CrackMapStyle style;  style.origin = {0.0f, 120.0f};  style.px_per_cm = 24.0f;
//   return draw_crack_map(canvas, bark, p.T, bark.net.W.data(), style);
//
// Geometry: (u, z) cm -> pixel (origin.x + u·px_per_cm, origin.y - z·px_per_cm): u around the
// trunk from the seam, z up. A triangle or ribbon reaching past the grown circumference C is
// drawn a second time shifted by -C, so the map tiles around the trunk (one reaching below
// u = 0 is not copied to the right edge, as the figures always drew it).
// Plates are drawn without antialiasing on a RasterCanvas (they tile exactly), cracks with it.
// With `regions` (crack_regions.hpp) each region's plates are drawn slightly lighter or
// darker (factor 0.88 + 0.24·hash, 0.8 for plates in no region; chosen here so the blocks
// read). Weak springs (include_weak) are drawn at min_width_cm as a crack that opened by
// sliding, except weak axial springs (family 1), which are one-node-wide slivers between two
// vertical cracks, not cracks across them (chosen here).
#pragma once

#include "shitsukan/bark/crack_regions.hpp"
#include "shitsukan/bark/cylinder_lattice.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/image/canvas.hpp"

namespace shitsukan {

struct CrackMapStyle {
    Vec2 origin{0.0f, 0.0f};   // pixel of (u, z) = (0, 0): the seam at the bottom
    float px_per_cm = 24.0f;   // pixels per cm
    float min_width_cm = 0.0f; // narrowest crack drawn (a fresh crack has width ~0)
    Rgb8 plate{150, 128, 104}; // grey-brown bark plate (chosen here)
    Rgb8 crack{28, 20, 14};    // near-black crack (chosen here)
    bool draw_plates = true;   // false: only the cracks, on whatever the canvas holds
    bool include_weak = true;  // weak springs drawn as cracks (see the comment above)
    const RegionReport* regions = nullptr;  // optional: shade each region's plates
};

// The bark at time t with displacements W (bark.net.W at t, or a snapshot's). Fails only when
// the cracks cannot be listed (crack_ribbons' Status).
Status draw_crack_map(Canvas& canvas, const BarkCylinder& bark, float t, const Vec3* W,
                      const CrackMapStyle& style);

// The size, in pixels, of the whole unrolled map at t: ceil(C(t)·px_per_cm) x
// ceil(H(t)·px_per_cm), at least 8 x 8, with C(t), H(t) the grown circumference and height
// (Table 1's strains). The size grows with the inputs (L0, N_R, N_H, T, the growth rates), so
// it is checked here, before anyone allocates it: a side past INT_MAX, a side that is not
// finite or px_per_cm not > 0 -> invalid_argument / out_of_range; width·height·3 bytes (an
// 8-bit RGB map) over the memory budget (core/memory_budget.hpp) -> too_large.
Status crack_map_size(const BarkCylinder& bark, float t, float px_per_cm, int& width,
                      int& height);

}  // namespace shitsukan
