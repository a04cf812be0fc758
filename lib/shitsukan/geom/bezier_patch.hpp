// shitsukan/geom/bezier_patch.hpp — bicubic Bezier patches (tokai1994 eq. 5, fig. 16).
//
// Manual
//   BezierPatch patch;                       // patch.p[i][j]: 16 control points P_00..P_33,
//   for (int i = 0; i < 4; ++i)              // i along u, j along v (here a gentle bump)
//       for (int j = 0; j < 4; ++j)
//           patch.p[i][j] = Vec3{i / 3.0f, j / 3.0f, (i % 3 && j % 3) ? 0.3f : 0.0f};
//   Status s = validate_patch(patch);        // finite, no collapsed boundary edge, not flat-0
//   float u = 0.5f, v = 0.25f;
//   PatchPoint q = patch_point(patch, u, v); // position, dP/du, dP/dv, unit normal; u,v in [0,1]
//   float len = patch_iso_length(patch, true, v, 32);   // arc length of the u-curve at v
//   return s;
//
// eq. (5): P(u, v) = sum_i sum_j p_ij B_i(u) B_j(v), B_k(u) = 3!/(k!(3-k)!) u^k (1-u)^(3-k)
// (the Bernstein bases of geom/basis.hpp). The normal is dP/du x dP/dv normalised; where that
// cross product vanishes (a collapsed edge, a cusp) it is taken from a point slightly inside
// the patch, so it is always a finite unit vector (validate_patch still reports the collapse,
// since the texture mapping of §4 needs edges of positive length).
// Small-device: float, no allocation.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct BezierPatch {
    Vec3 p[4][4];  // p[i][j] = P_ij of eq. (5): i is the u index, j the v index
};

struct PatchPoint {
    Vec3 position;
    Vec3 du, dv;  // partial derivatives
    Vec3 normal;  // unit, du x dv direction
};

// eq. (5) and its partial derivatives.
PatchPoint patch_point(const BezierPatch& patch, float u, float v);

// invalid_argument for a NaN/inf control point (the message names P_ij); degenerate for a
// boundary edge shorter than 1e-6 of the control net's size ("edge v = 0 collapses to a
// point") or a net with no extent.
Status validate_patch(const BezierPatch& patch);

// Arc length of an iso-parameter curve, by `steps` chords: along_u = true measures
// u -> P(u, at) from u = 0 to 1, otherwise v -> P(at, v).
float patch_iso_length(const BezierPatch& patch, bool along_u, float at, int steps);

}  // namespace shitsukan
