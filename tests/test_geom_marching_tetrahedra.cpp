// Tests for lib/shitsukan/geom/{marching_tetrahedra,mesh_topology}: a sphere comes out closed,
// manifold, outward and of the right size; a cylinder cut by the z faces has two open rims lying
// exactly on the planes; bad boxes and spacings give a Status.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "shitsukan/geom/marching_tetrahedra.hpp"
#include "shitsukan/geom/mesh_topology.hpp"

using namespace shitsukan;

namespace {

float unit_sphere(Vec3 p, const void*) { return length(p) - 1.0f; }
float cylinder_half(Vec3 p, const void*) { return std::sqrt(p.x * p.x + p.y * p.y) - 0.5f; }

double signed_volume(const TriangleMesh& m) {  // divergence theorem
    double v = 0;
    for (int t = 0; t < m.triangle_count(); ++t) {
        Vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
             c = m.positions[m.indices[3 * t + 2]];
        v += double(dot(a, cross(b, c))) / 6.0;
    }
    return v;
}

double surface_area(const TriangleMesh& m) {
    double s = 0;
    for (int t = 0; t < m.triangle_count(); ++t) {
        Vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
             c = m.positions[m.indices[3 * t + 2]];
        s += 0.5 * double(length(cross(b - a, c - a)));
    }
    return s;
}

MarchingTetrahedraOptions sphere_box(float h) {
    MarchingTetrahedraOptions o;
    o.box_min = {-1.3f, -1.25f, -1.2f};  // not centred: the grid is not symmetric
    o.box_max = {1.2f, 1.3f, 1.25f};
    o.spacing = h;
    return o;
}

}  // namespace

TEST_CASE("marching tetrahedra: a sphere is closed, manifold, genus 0 and outward") {
    TriangleMesh m;
    MarchingTetrahedraStats st;
    REQUIRE(marching_tetrahedra(&unit_sphere, nullptr, sphere_box(0.08f), m, &st));
    MeshTopology topo;
    Status s = mesh_topology(m, topo);
    INFO(s.message());
    REQUIRE(s);
    CHECK(topo.manifold);
    CHECK(topo.boundary_edges == 0);
    CHECK(topo.boundary_loops == 0);
    CHECK(topo.euler_characteristic == 2);
    CHECK(topo.unreferenced == 0);
    // Linear interpolation of f = |p| - 1 on an edge of length <= √3 h misses the sphere by at
    // most ~(√3 h)²/8 inward (the chord sag); h = 0.08 -> 2.4e-3 (measured 2.34e-3).
    for (Vec3 p : m.positions) CHECK(std::fabs(length(p) - 1.0f) < 2.5e-3f);
    // Volume and area within 1 % of 4π/3 and 4π (measured: -0.31 %, -0.16 %).
    const double pi = 3.14159265358979;
    CHECK(std::fabs(signed_volume(m) / (4.0 * pi / 3.0) - 1.0) < 0.01);
    CHECK(std::fabs(surface_area(m) / (4.0 * pi) - 1.0) < 0.01);
    // Every triangle faces away from the centre; the normals are the normalised gradient.
    for (int t = 0; t < m.triangle_count(); ++t) {
        Vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
             c = m.positions[m.indices[3 * t + 2]];
        CHECK(dot(cross(b - a, c - a), a + b + c) > 0.0f);
    }
    for (int v = 0; v < m.vertex_count(); ++v)
        CHECK(dot(m.normals[std::size_t(v)], normalize(m.positions[std::size_t(v)])) > 0.9999f);
    CHECK(st.cell.x <= 0.08f);
    CHECK(st.cell.z <= 0.08f);
    // Deterministic: the same call gives the same bits.
    TriangleMesh again;
    REQUIRE(marching_tetrahedra(&unit_sphere, nullptr, sphere_box(0.08f), again));
    REQUIRE(again.positions.size() == m.positions.size());
    CHECK(again.indices == m.indices);
    CHECK(std::memcmp(again.positions.data(), m.positions.data(),
                      m.positions.size() * sizeof(Vec3)) == 0);
}

