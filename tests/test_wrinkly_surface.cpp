// Tests for lib/shitsukan/wrinkly/{control_mesh, wr_surface, superposition, hierarchical_sampling,
// wr_tessellation}: fujimoto2000 eqs. (15)-(20) and the control-mesh validation.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "shitsukan/geom/tensor_surface.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/superposition.hpp"
#include "shitsukan/wrinkly/wr_surface.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"

using namespace shitsukan;

namespace {

WrControlMesh test_mesh(int cols, int rows) {
    WrControlMesh m = make_control_mesh(cols, rows);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            WrControlPoint& p = m.at(c, r);
            p.position = {float(c), float(r), 0.3f * std::sin(float(c + 2 * r))};
            p.height = 0.2f + 0.1f * float((c * 7 + r * 3) % 5);
            p.color = {float(c) / float(cols - 1), 0.5f, 1.0f - float(r) / float(rows - 1)};
            p.delta = 0.4f;
        }
    return m;
}

// A simple non-identity axis map for the tests that need "some" transformation: reflect the
// coordinate inside every small interval of step k (an involution, like the ISTs, eqs. 8, 13).
float reflect_inverse(const void*, float s, int k) {
    float w = 1.0f;
    for (int i = 0; i < k; ++i) w /= 3.0f;
    float cell = std::floor(s / w);
    return (cell + 1.0f) * w - (s - cell * w);
}

}  // namespace

TEST_CASE("WR surface with zero heights equals the base surface; with K = 0 the plain surface") {
    for (SurfaceBasis basis : {SurfaceBasis::bezier, SurfaceBasis::bspline}) {
        WrControlMesh m =
            test_mesh(basis == SurfaceBasis::bezier ? 4 : 7, basis == SurfaceBasis::bezier ? 4 : 6);
        for (auto& p : m.points) p.height = 0;
        WrSurface s;
        REQUIRE(make_wr_surface(m, basis, 3, s));
        WrAxis au = identity_axis(s.spans_u(), 3), av = identity_axis(s.spans_v(), 3);
        au.inverse = reflect_inverse;
        av.inverse = reflect_inverse;
        REQUIRE(s.set_axes(au, av));
        for (float u : {0.05f, 0.31f, 0.5f, 0.93f})
            for (float v : {0.0f, 0.27f, 0.71f}) {
                const Vec3 r = s.wr_point(u, v, 4);
                const Vec3 p = s.base_point(u, v).position;
                CHECK(length(r - p) < 1e-6f);
            }
        WrControlMesh m2 = test_mesh(m.cols, m.rows);
        REQUIRE(make_wr_surface(m2, basis, 3, s));
        REQUIRE(s.set_axes(au, av));
        // K = 0: F^0 is the identity, R = P + H N exactly.
        const BasePoint b = s.base_point(0.37f, 0.61f);
        const Vec3 expect = b.position + b.normal * s.attributes(0.37f, 0.61f).height;
        CHECK(length(s.wr_point(0.37f, 0.61f, 0) - expect) < 1e-6f);
        // With the transformation on, R differs from the plain surface somewhere.
        CHECK(length(s.wr_point(0.37f, 0.61f, 3) - expect) > 1e-3f);
    }
}

TEST_CASE("superposition weights: eq. (19) and the truncated eq. (18)") {
    for (float d : {0.25f, 0.5f, 0.6f, 0.75f}) {
        for (int K = 0; K <= 8; ++K) {
            float sum = 0;
            for (int k = 0; k <= K; ++k) sum += superposition_weight(d, k);
            CHECK(sum == doctest::Approx(1.0 - std::pow(double(d), K + 1)).epsilon(1e-5));
            CHECK(superposition_weight_sum(d, K) == doctest::Approx(sum).epsilon(1e-5));
        }
        CHECK(superposition_weight(d, 3) == doctest::Approx((1 - d) * d * d * d).epsilon(1e-6));
    }
}

