// Tests for lib/shitsukan/bark/branch_bark: springs on an irregular mesh, Fig. 9's connection
// areas on it, growth and cracking on the branching trunk (§5).
#include <doctest/doctest.h>
#include "measured.hpp"

#include <cmath>
#include <vector>

#include "shitsukan/bark/branch_bark.hpp"
#include "shitsukan/geom/mesh_builders.hpp"

using namespace shitsukan;

TEST_CASE("connection areas on the branch mesh sum to its area; every spring has a face") {
    BranchBarkParams p;
    p.edge_length = 0.6f;  // coarse: fast
    BranchBark b;
    REQUIRE(build_branch_bark(p, b).ok());
    double total = 0, mesh_area = 0;
    for (float a : b.node_area) total += a;
    for (const ConnectionTriangle& t : b.triangles)
        mesh_area += 0.5 * double(length(cross(t.corner[1] - t.corner[0], t.corner[2] - t.corner[0])));
    CHECK(total == doctest::Approx(mesh_area).epsilon(1e-5));
    int boundary = 0;
    for (std::size_t s = 0; s < b.spring_face.size(); ++s) {
        CHECK(b.spring_face[s] > 0.0f);
        boundary += b.spring_triangles[2 * s + 1] < 0;
        CHECK(b.net.springs[s].k > 0.0f);
    }
    CHECK(boundary > 0);  // the three open ends
    // Each spring is a mesh edge: Euler's formula for the open surface (chi = -1).
    CHECK(b.mesh.vertex_count() - int(b.net.springs.size()) + b.mesh.triangle_count() == -1);
}

TEST_CASE("branch cracks: around the trunk where hoop growth dominates, denser on the branch") {
    BranchBarkParams p;
    p.edge_length = 0.6f;
    BranchBark b;
    REQUIRE(build_branch_bark(p, b).ok());
    CrackRun run;
    REQUIRE(grow_branch_bark(b, CrackRunOptions{}, run).ok());
    REQUIRE(run.breaks.size() > 50);
    int trunk = 0, around = 0, branch = 0;
    double trunk_area = 0, branch_area = 0;
    for (int i = 0; i < b.mesh.vertex_count(); ++i) {
        const LimbDistances d = limb_distances(p.shape, b.mesh.positions[std::size_t(i)]);
        (d.f_trunk < d.f_branch ? trunk_area : branch_area) += b.node_area[std::size_t(i)];
    }
    for (const BarkSpring& s : b.net.springs) {
        if (s.intact()) continue;
        const LimbDistances d =
            limb_distances(p.shape, (b.mesh.positions[s.i] + b.mesh.positions[s.j]) * 0.5f);
        if (d.f_trunk < d.f_branch) {
            ++trunk;
            around += std::fabs(s.n.z) < 0.7f;
        } else {
            ++branch;
        }
    }
    CHECK(float(around) >= 0.6f * float(trunk));
    CHECK(branch / branch_area > trunk / trunk_area);
    // At T no intact spring is past its threshold.
    for (std::uint32_t s = 0; s < std::uint32_t(b.net.springs.size()); ++s)
        if (b.net.springs[s].intact())
            CHECK(p.growth.duration * strain_rate(b.net, s) <= b.net.springs[s].eps_c * 1.0001f);
    // §5.3 "cracks connect naturally between trunk and branch": a crack network (as the picture
    // draws it) reaches kCrotchDepth into both limbs. The crotch itself cracks less than the
    // trunk (the normal offset shortens its concave fillet across the junction): pinned where
    // it stands.
    CrotchCrackStats crotch;
    REQUIRE(crotch_crack_stats(b, p.growth.duration, kCrotchDepth, crotch).ok());
    MEASURED("crossing networks " << crotch.crossing << " of " << crotch.networks
                                 << ", crotch / trunk density "
                                 << crotch.density_crotch / crotch.density_trunk);
    CHECK(crotch.crossing >= 1);
    CHECK(crotch.largest_crossing >= 50);
    CHECK(crotch.density_crotch > 0.4 * crotch.density_trunk);
    CHECK(crotch.density_branch > crotch.density_trunk);
}

