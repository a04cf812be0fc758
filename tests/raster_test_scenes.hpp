// tests/raster_test_scenes.hpp — hand-made meshes and counting helpers shared by the
// tests/test_raster_*.cpp files (built inline so the rasterizer tests need nothing from
// geom/mesh_builders).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "shitsukan/core/core.hpp"
#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/raster/rasterizer.hpp"

namespace raster_test {

using namespace shitsukan;

// A box with four vertices per face (duplicated corners, as a builder makes for flat
// normals), counter-clockwise seen from outside.
inline TriangleMesh box_mesh(Vec3 lo, Vec3 hi) {
    TriangleMesh m;
    const Vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                       {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                       {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    // Each face: corners in counter-clockwise order seen from outside, and its normal.
    const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6},
                             {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    const Vec3 normals[6] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    for (int f = 0; f < 6; ++f) {
        std::uint32_t a = m.add_vertex(c[faces[f][0]], normals[f], {0, 0});
        std::uint32_t b = m.add_vertex(c[faces[f][1]], normals[f], {1, 0});
        std::uint32_t d = m.add_vertex(c[faces[f][2]], normals[f], {1, 1});
        std::uint32_t e = m.add_vertex(c[faces[f][3]], normals[f], {0, 1});
        m.add_triangle(a, b, d);
        m.add_triangle(a, d, e);
    }
    return m;
}

// A closed UV sphere (poles on y), shared vertices, counter-clockwise from outside.
inline TriangleMesh sphere_mesh(float r, int slices, int stacks) {
    TriangleMesh m;
    std::uint32_t top = m.add_vertex({0, r, 0}, {0, 1, 0});
    for (int i = 1; i < stacks; ++i) {
        float theta = kPi * float(i) / float(stacks);
        for (int j = 0; j < slices; ++j) {
            float phi = kTwoPi * float(j) / float(slices);
            Vec3 n{std::sin(theta) * std::cos(phi), std::cos(theta),
                   -std::sin(theta) * std::sin(phi)};
            m.add_vertex(n * r, n);
        }
    }
    std::uint32_t bottom = m.add_vertex({0, -r, 0}, {0, -1, 0});
    auto ring = [&](int i, int j) { return std::uint32_t(1 + (i - 1) * slices + (j % slices)); };
    for (int j = 0; j < slices; ++j) m.add_triangle(top, ring(1, j), ring(1, j + 1));
    for (int i = 1; i + 1 < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            m.add_triangle(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
            m.add_triangle(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
        }
    for (int j = 0; j < slices; ++j)
        m.add_triangle(bottom, ring(stacks - 1, j + 1), ring(stacks - 1, j));
    return m;
}

// A closed torus around the y axis (not convex: its front layer is not its only layer).
inline TriangleMesh torus_mesh(float big_r, float small_r, int nu, int nv) {
    TriangleMesh m;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            float u = kTwoPi * float(i) / float(nu), v = kTwoPi * float(j) / float(nv);
            Vec3 centre{big_r * std::cos(u), 0, -big_r * std::sin(u)};
            Vec3 n{std::cos(v) * std::cos(u), std::sin(v), -std::cos(v) * std::sin(u)};
            m.add_vertex(centre + n * small_r, n);
        }
    auto id = [&](int i, int j) { return std::uint32_t((i % nu) * nv + (j % nv)); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            m.add_triangle(id(i, j), id(i + 1, j), id(i + 1, j + 1));
            m.add_triangle(id(i, j), id(i + 1, j + 1), id(i, j + 1));
        }
    return m;
}

// Per-pixel write counts of a frame.
struct Counts {
    int width = 0, height = 0;
    std::vector<int> n;
    Counts(int w, int h) : width(w), height(h), n(std::size_t(w) * std::size_t(h), 0) {}
    int& at(int x, int y) { return n[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// Counts, per pixel, how many triangles of `mesh` cover it: each triangle is drawn on its
// own and the depth of the pixels it wrote is reset afterwards, so the depth test cannot
// hide a second write.
inline Counts coverage_per_triangle(const Camera& cam, const MeshView& mesh, CullMode cull,
                                    const Mat4& model = Mat4::identity()) {
    Counts counts(cam.width, cam.height);
    RgbImage color(cam.width, cam.height);
    FloatImage depth(cam.width, cam.height, INFINITY);
    FrameBand band = full_frame_band(color.view(), depth.view());
    std::vector<int> touched;
    auto count = [&](const Fragment& f) {
        ++counts.at(f.x, f.y);
        touched.push_back(f.y * cam.width + f.x);
        return Rgb8{255, 255, 255};
    };
    DrawOptions opt;
    opt.cull = cull;
    opt.model = model;
    for (int t = 0; t < mesh.triangle_count; ++t) {
        MeshView one = mesh;
        one.indices = mesh.indices + 3 * t;
        one.triangle_count = 1;
        Status s = draw_mesh(cam, band, one, opt, count);
        if (!s) counts.n.assign(counts.n.size(), -1000);  // makes every check fail
        for (int i : touched) depth.data()[i] = INFINITY;
        touched.clear();
    }
    return counts;
}

// FNV-1a (32 bit) of a byte range: the golden-image hash.
inline std::uint32_t fnv1a(const void* data, std::size_t bytes, std::uint32_t h = 2166136261u) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
        h ^= p[i];
        h *= 16777619u;
    }
    return h;
}

}  // namespace raster_test