TEST_CASE("hierarchical sampling: samples take H at F^{-1}; H^k passes through them") {
    WrControlMesh m = test_mesh(7, 6);
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    WrAxis au = identity_axis(s.spans_u(), 3), av = identity_axis(s.spans_v(), 3);
    au.inverse = reflect_inverse;
    av.inverse = reflect_inverse;
    REQUIRE(s.set_axes(au, av));
    for (SampleInterpolation mode : {SampleInterpolation::linear, SampleInterpolation::hermite}) {
        HierarchicalOptions o;
        o.levels = 2;
        o.interpolation = mode;
        HierarchicalSampling hs;
        REQUIRE(sample_hierarchy(s, o, hs));
        for (int k = 1; k <= 2; ++k) {
            const auto& pu = hs.positions_u(k);
            const auto& pv = hs.positions_v(k);
            CHECK(int(pu.size()) == s.spans_u() * (k == 1 ? 3 : 9) + 2);  // N^k per span + 2 ends
            for (std::size_t i = 0; i < pu.size(); i += 5)
                for (std::size_t j = 0; j < pv.size(); j += 3) {
                    const float* v = hs.sample(k, int(i), int(j));
                    const WrAttributes h = s.wr_attributes(pu[i], pv[j], k);
                    CHECK(v[0] == doctest::Approx(h.height).epsilon(1e-5));
                    // interpolated H^k passes through the sample (both modes)
                    CHECK(hs.interpolate(k, pu[i], pv[j]).height ==
                          doctest::Approx(v[0]).epsilon(1e-4));
                }
        }
    }
    // k = 0: H^0 is H itself, so with K = 0 the sum is H (the single weight is 1, eq. 18).
    HierarchicalOptions o0;
    o0.levels = 0;
    HierarchicalSampling hs0;
    REQUIRE(sample_hierarchy(s, o0, hs0));
    const SuperposedSample p = superposed_sampled(s, hs0, 0.3f, 0.8f);
    CHECK(p.attributes.height == doctest::Approx(s.attributes(0.3f, 0.8f).height).epsilon(1e-5));
}

TEST_CASE("linear and Hermite interpolation agree at the samples and differ between them") {
    const float x[] = {0.0f, 0.1f, 0.3f, 0.5f, 0.7f, 0.9f, 1.0f};
    const float y[] = {0.0f, 1.0f, -1.0f, 2.0f, 0.5f, 0.0f, 1.0f};
    bool differ = false;
    for (int i = 0; i < 7; ++i) {
        for (float du : {0.0f, 0.037f}) {
            const float u = x[i] + (i < 6 ? du : 0.0f);
            float vals[2];
            int m = 0;
            for (SampleInterpolation mode :
                 {SampleInterpolation::linear, SampleInterpolation::hermite}) {
                int first;
                float w[4];
                sample_interpolation_weights(x, 7, u, mode, &first, w);
                float s = 0, wsum = 0;
                for (int a = 0; a < 4; ++a) {
                    if (w[a] != 0) {
                        REQUIRE(first + a >= 0);
                        REQUIRE(first + a < 7);
                        s += w[a] * y[first + a];
                    }
                    wsum += w[a];
                }
                CHECK(wsum == doctest::Approx(1.0f).epsilon(1e-5));  // constants are reproduced
                vals[m++] = s;
            }
            if (du == 0.0f) {
                CHECK(vals[0] == doctest::Approx(y[i]).epsilon(1e-5));
                CHECK(vals[1] == doctest::Approx(y[i]).epsilon(1e-5));
            } else if (std::fabs(vals[0] - vals[1]) > 1e-3f) {
                differ = true;
            }
        }
    }
    CHECK(differ);
}

