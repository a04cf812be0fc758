// shitsukan/leather/products.hpp — the leather products of tokai1994 §5: the handbag of figs.
// 17-18 (7 bicubic Bezier patches + 2 spherical segments) and the belt of fig. 19.
//
// Manual
//   Handbag bag = make_handbag();                    // the design (chosen here, see below)
//   PatchStripOptions opt;                           // geom/bezier_patch_mesh.hpp
//   TriangleMesh body;
//   Status s = tessellate_patch_strip(bag.patches + bag.body_first, bag.body_count, opt, body);
//   TriangleMesh clasp;
//   if (s) s = make_spherical_segment(bag.clasp[0], 24, 12, clasp);
//   std::vector<BezierPatch> belt;
//   if (s) s = make_belt(BeltDesign{}, belt);       // a coiled strip
//   return s;
//   #include "shitsukan/geom/bezier_patch_mesh.hpp"
//
// The paper prints neither the handbag's control points nor its dimensions, only "7 cubic
// Bezier segments and 2 spherical segments" and the wireframe of fig. 17. Everything below is
// chosen here so that it reads as a handbag (a kiss-lock frame bag with a top handle):
//   units: 1 = the bag's height (about 25 cm); y up, the bag stands on y = 0, front faces +z.
//   patches 0-3, the body: one tube around the bag in the order front, right side, back, left
//     side; v runs up. Its cross-section at the four control heights is a rounded rectangle
//     of half-width W, half-depth D and corner cut k (the patches meet at the 45-degree
//     points of the rounded corners, with collinear control points there: G1, no crease):
//        control row  y      W      D      k
//        0 (bottom)   0.00   0.56   0.28   0.12
//        1            0.34   0.60   0.33   0.14
//        2            0.70   0.63   0.21   0.09
//        3 (frame)    0.92   0.64   0.03   0.015
//     The bag bulges at row 1 and closes to a thin lens at the frame on top.
//   patch 4, the bottom: one patch whose four edges are the four bottom rows of the body, so
//     it closes the tube exactly; its inner control points lie in y = 0.
//   patches 5-6, the handle: an arch from (-0.40, 0.92, 0) up to (0, 1.42, 0) and down to
//     (0.40, 0.92, 0), two patches joined G1 at the top (control points (-0.40, 0.92),
//     (-0.40, 1.25), (-0.22, 1.42), (0, 1.42) and mirrored); across the arch (v) a half-round
//     strap of radius 0.045 (the cubic half-circle (R,0) (R,4R/3) (-R,4R/3) (-R,0) laid
//     across z and along the arch's outward normal).
//   clasp: two spherical segments (the kiss-lock knobs), radius 0.045, centred at
//     (-0.05, 0.95, +0.012) and (+0.05, 0.95, -0.012), cut off below -0.6·radius (where
//     they sit on the frame).
// Tessellating 0-3 as one strip and 5-6 as one strip gives a texture that runs around the
// bag and along the handle without a break (geom/bezier_patch_mesh.hpp), except where the
// tube closes on itself; start the strip at the left side (3, 0, 1, 2) to put that at the
// back left corner.
//
// The belt (fig. 19): a strip of width `width` coiled as a flat spiral, lying on its edge
// (width along y), from radius r0 to r1 over `turns` turns, one cubic patch per quarter turn.
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/bezier_patch.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

// A sphere of radius r about center, kept for heights (along y) from cut_below·r to r:
// cut_below in [-1, 1); -1 keeps the whole sphere.
struct SphericalSegment {
    Vec3 center{0, 0, 0};
    float radius = 1.0f;
    float cut_below = -1.0f;
};

struct Handbag {
    BezierPatch patches[7];
    const char* names[7] = {"front",
                            "right side",
                            "back",
                            "left side",
                            "bottom",
                            "handle (left half)",
                            "handle (right half)"};
    int body_first = 0, body_count = 4;      // the tube strip
    int bottom = 4;                          // one patch
    int handle_first = 5, handle_count = 2;  // the handle strip
    SphericalSegment clasp[2];
};

Handbag make_handbag();

struct BeltDesign {
    float width = 0.40f;  // across the belt (y)
    float r0 = 0.70f;     // inner radius of the coil
    float r1 = 1.25f;     // outer radius
    float turns = 1.5f;   // coil turns (quarter turns are rounded up)
};

// invalid_argument for non-finite or non-positive sizes, r1 <= r0, or turns outside 0.25..8.
Status make_belt(const BeltDesign& design, std::vector<BezierPatch>& out);

// Triangles of a spherical segment (outward normals, uv = (longitude, latitude) in [0, 1]).
// invalid_argument for radius <= 0, cut_below outside [-1, 1), slices < 3 or stacks < 1.
Status make_spherical_segment(const SphericalSegment& segment, int slices, int stacks,
                              TriangleMesh& out);

}  // namespace shitsukan
