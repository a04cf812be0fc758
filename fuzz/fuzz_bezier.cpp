// fuzz/fuzz_bezier.cpp — Bezier sections (geom/bezier_curve.hpp: validate_section,
// section_at_r, tokai1994 §3.2) and patches (geom/bezier_patch.hpp: validate_patch,
// patch_point, tokai1994 eq. 5) on any control points.
// Contract: a section that validate_section accepts gives, for any finite r, a sample with
// finite z, dr, dz, t in [0, 1], a segment in range, and dr >= 0 (r(t) non-decreasing, up
// to 1e-6 of the largest |r| for rounding);
// z(r) lies within the z range of the section's control points. A patch with finite control
// points gives, for any u, v in [0, 1], a finite position and derivatives and a finite normal
// of unit length (the header's promise, also at collapsed edges and cusps), whether or not
// validate_patch accepts it.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fuzz_input.hpp"
#include "shitsukan/geom/bezier_curve.hpp"
#include "shitsukan/geom/bezier_patch.hpp"

using namespace shitsukan;

namespace {

float value(fuzz::Input& in) {
    const std::uint8_t mode = in.take<std::uint8_t>();
    if (mode & 1) return in.take<float>();
    return float(in.take<std::int16_t>()) / float(1 << (mode >> 4));
}
float unit(fuzz::Input& in) { return float(in.take<std::uint16_t>()) / 65535.0f; }
void section(fuzz::Input& in) {
    BezierChain chain;
    chain.count = int(in.take<std::uint8_t>() % (kMaxChainSegments + 2));
    const bool joined = in.take<std::uint8_t>() & 1;
    for (int k = 0; k < chain.count && k < kMaxChainSegments; ++k)
        for (int i = 0; i < 4; ++i) {
            Vec2& p = chain.segments[k].p[i];
            p = {value(in), value(in)};
            if (joined && k > 0 && i == 0) p = chain.segments[k - 1].p[3];
        }
    if (!validate_section(chain).ok()) return;
    float zmin = INFINITY, zmax = -INFINITY, rscale = 0.0f;
    for (int k = 0; k < chain.count; ++k)
        for (int i = 0; i < 4; ++i) {
            const float z = chain.segments[k].p[i].y;
            rscale = std::max(rscale, std::fabs(chain.segments[k].p[i].x));
            zmin = std::min(zmin, z);
            zmax = std::max(zmax, z);
        }
    const float r0 = section_r_first(chain), r1 = section_r_last(chain);
    for (int j = 0; j < 8 && !in.empty(); ++j) {
        const std::uint8_t mode = in.take<std::uint8_t>();
        const float r = (mode & 1) ? value(in) : r0 + (r1 - r0) * unit(in);
        if (!std::isfinite(r)) continue;
        const SectionSample q = section_at_r(chain, r);
        FUZZ_REQUIRE(q.segment >= 0 && q.segment < chain.count);
        FUZZ_REQUIRE(q.t >= 0.0f && q.t <= 1.0f);
        FUZZ_REQUIRE(std::isfinite(q.z) && std::isfinite(q.dr) && std::isfinite(q.dz));
        FUZZ_REQUIRE(q.dr >= -1e-6f * rscale);  // r(t) non-decreasing, up to rounding
        const float slack = 1e-5f * std::max(1.0f, std::max(std::fabs(zmin), std::fabs(zmax)));
        FUZZ_REQUIRE(q.z >= zmin - slack && q.z <= zmax + slack);
    }
}

void patch(fuzz::Input& in) {
    BezierPatch p;
    const float scale = std::ldexp(1.0f, int(in.take<std::int8_t>()) % 40);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p.p[i][j] = Vec3{value(in), value(in), value(in)} * scale;
    const std::uint8_t collapse = in.take<std::uint8_t>();
    if (collapse & 1)  // a collapsed edge u = 0
        for (int j = 1; j < 4; ++j) p.p[0][j] = p.p[0][0];
    if (collapse & 2)  // a collapsed edge v = 1
        for (int i = 0; i < 3; ++i) p.p[i][3] = p.p[3][3];
    bool finite = true;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) finite = finite && fuzz::finite3(p.p[i][j]);
    const Status s = validate_patch(p);
    if (!finite) {
        FUZZ_REQUIRE(!s.ok());
        return;
    }
    // Overflow of the control net (values near FLT_MAX) is out of scope: derivatives of a
    // finite net can exceed float. Keep to nets whose derivatives fit.
    float mag = 0.0f;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            mag = std::max({mag, std::fabs(p.p[i][j].x), std::fabs(p.p[i][j].y),
                            std::fabs(p.p[i][j].z)});
    if (!(mag < 1e18f)) return;
    for (int k = 0; k < 6 && !in.empty(); ++k) {
        const float u = unit(in), v = unit(in);
        const PatchPoint q = patch_point(p, u, v);
        FUZZ_REQUIRE(fuzz::finite3(q.position) && fuzz::finite3(q.du) && fuzz::finite3(q.dv));
        FUZZ_REQUIRE(fuzz::finite3(q.normal));
        if (s.ok()) FUZZ_REQUIRE(std::fabs(length(q.normal) - 1.0f) < 1e-4f);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    if (in.take<std::uint8_t>() & 1)
        patch(in);
    else
        section(in);
    return 0;
}
