// Tests for lib/shitsukan/leather/products: the handbag (7 patches + 2 spherical segments) and
// the belt of tokai1994 §5 fit together without gaps or creases.
#include <doctest/doctest.h>
#include "measured.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "shitsukan/geom/bezier_patch_mesh.hpp"
#include "shitsukan/leather/products.hpp"

using namespace shitsukan;

namespace {

float angle_degrees(Vec3 a, Vec3 b) {
    return std::acos(clamp(dot(normalize(a), normalize(b)), -1.0f, 1.0f)) * 180.0f / kPi;
}

// Winding agrees with the vertex normals for every non-degenerate triangle.
void check_winding(const TriangleMesh& m) {
    int bad = 0;
    for (int t = 0; t < m.triangle_count(); ++t) {
        std::uint32_t a = m.indices[3 * t], b = m.indices[3 * t + 1], c = m.indices[3 * t + 2];
        Vec3 n = cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
        if (length(n) < 1e-12f) continue;
        if (dot(n, m.normals[a] + m.normals[b] + m.normals[c]) <= 0) ++bad;
    }
    CHECK(bad == 0);
}

}  // namespace

TEST_CASE("handbag: 7 valid patches; the body tube and the handle join G1; normals outward") {
    Handbag bag = make_handbag();
    for (int k = 0; k < 7; ++k) {
        INFO("patch " << k << " " << bag.names[k]);
        CHECK(validate_patch(bag.patches[k]).ok());
    }
    // Around the tube: side k's u = 1 edge is side (k+1)'s u = 0 edge, same position and
    // same normal (the control points are collinear across the joint).
    for (int k = 0; k < 4; ++k) {
        const BezierPatch& a = bag.patches[k];
        const BezierPatch& b = bag.patches[(k + 1) % 4];
        for (int s = 0; s <= 10; ++s) {
            float v = float(s) / 10.0f;
            PatchPoint pa = patch_point(a, 1.0f, v), pb = patch_point(b, 0.0f, v);
            CHECK(length(pa.position - pb.position) < 1e-6f);
            CHECK(angle_degrees(pa.normal, pb.normal) < 0.5f);
        }
    }
    // The bottom's four edges are the body's bottom rows; its normal points down.
    const BezierPatch& bottom = bag.patches[bag.bottom];
    for (int s = 0; s <= 10; ++s) {
        float t = float(s) / 10.0f;
        float gap = 1e9f;
        Vec3 q = patch_point(bottom, t, 0.0f).position;
        for (int k = 0; k < 4; ++k)
            for (int r = 0; r <= 200; ++r)
                gap = std::fmin(
                    gap, length(patch_point(bag.patches[k], float(r) / 200.0f, 0.0f).position - q));
        CHECK(gap < 5e-3f);
    }
    CHECK(patch_point(bottom, 0.5f, 0.5f).normal.y < -0.99f);
    // Body normals point away from the bag's axis.
    for (int k = 0; k < 4; ++k)
        for (int s = 0; s <= 4; ++s) {
            PatchPoint q = patch_point(bag.patches[k], float(s) / 4.0f, 0.4f);
            CHECK(dot(q.normal, Vec3{q.position.x, 0, q.position.z}) > 0.0f);
        }
    // Handle halves meet at the top with the same position and normal.
    for (int s = 0; s <= 10; ++s) {
        float v = float(s) / 10.0f;
        PatchPoint a = patch_point(bag.patches[5], 1.0f, v),
                   b = patch_point(bag.patches[6], 0.0f, v);
        CHECK(length(a.position - b.position) < 1e-6f);
        CHECK(angle_degrees(a.normal, b.normal) < 0.5f);
    }
    CHECK(patch_point(bag.patches[5], 1.0f, 0.5f).normal.y > 0.99f);  // strap's top faces up
    // Tessellation of the strips succeeds; winding follows the normals.
    PatchStripOptions opt;
    opt.segments_u = opt.segments_v = 8;
    TriangleMesh body, handle, bottom_mesh, knob;
    REQUIRE(tessellate_patch_strip(bag.patches, 4, opt, body).ok());
    REQUIRE(tessellate_patch_strip(bag.patches + 5, 2, opt, handle).ok());
    REQUIRE(tessellate_patch_strip(&bag.patches[4], 1, opt, bottom_mesh).ok());
    check_winding(body);
    check_winding(handle);
    check_winding(bottom_mesh);
    for (const SphericalSegment& s : bag.clasp) {
        REQUIRE(make_spherical_segment(s, 16, 8, knob).ok());
        check_winding(knob);
        for (int i = 0; i < knob.vertex_count(); ++i) {
            CHECK(length(knob.positions[std::size_t(i)] - s.center) == doctest::Approx(s.radius));
            CHECK(knob.positions[std::size_t(i)].y >= s.center.y + s.cut_below * s.radius - 1e-5f);
        }
    }
}

