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

Status check_strip_options(int count, const PatchStripOptions& options) {
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
    return Status::success();
}

// Every patch valid, and neighbours sharing their edge (u = 1 of patch k is u = 0 of k + 1).
Status check_strip_patches(const BezierPatch* patches, int count) {
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
    return Status::success();
}

// The strip's vertex grid: `columns` across all patches (nu per patch, shared edges once),
// `rows` along v.
struct StripGrid {
    const BezierPatch* patches;
    int count, nu, nv, columns, rows;
    // Column c lies in patch k = c / nu (the last column in the last patch) at local u.
    int column_patch(int c, float* u) const {
        int k = c / nu;
        if (k >= count) k = count - 1;
        *u = float(c - k * nu) / float(nu);
        return k;
    }
    Vec2& at(std::vector<Vec2>& texture, int c, int j) const {
        return texture[std::size_t(j) * std::size_t(columns) + std::size_t(c)];
    }
};

// §4: x from the arc length of each row across the strip, y from each column's.
void arc_length_texture(const StripGrid& g, const PatchStripOptions& options,
                        std::vector<Vec2>& texture) {
    const int nu = g.nu, nv = g.nv;
    for (int j = 0; j < g.rows; ++j) {
        float v = float(j) / float(nv), x = 0.0f;
        g.at(texture, 0, j).x = 0.0f;
        for (int c = 1; c < g.columns; ++c) {
            int k = (c - 1) / nu;  // the segment from column c-1 to c is in patch k
            float u0 = float(c - 1 - k * nu) / float(nu), u1 = float(c - k * nu) / float(nu);
            x += chord_length(g.patches[k], {u0, v}, {u1, v}, options.chords);
            g.at(texture, c, j).x = x;
        }
        // Measure the row from the anchor column.
        int anchor = int(std::lround(options.anchor * float(nu)));
        float x_anchor = g.at(texture, anchor, j).x;
        for (int c = 0; c < g.columns; ++c) g.at(texture, c, j).x -= x_anchor;
    }
    if (options.reference_row >= 0.0f) {
        // One row's arc length for all rows: a strip bent without stretching (header).
        const int ref = int(std::lround(options.reference_row * float(nv)));
        for (int j = 0; j < g.rows; ++j)
            for (int c = 0; c < g.columns; ++c) g.at(texture, c, j).x = g.at(texture, c, ref).x;
    }
    for (int c = 0; c < g.columns; ++c) {
        float u;
        int k = g.column_patch(c, &u);
        float y = 0.0f;
        g.at(texture, c, 0).y = 0.0f;
        for (int j = 1; j < g.rows; ++j) {
            float v0 = float(j - 1) / float(nv), v1 = float(j) / float(nv);
            y += chord_length(g.patches[k], {u, v0}, {u, v1}, options.chords);
            g.at(texture, c, j).y = y;
        }
    }
}

// The uncorrected mapping: parameters stretched to each patch's mean size.
void mean_size_texture(const StripGrid& g, std::vector<Vec2>& texture) {
    const int nu = g.nu, nv = g.nv;
    float x0 = 0.0f;
    for (int k = 0; k < g.count; ++k) {
        float mean_u = 0.0f, mean_v = 0.0f;
        for (int s = 0; s <= 4; ++s) {
            mean_u += patch_iso_length(g.patches[k], true, float(s) / 4.0f, 8 * nu) / 5.0f;
            mean_v += patch_iso_length(g.patches[k], false, float(s) / 4.0f, 8 * nv) / 5.0f;
        }
        for (int c = k * nu; c <= (k + 1) * nu; ++c) {
            float u = float(c - k * nu) / float(nu);
            for (int j = 0; j < g.rows; ++j)
                g.at(texture, c, j) = {x0 + u * mean_u, float(j) / float(nv) * mean_v};
        }
        x0 += mean_u;
    }
}

// Vertices (normals averaged across shared edges) and two triangles per grid cell.
void emit_strip_mesh(const StripGrid& g, const PatchStripOptions& options,
                     std::vector<Vec2>& texture, TriangleMesh* out) {
    for (int j = 0; j < g.rows; ++j) {
        float v = float(j) / float(g.nv);
        for (int c = 0; c < g.columns; ++c) {
            float u;
            int k = g.column_patch(c, &u);
            PatchPoint q = patch_point(g.patches[k], u, v);
            Vec3 n = q.normal;
            if (u == 0.0f && k > 0)  // shared edge: average the two patches' normals
                n = normalize(n + patch_point(g.patches[k - 1], 1.0f, v).normal);
            Vec2 t = g.at(texture, c, j);
            out->add_vertex(q.position, n, options.texture_origin + t * options.texture_scale);
        }
    }
    const int columns = g.columns;
    for (int j = 0; j < g.nv; ++j)
        for (int c = 0; c + 1 < columns; ++c) {
            auto id = [&](int cc, int jj) { return std::uint32_t(jj * columns + cc); };
            out->add_triangle(id(c, j), id(c + 1, j), id(c + 1, j + 1));
            out->add_triangle(id(c, j), id(c + 1, j + 1), id(c, j + 1));
        }
}

}  // namespace

Status tessellate_patch_strip(const BezierPatch* patches, int count,
                              const PatchStripOptions& options, TriangleMesh& out) {
    if (patches == nullptr || count < 1)
        return Status::error(StatusCode::invalid_argument,
                             "patch strip: need at least one patch (got %d)", count);
    SHITSUKAN_TRY(check_strip_options(count, options));
    SHITSUKAN_TRY(check_strip_patches(patches, count));
    const int nu = options.segments_u, nv = options.segments_v;
    const StripGrid grid{patches, count, nu, nv, count * nu + 1, nv + 1};
    out = TriangleMesh{};
    out.positions.reserve(std::size_t(grid.columns) * std::size_t(grid.rows));
    std::vector<Vec2> texture(std::size_t(grid.columns) * std::size_t(grid.rows));
    if (options.arc_length)
        arc_length_texture(grid, options, texture);
    else
        mean_size_texture(grid, texture);
    emit_strip_mesh(grid, options, texture, &out);
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
