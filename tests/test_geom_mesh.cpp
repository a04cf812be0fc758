// Tests for lib/shitsukan/geom/mesh_builders, triangulate, block_letters, obj:
// closed solids are watertight and outward-facing with the right volume.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <tuple>

#include "shitsukan/geom/block_letters.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/geom/obj.hpp"
#include "shitsukan/geom/triangulate.hpp"

using namespace shitsukan;

namespace {

using Key = std::tuple<float, float, float>;
Key key(Vec3 p) { return Key{p.x, p.y, p.z}; }

// Every directed edge (by exact end-point positions) must be matched by its reverse exactly
// once: the surface is closed, with consistent orientation, and has no cracks.
bool watertight(const TriangleMesh& m, std::string* why) {
    std::map<std::pair<Key, Key>, int> directed;
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            Vec3 a = m.positions[m.indices[t + std::size_t(k)]];
            Vec3 b = m.positions[m.indices[t + std::size_t((k + 1) % 3)]];
            directed[{key(a), key(b)}] += 1;
        }
    for (auto& [e, count] : directed) {
        auto it = directed.find({e.second, e.first});
        int back = it == directed.end() ? 0 : it->second;
        if (count != back) {
            char buf[160];
            std::snprintf(buf, sizeof buf, "edge (%g,%g,%g)->(%g,%g,%g) used %d times, reverse %d",
                          double(std::get<0>(e.first)), double(std::get<1>(e.first)),
                          double(std::get<2>(e.first)), double(std::get<0>(e.second)),
                          double(std::get<1>(e.second)), double(std::get<2>(e.second)), count,
                          back);
            *why = buf;
            return false;
        }
    }
    return true;
}

double volume(const TriangleMesh& m) {  // divergence theorem: sum of signed tetrahedra
    double v = 0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        Vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
             c = m.positions[m.indices[t + 2]];
        v += double(dot(a, cross(b, c))) / 6.0;
    }
    return v;
}

// Vertex normals are unit and agree with the winding of every triangle that uses them.
void check_normals(const TriangleMesh& m) {
    REQUIRE(m.normals.size() == m.positions.size());
    for (const Vec3& n : m.normals) REQUIRE(length(n) == doctest::Approx(1.0f).epsilon(1e-4));
    int disagree = 0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
        Vec3 fn = cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
        for (std::uint32_t i : {a, b, c})
            if (dot(fn, m.normals[i]) <= 0.0f) ++disagree;
    }
    CHECK(disagree == 0);
}

void check_closed(const TriangleMesh& m, double expected_volume, double rel_tol) {
    std::string why;
    CHECK_MESSAGE(watertight(m, &why), why);
    CHECK(volume(m) == doctest::Approx(expected_volume).epsilon(rel_tol));
    check_normals(m);
}

}  // namespace

TEST_CASE("box, sphere, cylinder, torus: watertight, outward, right volume") {
    TriangleMesh m;
    REQUIRE(make_box({-1, -2, -3}, {1, 2, 3}, m).ok());
    CHECK(m.triangle_count() == 12);
    check_closed(m, 2.0 * 4.0 * 6.0, 1e-6);
    REQUIRE(make_uv_sphere(1.5f, 96, 48, m).ok());
    check_closed(m, 4.0 / 3.0 * kPiD * 1.5 * 1.5 * 1.5, 0.01);
    REQUIRE(make_cylinder(0.5f, -1.0f, 2.0f, 128, true, m).ok());
    check_closed(m, kPiD * 0.25 * 3.0, 0.01);
    REQUIRE(make_torus(1.0f, 0.3f, 128, 64, m).ok());
    check_closed(m, 2.0 * kPiD * kPiD * 1.0 * 0.09, 0.01);
}

TEST_CASE("sphere without its +x+y+z octant is closed and has 7/8 of the volume") {
    TriangleMesh m;
    REQUIRE(make_sphere_without_octant(1.0f, 32, m).ok());
    check_closed(m, 7.0 / 8.0 * 4.0 / 3.0 * kPiD, 0.01);
    // No vertex lies strictly inside the removed octant.
    for (const Vec3& p : m.positions) CHECK_FALSE((p.x > 1e-6f && p.y > 1e-6f && p.z > 1e-6f));
}

