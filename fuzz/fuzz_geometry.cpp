// fuzz/fuzz_geometry.cpp — geometry and lattice builders on any values, chosen by the first
// byte: 0 triangulate_polygon (up to 4 rings of up to 24 points), 1 marching_tetrahedra (a
// union of up to 3 spheres and a plane, any box and spacing, at most 24^3 cubes),
// 2 isotropic_remesh (the marching-tetrahedra sphere re-meshed with any L, at most 3 passes),
// 3 build_quadtree_lattice (any R, beta, corners, levels and buffer size). Memory budget 16 MiB.
// Contracts (a non-ok Status is always fine):
//   triangulation: every ring vertex once, indices in range, a multiple of 3;
//   marching tetrahedra and remesh: indices in range, positions finite (inside the box, for
//     marching tetrahedra), normals unit or zero, and an oriented manifold (mesh_topology);
//   quadtree: side 2^R + 1 within the buffer; with finite corners, every point of the levels
//     built finite, every point of the levels not built NaN.
#include <cmath>
#include <vector>

#include "fuzz_input.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/geom/isotropic_remesh.hpp"
#include "shitsukan/geom/marching_tetrahedra.hpp"
#include "shitsukan/geom/mesh_topology.hpp"
#include "shitsukan/geom/triangulate.hpp"
#include "shitsukan/solid/quadtree_lattice.hpp"

using namespace shitsukan;

