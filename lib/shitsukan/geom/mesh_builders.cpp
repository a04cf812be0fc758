#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/geom/block_letters.hpp"
#include "shitsukan/geom/mesh_arrays.hpp"
#include "shitsukan/geom/triangulate.hpp"

namespace shitsukan {

namespace {

constexpr int kMinSegments = 3, kMaxSegments = 4096;

Status check_segments(const char* what, const char* name, int n, int lo = kMinSegments) {
    if (n < lo || n > kMaxSegments)
        return Status::error(StatusCode::invalid_argument, "%s: %s must be in [%d, %d] (got %d)",
                             what, name, lo, kMaxSegments, n);
    return Status::success();
}

Status check_positive(const char* what, const char* name, float v) {
    if (!(v > 0.0f) || !std::isfinite(v))
        return Status::error(StatusCode::invalid_argument, "%s: %s must be finite and > 0 (got %g)",
                             what, name, double(v));
    return Status::success();
}

// Adds triangle a b c, flipped if needed so that its winding is counter-clockwise seen from
// the side `outward` points to. Zero-area triangles are dropped (poles, axis points).
void add_oriented(TriangleMesh* m, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                  Vec3 outward) {
    Vec3 n = cross(m->positions[b] - m->positions[a], m->positions[c] - m->positions[a]);
    if (length_squared(n) == 0.0f) return;
    if (dot(n, outward) < 0.0f) std::swap(b, c);
    m->add_triangle(a, b, c);
}

}  // namespace

Status make_box(Vec3 lo, Vec3 hi, TriangleMesh& out) {
    // The caller-array builder (mesh_arrays.hpp) is the one box: same vertices, same order.
    Vec3 positions[kBoxVertexCount], normals[kBoxVertexCount];
    Vec2 uvs[kBoxVertexCount];
    std::uint32_t indices[3 * kBoxTriangleCount];
    MeshView box;
    SHITSUKAN_TRY(make_box_arrays(lo, hi, positions, normals, uvs, kBoxVertexCount, indices,
                                  3 * kBoxTriangleCount, box));
    out = TriangleMesh();
    for (int i = 0; i < box.vertex_count; ++i) out.add_vertex(positions[i], normals[i], uvs[i]);
    for (int t = 0; t < box.triangle_count; ++t)
        out.add_triangle(indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]);
    return Status::success();
}

namespace {

// Runs a caller-array builder (mesh_arrays.hpp) into vectors of the sizes it needs, then
// moves the result into out: the small-device builders are the only ones.
template <class Build> Status build_into(MeshSizes need, TriangleMesh& out, Build&& build) {
    std::vector<Vec3> positions(std::size_t(need.vertices)), normals(positions.size());
    std::vector<Vec2> uvs(positions.size());
    std::vector<std::uint32_t> indices(std::size_t(need.indices));
    MeshView view;
    SHITSUKAN_TRY(build(positions.data(), normals.data(), uvs.data(), need.vertices, indices.data(),
                        need.indices, &view));
    out = TriangleMesh();
    for (int i = 0; i < view.vertex_count; ++i)
        out.add_vertex(positions[std::size_t(i)], normals[std::size_t(i)], uvs[std::size_t(i)]);
    for (int t = 0; t < view.triangle_count; ++t)
        out.add_triangle(indices[3 * std::size_t(t)], indices[3 * std::size_t(t) + 1],
                          indices[3 * std::size_t(t) + 2]);
    return Status::success();
}

}  // namespace

Status make_uv_sphere(float radius, int slices, int stacks, TriangleMesh& out) {
    SHITSUKAN_TRY(check_positive("make_uv_sphere", "radius", radius));
    SHITSUKAN_TRY(check_segments("make_uv_sphere", "slices", slices));
    SHITSUKAN_TRY(check_segments("make_uv_sphere", "stacks", stacks, 2));
    return build_into(
        uv_sphere_sizes(slices, stacks), out,
        [&](Vec3* p, Vec3* n, Vec2* uv, int nv, std::uint32_t* i, int ni, MeshView* view) {
            return make_uv_sphere_arrays(radius, slices, stacks, p, n, uv, nv, i, ni, *view);
        });
}