TEST_CASE("revolution of a spline profile (a pot) is closed; spline passes its controls") {
    const Vec2d ctrl[] = {{0.0, 0.0}, {0.6, 0.0}, {0.9, 0.5}, {0.5, 1.2}, {0.7, 1.6}, {0.0, 1.6}};
    std::vector<Vec2d> prof;
    REQUIRE(sample_spline(ctrl, 6, 8, prof).ok());
    CHECK(prof.size() == 5 * 8 + 1);
    for (int k = 0; k < 6; ++k) {
        CHECK(prof[std::size_t(k) * 8].x == ctrl[k].x);
        CHECK(prof[std::size_t(k) * 8].y == ctrl[k].y);
    }
    TriangleMesh m;
    REQUIRE(make_revolution(prof.data(), int(prof.size()), 64, m).ok());
    std::string why;
    CHECK_MESSAGE(watertight(m, &why), why);
    CHECK(volume(m) > 0.0);
    check_normals(m);
}

TEST_CASE("triangulation with holes covers outer minus holes") {
    std::vector<std::vector<Vec2>> rings = {{{0, 0}, {4, 0}, {4, 3}, {0, 3}},
                                            {{1, 1}, {1, 2}, {2, 2}, {2, 1}},
                                            {{2.5f, 0.5f}, {3.5f, 0.5f}, {3.0f, 2.5f}}};
    std::vector<Vec2> pts;
    std::vector<std::uint32_t> tris;
    REQUIRE(triangulate_polygon(rings, pts, tris).ok());
    double area = 0;
    for (std::size_t t = 0; t < tris.size(); t += 3) {
        double a2 = double(cross(pts[tris[t + 1]] - pts[tris[t]], pts[tris[t + 2]] - pts[tris[t]]));
        CHECK(a2 > 0);  // counter-clockwise
        area += a2 / 2;
    }
    CHECK(area == doctest::Approx(12.0 - 1.0 - 1.0));
    // Bad input.
    CHECK(triangulate_polygon({{{0, 0}, {1, 0}}}, pts, tris).code() ==
          StatusCode::invalid_argument);
    CHECK(triangulate_polygon({{{0, 0}, {1, 0}, {2, 0}}}, pts, tris).code() ==
          StatusCode::degenerate);
    CHECK_FALSE(triangulate_polygon({{{0, 0}, {1, NAN}, {2, 1}}}, pts, tris).ok());
    // A hole outside the outer ring, a hole crossing it, and nested holes are refused.
    std::vector<Vec2> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    CHECK(triangulate_polygon({square, {{5, 1}, {6, 1}, {6, 2}}}, pts, tris).code() ==
          StatusCode::invalid_argument);
    CHECK(triangulate_polygon({square, {{3, 1}, {5, 1}, {3, 2}}}, pts, tris).code() ==
          StatusCode::invalid_argument);
    CHECK(triangulate_polygon(
              {square, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}, {{1.5f, 1.5f}, {2, 1.5f}, {2, 2}}}, pts,
              tris)
              .code() == StatusCode::invalid_argument);
}

TEST_CASE("block letters: NAGOYA extrudes to closed solids with the outline's area") {
    for (char c : std::string("AEFGHILNOTY")) {
        std::vector<std::vector<Vec2>> rings;
        REQUIRE(block_letter_outline(c, rings).ok());
        double area = 0;
        for (std::size_t r = 0; r < rings.size(); ++r)
            area += std::abs(signed_area2(rings[r])) / 2 * (r == 0 ? 1 : -1);
        TriangleMesh m;
        INFO("letter " << c);
        REQUIRE(make_extrusion(rings, 0.0f, 0.25f, m).ok());
        check_closed(m, area * 0.25, 1e-4);
    }
    TriangleMesh text;
    REQUIRE(make_block_text("NAGOYA", 1.0f, 0.3f, text).ok());
    std::string why;
    CHECK_MESSAGE(watertight(text, &why), why);
    CHECK(make_block_text("NAGOYA!", 1.0f, 0.3f, text).code() == StatusCode::not_supported);
}