TEST_CASE("belt: a G1 chain of quarter turns; bad designs are refused") {
    std::vector<BezierPatch> belt;
    BeltDesign d;
    REQUIRE(make_belt(d, belt).ok());
    CHECK(belt.size() == 6);  // 1.5 turns
    for (std::size_t k = 0; k + 1 < belt.size(); ++k)
        for (int s = 0; s <= 4; ++s) {
            float v = float(s) / 4.0f;
            PatchPoint a = patch_point(belt[k], 1.0f, v), b = patch_point(belt[k + 1], 0.0f, v);
            CHECK(length(a.position - b.position) < 1e-5f);
            CHECK(angle_degrees(a.normal, b.normal) < 0.5f);
            CHECK(dot(a.normal, Vec3{a.position.x, 0, a.position.z}) > 0.0f);  // faces out
        }
    TriangleMesh m;
    REQUIRE(tessellate_patch_strip(belt.data(), int(belt.size()), PatchStripOptions{}, m).ok());
    check_winding(m);
    BeltDesign bad = d;
    bad.r1 = 0.1f;
    CHECK(!make_belt(bad, belt).ok());
    bad = d;
    bad.turns = NAN;
    CHECK(!make_belt(bad, belt).ok());
    SphericalSegment s;
    s.cut_below = 1.0f;
    CHECK(!make_spherical_segment(s, 8, 8, m).ok());
    s.cut_below = 0.0f;
    CHECK(!make_spherical_segment(s, 2, 8, m).ok());
}

TEST_CASE("handbag: the arc-length mapping keeps the texel density near 1 on the body") {
    // Per-triangle density sqrt(texture area / (scale^2 world area)), 1st..99th percentile.
    Handbag bag = make_handbag();
    auto percentiles = [](const TriangleMesh& m, float scale, float* p1, float* p99) {
        std::vector<float> d;
        for (int t = 0; t < m.triangle_count(); ++t) {
            std::uint32_t a = m.indices[3 * std::size_t(t)], b = m.indices[3 * std::size_t(t) + 1],
                          c = m.indices[3 * std::size_t(t) + 2];
            float w = 0.5f * length(cross(m.positions[b] - m.positions[a],
                                          m.positions[c] - m.positions[a]));
            float x = 0.5f * std::fabs(cross(m.uvs[b] - m.uvs[a], m.uvs[c] - m.uvs[a]));
            if (w > 1e-9f) d.push_back(std::sqrt(x / (scale * scale * w)));
        }
        std::sort(d.begin(), d.end());
        *p1 = d[d.size() / 100];
        *p99 = d[d.size() * 99 / 100];
    };
    PatchStripOptions opt;
    opt.segments_u = opt.segments_v = 32;
    opt.texture_scale = 0.8f;
    TriangleMesh arc, plain;
    REQUIRE(tessellate_patch_strip(bag.patches, 4, opt, arc).ok());
    opt.arc_length = false;
    REQUIRE(tessellate_patch_strip(bag.patches, 4, opt, plain).ok());
    float a1, a99, p1, p99;
    percentiles(arc, 0.8f, &a1, &a99);
    percentiles(plain, 0.8f, &p1, &p99);
    MEASURED("body texel density 1st..99th percentile: arc length "
            << a1 << ".." << a99 << ", plain (u, v) " << p1 << ".." << p99);
    // Measured 1.00..1.25 (the rest: the side panels taper to the thin frame) vs 0.70..2.82.
    CHECK(a1 > 0.95f);
    CHECK(a99 < 1.3f);
    CHECK(p99 / p1 > 2.0f * (a99 / a1));
}