Status make_cylinder(float radius, float y0, float y1, int slices, bool caps, TriangleMesh& out) {
    SHITSUKAN_TRY(check_positive("make_cylinder", "radius", radius));
    SHITSUKAN_TRY(check_segments("make_cylinder", "slices", slices));
    if (!std::isfinite(y0) || !std::isfinite(y1) || !(y0 < y1))
        return Status::error(StatusCode::invalid_argument,
                             "make_cylinder: need finite y0 < y1 (got %g, %g)", double(y0),
                             double(y1));
    return build_into(
        cylinder_sizes(slices, caps), out,
        [&](Vec3* p, Vec3* n, Vec2* uv, int nv, std::uint32_t* i, int ni, MeshView* view) {
            return make_cylinder_arrays(radius, y0, y1, slices, caps, p, n, uv, nv, i, ni, *view);
        });
}

Status make_torus(float major_radius, float minor_radius, int major_segments, int minor_segments,
                  TriangleMesh& out) {
    SHITSUKAN_TRY(check_positive("make_torus", "major_radius", major_radius));
    SHITSUKAN_TRY(check_positive("make_torus", "minor_radius", minor_radius));
    if (!(minor_radius < major_radius))
        return Status::error(
            StatusCode::invalid_argument,
            "make_torus: minor_radius %g must be < major_radius %g (no self-intersection)",
            double(minor_radius), double(major_radius));
    SHITSUKAN_TRY(check_segments("make_torus", "major_segments", major_segments));
    SHITSUKAN_TRY(check_segments("make_torus", "minor_segments", minor_segments));
    // The torus is the revolution of a circle (r, y) = (R + r cos v, r sin v) about y.
    return build_into(
        torus_sizes(major_segments, minor_segments), out,
        [&](Vec3* p, Vec3* n, Vec2* uv, int nv, std::uint32_t* i, int ni, MeshView* view) {
            return make_torus_arrays(major_radius, minor_radius, major_segments, minor_segments, p,
                                     n, uv, nv, i, ni, *view);
        });
}

// Revolve the profile (r_k, y_k) about the y axis (make_revolution_arrays, mesh_arrays.hpp,
// after dropping repeated points). Normals come from the profile's tangent: the outward side
// is the one to the right of the direction of travel in the (r, y) half plane, i.e. a
// profile that climbs the outside of a solid and descends the inside (a cup) gets outward
// normals on both walls. Corners sharper than 40 degrees keep two vertices (one per side) so
// that rims stay crisp; elsewhere normals are averaged.
Status make_revolution(const Vec2d* profile, int count, int segments, TriangleMesh& out) {
    if (!profile || count < 2)
        return Status::error(StatusCode::invalid_argument,
                             "make_revolution: need >= 2 profile points (got %d)", count);
    SHITSUKAN_TRY(check_segments("make_revolution", "segments", segments));
    for (int k = 0; k < count; ++k)
        if (!std::isfinite(profile[k].x) || !std::isfinite(profile[k].y) || profile[k].x < 0.0)
            return Status::error(
                StatusCode::invalid_argument,
                "make_revolution: profile point %d must be finite with r >= 0 (got r = %g, y = %g)",
                k, profile[k].x, profile[k].y);
    // Repeated consecutive points would give zero-length segments with no normal: drop them.
    std::vector<Vec2d> pts;
    for (int k = 0; k < count; ++k)
        if (pts.empty() || profile[k].x != pts.back().x || profile[k].y != pts.back().y)
            pts.push_back(profile[k]);
    if (pts.size() < 2)
        return Status::error(StatusCode::degenerate,
                             "make_revolution: the profile's points all coincide");
    const int n = int(pts.size());
    return build_into(
        revolution_sizes(pts.data(), n, segments), out,
        [&](Vec3* p, Vec3* nrm, Vec2* uv, int nv, std::uint32_t* i, int ni, MeshView* view) {
            return make_revolution_arrays(pts.data(), n, segments, p, nrm, uv, nv, i, ni, *view);
        });
}