namespace {

void fuzz_triangulate(fuzz::Input& in) {
    std::vector<std::vector<Vec2>> rings(1 + in.take<std::uint8_t>() % 4);
    std::size_t total = 0;
    for (std::vector<Vec2>& ring : rings) {
        ring.resize(in.take<std::uint8_t>() % 25);
        for (Vec2& p : ring) p = {in.value(), in.value()};
        total += ring.size();
    }
    std::vector<Vec2> points;
    std::vector<std::uint32_t> tris;
    if (!triangulate_polygon(rings, points, tris)) return;
    FUZZ_REQUIRE(points.size() == total);
    FUZZ_REQUIRE(tris.size() % 3 == 0);
    for (std::uint32_t i : tris) FUZZ_REQUIRE(i < points.size());
}

struct Blobs {
    Vec3 centre[3];
    float radius[3];
    int count;
    Vec3 plane_normal;
    float plane_offset;
    bool plane;
};

float blobs(Vec3 p, const void* user) {
    const Blobs& b = *static_cast<const Blobs*>(user);
    float f = 1e30f;
    for (int i = 0; i < b.count; ++i) {
        const float d = length(p - b.centre[i]) - b.radius[i];
        f = d < f ? d : f;
    }
    if (b.plane) {
        const float d = dot(p, b.plane_normal) - b.plane_offset;
        f = d < f ? d : f;
    }
    return f;
}

void check_surface(const TriangleMesh& m, bool closed_or_open) {
    const std::size_t n = m.positions.size();
    FUZZ_REQUIRE(m.indices.size() % 3 == 0);
    for (std::uint32_t i : m.indices) FUZZ_REQUIRE(i < n);
    for (const Vec3& p : m.positions) FUZZ_REQUIRE(fuzz::finite3(p));
    for (const Vec3& v : m.normals) {
        FUZZ_REQUIRE(fuzz::finite3(v));
        const float l = length(v);
        FUZZ_REQUIRE(l == 0.0f || std::fabs(l - 1.0f) < 1e-3f);
    }
    if (closed_or_open && !m.indices.empty()) {
        MeshTopology topo;
        FUZZ_REQUIRE(mesh_topology(m, topo).ok());
    }
}

bool marching_setup(fuzz::Input& in, Blobs* b, MarchingTetrahedraOptions* o) {
    b->count = 1 + in.take<std::uint8_t>() % 3;
    for (int i = 0; i < 3; ++i) {
        b->centre[i] = {in.value(), in.value(), in.value()};
        b->radius[i] = in.value();
    }
    b->plane = in.take<std::uint8_t>() & 1;
    b->plane_normal = {in.value(), in.value(), in.value()};
    b->plane_offset = in.value();
    o->box_min = {in.value(), in.value(), in.value()};
    o->box_max = {in.value(), in.value(), in.value()};
    o->spacing = in.value();
    const std::uint8_t flags = in.take<std::uint8_t>();
    o->cut_z_min = flags & 1, o->cut_z_max = flags & 2, o->compute_normals = flags & 4;
    // Keep one input cheap: at most 24 cubes an axis (time, not correctness).
    for (int a = 0; a < 3; ++a) {
        const double cubes = (double(o->box_max[a]) - double(o->box_min[a])) / double(o->spacing);
        if (!(cubes <= 24.0)) return false;
    }
    return true;
}

void fuzz_marching(fuzz::Input& in) {
    Blobs b;
    MarchingTetrahedraOptions o;
    if (!marching_setup(in, &b, &o)) return;
    TriangleMesh m;
    if (!marching_tetrahedra(blobs, &b, o, m)) return;
    check_surface(m, true);
    const float slack = 1e-4f * o.spacing;
    for (const Vec3& p : m.positions)
        for (int a = 0; a < 3; ++a)
            FUZZ_REQUIRE(p[a] >= o.box_min[a] - slack && p[a] <= o.box_max[a] + slack);
}

void fuzz_remesh(fuzz::Input& in) {
    Blobs b{};
    b.count = 1;
    b.radius[0] = 1.0f;
    MarchingTetrahedraOptions o;
    o.box_min = {-1.2f, -1.2f, -1.2f};
    o.box_max = {1.2f, 1.2f, 1.2f};
    o.spacing = 0.3f + float(in.take<std::uint8_t>() % 8) * 0.05f;
    o.cut_z_min = o.cut_z_max = in.take<std::uint8_t>() & 1;
    if (o.cut_z_min) o.box_min.z = -0.5f, o.box_max.z = 0.5f;
    TriangleMesh m;
    FUZZ_REQUIRE(marching_tetrahedra(blobs, &b, o, m).ok());
    IsotropicRemeshOptions r;
    r.target_edge_length = in.value();
    r.passes = int(in.take<std::uint8_t>() % 5) - 1;
    r.newton_steps = int(in.take<std::uint8_t>() % 23) - 1;
    r.smoothing = in.value();
    r.surface = blobs;
    r.user = &b;
    // Keep one input cheap: the sphere's area over L^2 at most ~2000 triangles.
    if (!(r.target_edge_length >= 0.08f) || r.passes > 3) return;
    IsotropicRemeshStats stats;
    if (!isotropic_remesh(r, m, &stats)) return;
    check_surface(m, true);
}

void fuzz_quadtree(fuzz::Input& in) {
    QuadtreeParams q;
    q.R = int(in.take<std::uint8_t>() % 15) - 1;
    q.beta = in.value();
    q.seed = in.take<std::uint32_t>();
    bool finite = true;
    for (float& c : q.corners) {
        c = in.value();
        finite = finite && std::isfinite(c);
    }
    const int levels = int(in.take<std::uint8_t>() % 16) - 2;
    // at most 2^7 + 1 a side here (time, not correctness); the buffer sometimes too small
    const std::size_t side_max = 129;
    std::vector<float> buffer(side_max * side_max);
    std::size_t bytes = buffer.size() * sizeof(float);
    if (in.take<std::uint8_t>() & 1) bytes = in.take<std::uint16_t>();
    if (q.R > 7) return;
    int side = 0;
    if (!build_quadtree_lattice(q, buffer.data(), bytes, side, levels)) return;
    FUZZ_REQUIRE(side == (1 << q.R) + 1);
    FUZZ_REQUIRE(std::size_t(side) * std::size_t(side) * sizeof(float) <= bytes);
    if (!finite) return;
    const int built = levels < 0 || levels > q.R ? q.R : levels;
    const int step = 1 << (q.R - built);  // points on this grid are built
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const float v = buffer[std::size_t(y) * std::size_t(side) + std::size_t(x)];
            if (x % step == 0 && y % step == 0)
                FUZZ_REQUIRE(std::isfinite(v));
            else
                FUZZ_REQUIRE(std::isnan(v));
        }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    set_memory_budget(std::uint64_t(16) << 20);
    fuzz::Input in(data, size);
    switch (in.take<std::uint8_t>() % 4) {
    case 0: fuzz_triangulate(in); break;
    case 1: fuzz_marching(in); break;
    case 2: fuzz_remesh(in); break;
    default: fuzz_quadtree(in); break;
    }
    return 0;
}
