// shitsukan/raster/clip.hpp — homogeneous clipping of one triangle (Sutherland-Hodgman).
//
// Manual
//   Vec4 clip0{-0.5f, -0.5f, 0.5f, 1}, clip1{0.5f, -0.5f, -2.0f, 1}, clip2{0, 0.5f, 0.5f, 1};
//   ClipPolygon poly;
//   ClipSpaceVertex tri[3] = {{clip0, {1, 0, 0}}, {clip1, {0, 1, 0}}, {clip2, {0, 0, 1}}};
//   ClipResult r = clip_triangle(tri, &poly);   // r.outside, r.not_finite, r.clipped_near
//   int fans = 0;
//   for (int i = 1; i + 1 < poly.count; ++i) ++fans;  // draw(poly.v[0], poly.v[i], poly.v[i + 1])
//
// Why in clip space: before the divide by w a point behind the eye (w <= 0) is still on the
// right side of the line through the triangle; clipping there keeps the visible part of a
// triangle with a vertex behind the eye, never dropping it whole nor wrapping it around.
//
// Planes, in this order (a vertex is inside when the value is >= 0):
//   near      z + w          (OpenGL clip space: z_ndc = -1 on the near plane; for an
//                             orthographic camera w = 1 and this is z_ndc >= -1)
//   guard     G·w - x, G·w + x, G·w - y, G·w + y with G = kGuardBand (NDC units): a guard
//             band far outside the screen, so screen coordinates stay small enough for the
//             rasterizer's 64-bit fixed-point arithmetic. Triangles inside it (nearly all)
//             are not touched by these planes.
// Each vertex carries its barycentric coordinates in the ORIGINAL triangle; clipping is
// linear in clip space, so attributes follow from them (the rasterizer interpolates the
// barycentrics perspective-correctly and reads the three original vertices).
// A new vertex on an edge is always computed from the edge's inside end towards its outside
// end, so two triangles sharing an edge get the very same cut point (no cracks).
// At most 3 + 5 = 8 vertices result (one per plane; room for a few more in case rounding
// makes a sliver non-convex); no allocation.
#pragma once

#include "shitsukan/core/vec.hpp"

namespace shitsukan {

constexpr float kGuardBand = 8.0f;  // chosen here: |x|, |y| <= 8·w, i.e. 4 screens each way
constexpr int kMaxClipVertices = 12;

struct ClipSpaceVertex {
    Vec4 clip;  // homogeneous clip coordinates
    Vec3 bary;  // barycentric coordinates in the original triangle
};

struct ClipPolygon {
    ClipSpaceVertex v[kMaxClipVertices];
    int count = 0;
};

struct ClipResult {
    bool not_finite = false;    // a vertex has a NaN/inf coordinate: degenerate, nothing drawn
    bool outside = false;       // nothing of the triangle is inside: nothing drawn
    bool clipped_near = false;  // the near plane cut it
};

// Clips a triangle (counter-clockwise order is kept) against the near plane and the guard
// band. Trivially rejects triangles entirely outside one side of the view volume (x, y or
// the far plane), since nothing of them can be drawn.
ClipResult clip_triangle(const ClipSpaceVertex triangle[3], ClipPolygon* out);

// Outcode of a clip-space point: which clipping planes it is outside of (bits 0-4, in the
// order above) and on which sides of the view volume it lies (bits 5-10: right, left, top,
// bottom, far, near). A triangle whose three outcodes share a view-volume bit is invisible;
// one whose outcodes have no plane bit needs no clipping. NaN gives neither: check finiteness
// first (clip_triangle does).
constexpr unsigned kClipPlaneBits = 0x1fu;
constexpr unsigned kOutsideBits = 0x7e0u;
inline unsigned clip_outcode(Vec4 p) {
    unsigned code = 0;
    if (p.z + p.w < 0.0f) code |= 1u | (1u << 10);  // near (a clipping plane and a side)
    if (kGuardBand * p.w - p.x < 0.0f) code |= 1u << 1;
    if (kGuardBand * p.w + p.x < 0.0f) code |= 1u << 2;
    if (kGuardBand * p.w - p.y < 0.0f) code |= 1u << 3;
    if (kGuardBand * p.w + p.y < 0.0f) code |= 1u << 4;
    if (p.x > p.w) code |= 1u << 5;
    if (p.x < -p.w) code |= 1u << 6;
    if (p.y > p.w) code |= 1u << 7;
    if (p.y < -p.w) code |= 1u << 8;
    if (p.z > p.w) code |= 1u << 9;
    return code;
}

namespace detail {
// Signed distance-like value of a clip point to plane `plane` (0 = near, 1..4 = guard);
// inside when >= 0. Must agree with clip_outcode.
float clip_plane_value(int plane, Vec4 p);
}  // namespace detail

}  // namespace shitsukan