TEST_CASE("mesh builders reject bad input with a clear status") {
    TriangleMesh m;
    CHECK(make_box({0, 0, 0}, {0, 1, 1}, m).code() == StatusCode::invalid_argument);
    CHECK(make_uv_sphere(-1.0f, 8, 8, m).code() == StatusCode::invalid_argument);
    CHECK(make_uv_sphere(NAN, 8, 8, m).code() == StatusCode::invalid_argument);
    CHECK(make_uv_sphere(1.0f, 2, 8, m).code() == StatusCode::invalid_argument);
    CHECK(make_torus(1.0f, 1.5f, 8, 8, m).code() == StatusCode::invalid_argument);
    CHECK(make_cylinder(1.0f, 2.0f, 1.0f, 8, true, m).code() == StatusCode::invalid_argument);
    const Vec2d bad[] = {{-1, 0}, {1, 1}};
    CHECK(make_revolution(bad, 2, 16, m).code() == StatusCode::invalid_argument);
    CHECK(make_sphere_without_octant(1.0f, 0, m).code() == StatusCode::invalid_argument);
    const Vec2d same[] = {{1, 1}, {1, 1}, {1, 1}};
    CHECK(make_revolution(same, 3, 16, m).code() == StatusCode::degenerate);
    // Repeated profile points are dropped, not turned into flipped triangles.
    const Vec2d repeated[] = {{0, 0}, {1, 0}, {1, 0}, {1, 1}, {1, 1}, {0, 1}};
    REQUIRE(make_revolution(repeated, 6, 32, m).ok());
    std::string why;
    CHECK_MESSAGE(watertight(m, &why), why);
    check_normals(m);
    // Out-of-range indices and singular transforms are refused, not written through.
    TriangleMesh broken;
    broken.add_vertex({0, 0, 0});
    broken.add_triangle(0, 1, 2);
    CHECK(compute_vertex_normals(broken).code() == StatusCode::invalid_argument);
    TriangleMesh sink;
    CHECK(append(sink, broken, Mat4::identity()).code() == StatusCode::invalid_argument);
    TriangleMesh box;
    REQUIRE(make_box({0, 0, 0}, {1, 1, 1}, box).ok());
    CHECK(append(sink, box, Mat4::scale({1, 0, 1})).code() == StatusCode::invalid_argument);
    Status s = make_uv_sphere(1.0f, 100000, 8, m);
    CHECK(std::strstr(s.message(), "slices") != nullptr);
}

TEST_CASE("append transforms points and normals; OBJ export writes every element") {
    TriangleMesh a, b;
    REQUIRE(make_box({0, 0, 0}, {1, 1, 1}, a).ok());
    REQUIRE(append(b, a, Mat4::translate({2, 0, 0}) * Mat4::scale({2, 1, 1})).ok());
    CHECK(b.positions.size() == a.positions.size());
    CHECK(volume(b) == doctest::Approx(2.0));
    check_normals(b);
    const char* path = "build/test_geom_mesh.obj";
    REQUIRE(write_obj(path, b).ok());
    std::FILE* f = std::fopen(path, "rb");
    REQUIRE(f != nullptr);
    char line[256];
    int v = 0, vt = 0, vn = 0, faces = 0;
    while (std::fgets(line, sizeof line, f)) {
        if (!std::strncmp(line, "v ", 2))
            ++v;
        else if (!std::strncmp(line, "vt ", 3))
            ++vt;
        else if (!std::strncmp(line, "vn ", 3))
            ++vn;
        else if (!std::strncmp(line, "f ", 2))
            ++faces;
    }
    std::fclose(f);
    std::remove(path);
    CHECK(v == 24);
    CHECK(vt == 24);
    CHECK(vn == 24);
    CHECK(faces == 12);
    CHECK(write_obj("/nonexistent-dir/x.obj", b).code() == StatusCode::io_error);
}
