// small-device: yes (no allocation, no exceptions)
#include "shitsukan/raster/clip.hpp"

namespace shitsukan {

namespace detail {

float clip_plane_value(int plane, Vec4 p) {
    switch (plane) {
        case 0: return p.z + p.w;               // near: z_ndc >= -1
        case 1: return kGuardBand * p.w - p.x;  // guard band, right
        case 2: return kGuardBand * p.w + p.x;  // guard band, left
        case 3: return kGuardBand * p.w - p.y;  // guard band, top
        default: return kGuardBand * p.w + p.y; // guard band, bottom
    }
}

namespace {

constexpr int kPlaneCount = 5;

// The point where the edge from `in` (inside, value di >= 0) to `out` (value do < 0) crosses
// the plane. Always evaluated from the inside end so both triangles of a shared edge agree.
ClipSpaceVertex cut_edge(const ClipSpaceVertex& in, float di, const ClipSpaceVertex& out,
                         float d_out) {
    float t = di / (di - d_out);  // in (0, 1]: di >= 0 > d_out
    ClipSpaceVertex r;
    r.clip = in.clip + (out.clip - in.clip) * t;
    r.bary = in.bary + (out.bary - in.bary) * t;
    return r;
}

// Sutherland-Hodgman step: keep the part of polygon `src` on the inside of `plane`.
void clip_against(int plane, const ClipPolygon& src, ClipPolygon* dst) {
    dst->count = 0;
    for (int i = 0; i < src.count; ++i) {
        const ClipSpaceVertex& a = src.v[i];
        const ClipSpaceVertex& b = src.v[(i + 1) % src.count];
        float da = clip_plane_value(plane, a.clip);
        float db = clip_plane_value(plane, b.clip);
        bool a_in = da >= 0.0f, b_in = db >= 0.0f;
        if (a_in && dst->count < kMaxClipVertices) dst->v[dst->count++] = a;
        if (a_in != b_in && dst->count < kMaxClipVertices) {
            dst->v[dst->count++] = a_in ? cut_edge(a, da, b, db) : cut_edge(b, db, a, da);
        }
    }
}

}  // namespace
}  // namespace detail

ClipResult clip_triangle(const ClipSpaceVertex triangle[3], ClipPolygon* out) {
    ClipResult result;
    out->count = 0;
    for (int i = 0; i < 3; ++i) {
        if (!is_finite(triangle[i].clip.x) || !is_finite(triangle[i].clip.y) ||
            !is_finite(triangle[i].clip.z) || !is_finite(triangle[i].clip.w)) {
            result.not_finite = true;
            return result;
        }
    }
    unsigned c0 = clip_outcode(triangle[0].clip), c1 = clip_outcode(triangle[1].clip),
             c2 = clip_outcode(triangle[2].clip);
    if (c0 & c1 & c2 & kOutsideBits) {  // all three beyond one side of the view volume
        result.outside = true;
        return result;
    }
    // Which planes does the triangle cross? (Most triangles: none, and no copy is made.)
    unsigned crossing = (c0 | c1 | c2) & kClipPlaneBits;
    for (int i = 0; i < 3; ++i) out->v[i] = triangle[i];
    out->count = 3;
    if (crossing == 0) return result;
    result.clipped_near = (crossing & 1u) != 0;
    ClipPolygon scratch;
    ClipPolygon* src = out;
    ClipPolygon* dst = &scratch;
    for (int plane = 0; plane < detail::kPlaneCount; ++plane) {
        if (!(crossing & (1u << plane))) continue;
        detail::clip_against(plane, *src, dst);
        ClipPolygon* t = src;
        src = dst;
        dst = t;
        if (src->count < 3) break;
    }
    if (src != out) *out = *src;
    if (out->count < 3) {
        out->count = 0;
        result.outside = true;
    }
    return result;
}

}  // namespace shitsukan
