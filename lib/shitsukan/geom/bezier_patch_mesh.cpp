#include "shitsukan/geom/bezier_patch_mesh.hpp"

#include <cmath>
#include <vector>

namespace shitsukan {

namespace {

// Chord length of the patch curve between two parameter points (sub-divided).
float chord_length(const BezierPatch& patch, Vec2 a, Vec2 b, int chords) {
    float total = 0.0f;
    Vec3 prev = patch_point(patch, a.x, a.y).position;
    for (int k = 1; k <= chords; ++k) {
        float s = float(k) / float(chords);
        Vec2 q = a + (b - a) * s;
        Vec3 p = patch_point(patch, q.x, q.y).position;
        total += length(p - prev);
        prev = p;
    }
    return total;
}

}  // namespace

Status tessellate_patch_strip(const BezierPatch* patches, int count,
                              const PatchStripOptions& options, TriangleMesh* out) {
    if (patches == nullptr || count < 1)
        return Status::error(StatusCode::invalid_argument,
                             "patch strip: need at least one patch (got %d)", count);
    if (options.segments_u < 1 || options.segments_u > 1024 || options.segments_v < 1 ||
        options.segments_v > 1024)
        return Status::error(StatusCode::invalid_argument,
                             "patch strip: segments must be 1..1024 (got %d x %d)",
                             options.segments_u, options.segments_v);
    // columns · rows vertices, indexed by int and uint32: refuse a strip that would overflow.
    const long long vertices = (static_cast<long long>(count) * options.segments_u + 1) *
                               (static_cast<long long>(options.segments_v) + 1);
    if (vertices > kMaxStripVertices)
        return Status::error(StatusCode::invalid_argument,
                             "patch strip: %d patches of %d x %d segments make %lld vertices "
                             "(at most %lld)",
                             count, options.segments_u, options.segments_v, vertices,
                             kMaxStripVertices);
    if (options.chords < 1 || options.chords > 1024)
        return Status::error(StatusCode::invalid_argument,
                             "patch strip: chords must be 1..1024 (got %d)", options.chords);
    if (!(options.reference_row == -1.0f ||
          (options.reference_row >= 0.0f && options.reference_row <= 1.0f)))
        return Status::error(StatusCode::invalid_argument,
                             "patch strip: reference_row must be -1 or in [0, 1] (got %g)",
                             double(options.reference_row));
    if (!(options.anchor >= 0.0f && options.anchor <= float(count)))
        return Status::error(StatusCode::invalid_argument,
                             "patch strip: anchor must be in [0, %d] (got %g)", count,
                             double(options.anchor));
    if (!(options.texture_scale > 0.0f) || !is_finite(options.texture_scale))
        return Status::error(StatusCode::invalid_argument,
                             "patch strip: texture_scale must be finite and > 0 (got %g)",
                             double(options.texture_scale));
    if (!is_finite(options.texture_origin))
        return Status::error(StatusCode::invalid_argument,
                             "patch strip: texture_origin must be finite (got (%g, %g))",
                             double(options.texture_origin.x), double(options.texture_origin.y));
    Vec3 lo = patches[0].p[0][0], hi = lo;
    for (int k = 0; k < count; ++k) {
        Status s = validate_patch(patches[k]);
        if (!s.ok()) return Status::error(s.code(), "patch strip: patch %d: %s", k, s.message());
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                lo = vmin(lo, patches[k].p[i][j]);
                hi = vmax(hi, patches[k].p[i][j]);
            }
    }
    const float size = length(hi - lo);
    for (int k = 0; k + 1 < count; ++k) {
        float gap = 0.0f;
        for (int s = 0; s <= 8; ++s) {
            float v = float(s) / 8.0f;
            Vec3 a = patch_point(patches[k], 1.0f, v).position;
            Vec3 b = patch_point(patches[k + 1], 0.0f, v).position;
            gap = std::fmax(gap, length(a - b));
        }
        if (gap > 1e-4f * size)
            return Status::error(StatusCode::invalid_argument,
                                 "patch strip: patch %d's edge u = 1 and patch %d's edge u = 0 "
                                 "are %g apart; neighbours must share their edge",
                                 k, k + 1, double(gap));
    }

    const int nu = options.segments_u, nv = options.segments_v;
    const int columns = count * nu + 1, rows = nv + 1;
    // Column c lies in patch k = c / nu (the last column in the last patch) at local u.
    auto column_patch = [&](int c, float* u) {
        int k = c / nu;
        if (k >= count) k = count - 1;
        *u = float(c - k * nu) / float(nu);
        return k;
    };

