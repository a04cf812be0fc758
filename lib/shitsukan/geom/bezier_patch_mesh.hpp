// shitsukan/geom/bezier_patch_mesh.hpp — tessellation of a strip of bicubic Bezier patches
// into a triangle mesh whose uv are texture coordinates corrected by arc length (tokai1994 §4).
//
// Manual
//   BezierPatch strip[3];                      // strip[k]'s edge u = 1 is strip[k+1]'s u = 0
//   for (int k = 0; k < 3; ++k)                // here: three flat unit squares side by side
//       for (int i = 0; i < 4; ++i)
//           for (int j = 0; j < 4; ++j) strip[k].p[i][j] = Vec3{k + i / 3.0f, j / 3.0f, 0.0f};
//   PatchStripOptions opt;                     // defaults below
//   opt.texture_scale = 0.8f;                  // texture units per world unit
//   TriangleMesh mesh;
//   Status s = tessellate_patch_strip(strip, 3, opt, mesh);
//   // mesh.uvs[i] = (x, y): the texture point shown at vertex i (texture units, not [0, 1])
//   return s;
//
// §4: the (u, v) of a patch are "quite distorted seen from space" for some control nets, so
// the texture coordinate is computed from space as well ("空間座標の値も利用して"), for a
// "nearly strip-like" surface onto which a rectangle of the leather texture is mapped.
// With arc_length = true (default) the texture point of the vertex at (u, v) is
//   x = origin.x + scale · (arc length of the row v = const from the strip's start to u),
//   y = origin.y + scale · (arc length of the column u = const from v = 0 to v),
// measured across all patches of the strip. Because neighbouring patches share their edge
// curve, both sides of an edge get the same texture points: no seam, and the density is one
// texel per scale along every row and column (it departs from 1 only by the shear between
// rows and columns and the taper of the rows). With arc_length = false the texture point is
// the plain parameter stretched to the same overall size: x = origin.x + scale · (sum of the
// previous patches' mean row lengths + u · this patch's mean row length), y likewise: this
// is the distorted mapping §4 corrects.
// anchor (strip parameter in [0, count], default 0): each row's x is measured from the
// point of the row at that position (rounded to a vertex column; arc_length mode), e.g.
// 0.5 = the middle of the first patch, so the texture's centre line follows a panel's middle.
// reference_row (v in [0, 1], or -1 = off, default): every row takes its x from the arc length
// of the one row at that v (rounded to a vertex row) instead of its own. For a strap bent
// along its length (the handbag's handle: a half-round strap around a tight arch) the rows on
// the outside of the bend are longer than those inside; measured each on its own, their x
// drift apart along the strap and the texture shears (a pattern edge across the strap turns
// into a long diagonal). One reference row (the strap's middle) keeps every column at one x:
// the leather is mapped as a strip bent without stretching along its centre line.
// Options (defaults): segments_u = segments_v = 16 per patch (1..1024), arc_length = true,
// texture_scale = 1, texture_origin = (0, 0), chords = 8 per segment for the arc lengths,
// anchor = 0, reference_row = -1.
// Normals: du x dv of eq. (5), averaged across a shared edge. Triangles counter-clockwise
// seen from the normal side.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/bezier_patch.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

struct PatchStripOptions {
    int segments_u = 16;
    int segments_v = 16;
    bool arc_length = true;
    float texture_scale = 1.0f;
    Vec2 texture_origin{0, 0};
    int chords = 8;
    float anchor = 0.0f;
    float reference_row = -1.0f;  // -1: each row its own arc length; v in [0, 1]: that row's
};

constexpr long long kMaxStripVertices = 1LL << 26;  // keeps int / uint32 indices exact

// invalid_argument for count < 1, sizes outside range, more than kMaxStripVertices vertices,
// a non-finite or non-positive scale, patches that fail validate_patch (the message names the
// patch), or neighbours that do not share their edge (max gap > 1e-4 of the strip's size).
Status tessellate_patch_strip(const BezierPatch* patches, int count,
                              const PatchStripOptions& options, TriangleMesh& out);

// The control net of a patch as line segments (for fig. 16 and wireframes): 24 segments,
// 48 points written to out (out must hold 48).
void patch_control_net(const BezierPatch& patch, Vec3* out);

}  // namespace shitsukan