TEST_CASE("marching tetrahedra: a cylinder cut by both z faces has two rims on the planes") {
    MarchingTetrahedraOptions o;
    o.box_min = {-0.7f, -0.7f, 0.0f};
    o.box_max = {0.7f, 0.7f, 1.0f};
    o.spacing = 0.07f;
    o.cut_z_min = o.cut_z_max = true;
    TriangleMesh m;
    REQUIRE(marching_tetrahedra(&cylinder_half, nullptr, o, m));
    MeshTopology topo;
    REQUIRE(mesh_topology(m, topo));
    CHECK(topo.boundary_loops == 2);
    CHECK(topo.euler_characteristic == 0);  // an open tube (annulus)
    // Boundary vertices lie exactly on z = 0 or z = 1, and every vertex on those planes is on
    // the boundary (cut, not capped).
    std::vector<int> opp;
    REQUIRE(halfedge_opposites(m.indices.data(), m.triangle_count(), m.vertex_count(), opp));
    int rim = 0;
    std::vector<char> on_rim(m.positions.size(), 0);
    for (std::size_t h = 0; h < opp.size(); ++h)
        if (opp[h] < 0) {
            float z = m.positions[m.indices[h]].z;
            CHECK((z == 0.0f || z == 1.0f));
            on_rim[m.indices[h]] = 1;
            ++rim;
        }
    for (std::size_t v = 0; v < m.positions.size(); ++v)
        if (m.positions[v].z == 0.0f || m.positions[v].z == 1.0f) CHECK(on_rim[v]);
    // The rims are the circles of radius 0.5 polygonised: about 2π·0.5/h edges or more each.
    CHECK(rim >= 2 * 40);
    for (Vec3 p : m.positions) CHECK(std::fabs(std::sqrt(p.x * p.x + p.y * p.y) - 0.5f) < 0.003f);
    double area = surface_area(m);
    CHECK(std::fabs(area / (2.0 * 3.14159265358979 * 0.5) - 1.0) < 0.01);

    // One face cut: one rim and a cap (a disc, Euler characteristic 1); none cut: closed.
    o.cut_z_max = false;
    REQUIRE(marching_tetrahedra(&cylinder_half, nullptr, o, m));
    REQUIRE(mesh_topology(m, topo));
    CHECK(topo.boundary_loops == 1);
    CHECK(topo.euler_characteristic == 1);
    o.cut_z_min = false;
    REQUIRE(marching_tetrahedra(&cylinder_half, nullptr, o, m));
    REQUIRE(mesh_topology(m, topo));
    CHECK(topo.boundary_loops == 0);
    CHECK(topo.euler_characteristic == 2);
    CHECK(signed_volume(m) > 0.0);
}

TEST_CASE("marching tetrahedra: lambdas, empty results and bad input") {
    MarchingTetrahedraOptions o = sphere_box(0.2f);
    TriangleMesh m;
    const float r = 0.8f;
    auto ball = [r](Vec3 p) { return length(p) - r; };
    REQUIRE(marching_tetrahedra(ball, o, m));
    CHECK(m.triangle_count() > 0);
    auto nothing = [](Vec3) { return 1.0f; };
    REQUIRE(marching_tetrahedra(nothing, o, m));
    CHECK(m.triangle_count() == 0);

    MarchingTetrahedraOptions bad = o;
    bad.box_min.x = std::nanf("");
    Status s = marching_tetrahedra(ball, bad, m);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::strstr(s.message(), "not finite") != nullptr);
    bad = o;
    bad.box_max.y = bad.box_min.y;
    CHECK(marching_tetrahedra(ball, bad, m).code() == StatusCode::invalid_argument);
    for (float h : {0.0f, -1.0f, std::nanf(""), INFINITY}) {
        bad = o;
        bad.spacing = h;
        CHECK(marching_tetrahedra(ball, bad, m).code() == StatusCode::invalid_argument);
    }
    bad = o;
    bad.spacing = 1e-4f;
    s = marching_tetrahedra(ball, bad, m);
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::strstr(s.message(), "bytes") != nullptr);
}

TEST_CASE("mesh topology: non-manifold meshes are refused, counts of simple meshes") {
    TriangleMesh m;
    for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{1, 1, 1}})
        m.add_vertex(p);
    // A tetrahedron: closed, χ = 2.
    m.add_triangle(0, 2, 1);
    m.add_triangle(0, 1, 3);
    m.add_triangle(1, 2, 3);
    m.add_triangle(2, 0, 3);
    MeshTopology topo;
    REQUIRE(mesh_topology(m, topo));
    CHECK(topo.euler_characteristic == 2);
    CHECK(topo.edges == 6);
    CHECK(topo.unreferenced == 1);
    // A third triangle on edge (0, 1).
    m.add_triangle(0, 1, 4);
    Status s = mesh_topology(m, topo);
    CHECK(!s);
    CHECK(!topo.manifold);
    CHECK(std::strstr(s.message(), "not manifold") != nullptr);
    // Two triangles touching at one vertex only (a bow tie).
    TriangleMesh bow;
    for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{-1, 0, 0}, Vec3{-1, -1, 0}})
        bow.add_vertex(p);
    bow.add_triangle(0, 1, 2);
    bow.add_triangle(0, 3, 4);
    s = mesh_topology(bow, topo);
    CHECK(!s);
    CHECK(std::strstr(s.message(), "bow-tie") != nullptr);
    // Two triangles of opposite orientation on one edge.
    TriangleMesh flipped;
    for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{1, 1, 0}})
        flipped.add_vertex(p);
    flipped.add_triangle(0, 1, 2);
    flipped.add_triangle(1, 2, 3);
    CHECK(!mesh_topology(flipped, topo));
    // A repeated vertex and an index out of range.
    TriangleMesh bad;
    bad.add_vertex({0, 0, 0});
    bad.add_vertex({1, 0, 0});
    bad.add_triangle(0, 1, 1);
    CHECK(mesh_topology(bad, topo).code() == StatusCode::degenerate);
    bad.indices = {0, 1, 7};
    CHECK(mesh_topology(bad, topo).code() == StatusCode::invalid_argument);
}