    *out = TriangleMesh{};
    out->positions.reserve(std::size_t(columns) * std::size_t(rows));
    std::vector<Vec2> texture(std::size_t(columns) * std::size_t(rows));
    const float scale = options.texture_scale;
    if (options.arc_length) {
        // §4: x from the arc length of each row across the strip, y from each column's.
        for (int j = 0; j < rows; ++j) {
            float v = float(j) / float(nv), x = 0.0f;
            texture[std::size_t(j) * std::size_t(columns)].x = 0.0f;
            for (int c = 1; c < columns; ++c) {
                int k = (c - 1) / nu;  // the segment from column c-1 to c is in patch k
                float u0 = float(c - 1 - k * nu) / float(nu), u1 = float(c - k * nu) / float(nu);
                x += chord_length(patches[k], {u0, v}, {u1, v}, options.chords);
                texture[std::size_t(j) * std::size_t(columns) + std::size_t(c)].x = x;
            }
            // Measure the row from the anchor column.
            int anchor = int(std::lround(options.anchor * float(nu)));
            float x_anchor = texture[std::size_t(j) * std::size_t(columns) + std::size_t(anchor)].x;
            for (int c = 0; c < columns; ++c)
                texture[std::size_t(j) * std::size_t(columns) + std::size_t(c)].x -= x_anchor;
        }
        if (options.reference_row >= 0.0f) {
            // One row's arc length for all rows: a strip bent without stretching (header).
            const int ref = int(std::lround(options.reference_row * float(nv)));
            for (int j = 0; j < rows; ++j)
                for (int c = 0; c < columns; ++c)
                    texture[std::size_t(j) * std::size_t(columns) + std::size_t(c)].x =
                        texture[std::size_t(ref) * std::size_t(columns) + std::size_t(c)].x;
        }
        for (int c = 0; c < columns; ++c) {
            float u;
            int k = column_patch(c, &u);
            float y = 0.0f;
            texture[std::size_t(c)].y = 0.0f;
            for (int j = 1; j < rows; ++j) {
                float v0 = float(j - 1) / float(nv), v1 = float(j) / float(nv);
                y += chord_length(patches[k], {u, v0}, {u, v1}, options.chords);
                texture[std::size_t(j) * std::size_t(columns) + std::size_t(c)].y = y;
            }
        }
    } else {
        // The uncorrected mapping: parameters stretched to each patch's mean size.
        float x0 = 0.0f;
        for (int k = 0; k < count; ++k) {
            float mean_u = 0.0f, mean_v = 0.0f;
            for (int s = 0; s <= 4; ++s) {
                mean_u += patch_iso_length(patches[k], true, float(s) / 4.0f, 8 * nu) / 5.0f;
                mean_v += patch_iso_length(patches[k], false, float(s) / 4.0f, 8 * nv) / 5.0f;
            }
            for (int c = k * nu; c <= (k + 1) * nu; ++c) {
                float u = float(c - k * nu) / float(nu);
                for (int j = 0; j < rows; ++j)
                    texture[std::size_t(j) * std::size_t(columns) + std::size_t(c)] = {
                        x0 + u * mean_u, float(j) / float(nv) * mean_v};
            }
            x0 += mean_u;
        }
    }

    for (int j = 0; j < rows; ++j) {
        float v = float(j) / float(nv);
        for (int c = 0; c < columns; ++c) {
            float u;
            int k = column_patch(c, &u);
            PatchPoint q = patch_point(patches[k], u, v);
            Vec3 n = q.normal;
            if (u == 0.0f && k > 0)  // shared edge: average the two patches' normals
                n = normalize(n + patch_point(patches[k - 1], 1.0f, v).normal);
            Vec2 t = texture[std::size_t(j) * std::size_t(columns) + std::size_t(c)];
            out->add_vertex(q.position, n, options.texture_origin + t * scale);
        }
    }
    for (int j = 0; j < nv; ++j)
        for (int c = 0; c + 1 < columns; ++c) {
            auto id = [&](int cc, int jj) { return std::uint32_t(jj * columns + cc); };
            out->add_triangle(id(c, j), id(c + 1, j), id(c + 1, j + 1));
            out->add_triangle(id(c, j), id(c + 1, j + 1), id(c, j + 1));
        }
    return Status::success();
}

void patch_control_net(const BezierPatch& patch, Vec3* out) {
    int k = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) {
            out[k++] = patch.p[i][j];
            out[k++] = patch.p[i][j + 1];
            out[k++] = patch.p[j][i];
            out[k++] = patch.p[j + 1][i];
        }
}

}  // namespace shitsukan