TEST_CASE("adaptive end of the superposition: a tolerance drops the small steps") {
    WrControlMesh m = test_mesh(7, 6);
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    REQUIRE(s.set_axes(identity_axis(s.spans_u(), 3), identity_axis(s.spans_v(), 3)));
    HierarchicalOptions o;
    o.levels = 4;
    HierarchicalSampling hs;
    REQUIRE(sample_hierarchy(s, o, hs));
    const SuperposedSample all = superposed_sampled(s, hs, 0.42f, 0.58f, 0.0f);
    CHECK(all.levels_used == 4);
    const float tol = 0.05f;
    const SuperposedSample cut = superposed_sampled(s, hs, 0.42f, 0.58f, tol);
    CHECK(cut.levels_used < 4);
    // What was dropped is bounded by the tolerance (delta^k max|h| < tol), twice that after the
    // weights used are renormalised (eq. 18 on the finite sum).
    CHECK(std::fabs(cut.attributes.height - all.attributes.height) < 2 * tol);
}

TEST_CASE("tessellation: grid, triangle count, superposed vs plain") {
    WrControlMesh m = test_mesh(7, 6);
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    REQUIRE(s.set_axes(identity_axis(s.spans_u(), 3), identity_axis(s.spans_v(), 3)));
    HierarchicalOptions ho;
    ho.levels = 2;
    HierarchicalSampling hs;
    REQUIRE(sample_hierarchy(s, ho, hs));
    WrTessellationOptions o;
    o.grid_level = 2;
    WrMesh wm;
    REQUIRE(tessellate_wr_surface(s, &hs, o, wm));
    CHECK(wm.grid_u == 4 * 9 + 2);
    CHECK(wm.grid_v == 3 * 9 + 2);
    CHECK(wm.mesh.triangle_count() == 2 * (wm.grid_u - 1) * (wm.grid_v - 1));
    CHECK(wm.mesh.colors.size() == wm.mesh.positions.size());
    CHECK(wm.transparency.size() == wm.mesh.positions.size());
    for (const Vec3& n : wm.mesh.normals) CHECK(std::fabs(length(n) - 1.0f) < 1e-4f);
    // zoom window: only parameters inside it
    o.u0 = 0.25f;
    o.u1 = 0.5f;
    REQUIRE(tessellate_wr_surface(s, &hs, o, wm));
    for (const Vec2& uv : wm.mesh.uvs) CHECK((uv.x >= 0.25f && uv.x <= 0.5f));
}

