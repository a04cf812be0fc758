// Tests for lib/shitsukan/geom/isotropic_remesh: near-uniform edges and good angles on a sphere
// and an open cylinder, the topology kept, the rims kept on their planes, bad input refused.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "shitsukan/geom/isotropic_remesh.hpp"
#include "shitsukan/geom/marching_tetrahedra.hpp"
#include "shitsukan/geom/mesh_topology.hpp"

using namespace shitsukan;

namespace {

float unit_sphere(Vec3 p, const void*) { return length(p) - 1.0f; }
float tube(Vec3 p, const void*) { return std::sqrt(p.x * p.x + p.y * p.y) - 1.0f; }

TriangleMesh marched(ImplicitFunction f, Vec3 lo, Vec3 hi, float h, bool cut) {
    MarchingTetrahedraOptions o;
    o.box_min = lo;
    o.box_max = hi;
    o.spacing = h;
    o.cut_z_min = o.cut_z_max = cut;
    TriangleMesh m;
    Status s = marching_tetrahedra(f, nullptr, o, m);
    REQUIRE(s);
    return m;
}

IsotropicRemeshOptions options(ImplicitFunction f, float L) {
    IsotropicRemeshOptions o;
    o.target_edge_length = L;
    o.surface = f;
    return o;
}

}  // namespace

TEST_CASE("isotropic remesh: a marched sphere becomes near-uniform and stays a sphere") {
    TriangleMesh m =
        marched(&unit_sphere, {-1.2f, -1.2f, -1.2f}, {1.2f, 1.2f, 1.2f}, 0.075f, false);
    const float L = 0.15f;
    IsotropicRemeshStats st;
    Status s = isotropic_remesh(options(&unit_sphere, L), m, &st);
    INFO(s.message());
    REQUIRE(s);
    // The marched input is far from uniform (slivers): the remesher does the work.
    CHECK(st.before.edge_length_cv > 0.4);
    CHECK(st.before.fraction_angle_above_25 < 0.8);
    CHECK(st.collapses > 0);
    CHECK(st.flips > 0);
    // Acceptance (docs/papers/hirota1998.md §6): CV < 0.15, 99 % of triangles with min angle
    // > 25°.
    CHECK(st.after.edge_length_cv < 0.15);
    CHECK(st.after.fraction_angle_above_25 >= 0.99);
    CHECK(std::fabs(st.after.edge_length_mean / double(L) - 1.0) < 0.1);
    CHECK(st.after.vertices == m.vertex_count());
    MeshTopology topo;
    REQUIRE(mesh_topology(m, topo));
    CHECK(topo.euler_characteristic == 2);
    CHECK(topo.boundary_loops == 0);
    for (Vec3 p : m.positions) CHECK(std::fabs(length(p) - 1.0f) < 1e-4f);  // projected
    for (int v = 0; v < m.vertex_count(); ++v)
        CHECK(dot(m.normals[std::size_t(v)], normalize(m.positions[std::size_t(v)])) > 0.999f);
    // mesh_quality measures the same numbers.
    MeshQuality q;
    REQUIRE(mesh_quality(m, q));
    CHECK(q.triangles == st.after.triangles);
    CHECK(q.edge_length_cv == doctest::Approx(st.after.edge_length_cv));
    CHECK(std::fabs(q.area / (4.0 * 3.14159265358979) - 1.0) < 0.01);
}

TEST_CASE("isotropic remesh: an open cylinder keeps two rims on their planes; deterministic") {
    const TriangleMesh input =
        marched(&tube, {-1.25f, -1.25f, 0.0f}, {1.25f, 1.25f, 3.0f}, 0.125f, true);
    TriangleMesh m = input;
    const float L = 0.25f;
    IsotropicRemeshStats st;
    REQUIRE(isotropic_remesh(options(&tube, L), m, &st));
    CHECK(st.after.edge_length_cv < 0.15);
    CHECK(st.after.fraction_angle_above_25 >= 0.99);
    MeshTopology topo;
    REQUIRE(mesh_topology(m, topo));
    CHECK(topo.boundary_loops == 2);
    CHECK(topo.euler_characteristic == 0);
    std::vector<int> opp;
    REQUIRE(halfedge_opposites(m.indices.data(), m.triangle_count(), m.vertex_count(), opp));
    int rim = 0;
    for (std::size_t h = 0; h < opp.size(); ++h)
        if (opp[h] < 0) {
            Vec3 p = m.positions[m.indices[h]];
            CHECK((p.z == 0.0f || p.z == 3.0f));
            CHECK(std::fabs(std::sqrt(p.x * p.x + p.y * p.y) - 1.0f) < 1e-4f);
            ++rim;
        }
    // Rim edges near L too: 2π/L ≈ 25 per rim.
    CHECK(rim >= 2 * 20);
    CHECK(rim <= 2 * 32);
    TriangleMesh again = input;
    REQUIRE(isotropic_remesh(options(&tube, L), again));
    REQUIRE(again.positions.size() == m.positions.size());
    CHECK(again.indices == m.indices);
    CHECK(std::memcmp(again.positions.data(), m.positions.data(),
                      m.positions.size() * sizeof(Vec3)) == 0);
}

TEST_CASE("isotropic remesh: bad input gives a Status naming the problem") {
    TriangleMesh good;
    for (Vec3 p : {Vec3{0, 0, 1}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{-1, -1, -1}})
        good.add_vertex(normalize(p));
    good.add_triangle(0, 1, 2);
    good.add_triangle(0, 2, 3);
    good.add_triangle(0, 3, 1);
    good.add_triangle(1, 3, 2);
    TriangleMesh m = good;
    REQUIRE(isotropic_remesh(options(&unit_sphere, 0.5f), m));

    m = good;
    m.positions[2].y = std::nanf("");
    Status s = isotropic_remesh(options(&unit_sphere, 0.5f), m);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::strstr(s.message(), "not finite") != nullptr);

    m = good;
    m.positions[3] = (m.positions[1] + m.positions[2]) * 0.5f;  // triangle 3 collinear
    s = isotropic_remesh(options(&unit_sphere, 0.5f), m);
    CHECK(s.code() == StatusCode::degenerate);
    CHECK(std::strstr(s.message(), "degenerate") != nullptr);

    m = good;
    m.indices[5] = m.indices[4];  // a repeated vertex
    CHECK(isotropic_remesh(options(&unit_sphere, 0.5f), m).code() == StatusCode::degenerate);

    m = good;
    m.add_vertex({0.5f, 0.5f, 0.5f});
    m.add_triangle(0, 1, 4);  // a third triangle on edge (0, 1)
    s = isotropic_remesh(options(&unit_sphere, 0.5f), m);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::strstr(s.message(), "not manifold") != nullptr);

    m = good;
    for (float L : {0.0f, -1.0f, std::nanf("")})
        CHECK(isotropic_remesh(options(&unit_sphere, L), m).code() ==
              StatusCode::invalid_argument);
    CHECK(isotropic_remesh(options(nullptr, 0.5f), m).code() == StatusCode::invalid_argument);
    IsotropicRemeshOptions o = options(&unit_sphere, 0.5f);
    o.passes = 0;
    CHECK(isotropic_remesh(o, m).code() == StatusCode::invalid_argument);
    o = options(&unit_sphere, 0.5f);
    o.smoothing = 1.5f;
    CHECK(isotropic_remesh(o, m).code() == StatusCode::invalid_argument);
    s = isotropic_remesh(options(&unit_sphere, 1e-5f), m);
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::strstr(s.message(), "bytes") != nullptr);
    // Nothing was changed by the refused calls.
    CHECK(m.positions.size() == good.positions.size());
}