TEST_CASE("the crotch-crossing measure on prescribed cracks") {
    BranchBarkParams p;
    p.edge_length = 0.6f;
    BranchBark b;
    REQUIRE(build_branch_bark(p, b).ok());
    CrotchCrackStats st;
    REQUIRE(crotch_crack_stats(b, 1.0f, kCrotchDepth, st).ok());  // nothing broken
    CHECK(st.networks == 0);
    CHECK(st.crossing == 0);
    CHECK(st.density_trunk == 0.0);
    // Every spring of the trunk zone broken (zones 2 cm deep): the cracks, and the intact
    // springs they leave in no intact triangle, stay short of the branch zone.
    const float depth = 2.0f;
    for (std::uint32_t s = 0; s < std::uint32_t(b.net.springs.size()); ++s) {
        const BarkSpring& sp = b.net.springs[s];
        const LimbDistances d =
            limb_distances(p.shape, (b.mesh.positions[sp.i] + b.mesh.positions[sp.j]) * 0.5f);
        if (d.f_trunk < d.f_branch - depth) break_spring(b.net, s, 0.5f);
    }
    REQUIRE(crotch_crack_stats(b, 1.0f, depth, st).ok());
    CHECK(st.networks >= 1);
    CHECK(st.crossing == 0);
    CHECK(st.density_trunk > 0.0);
    CHECK(st.density_branch == 0.0);
    // Before the breaks (t = 0.25) nothing is cracked yet.
    REQUIRE(crotch_crack_stats(b, 0.25f, kCrotchDepth, st).ok());
    CHECK(st.networks == 0);
    // Everything broken: one network spanning both limbs.
    for (std::uint32_t s = 0; s < std::uint32_t(b.net.springs.size()); ++s)
        if (b.net.springs[s].intact()) break_spring(b.net, s, 0.5f);
    REQUIRE(crotch_crack_stats(b, 1.0f, kCrotchDepth, st).ok());
    CHECK(st.networks == 1);
    CHECK(st.crossing == 1);
    CHECK(st.largest_crossing == int(b.net.springs.size()));
    CHECK(crotch_crack_stats(b, -1.0f, kCrotchDepth, st).code() == StatusCode::invalid_argument);
}

namespace {

// Breaks every intact spring of b that crosses the plane dot(x, n) = c and passes `keep`
// (tested on its reference midpoint).
template <class Keep>
void cut_plane(BranchBark& b, Vec3 n, float c, Keep keep) {
    for (std::uint32_t s = 0; s < std::uint32_t(b.net.springs.size()); ++s) {
        const BarkSpring& sp = b.net.springs[s];
        const Vec3 xi = b.mesh.positions[sp.i], xj = b.mesh.positions[sp.j];
        if (sp.intact() && (dot(xi, n) - c) * (dot(xj, n) - c) < 0.0f && keep((xi + xj) * 0.5f))
            break_spring(b.net, s, 0.5f);
    }
}

}  // namespace

TEST_CASE("crossing paths count the cracks across the crotch, networks what they join") {
    BranchBarkParams p;
    p.edge_length = 0.6f;
    BranchBark b;
    REQUIRE(build_branch_bark(p, b).ok());
    // The plane y = 0 (a hair off, clear of vertices on it) holds both axes. On the branch's
    // side (x > 1) it meets the bark in two curves, each from a cut end to a cut end: up the
    // trunk, under the branch and out along it; and down the branch's upper side, through the
    // saddle of the crotch and up the trunk. Each crosses the crotch once.
    cut_plane(b, Vec3{0, 1, 0}, 0.013f, [](Vec3 m) { return m.x > 1.0f; });
    CrotchCrackStats st;
    REQUIRE(crotch_crack_stats(b, 1.0f, kCrotchDepth, st).ok());
    CHECK(st.crossing_paths == 2);
    CHECK(st.crossing == 2);
    // A ring round the branch, 8 cm along its axis and well inside the branch zone, joins the
    // two curves: one network, still two cracks across the crotch.
    const Vec3 u = branch_axis_direction(p.shape), o = p.shape.branch_origin;
    cut_plane(b, u, dot(o, u) + 8.0f, [&](Vec3 m) {
        const LimbDistances d = limb_distances(p.shape, m);
        return d.f_branch < d.f_trunk - 1.0f;
    });
    REQUIRE(crotch_crack_stats(b, 1.0f, kCrotchDepth, st).ok());
    CHECK(st.crossing == 1);
    CHECK(st.crossing_paths == 2);
    // The ring alone crosses nothing.
    BranchBark ring;
    REQUIRE(build_branch_bark(p, ring).ok());
    cut_plane(ring, u, dot(o, u) + 8.0f, [&](Vec3 m) {
        const LimbDistances d = limb_distances(p.shape, m);
        return d.f_branch < d.f_trunk - 1.0f;
    });
    REQUIRE(crotch_crack_stats(ring, 1.0f, kCrotchDepth, st).ok());
    CHECK(st.networks == 1);
    CHECK(st.crossing == 0);
    CHECK(st.crossing_paths == 0);
}

