// Tests for lib/shitsukan/bark/branch_shape (hirota1998 §5; docs/papers/hirota1998.md §6): the
// trunk-with-branch mesh is a manifold pair of pants of near-uniform edges; the anisotropic growth
// field on a plain cylinder equals the cylinder model's.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "shitsukan/bark/branch_shape.hpp"
#include "shitsukan/geom/marching_tetrahedra.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/geom/mesh_topology.hpp"

using namespace shitsukan;

namespace {

constexpr float kR = 2.5f;  // the trunk radius

float trunk_only(Vec3 p, const void*) { return std::sqrt(p.x * p.x + p.y * p.y) - kR; }

AnisotropicGrowth fig11_growth() {
    AnisotropicGrowth g;
    g.r_h = 0.010f;
    g.r_n = (0.030f - 0.010f) * kR;  // r_n = (r_r - r_h) R_t = 0.05 cm
    g.duration = 100.0f;
    g.centre = {0, 0, 0};
    return g;
}

}  // namespace

TEST_CASE("branch shape: the implicit function and its zones") {
    BranchShapeParams s;
    REQUIRE(validate_branch_shape(s));
    // Far from the crotch the surface is the trunk (radius 2.5) and the branch (radius 1.5).
    CHECK(branch_shape_value(s, {2.5f, 0.0f, 1.0f}) == doctest::Approx(0.0f).epsilon(1e-6));
    CHECK(branch_shape_value(s, {0.0f, 2.5f, 14.0f}) == doctest::Approx(0.0f).epsilon(1e-6));
    const Vec3 u = branch_axis_direction(s);
    const Vec3 on_axis = s.branch_origin + u * 11.0f;  // z = 14.4, x = 7.1
    CHECK(branch_shape_value(s, on_axis) == doctest::Approx(-1.5f).epsilon(1e-5));
    const Vec3 on_branch = on_axis + Vec3{0.0f, 1.5f, 0.0f};
    CHECK(std::fabs(branch_shape_value(s, on_branch)) < 1e-5f);
    // The blend only adds wood: f <= min(f_trunk, f_branch), by at most k/4.
    for (float z = 0.5f; z < 16.0f; z += 0.5f)
        for (float x = -3.0f; x < 10.0f; x += 0.25f) {
            Vec3 p{x, 0.3f, z};
            LimbDistances d = limb_distances(s, p);
            float f = branch_shape_value(s, p), m = std::fmin(d.f_trunk, d.f_branch);
            CHECK(f <= m + 1e-6f);
            CHECK(f >= m - 0.25f * s.blend - 1e-6f);
            // The analytic gradient agrees with central differences.
            Vec3 g = branch_shape_gradient(s, p);
            const float e = 1e-3f;
            Vec3 num{(branch_shape_value(s, p + Vec3{e, 0, 0}) -
                      branch_shape_value(s, p - Vec3{e, 0, 0})) /
                         (2 * e),
                     (branch_shape_value(s, p + Vec3{0, e, 0}) -
                      branch_shape_value(s, p - Vec3{0, e, 0})) /
                         (2 * e),
                     (branch_shape_value(s, p + Vec3{0, 0, e}) -
                      branch_shape_value(s, p - Vec3{0, 0, e})) /
                         (2 * e)};
            CHECK(length(g - num) < 2e-2f);
        }
    LimbDistances d = limb_distances(s, {2.5f, 0.0f, 1.0f});
    CHECK(d.trunk_axis == doctest::Approx(2.5f));
    CHECK(d.f_trunk == doctest::Approx(0.0f));
    CHECK(d.f_trunk < d.f_branch - 0.5f);  // the trunk zone of fig11
    d = limb_distances(s, on_branch);
    CHECK(d.branch_axis == doctest::Approx(1.5f).epsilon(1e-5));
    CHECK(d.f_branch < d.f_trunk - 0.5f);  // the branch zone

    BranchShapeParams bad = s;
    bad.blend = 0.0f;
    CHECK(!validate_branch_shape(bad));
    bad = s;
    bad.trunk_radius = std::nanf("");
    CHECK(!validate_branch_shape(bad));
    bad = s;
    bad.branch_origin.z = 20.0f;
    CHECK(!validate_branch_shape(bad));
    bad = s;
    bad.branch_angle_degrees = 90.0f;
    CHECK(!validate_branch_shape(bad));
}