// Uniform Catmull-Rom spline through the control points, in double (okada1987: "the spline
// in 8-byte reals"). The end tangents use a doubled end point. Returns every control point
// exactly, with samples_per_segment - 1 points in between.
Status sample_spline(const Vec2d* control, int count, int samples_per_segment,
                     std::vector<Vec2d>& out) {
    if (!control || count < 2)
        return Status::error(StatusCode::invalid_argument,
                             "sample_spline: need >= 2 control points (got %d)", count);
    if (samples_per_segment < 1 || samples_per_segment > kMaxSegments)
        return Status::error(StatusCode::invalid_argument,
                             "sample_spline: samples_per_segment must be in [1, %d] (got %d)",
                             kMaxSegments, samples_per_segment);
    for (int k = 0; k < count; ++k)
        if (!std::isfinite(control[k].x) || !std::isfinite(control[k].y))
            return Status::error(StatusCode::invalid_argument,
                                 "sample_spline: control point %d is not finite", k);
    out.clear();
    for (int k = 0; k + 1 < count; ++k) {
        Vec2d p0 = control[k > 0 ? k - 1 : 0], p1 = control[k], p2 = control[k + 1];
        Vec2d p3 = control[k + 2 < count ? k + 2 : count - 1];
        for (int s = 0; s < samples_per_segment; ++s) {
            double t = double(s) / samples_per_segment, t2 = t * t, t3 = t2 * t;
            // C(t) = 0.5·[2P1 + (-P0 + P2)t + (2P0 - 5P1 + 4P2 - P3)t^2 + (-P0 + 3P1 - 3P2 +
            // P3)t^3]
            auto eval = [&](double a, double b, double c, double d) {
                return 0.5 * (2 * b + (-a + c) * t + (2 * a - 5 * b + 4 * c - d) * t2 +
                              (-a + 3 * b - 3 * c + d) * t3);
            };
            out.push_back(
                s == 0 ? p1 : Vec2d{eval(p0.x, p1.x, p2.x, p3.x), eval(p0.y, p1.y, p2.y, p3.y)});
        }
    }
    out.push_back(control[count - 1]);
    return Status::success();
}

Status make_extrusion(const std::vector<std::vector<Vec2>>& outline, float z0, float z1,
                      TriangleMesh& out) {
    if (!std::isfinite(z0) || !std::isfinite(z1) || !(z0 < z1))
        return Status::error(StatusCode::invalid_argument,
                             "make_extrusion: need finite z0 < z1 (got %g, %g)", double(z0),
                             double(z1));
    std::vector<Vec2> pts;
    std::vector<std::uint32_t> tris;
    SHITSUKAN_TRY(triangulate_polygon(outline, pts, tris));
    out = TriangleMesh();
    // Front (z1, +z) and back (z0, -z) faces share the triangulation.
    for (int side = 0; side < 2; ++side) {
        float z = side == 0 ? z1 : z0;
        Vec3 n{0, 0, side == 0 ? 1.0f : -1.0f};
        std::uint32_t base = std::uint32_t(out.positions.size());
        for (const Vec2& p : pts) out.add_vertex({p.x, p.y, z}, n, p);
        for (std::size_t t = 0; t < tris.size(); t += 3)
            add_oriented(&out, base + tris[t], base + tris[t + 1], base + tris[t + 2], n);
    }
    // Side walls: one quad per ring edge, flat normals pointing away from the solid.
    for (std::size_t r = 0; r < outline.size(); ++r) {
        const std::vector<Vec2>& ring = outline[r];
        bool ccw = signed_area2(ring) > 0;
        bool outward_left = (r == 0) ? !ccw : ccw;  // material on the left of travel otherwise
        for (std::size_t k = 0; k < ring.size(); ++k) {
            Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
            Vec2 d = b - a;
            if (length_squared(d) == 0.0f) continue;
            Vec2 right{d.y, -d.x};
            Vec2 nn2 = normalize(outward_left ? -right : right);
            Vec3 n{nn2.x, nn2.y, 0};
            std::uint32_t base = std::uint32_t(out.positions.size());
            float la = 0, lb = length(d);
            out.add_vertex({a.x, a.y, z0}, n, {la, 0});
            out.add_vertex({b.x, b.y, z0}, n, {lb, 0});
            out.add_vertex({b.x, b.y, z1}, n, {lb, 1});
            out.add_vertex({a.x, a.y, z1}, n, {la, 1});
            add_oriented(&out, base, base + 1, base + 2, n);
            add_oriented(&out, base, base + 2, base + 3, n);
        }
    }
    return Status::success();
}

