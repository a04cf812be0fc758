// small-device: yes (no allocation, no exceptions)
#include "shitsukan/geom/mesh_arrays.hpp"

#include <cmath>

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {

// Where a builder writes: the caller's arrays and how much of them is used.
struct ArrayMesh {
    Vec3* positions;
    Vec3* normals;
    Vec2* uvs;
    std::uint32_t* indices;
    int vertices = 0, index_count = 0;

    void add_vertex(Vec3 p, Vec3 n, Vec2 uv) {
        positions[vertices] = p;
        normals[vertices] = n;
        if (uvs) uvs[vertices] = uv;
        ++vertices;
    }
    // Triangle a b c, flipped to be counter-clockwise seen from the side `outward` points
    // to; zero-area triangles (poles, axis points) are dropped.
    void add_oriented(std::uint32_t a, std::uint32_t b, std::uint32_t c, Vec3 outward) {
        Vec3 n = cross(positions[b] - positions[a], positions[c] - positions[a]);
        if (length_squared(n) == 0.0f) return;
        if (dot(n, outward) < 0.0f) {
            const std::uint32_t s = b;
            b = c;
            c = s;
        }
        indices[index_count++] = a;
        indices[index_count++] = b;
        indices[index_count++] = c;
    }
    MeshView view() const {
        MeshView v;
        v.positions = positions;
        v.normals = normals;
        v.uvs = uvs;
        v.vertex_count = vertices;
        v.indices = indices;
        v.triangle_count = index_count / 3;
        return v;
    }
};

}  // namespace

Status make_box_arrays(Vec3 lo, Vec3 hi, Vec3* positions, Vec3* normals, Vec2* uvs,
                       int vertex_capacity, std::uint32_t* indices, int index_capacity,
                       MeshView& out) {
    if (!positions || !normals || !indices)
        return Status::error(StatusCode::invalid_argument,
                             "make_box_arrays: null positions, normals or indices");
    if (!is_finite(lo) || !is_finite(hi) || !(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
        return Status::error(StatusCode::invalid_argument,
                             "make_box: need finite corners with min < max on every axis "
                             "(got (%g,%g,%g) .. (%g,%g,%g))",
                             double(lo.x), double(lo.y), double(lo.z), double(hi.x), double(hi.y),
                             double(hi.z));
    if (vertex_capacity < kBoxVertexCount || index_capacity < 3 * kBoxTriangleCount)
        return Status::error(StatusCode::buffer_too_small,
                             "make_box_arrays: a box needs %d vertices and %d indices (got "
                             "capacity %d and %d)",
                             kBoxVertexCount, 3 * kBoxTriangleCount, vertex_capacity,
                             index_capacity);
    ArrayMesh m{positions, normals, uvs, indices};
    // Each face: normal axis, sign; its four corners get their own vertices (flat normals),
    // then two triangles (base, +1, +2) and (base, +2, +3), counter-clockwise from outside.
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign = -1; sign <= 1; sign += 2) {
            Vec3 n{};
            n[axis] = float(sign);
            const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
            const std::uint32_t base = std::uint32_t(m.vertices);
            for (int k = 0; k < 4; ++k) {
                const int du = (k == 1 || k == 2), dv = (k >= 2);
                Vec3 p;
                p[axis] = sign > 0 ? hi[axis] : lo[axis];
                p[u_axis] = du ? hi[u_axis] : lo[u_axis];
                p[v_axis] = dv ? hi[v_axis] : lo[v_axis];
                m.add_vertex(p, n, Vec2{float(du), float(dv)});
            }
            m.add_oriented(base, base + 1, base + 2, n);
            m.add_oriented(base, base + 2, base + 3, n);
        }
    }
    out = m.view();
    return Status::success();
}

}  // namespace shitsukan

// ---- sphere, revolution (cylinder, torus) into caller arrays ----

