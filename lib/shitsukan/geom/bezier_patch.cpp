// small-device: yes (no allocation, no exceptions)
#include "shitsukan/geom/bezier_patch.hpp"

#include <cmath>

#include "shitsukan/geom/basis.hpp"

namespace shitsukan {

namespace {

void evaluate(const BezierPatch& patch, float u, float v, Vec3* p, Vec3* du, Vec3* dv) {
    float bu[4], dbu[4], bv[4], dbv[4];
    bernstein_basis(3, u, bu, dbu);  // B_i(u) of eq. (5) and dB_i/du
    bernstein_basis(3, v, bv, dbv);
    Vec3 sp{0, 0, 0}, su{0, 0, 0}, sv{0, 0, 0};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            Vec3 c = patch.p[i][j];
            sp += c * (bu[i] * bv[j]);
            su += c * (dbu[i] * bv[j]);
            sv += c * (bu[i] * dbv[j]);
        }
    *p = sp;
    *du = su;
    *dv = sv;
}

}  // namespace

PatchPoint patch_point(const BezierPatch& patch, float u, float v) {
    PatchPoint q;
    evaluate(patch, u, v, &q.position, &q.du, &q.dv);
    Vec3 n = cross(q.du, q.dv);
    float scale = length(q.du) * length(q.dv);
    if (!(length(n) > 1e-7f * scale) || scale == 0.0f) {
        // Collapsed edge or cusp: the normal's limit, taken a little way inside the patch.
        const float e = 1e-3f;
        for (int k = 0; k < 3 && !(length(n) > 0.0f && length(n) > 1e-7f * scale); ++k) {
            float step = e * float(1 << (3 * k));
            float ui = u < 0.5f ? u + step : u - step;
            float vi = v < 0.5f ? v + step : v - step;
            Vec3 p, du, dv;
            evaluate(patch, ui, vi, &p, &du, &dv);
            n = cross(du, dv);
            scale = length(du) * length(dv);
        }
    }
    // Scaled by its largest component first: near a cusp (or on a tiny patch) the squares of
    // n's components underflow and a plain normalize() gave normals 1.076 long.
    const float big = std::fmax(std::fabs(n.x), std::fmax(std::fabs(n.y), std::fabs(n.z)));
    q.normal = big > 0.0f ? normalize(n / big) : Vec3{0, 0, 1};
    return q;
}

Status validate_patch(const BezierPatch& patch) {
    Vec3 lo = patch.p[0][0], hi = patch.p[0][0];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            if (!is_finite(patch.p[i][j]))
                return Status::error(StatusCode::invalid_argument,
                                     "bezier patch: control point P_%d%d is not finite", i, j);
            lo = vmin(lo, patch.p[i][j]);
            hi = vmax(hi, patch.p[i][j]);
        }
    float size = length(hi - lo);
    if (!(size > 0.0f))
        return Status::error(StatusCode::degenerate,
                             "bezier patch: all 16 control points coincide");
    const char* names[4] = {"v = 0", "v = 1", "u = 0", "u = 1"};
    float lengths[4] = {
        patch_iso_length(patch, true, 0.0f, 16), patch_iso_length(patch, true, 1.0f, 16),
        patch_iso_length(patch, false, 0.0f, 16), patch_iso_length(patch, false, 1.0f, 16)};
    for (int e = 0; e < 4; ++e)
        if (!(lengths[e] > 1e-6f * size))
            return Status::error(StatusCode::degenerate,
                                 "bezier patch: edge %s collapses to a point (length %g); the "
                                 "texture mapping needs edges of positive length",
                                 names[e], double(lengths[e]));
    return Status::success();
}

float patch_iso_length(const BezierPatch& patch, bool along_u, float at, int steps) {
    if (steps < 1) steps = 1;
    float total = 0.0f;
    Vec3 prev, p, du, dv;
    if (along_u)
        evaluate(patch, 0.0f, at, &prev, &du, &dv);
    else
        evaluate(patch, at, 0.0f, &prev, &du, &dv);
    for (int k = 1; k <= steps; ++k) {
        float s = float(k) / float(steps);
        if (along_u)
            evaluate(patch, s, at, &p, &du, &dv);
        else
            evaluate(patch, at, s, &p, &du, &dv);
        total += length(p - prev);
        prev = p;
    }
    return total;
}

}  // namespace shitsukan