Status make_block_text(const char* text, float letter_height, float depth, TriangleMesh& out) {
    if (!text) return Status::error(StatusCode::invalid_argument, "make_block_text: null text");
    SHITSUKAN_TRY(check_positive("make_block_text", "letter_height", letter_height));
    SHITSUKAN_TRY(check_positive("make_block_text", "depth", depth));
    out = TriangleMesh();
    float pen = 0.0f;
    for (const char* c = text; *c; ++c) {
        if (*c == ' ') {
            pen += kBlockLetterAdvance * letter_height;
            continue;
        }
        std::vector<std::vector<Vec2>> rings;
        SHITSUKAN_TRY(block_letter_outline(*c, rings));
        for (auto& ring : rings)
            for (Vec2& p : ring) p = Vec2{pen + p.x * letter_height, p.y * letter_height};
        TriangleMesh letter;
        SHITSUKAN_TRY(make_extrusion(rings, -0.5f * depth, 0.5f * depth, letter));
        SHITSUKAN_TRY(append(out, letter, Mat4::identity()));
        pen += kBlockLetterAdvance * letter_height;
    }
    return Status::success();
}

// The sphere as eight octant patches: each octant face of the octahedron subdivided into
// n^2 triangles whose vertices are the integer points (a, b, c), |a| + |b| + |c| = n,
// projected to the sphere. Computing every point from its integer coordinates makes the
// points shared by two patches (or by a patch and a cut face) bit-identical: no cracks.
Status make_sphere_without_octant(float radius, int n, TriangleMesh& out) {
    SHITSUKAN_TRY(check_positive("make_sphere_without_octant", "radius", radius));
    SHITSUKAN_TRY(check_segments("make_sphere_without_octant", "subdivisions", n, 1));
    out = TriangleMesh();
    auto sphere_point = [&](int a, int b, int c) {
        Vec3d d{double(a), double(b), double(c)};
        double l = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        return Vec3{float(d.x / l * radius), float(d.y / l * radius), float(d.z / l * radius)};
    };
    for (int oct = 0; oct < 8; ++oct) {
        int sx = (oct & 1) ? -1 : 1, sy = (oct & 2) ? -1 : 1, sz = (oct & 4) ? -1 : 1;
        if (sx > 0 && sy > 0 && sz > 0) continue;  // the removed octant
        // Vertex (i, j) of the patch: i along x, j along y, k = n - i - j along z.
        std::vector<std::uint32_t> idx(std::size_t((n + 1) * (n + 1)), 0);
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                Vec3 p = sphere_point(sx * i, sy * j, sz * (n - i - j));
                Vec3 nn = normalize(p);
                float u = 0.5f + det_atan2(-nn.z, nn.x) / kTwoPi,
                      v = det_acos(clamp(nn.y, -1.0f, 1.0f)) / kPi;
                idx[std::size_t(i * (n + 1) + j)] = out.add_vertex(p, nn, {u, v});
            }
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j) {
                std::uint32_t a = idx[std::size_t(i * (n + 1) + j)],
                              b = idx[std::size_t((i + 1) * (n + 1) + j)];
                std::uint32_t c = idx[std::size_t(i * (n + 1) + j + 1)];
                add_oriented(&out, a, b, c,
                             out.positions[a] + out.positions[b] + out.positions[c]);
                if (i + j + 1 < n) {
                    std::uint32_t d = idx[std::size_t((i + 1) * (n + 1) + j + 1)];
                    add_oriented(&out, b, d, c,
                                 out.positions[b] + out.positions[d] + out.positions[c]);
                }
            }
    }
    // Three quarter-disc cut faces in the planes x = 0, y = 0, z = 0, bounding the removed
    // octant; each is a fan from the centre through the arc points the patches use.
    for (int axis = 0; axis < 3; ++axis) {
        Vec3 nrm{};
        nrm[axis] = 1.0f;  // the removed octant is on the + side: that is outside the solid
        std::uint32_t centre = out.add_vertex({0, 0, 0}, nrm, {0.5f, 0.5f});
        std::uint32_t prev = 0;
        for (int k = 0; k <= n; ++k) {
            int c[3] = {0, 0, 0};
            c[(axis + 1) % 3] = n - k;
            c[(axis + 2) % 3] = k;
            Vec3 p = sphere_point(c[0], c[1], c[2]);
            std::uint32_t cur = out.add_vertex(p, nrm,
                                                {0.5f + 0.5f * p[(axis + 1) % 3] / radius,
                                                 0.5f + 0.5f * p[(axis + 2) % 3] / radius});
            if (k > 0) add_oriented(&out, centre, prev, cur, nrm);
            prev = cur;
        }
    }
    return Status::success();
}