namespace shitsukan {

namespace {


Status check_arrays(const char* what, const Vec3* positions, const Vec3* normals,
                    const std::uint32_t* indices) {
    if (!positions || !normals || !indices)
        return Status::error(StatusCode::invalid_argument,
                             "%s: null positions, normals or indices", what);
    return Status::success();
}

Status check_capacity(const char* what, const MeshSizes& need, int vertex_capacity,
                      int index_capacity) {
    if (vertex_capacity < need.vertices || index_capacity < need.indices)
        return Status::error(StatusCode::buffer_too_small,
                             "%s: needs %d vertices and %d indices (got capacity %d and %d)", what,
                             need.vertices, need.indices, vertex_capacity, index_capacity);
    return Status::success();
}

// The revolution's profile: given points, or the torus's circle computed point by point.
struct Profile {
    const Vec2d* points = nullptr;
    double major = 0, minor = 0;  // circle: (major + minor cos v, minor sin v)
    int count = 0;
    Vec2d at(int k) const {
        if (points) return points[k];
        const int m = count - 1;  // the last point closes the circle at v = 0
        const double v = 2.0 * kPiD * (k == m ? 0 : k) / m;
        return {major + minor * det_cos(v), minor * det_sin(v)};
    }
};

// The ring rules of make_revolution (mesh_builders.hpp): a sharp corner gets two rings.
struct RingWalk {
    const Profile* profile;
    bool closed;
    int n, nseg;  // distinct points, segments