TEST_CASE("branch mesh: manifold pair of pants with near-uniform edges ") {
    // The figure's size (L0 = 0.33 cm); the mesh docs/papers/hirota1998.md §6 describes.
    BranchShapeParams s;
    TriangleMesh m;
    BranchMeshStats st;
    Status status = make_branch_mesh(s, 0.33f, m, &st);
    INFO(status.message());
    REQUIRE(status);
    MeshTopology topo;
    REQUIRE(mesh_topology(m, topo));
    CHECK(topo.manifold);
    CHECK(topo.boundary_loops == 3);
    CHECK(topo.euler_characteristic == -1);
    CHECK(st.boundary_loops == 3);
    CHECK(st.euler_characteristic == -1);
    // measured 3,465 nodes.
    CHECK(m.vertex_count() > 3000);
    CHECK(m.vertex_count() < 4200);
    CHECK(st.remesh.after.edge_length_cv < 0.15);
    CHECK(st.remesh.after.fraction_angle_above_25 >= 0.99);
    CHECK(std::fabs(st.remesh.after.edge_length_mean / 0.33 - 1.0) < 0.1);
    // On the surface, normals = ∇f/|∇f|, rims on z = 0 and z = 16.
    for (int v = 0; v < m.vertex_count(); ++v) {
        Vec3 p = m.positions[std::size_t(v)];
        CHECK(std::fabs(branch_shape_value(s, p)) < 1e-3f);
        CHECK(length(m.normals[std::size_t(v)] - branch_shape_normal(s, p)) < 1e-6f);
        CHECK(p.z >= 0.0f);
        CHECK(p.z <= 16.0f);
    }
    std::vector<int> opp;
    REQUIRE(halfedge_opposites(m.indices.data(), m.triangle_count(), m.vertex_count(), opp));
    for (std::size_t h = 0; h < opp.size(); ++h)
        if (opp[h] < 0) {
            float z = m.positions[m.indices[h]].z;
            CHECK((z == 0.0f || z == 16.0f));
        }
    CHECK(make_branch_mesh(s, 0.0f, m).code() == StatusCode::invalid_argument);
    CHECK(make_branch_mesh(s, 0.01f, m).code() == StatusCode::too_large);
}

TEST_CASE("growth: s(t), d(t) and the anchor (§5.2, Fig. 10)") {
    AnisotropicGrowth g = fig11_growth();
    REQUIRE(validate_growth(g));
    CHECK(isotropic_scaling(g, 0.0f) == 1.0f);
    CHECK(isotropic_scaling(g, 100.0f) == doctest::Approx(1.01f));
    CHECK(normal_offset(g, 50.0f) == doctest::Approx(0.025f));
    const Vec3 x{2.5f, 0.0f, 4.0f}, n{1.0f, 0.0f, 0.0f};
    Vec3 a = anisotropic_growth_anchor(g, x, n, 100.0f);
    CHECK(a.x == doctest::Approx(2.5f * 1.01f + 0.05f));
    CHECK(a.z == doctest::Approx(4.0f * 1.01f));
    AnisotropicGrowth bad = g;
    bad.duration = 0.0f;
    CHECK(!validate_growth(bad));
    bad = g;
    bad.r_n = std::nanf("");
    CHECK(!validate_growth(bad));
}

TEST_CASE("growth: on a regular cylinder, hoop edges grow at r_h + r_n/R, axial edges at r_h") {
    // make_cylinder's axis is y; c on the axis; its normals are exactly radial.
    TriangleMesh m;
    REQUIRE(make_cylinder(kR, 0.0f, 16.0f, 48, false, m));
    AnisotropicGrowth g = fig11_growth();
    const double hoop = double(g.r_h + g.r_n / kR), axial = double(g.r_h);
    int n_hoop = 0, n_axial = 0;
    for (int t = 0; t < m.triangle_count(); ++t)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t i = m.indices[3 * t + k], j = m.indices[3 * t + (k + 1) % 3];
            Vec3 e = normalize(m.positions[j] - m.positions[i]);
            double rate = double(edge_growth_rate(g, m.positions[i], m.positions[j], m.normals[i],
                                                  m.normals[j])) *
                          g.duration;
            if (std::fabs(e.y) < 1e-4f) {
                CHECK(std::fabs(rate / hoop - 1.0) < 0.05);
                CHECK(std::fabs(rate / hoop - 1.0) < 1e-4);  // exact for a chord: 1/R
                ++n_hoop;
            } else if (std::fabs(e.y) > 1.0f - 1e-4f) {
                CHECK(std::fabs(rate / axial - 1.0) < 1e-4);
                ++n_axial;
            }
        }
    CHECK(n_hoop > 0);
    CHECK(n_axial > 0);
}

