// shitsukan/bark/crack_drawing.hpp — hirota1998 Fig. 4: a broken spring drawn as a crack.
//
// Manual
//   CylinderParams params;  params.N_R = 16;  params.N_H = 12;  // a small trunk (chosen 128 x 64)
//   params.species = species_preset(Species::camphor);
//   BarkCylinder bark;
//   Status s = build_cylinder(params, bark);
//   CrackRun run;
//   if (s) s = grow_and_crack(bark, CrackRunOptions{}, run);
//   if (!s) return s;
//   float T = params.T;
//   const Vec3* W = bark.net.W.data();
//   float t = T;
//   std::vector<CrackRibbon> cracks;
//   s = crack_ribbons(bark, t, W, cracks);          // one per spring broken by time t
//   Vec3 quads[2][4];
//   if (!cracks.empty()) ribbon_quads(cracks[0], quads);  // fill both quads in a dark colour
//   return s;
//   #include "shitsukan/bark/crack_events.hpp"
//
// The paper (§3.1, Fig. 4): "l is the node distance and l0 the natural length of the spring:
// a crack appears at the middle of the connection the spring represents, and its width is the
// amount by which the node distance exceeds the original length". So for a spring broken by
// time t: its two nodes at x_i, x_j (unrolled, at t), l = |x_j - x_i|, the crack centred on the
// midpoint M with width w = l - l0 measured along the spring, lying along the face the spring
// represents: the element boundary C1-M-C2 shared by the two nodes (Fig. 9; C1, C2 the
// centroids of the spring's triangles at t; on the regular lattice the hexagon side of length
// L0/sqrt(3) across the spring). A spring on the free top or bottom edge has one triangle; its
// face is continued through M to the mirror of C1. Cracks of neighbouring springs meet at the
// shared centroids, so a chain of broken springs draws as one continuous crack.
//
// Weak springs (include_weak): intact but in no intact triangle (crack_regions.hpp), i.e. the
// sliding lattice-line mechanism; they get width 0 (draw them at the minimum visible width) so
// a crack that opened by sliding still reads as one line.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/bark/cylinder_lattice.hpp"

namespace shitsukan {

struct CrackRibbon {
    std::uint32_t spring = 0;
    Vec3 node[2];       // x_i, x_j at t (unrolled; x_j seam-corrected next to x_i)
    Vec3 midpoint;      // M
    Vec3 along;         // unit vector x_i -> x_j
    Vec3 face[2];       // C1, C2: the ends of the shared face
    float l = 0, l0 = 0;
    float width = 0;    // l - l0 (0 for a weak spring)
    bool weak = false;
};

CrackRibbon crack_ribbon(const BarkCylinder& bark, std::uint32_t spring, float t, const Vec3* W);

// Every spring broken by time t (and, with include_weak, every weak spring), in spring order.
Status crack_ribbons(const BarkCylinder& bark, float t, const Vec3* W,
                     std::vector<CrackRibbon>& out, bool include_weak = false);

// The ribbon as two quads, C1-M and M-C2, each widened by width/2 (at least min_width/2) on
// both sides along the spring.
void ribbon_quads(const CrackRibbon& ribbon, Vec3 quads[2][4], float min_width = 0.0f);

// Mean width of the given springs' cracks at t (Fig. 4's l - l0), for "cracks widen as the
// trunk grows".
float mean_crack_width(const BarkCylinder& bark, const std::uint32_t* springs, int count,
                       float t, const Vec3* W);

}  // namespace shitsukan