    Vec2d point(int k) const { return profile->at(k % n); }
    Vec2d segment_normal(int k) const {  // of segment k -> k+1, in the (r, y) plane
        Vec2d a = point(k), b = point(k + 1);
        Vec2d d{b.x - a.x, b.y - a.y};
        double l = std::sqrt(d.x * d.x + d.y * d.y);
        return l > 0 ? Vec2d{d.y / l, -d.x / l} : Vec2d{0, 0};
    }
    double segment_length(int k) const {
        Vec2d a = profile->at(k), b = point(k + 1);
        return std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
    }
};

RingWalk ring_walk(const Profile& p) {
    RingWalk w;
    w.profile = &p;
    const Vec2d first = p.at(0), last = p.at(p.count - 1);
    w.closed = p.count > 2 && first.x == last.x && first.y == last.y;
    w.n = w.closed ? p.count - 1 : p.count;
    w.nseg = w.closed ? w.n : w.n - 1;
    return w;
}

// Calls ring(r, y, normal, v, joined_to_prev) for every ring, in order.
template <class RingFn> void walk_rings(const RingWalk& w, double total, RingFn&& ring) {
    double arc = 0.0;
    for (int k = 0; k <= w.nseg; ++k) {
        if (k > 0) arc += w.segment_length(k - 1);
        const Vec2d p = w.point(k);
        const double v = arc / total;
        const bool has_in = w.closed || k > 0, has_out = w.closed || k < w.nseg;
        const Vec2d nin = w.segment_normal(has_in ? (k + w.nseg - 1) % w.nseg : 0);
        const Vec2d nout = w.segment_normal(has_out ? k % w.nseg : w.nseg - 1);
        const Vec2d avg{nin.x + nout.x, nin.y + nout.y};
        const double l = std::sqrt(avg.x * avg.x + avg.y * avg.y);
        const bool sharp = has_in && has_out && (nin.x * nout.x + nin.y * nout.y) < 0.766;
        if (!sharp) {
            const Vec2d nn = !has_in    ? nout
                             : !has_out ? nin
                                        : (l > 0 ? Vec2d{avg.x / l, avg.y / l} : nout);
            ring(p, nn, v, k > 0);
        } else {
            if (k > 0) ring(p, nin, v, true);
            if (k < w.nseg) ring(p, nout, v, false);
        }
    }
}

Status check_profile(const Profile& p, int segments, double* total) {
    if (p.count < 2)
        return Status::error(StatusCode::invalid_argument,
                             "make_revolution: need >= 2 profile points (got %d)", p.count);
    if (segments < 3 || segments > kMaxMeshSegments)
        return Status::error(StatusCode::invalid_argument,
                             "make_revolution: segments must be in [3, %d] (got %d)",
                             kMaxMeshSegments, segments);
    for (int k = 0; k < p.count; ++k) {
        const Vec2d q = p.at(k);
        if (!is_finite(q.x) || !is_finite(q.y) || q.x < 0.0)
            return Status::error(
                StatusCode::invalid_argument,
                "make_revolution: profile point %d must be finite with r >= 0 (got r = %g, y = %g)",
                k, q.x, q.y);
        if (k > 0 && q.x == p.at(k - 1).x && q.y == p.at(k - 1).y)
            return Status::error(StatusCode::invalid_argument,
                                 "make_revolution_arrays: profile points %d and %d repeat (drop "
                                 "one)",
                                 k - 1, k);
    }
    const RingWalk w = ring_walk(p);
    *total = 0.0;
    for (int k = 0; k < w.nseg; ++k) *total += w.segment_length(k);
    if (*total == 0)
        return Status::error(StatusCode::degenerate, "make_revolution: profile has zero length");
    return Status::success();
}

MeshSizes profile_sizes(const Profile& p, int segments) {
    const RingWalk w = ring_walk(p);
    int rings = 0, joins = 0;
    double total = 1.0;  // only the count matters here
    walk_rings(w, total, [&](Vec2d, Vec2d, double, bool joined) {
        ++rings;
        joins += joined;
    });
    return MeshSizes{rings * (segments + 1), joins * segments * 6};
}

void revolve(const Profile& p, int segments, double total, ArrayMesh& m) {
    const RingWalk w = ring_walk(p);
    int ring_index = 0;
    walk_rings(w, total, [&](Vec2d q, Vec2d normal, double v, bool joined) {
        for (int j = 0; j <= segments; ++j) {
            const double phi = 2.0 * kPiD * (j == segments ? 0 : j) / segments;
            const double c = det_cos(phi), s = -det_sin(phi);
            const Vec3 pos{float(q.x * c), float(q.y), float(q.x * s)};
            const Vec3 nn{float(normal.x * c), float(normal.y), float(normal.x * s)};
            m.add_vertex(pos, nn, Vec2{float(j) / segments, float(v)});
        }
        if (joined && ring_index > 0)
            for (int j = 0; j < segments; ++j) {
                const std::uint32_t a = std::uint32_t((ring_index - 1) * (segments + 1) + j),
                                    b = a + 1;
                const std::uint32_t c = a + std::uint32_t(segments + 1), d = c + 1;
                const Vec3 outward = m.normals[a] + m.normals[b] + m.normals[c] + m.normals[d];
                m.add_oriented(a, c, d, outward);
                m.add_oriented(a, d, b, outward);
            }
        ++ring_index;
    });
}

Status revolution_arrays(const char* what, const Profile& p, int segments, Vec3* positions,
                         Vec3* normals, Vec2* uvs, int vertex_capacity, std::uint32_t* indices,
                         int index_capacity, MeshView& out) {
    SHITSUKAN_TRY(check_arrays(what, positions, normals, indices));
    double total = 0.0;
    SHITSUKAN_TRY(check_profile(p, segments, &total));
    SHITSUKAN_TRY(
        check_capacity(what, profile_sizes(p, segments), vertex_capacity, index_capacity));
    ArrayMesh m{positions, normals, uvs, indices};
    revolve(p, segments, total, m);
    out = m.view();
    return Status::success();
}

}  // namespace

MeshSizes revolution_sizes(const Vec2d* profile, int count, int segments) {
    Profile p;
    p.points = profile;
    p.count = count;
    if (!profile || count < 2 || segments < 3 || segments > kMaxMeshSegments) return {};
    return profile_sizes(p, segments);
}

Status make_revolution_arrays(const Vec2d* profile, int count, int segments, Vec3* positions,
                              Vec3* normals, Vec2* uvs, int vertex_capacity, std::uint32_t* indices,
                              int index_capacity, MeshView& out) {
    if (!profile)
        return Status::error(StatusCode::invalid_argument, "make_revolution_arrays: null profile");
    Profile p;
    p.points = profile;
    p.count = count;
    return revolution_arrays("make_revolution_arrays", p, segments, positions, normals, uvs,
                             vertex_capacity, indices, index_capacity, out);
}

MeshSizes torus_sizes(int major_segments, int minor_segments) {
    if (major_segments < 3 || minor_segments < 3 || major_segments > kMaxMeshSegments ||
        minor_segments > kMaxMeshSegments)
        return {};
    Profile p;  // the rings depend on the circle's angles only, not on its radii
    p.major = 2.0;
    p.minor = 1.0;
    p.count = minor_segments + 1;
    return profile_sizes(p, major_segments);
}

Status make_torus_arrays(float major_radius, float minor_radius, int major_segments,
                         int minor_segments, Vec3* positions, Vec3* normals, Vec2* uvs,
                         int vertex_capacity, std::uint32_t* indices, int index_capacity,
                         MeshView& out) {
    if (!(major_radius > 0.0f) || !is_finite(major_radius) || !(minor_radius > 0.0f) ||
        !is_finite(minor_radius) || !(minor_radius < major_radius))
        return Status::error(StatusCode::invalid_argument,
                             "make_torus: need finite radii 0 < minor_radius < major_radius (got "
                             "%g, %g)",
                             double(minor_radius), double(major_radius));
    if (minor_segments < 3 || minor_segments > kMaxMeshSegments)
        return Status::error(StatusCode::invalid_argument,
                             "make_torus: minor_segments must be in [3, %d] (got %d)",
                             kMaxMeshSegments, minor_segments);
    Profile p;
    p.major = major_radius;
    p.minor = minor_radius;
    p.count = minor_segments + 1;
    return revolution_arrays("make_torus_arrays", p, major_segments, positions, normals, uvs,
                             vertex_capacity, indices, index_capacity, out);
}

MeshSizes cylinder_sizes(int slices, bool caps) {
    const Vec2d profile[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    return caps ? revolution_sizes(profile, 4, slices) : revolution_sizes(profile + 1, 2, slices);
}

Status make_cylinder_arrays(float radius, float y0, float y1, int slices, bool caps,
                            Vec3* positions, Vec3* normals, Vec2* uvs, int vertex_capacity,
                            std::uint32_t* indices, int index_capacity, MeshView& out) {
    if (!(radius > 0.0f) || !is_finite(radius) || !is_finite(y0) || !is_finite(y1) || !(y0 < y1))
        return Status::error(StatusCode::invalid_argument,
                             "make_cylinder: need a finite radius > 0 and finite y0 < y1 (got "
                             "%g, %g, %g)",
                             double(radius), double(y0), double(y1));
    const Vec2d profile[4] = {{0, y0}, {radius, y0}, {radius, y1}, {0, y1}};
    Profile p;
    p.points = caps ? profile : profile + 1;
    p.count = caps ? 4 : 2;
    return revolution_arrays("make_cylinder_arrays", p, slices, positions, normals, uvs,
                             vertex_capacity, indices, index_capacity, out);
}

MeshSizes uv_sphere_sizes(int slices, int stacks) {
    if (slices < 3 || stacks < 2 || slices > kMaxMeshSegments || stacks > kMaxMeshSegments)
        return {};
    return MeshSizes{(stacks + 1) * (slices + 1), stacks * slices * 6};
}

Status make_uv_sphere_arrays(float radius, int slices, int stacks, Vec3* positions, Vec3* normals,
                             Vec2* uvs, int vertex_capacity, std::uint32_t* indices,
                             int index_capacity, MeshView& out) {
    SHITSUKAN_TRY(check_arrays("make_uv_sphere_arrays", positions, normals, indices));
    if (!(radius > 0.0f) || !is_finite(radius))
        return Status::error(StatusCode::invalid_argument,
                             "make_uv_sphere: radius must be finite and > 0 (got %g)",
                             double(radius));
    if (slices < 3 || stacks < 2 || slices > kMaxMeshSegments || stacks > kMaxMeshSegments)
        return Status::error(StatusCode::invalid_argument,
                             "make_uv_sphere: need 3 <= slices and 2 <= stacks, both <= %d (got "
                             "%d, %d)",
                             kMaxMeshSegments, slices, stacks);
    SHITSUKAN_TRY(check_capacity("make_uv_sphere_arrays", uv_sphere_sizes(slices, stacks),
                                 vertex_capacity, index_capacity));
    ArrayMesh m{positions, normals, uvs, indices};
    // Rings from the north pole (theta = 0, +y) to the south pole; the seam column is
    // duplicated so u runs 0..1, with identical positions (no crack).
    for (int i = 0; i <= stacks; ++i) {
        const double theta = kPiD * i / stacks;
        for (int j = 0; j <= slices; ++j) {
            const double phi = 2.0 * kPiD * (j == slices ? 0 : j) / slices;
            Vec3 n{float(det_sin(theta) * det_cos(phi)), float(det_cos(theta)),
                   float(-det_sin(theta) * det_sin(phi))};
            if (i == 0 || i == stacks) n = Vec3{0.0f, i == 0 ? 1.0f : -1.0f, 0.0f};
            m.add_vertex(n * radius, n, Vec2{float(j) / slices, float(i) / stacks});
        }
    }
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const std::uint32_t a = std::uint32_t(i * (slices + 1) + j), b = a + 1;
            const std::uint32_t c = a + std::uint32_t(slices + 1), d = c + 1;
            const Vec3 mid =
                normalize(m.positions[a] + m.positions[b] + m.positions[c] + m.positions[d]);
            m.add_oriented(a, c, d, mid);
            m.add_oriented(a, d, b, mid);
        }
    out = m.view();
    return Status::success();
}

}  // namespace shitsukan