TEST_CASE("growth: on a remeshed cylinder the field equals the cylinder model's (test 16)") {
    // The remesher's mesh of a trunk alone (L0 = 0.5 cm to stay fast), normals ∇f/|∇f|.
    MarchingTetrahedraOptions mt;
    mt.box_min = {-3.0f, -3.0f, 0.0f};
    mt.box_max = {3.0f, 3.0f, 6.0f};
    mt.spacing = 0.25f;
    mt.cut_z_min = mt.cut_z_max = true;
    TriangleMesh m;
    REQUIRE(marching_tetrahedra(&trunk_only, nullptr, mt, m));
    IsotropicRemeshOptions ro;
    ro.target_edge_length = 0.5f;
    ro.surface = &trunk_only;
    REQUIRE(isotropic_remesh(ro, m));
    AnisotropicGrowth g = fig11_growth();
    // ε̂T = r_h + (r_n/R) c², c the edge's circumferential direction cosine: fit a line in c²
    // over all edges; its ends are the axial (c = 0) and hoop (c = 1) rates.
    double s0 = 0, s1 = 0, s2 = 0, sy = 0, sxy = 0, worst = 0;
    double hoop_sum = 0, axial_sum = 0;
    int hoop_n = 0, axial_n = 0;
    for (int t = 0; t < m.triangle_count(); ++t)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t i = m.indices[3 * t + k], j = m.indices[3 * t + (k + 1) % 3];
            Vec3 xi = m.positions[i], xj = m.positions[j];
            Vec3 mid = (xi + xj) * 0.5f;
            Vec3 around = normalize(Vec3{-mid.y, mid.x, 0.0f});
            double c = double(dot(normalize(xj - xi), around)), c2 = c * c;
            double rate = double(edge_growth_rate(g, xi, xj, m.normals[i], m.normals[j])) *
                          double(g.duration);
            double model = double(g.r_h) + double(g.r_n / kR) * c2;
            worst = std::fmax(worst, std::fabs(rate - model) / model);
            s0 += 1;
            s1 += c2;
            s2 += c2 * c2;
            sy += rate;
            sxy += c2 * rate;
            if (c2 > 0.98) {
                hoop_sum += rate;
                ++hoop_n;
            }
            if (c2 < 0.02) {
                axial_sum += rate;
                ++axial_n;
            }
        }
    const double slope = (s0 * sxy - s1 * sy) / (s0 * s2 - s1 * s1);
    const double intercept = (sy - slope * s1) / s0;
    const double hoop = double(g.r_h + g.r_n / kR), axial = double(g.r_h);
    CHECK(std::fabs(intercept / axial - 1.0) < 0.05);
    CHECK(std::fabs((intercept + slope) / hoop - 1.0) < 0.05);
    CHECK(worst < 0.05);  // every edge within 5 % of r_h + (r_n/R) c²
    REQUIRE(hoop_n > 10);
    REQUIRE(axial_n > 10);
    CHECK(std::fabs(hoop_sum / hoop_n / hoop - 1.0) < 0.05);
    CHECK(std::fabs(axial_sum / axial_n / axial - 1.0) < 0.05);
    // The anchors at t: the trunk's radius grows to s(t)·R + d(t) (width 2(sR + d)).
    const float t = 100.0f;
    const double expect = double(isotropic_scaling(g, t) * kR + normal_offset(g, t));
    for (int v = 0; v < m.vertex_count(); ++v) {
        Vec3 a =
            anisotropic_growth_anchor(g, m.positions[std::size_t(v)], m.normals[std::size_t(v)], t);
        CHECK(std::fabs(std::sqrt(double(a.x * a.x + a.y * a.y)) / expect - 1.0) < 1e-4);
    }
}