TEST_CASE("bad input gives a clear status, never a crash") {
    WrSurface s;
    WrControlMesh m = test_mesh(7, 6);
    m.points.pop_back();  // not a square grid any more
    Status st = make_wr_surface(m, SurfaceBasis::bspline, 3, s);
    CHECK(!st);
    CHECK(std::string(st.message()).find("square grid") != std::string::npos);
    CHECK(!make_wr_surface(test_mesh(3, 6), SurfaceBasis::bspline, 3, s));   // too small
    CHECK(!make_wr_surface(test_mesh(5, 5), SurfaceBasis::bezier, 3, s));    // Bezier needs 4x4
    m = test_mesh(7, 6);
    m.at(2, 3).delta = 1.0f;
    st = make_wr_surface(m, SurfaceBasis::bspline, 3, s);
    CHECK(!st);
    CHECK(std::string(st.message()).find("delta") != std::string::npos);
    m.at(2, 3).delta = 0.0f;
    CHECK(!make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    m = test_mesh(7, 6);
    m.at(1, 1).position.y = std::nanf("");
    CHECK(!make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    // a huge grid is refused before anything is allocated (was a 65536^2-point resize)
    m = make_control_mesh(1 << 16, 1 << 16);
    CHECK(m.points.empty());
    st = make_wr_surface(m, SurfaceBasis::bspline, 3, s);
    CHECK(!st);
    CHECK(std::string(st.message()).find("limit") != std::string::npos);
    CHECK(make_control_mesh(-3, 5).points.empty());
    CHECK(!make_wr_surface(make_control_mesh(-3, 5), SurfaceBasis::bspline, 3, s));
    m = test_mesh(7, 6);
    m.at(1, 1).transparency = 1.5f;
    CHECK(!make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    REQUIRE(make_wr_surface(test_mesh(7, 6), SurfaceBasis::bspline, 3, s));
    CHECK(!s.set_axes(identity_axis(3), identity_axis(3)));  // base intervals != spans
    HierarchicalOptions o;
    o.levels = 99;
    HierarchicalSampling hs;
    CHECK(!sample_hierarchy(s, o, hs));
    o.levels = -1;
    CHECK(!sample_hierarchy(s, o, hs));
    o.levels = 2;
    o.jitter_height = -1;
    CHECK(!sample_hierarchy(s, o, hs));
    WrTessellationOptions to;
    to.form = WrSurfaceForm::superposed;
    WrMesh wm;
    CHECK(!tessellate_wr_surface(s, nullptr, to, wm));   // eq. (20) needs the sampling
    to.form = WrSurfaceForm::wr;
    to.u0 = 0.6f;
    to.u1 = 0.4f;
    CHECK(!tessellate_wr_surface(s, nullptr, to, wm));
}

TEST_CASE("constant h_i and c_i: eqs. (16) and (20) give h itself for every delta and K (eq. 18)") {
    // Whatever the IST moves, a constant H is moved onto itself, so every step contributes
    // W^k·h. Eq. (18) says the weights add up to 1 and delta only redistributes them; a sum
    // stopped at K keeps that (delta_0 = (1 - delta)/(1 - delta^(K+1))), so the result is h,
    // not h·(1 - delta^(K+1)) (fig. 21 (g) was 23 % low before), and the colour is c.
    for (float delta : {0.25f, 0.6f, 0.75f, 0.95f}) {
        WrControlMesh m = test_mesh(7, 6);
        for (WrControlPoint& p : m.points) {
            p.height = 0.3f;
            p.color = {0.2f, 0.6f, 0.9f};
            p.delta = delta;
        }
        WrSurface s;
        REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
        WrAxis au = identity_axis(s.spans_u(), 3), av = identity_axis(s.spans_v(), 3);
        au.inverse = reflect_inverse;
        av.inverse = reflect_inverse;
        REQUIRE(s.set_axes(au, av));
        for (int K : {0, 1, 3}) {
            for (SampleInterpolation mode :
                 {SampleInterpolation::linear, SampleInterpolation::hermite}) {
                HierarchicalOptions o;
                o.levels = K;
                o.interpolation = mode;
                HierarchicalSampling hs;
                REQUIRE(sample_hierarchy(s, o, hs));
                for (float u : {0.0f, 0.13f, 0.5f, 0.87f})
                    for (float v : {0.07f, 0.61f, 1.0f}) {
                        const WrAttributes d = superposed_attributes_direct(s, u, v, K);
                        const SuperposedSample h = superposed_sampled(s, hs, u, v);
                        CHECK(d.height == doctest::Approx(0.3f).epsilon(1e-4));
                        CHECK(h.attributes.height == doctest::Approx(0.3f).epsilon(1e-4));
                        CHECK(h.levels_used == K);
                        CHECK(length(h.attributes.color - Vec3{0.2f, 0.6f, 0.9f}) < 1e-4f);
                        // eq. (20): displaced along the unit base normal N(u, v)
                        CHECK(length(h.position - (h.base.position +
                                                   h.base.normal * h.attributes.height)) < 1e-4f);
                        // the adaptive end of the sum (§4.2) keeps the total as well
                        const SuperposedSample c = superposed_sampled(s, hs, u, v, 0.05f);
                        CHECK(c.levels_used <= K);
                        CHECK(c.attributes.height == doctest::Approx(0.3f).epsilon(1e-4));
                    }
            }
        }
    }
    // The truncated weights of eq. (19) add up to 1 for every K.
    for (float delta : {0.1f, 0.5f, 0.9f})
        for (int K = 0; K <= 6; ++K) {
            float sum = 0;
            for (int k = 0; k <= K; ++k) sum += superposition_weight_truncated(delta, k, K);
            CHECK(sum == doctest::Approx(1.0f).epsilon(1e-5));
        }
}

TEST_CASE("tessellated normals face the side of N(u, v) = dP/du x dP/dv") {
    // Flat control mesh in the x-y plane (u along +x, v along +y): N = +z everywhere, and the
    // displaced grid's normals must keep that side (not flip with the triangle winding).
    WrControlMesh m = test_mesh(7, 6);
    for (WrControlPoint& p : m.points) p.position.z = 0;
    WrSurface s;
    REQUIRE(make_wr_surface(m, SurfaceBasis::bspline, 3, s));
    CHECK(s.base_point(0.4f, 0.6f).normal.z == doctest::Approx(1.0f));
    WrTessellationOptions o;
    o.form = WrSurfaceForm::plain;
    o.grid_level = 1;
    WrMesh wm;
    REQUIRE(tessellate_wr_surface(s, nullptr, o, wm));
    for (const Vec3& n : wm.mesh.normals) CHECK(n.z > 0.3f);
    // and the triangles wind counter-clockwise seen from +z (their face normal is +z too)
    for (int t = 0; t < wm.mesh.triangle_count(); t += 7) {
        const Vec3 a = wm.mesh.positions[wm.mesh.indices[std::size_t(3 * t)]];
        const Vec3 b = wm.mesh.positions[wm.mesh.indices[std::size_t(3 * t + 1)]];
        const Vec3 c = wm.mesh.positions[wm.mesh.indices[std::size_t(3 * t + 2)]];
        CHECK(cross(b - a, c - a).z > 0);
    }
}

namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const Vec3& a, const Vec3& b) {
    return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

void count_progress(float fraction, void* user) {
    auto* seen = static_cast<std::vector<float>*>(user);
    seen->push_back(fraction);
}

}  // namespace

TEST_CASE("grid evaluation with bases located per row and column: the same bits as per point") {
    for (SurfaceBasis basis : {SurfaceBasis::bspline, SurfaceBasis::bezier}) {
        WrControlMesh m = basis == SurfaceBasis::bezier ? test_mesh(4, 4) : test_mesh(7, 6);
        WrSurface s;
        REQUIRE(make_wr_surface(m, basis, 3, s));
        WrAxis au = identity_axis(s.spans_u(), 3), av = identity_axis(s.spans_v(), 3);
        au.inverse = reflect_inverse;
        av.inverse = reflect_inverse;
        REQUIRE(s.set_axes(au, av));
        // The located bases against geom's evaluate_tensor_surface on the same positions.
        std::vector<float> xyz;
        for (const WrControlPoint& p : m.points)
            xyz.insert(xyz.end(), {p.position.x, p.position.y, p.position.z});
        const TensorGrid g{xyz.data(), m.cols, m.rows, 3};
        for (int n = 0; n < 200; ++n) {
            const float u = float((n * 37) % 101) / 100.0f, v = float((n * 53) % 97) / 96.0f;
            float p[3], pu[3], pv[3];
            evaluate_tensor_surface(basis, 3, g, u, v, p, pu, pv);
            const BasePoint b = s.base_point(s.basis_u(u), s.basis_v(v), u, v);
            CHECK(same_bits(b.position, Vec3{p[0], p[1], p[2]}));
            CHECK(same_bits(b.du, Vec3{pu[0], pu[1], pu[2]}));
            CHECK(same_bits(b.dv, Vec3{pv[0], pv[1], pv[2]}));
        }
        HierarchicalOptions ho;
        ho.levels = 2;
        HierarchicalSampling hs;
        REQUIRE(sample_hierarchy(s, ho, hs));
        for (WrSurfaceForm form : {WrSurfaceForm::base, WrSurfaceForm::plain, WrSurfaceForm::wr,
                                   WrSurfaceForm::superposed_direct, WrSurfaceForm::superposed}) {
            WrTessellationOptions o;
            o.form = form;
            o.levels = 2;
            o.grid_level = 2;
            o.subdivisions = 2;
            o.tail_tolerance = 0.01f;
            std::vector<float> seen;
            o.progress = Progress{count_progress, &seen};
            WrMesh wm;
            REQUIRE(evaluate_wr_grid(s, &hs, o, wm));
            CHECK(!seen.empty());
            CHECK(seen.size() <= 102);
            CHECK(seen.back() == 1.0f);
            for (std::size_t i = 1; i < seen.size(); ++i) CHECK(seen[i] >= seen[i - 1]);
            int mismatches = 0;
            for (std::size_t id = 0; id < wm.mesh.positions.size(); ++id) {
                const float u = wm.mesh.uvs[id].x, v = wm.mesh.uvs[id].y;
                Vec3 want;
                if (form == WrSurfaceForm::base)
                    want = s.base_point(u, v).position;
                else if (form == WrSurfaceForm::plain)
                    want = s.displace(s.base_point(u, v), s.attributes(u, v));
                else if (form == WrSurfaceForm::wr)
                    want = s.wr_point(u, v, 2);
                else if (form == WrSurfaceForm::superposed_direct)
                    want = superposed_point_direct(s, u, v, 2);
                else
                    want = superposed_sampled(s, hs, u, v, 0.01f).position;
                if (!same_bits(wm.mesh.positions[id], want)) ++mismatches;
            }
            CHECK(mismatches == 0);
        }
    }
}

TEST_CASE("fuzz_wr_tessellation finding: control points beyond kMaxWrCoordinate are refused") {
    // fuzz/corpus/fuzz_wr_tessellation/finding_nonfinite_mesh: a point at z = -3.4e35 (another
    // at y = -4.5e11) was accepted and the tessellation had NaN positions and normals.
    WrControlMesh mesh = make_control_mesh(4, 4);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) mesh.at(c, r).position = {c / 3.0f, r / 3.0f, 0.0f};
    REQUIRE(validate_control_mesh(mesh, SurfaceBasis::bspline, 3).ok());
    mesh.at(1, 2).position.z = -3.4e35f;
    Status s = validate_control_mesh(mesh, SurfaceBasis::bspline, 3);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("(1, 2)") != std::string::npos);
    // At the limit everything the surface computes stays finite.
    mesh.at(1, 2).position.z = -kMaxWrCoordinate;
    mesh.at(2, 1).position.y = kMaxWrCoordinate;
    mesh.at(2, 2).height = kMaxWrCoordinate;
    WrSurface surface;
    REQUIRE(make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface).ok());
    for (float u = 0.0f; u <= 1.0f; u += 0.25f)
        for (float v = 0.0f; v <= 1.0f; v += 0.25f) {
            BasePoint b = surface.base_point(u, v);
            CHECK(is_finite(b.position));
            CHECK(is_finite(b.normal));
        }
}

TEST_CASE("fuzz_wr_tessellation finding: jitter_height beyond kMaxJitterHeight is refused") {
    // fuzz/corpus/fuzz_wr_tessellation/finding_jitter_height_overflow: jitter_height = 3.4e38
    // was accepted and the height samples (1 + jitter g) h overflowed: -inf positions.
    WrControlMesh mesh = make_control_mesh(4, 4);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            mesh.at(c, r).position = {c / 3.0f, r / 3.0f, 0.0f};
            mesh.at(c, r).height = 0.1f;
        }
    WrSurface surface;
    REQUIRE(make_wr_surface(mesh, SurfaceBasis::bezier, 3, surface).ok());
    HierarchicalOptions o;
    o.levels = 0;
    o.jitter_height = 3.4e38f;
    HierarchicalSampling hs;
    Status s = sample_hierarchy(surface, o, hs);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("jitter_height") != std::string::npos);
    o.jitter_height = kMaxJitterHeight;
    CHECK(sample_hierarchy(surface, o, hs).ok());
}
