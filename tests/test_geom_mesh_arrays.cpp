// geom/mesh_arrays: sphere, cylinder, torus and revolution into caller arrays (no
// allocation) are the vector builders' meshes, vertex for vertex; sizes and refusals.
#include <doctest/doctest.h>

#include <cstring>
#include <string>
#include <vector>

#include "shitsukan/geom/mesh_arrays.hpp"
#include "shitsukan/geom/mesh_builders.hpp"

using namespace shitsukan;

namespace {
struct Arrays {
    std::vector<Vec3> p, n;
    std::vector<Vec2> uv;
    std::vector<std::uint32_t> idx;
    MeshView view;
    explicit Arrays(MeshSizes s)
        : p(std::size_t(s.vertices)), n(p.size()), uv(p.size()), idx(std::size_t(s.indices)) {}
};

bool same_mesh(const MeshView& a, const TriangleMesh& b) {
    if (a.vertex_count != b.vertex_count() || a.triangle_count != b.triangle_count()) return false;
    const std::size_t nv = std::size_t(a.vertex_count);
    return std::memcmp(a.positions, b.positions.data(), nv * sizeof(Vec3)) == 0 &&
           std::memcmp(a.normals, b.normals.data(), nv * sizeof(Vec3)) == 0 &&
           std::memcmp(a.uvs, b.uvs.data(), nv * sizeof(Vec2)) == 0 &&
           std::memcmp(a.indices, b.indices.data(), b.indices.size() * 4) == 0;
}
}  // namespace

TEST_CASE("mesh arrays: sphere, cylinder, torus, revolution equal the vector builders") {
    for (int slices : {3, 7, 32}) {
        Arrays s(uv_sphere_sizes(slices, slices / 2 + 2));
        REQUIRE(make_uv_sphere_arrays(1.5f, slices, slices / 2 + 2, s.p.data(), s.n.data(),
                                      s.uv.data(), int(s.p.size()), s.idx.data(), int(s.idx.size()),
                                      s.view)
                    .ok());
        TriangleMesh m;
        REQUIRE(make_uv_sphere(1.5f, slices, slices / 2 + 2, m).ok());
        CHECK(same_mesh(s.view, m));
        CHECK(s.view.triangle_count * 3 <= int(s.idx.size()));

        for (bool caps : {false, true}) {
            Arrays c(cylinder_sizes(slices, caps));
            REQUIRE(make_cylinder_arrays(0.5f, -1.0f, 2.0f, slices, caps, c.p.data(), c.n.data(),
                                         c.uv.data(), int(c.p.size()), c.idx.data(),
                                         int(c.idx.size()), c.view)
                        .ok());
            REQUIRE(make_cylinder(0.5f, -1.0f, 2.0f, slices, caps, m).ok());
            CHECK(same_mesh(c.view, m));
        }
        for (int minor : {3, 4, 12}) {
            Arrays t(torus_sizes(slices, minor));
            REQUIRE(make_torus_arrays(1.0f, 0.3f, slices, minor, t.p.data(), t.n.data(),
                                      t.uv.data(), int(t.p.size()), t.idx.data(), int(t.idx.size()),
                                      t.view)
                        .ok());
            REQUIRE(make_torus(1.0f, 0.3f, slices, minor, m).ok());
            CHECK(same_mesh(t.view, m));
        }
    }
    const Vec2d cup[] = {{0, 0}, {1, 0}, {1.2, 1.5}, {1.1, 1.5}, {0.9, 0.1}, {0, 0.1}};
    Arrays r(revolution_sizes(cup, 6, 24));
    REQUIRE(make_revolution_arrays(cup, 6, 24, r.p.data(), r.n.data(), r.uv.data(), int(r.p.size()),
                                   r.idx.data(), int(r.idx.size()), r.view)
                .ok());
    TriangleMesh m;
    REQUIRE(make_revolution(cup, 6, 24, m).ok());
    CHECK(same_mesh(r.view, m));
}

TEST_CASE("mesh arrays: too small, repeated profile points, bad counts are refused") {
    const MeshSizes need = uv_sphere_sizes(8, 4);
    CHECK(need.vertices == 45);
    std::vector<Vec3> p(std::size_t(need.vertices)), n(p.size());
    std::vector<std::uint32_t> idx(std::size_t(need.indices));
    MeshView view;
    Status s = make_uv_sphere_arrays(1.0f, 8, 4, p.data(), n.data(), nullptr, need.vertices - 1,
                                     idx.data(), need.indices, view);
    CHECK(s.code() == StatusCode::buffer_too_small);
    CHECK(std::string(s.message()).find("45 vertices") != std::string::npos);
    CHECK(make_uv_sphere_arrays(1.0f, 8, 4, p.data(), n.data(), nullptr, need.vertices, idx.data(),
                                need.indices, view)
              .ok());
    CHECK(view.uvs == nullptr);
    const Vec2d repeated[] = {{1, 0}, {1, 0}, {1, 1}};
    CHECK(make_revolution_arrays(repeated, 3, 8, p.data(), n.data(), nullptr, int(p.size()),
                                 idx.data(), int(idx.size()), view)
              .code() == StatusCode::invalid_argument);
    CHECK(uv_sphere_sizes(2, 4).vertices == 0);
    CHECK(make_torus_arrays(1.0f, 2.0f, 8, 8, p.data(), n.data(), nullptr, int(p.size()),
                            idx.data(), int(idx.size()), view)
              .code() == StatusCode::invalid_argument);
}