TEST_CASE("§5.2's normal offset shortens the concave crotch; isotropic scaling alone does not") {
    BranchBarkParams p;
    p.edge_length = 0.6f;
    BranchBark b;
    REQUIRE(build_branch_bark(p, b).ok());
    CrotchCrackStats st;
    REQUIRE(crotch_crack_stats(b, 0.0f, kCrotchDepth, st).ok());
    MEASURED("mean edge growth at T: trunk " << st.growth_trunk << ", crotch " << st.growth_crotch
                                             << ", branch " << st.growth_branch);
    // On the limbs r_h + r_n / R around and r_h along; the crotch's fillet is concave across
    // the junction (radius about the blend), where the offset shortens the edges.
    CHECK(st.growth_branch > st.growth_trunk);
    CHECK(st.growth_crotch < 0.5 * st.growth_trunk);
    // Across the junction the fillet (radius about the blend, 1 cm) is concave: r_h - r_n / 1
    // = -0.04; along it, convex round the branch's base.
    MEASURED("crotch edges: across " << st.growth_crotch_across << ", along "
                                     << st.growth_crotch_along);
    CHECK(st.growth_crotch_across < 0.0);
    CHECK(st.growth_crotch_along > 0.0);
    p.growth.r_n = 0.0f;  // isotropic enlargement only: every edge grows by r_h
    REQUIRE(build_branch_bark(p, b).ok());
    REQUIRE(crotch_crack_stats(b, 0.0f, kCrotchDepth, st).ok());
    CHECK(st.growth_trunk == doctest::Approx(p.growth.r_h).epsilon(1e-4));
    CHECK(st.growth_crotch == doctest::Approx(p.growth.r_h).epsilon(1e-4));
    CHECK(st.growth_branch == doctest::Approx(p.growth.r_h).epsilon(1e-4));
    CHECK(st.growth_crotch_across == doctest::Approx(p.growth.r_h).epsilon(1e-4));
}

TEST_CASE("springs on a mesh refuse NaN, degenerate and non-manifold input") {
    TriangleMesh m;
    m.add_vertex({0, 0, 0}), m.add_vertex({1, 0, 0}), m.add_vertex({0, 1, 0}), m.add_vertex({0, 0, 1});
    m.add_triangle(0, 1, 2);
    std::vector<ConnectionTriangle> tris;
    std::vector<std::uint32_t> edges;
    REQUIRE(mesh_springs(m, tris, edges).ok());
    CHECK(edges.size() == 6);
    // Three triangles on one edge: not a manifold.
    TriangleMesh fan = m;
    fan.add_vertex({1, 1, 1});
    fan.add_triangle(0, 1, 3), fan.add_triangle(0, 1, 4);
    CHECK(mesh_springs(fan, tris, edges).code() == StatusCode::invalid_argument);
    TriangleMesh bad = m;
    bad.positions[1].x = std::nanf("");
    CHECK(mesh_springs(bad, tris, edges).code() == StatusCode::invalid_argument);
    TriangleMesh repeated = m;
    repeated.add_triangle(0, 0, 2);
    CHECK(mesh_springs(repeated, tris, edges).code() == StatusCode::invalid_argument);
    // A flat (zero-area) triangle has no connection area.
    TriangleMesh flat;
    flat.add_vertex({0, 0, 0}), flat.add_vertex({1, 0, 0}), flat.add_vertex({2, 0, 0});
    flat.add_triangle(0, 1, 2);
    REQUIRE(mesh_springs(flat, tris, edges).ok());
    std::vector<float> area(3), face(3);
    CHECK(connection_areas(tris.data(), 1, 3, 3, area.data(), face.data()).code() ==
          StatusCode::degenerate);
    BranchBarkParams p;
    p.kappa = 1.0f;
    BranchBark b;
    CHECK(build_branch_bark(p, b).code() == StatusCode::invalid_argument);
    p = BranchBarkParams{};
    p.D = std::nanf("");
    CHECK(build_branch_bark(p, b).code() == StatusCode::invalid_argument);
}

TEST_CASE("the break sequence does not depend on how the mesh is numbered") {
    BranchBarkParams p;
    p.edge_length = 0.6f;
    BranchBark b;
    REQUIRE(build_branch_bark(p, b).ok());
    // The same mesh with its vertices in reverse order.
    TriangleMesh r = b.mesh;
    const int n = r.vertex_count();
    for (int i = 0; i < n; ++i) {
        r.positions[std::size_t(i)] = b.mesh.positions[std::size_t(n - 1 - i)];
        r.normals[std::size_t(i)] = b.mesh.normals[std::size_t(n - 1 - i)];
    }
    for (std::uint32_t& v : r.indices) v = std::uint32_t(n - 1) - v;
    BranchBark rb;
    REQUIRE(build_bark_on_mesh(p, r, rb).ok());
    CrackRun ra, rr;
    REQUIRE(grow_branch_bark(b, CrackRunOptions{}, ra).ok());
    REQUIRE(grow_branch_bark(rb, CrackRunOptions{}, rr).ok());
    REQUIRE(ra.breaks.size() == rr.breaks.size());
    bool same = true;
    for (std::size_t i = 0; i < ra.breaks.size(); ++i)
        same = same && b.net.springs[ra.breaks[i].spring].key == rb.net.springs[rr.breaks[i].spring].key;
    CHECK(same);
    TriangleMesh no_normals = r;
    no_normals.normals.clear();
    CHECK(build_bark_on_mesh(p, no_normals, rb).code() == StatusCode::invalid_argument);
}