namespace {

Status check_indices(const char* what, const TriangleMesh& m) {
    if (m.indices.size() % 3 != 0)
        return Status::error(StatusCode::invalid_argument, "%s: %zu indices is not a multiple of 3",
                             what, m.indices.size());
    for (std::size_t k = 0; k < m.indices.size(); ++k)
        if (m.indices[k] >= m.positions.size())
            return Status::error(StatusCode::invalid_argument,
                                 "%s: index %zu is %u but the mesh has %zu vertices", what, k,
                                 m.indices[k], m.positions.size());
    return Status::success();
}

}  // namespace

Status append(TriangleMesh& dst, const TriangleMesh& src, const Mat4& transform) {
    SHITSUKAN_TRY(check_indices("append", src));
    bool ok = true;
    Mat4 normal_matrix = transpose(inverse(transform, &ok));  // normals: inverse transpose
    if (!ok)
        return Status::error(StatusCode::invalid_argument,
                             "append: the transform is singular or not finite");
    if (dst.positions.size() + src.positions.size() > 0xffffffffULL)
        return Status::error(StatusCode::too_large,
                             "append: %zu + %zu vertices exceed 32-bit indices",
                             dst.positions.size(), src.positions.size());
    std::uint32_t base = std::uint32_t(dst.positions.size());
    bool had_colors = !dst.colors.empty() || (dst.positions.empty() && !src.colors.empty());
    for (std::size_t i = 0; i < src.positions.size(); ++i) {
        Vec3 n = i < src.normals.size() ? normalize(transform_vector(normal_matrix, src.normals[i]))
                                        : Vec3{};
        Vec2 uv = i < src.uvs.size() ? src.uvs[i] : Vec2{};
        dst.add_vertex(transform_point(transform, src.positions[i]), n, uv);
        if (had_colors)
            dst.colors.push_back(i < src.colors.size() ? src.colors[i] : Vec3{1, 1, 1});
    }
    for (std::uint32_t k : src.indices) dst.indices.push_back(base + k);
    return Status::success();
}

Status compute_vertex_normals(TriangleMesh& mesh) {
    SHITSUKAN_TRY(check_indices("compute_vertex_normals", mesh));
    mesh.normals.assign(mesh.positions.size(), Vec3{});
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        // The cross product's length is twice the area: an area-weighted sum.
        Vec3 n =
            cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        mesh.normals[a] += n;
        mesh.normals[b] += n;
        mesh.normals[c] += n;
    }
    for (Vec3& n : mesh.normals) n = normalize(n);
    return Status::success();
}

}  // namespace shitsukan
