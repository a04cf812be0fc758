// Host side: baking a solid texture onto a UV map, and flat slices (solid_bake.hpp).
#include "shitsukan/render/solid_bake.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "shitsukan/core/scalar.hpp"
#include "shitsukan/solid/periodic_lattice.hpp"
#include "shitsukan/solid/turbulence.hpp"

namespace shitsukan {
namespace {

constexpr int kMaxSide = 16384;

// 0..255 colour of eq. (12) to bytes, rounded to nearest (as render/solid_mesh.cpp).
std::uint8_t byte_rounded(float v) {
    return std::uint8_t(v <= 0.0f ? 0 : (v >= 255.0f ? 255 : int(v + 0.5f)));
}
Rgb8 to_rgb8(Vec3 c) { return Rgb8{byte_rounded(c.x), byte_rounded(c.y), byte_rounded(c.z)}; }

Status check_common(const LatticeView& lattice, const SolidMaterial& material, int width,
                    int height, const char* who) {
    if (lattice.values == nullptr || lattice.side < 2)
        return Status::error(StatusCode::invalid_argument, "%s: the lattice is empty", who);
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
        return Status::error(StatusCode::invalid_argument,
                             "%s: size %d x %d outside 1..%d a side", who, width, height, kMaxSide);
    return validate_solid_material(material);
}

// 2D edge function: > 0 when p is left of a -> b.
float edge(Vec2 a, Vec2 b, Vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// Dilation: each ring gives an uncovered texel the mean of its covered 4-neighbours (colour,
// and density when baked); `covered` ends as the texels any ring reached.
void dilate_rings(RgbImage& out, FloatImage* density, std::vector<std::uint8_t>& covered,
                  int rings) {
    const int width = out.width(), height = out.height();
    std::vector<std::uint8_t> next;
    for (int ring = 0; ring < rings; ++ring) {
        next = covered;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                if (covered[std::size_t(y) * width + x]) continue;
                int r = 0, g = 0, b = 0, n = 0;
                float d = 0.0f;
                const int dx[4] = {-1, 1, 0, 0}, dy[4] = {0, 0, -1, 1};
                for (int k = 0; k < 4; ++k) {
                    const int nx = x + dx[k], ny = y + dy[k];
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                    if (covered[std::size_t(ny) * width + nx] != 1) continue;
                    const Rgb8 c = out.at(nx, ny);
                    r += c.r, g += c.g, b += c.b, ++n;
                    if (density) d += density->at(nx, ny);
                }
                if (n == 0) continue;
                out.at(x, y) = Rgb8{std::uint8_t(r / n), std::uint8_t(g / n), std::uint8_t(b / n)};
                if (density) density->at(x, y) = d / float(n);
                next[std::size_t(y) * width + x] = 2;  // filled this ring: a source next ring
            }
        for (std::uint8_t& c : next) c = c ? 1 : 0;
        covered.swap(next);
    }
}

// Texels beyond the gutter get the covered texels' mean density (chosen here: flat, neither
// high nor low, so a height map made from it has no cliff at the gutter's edge).
void fill_uncovered_density(FloatImage& density, const std::vector<std::uint8_t>& covered) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < covered.size(); ++i)
        if (covered[i]) sum += double(density.data()[i]), ++n;
    const float mean = n ? float(sum / double(n)) : 0.0f;
    for (std::size_t i = 0; i < covered.size(); ++i)
        if (!covered[i]) density.data()[i] = mean;
}

// Both public overloads: the densities only when `density` is not null.
Status bake(const MeshView& mesh, const LatticeView& lattice, const SolidMaterial& material,
            const ObjectToLattice& mapping, int width, int height, RgbImage& out,
            FloatImage* density, Rgb8 background, int dilate, Progress progress) {
    SHITSUKAN_TRY(check_common(lattice, material, width, height, "bake_solid_texture"));
    if (mesh.uvs == nullptr)
        return Status::error(StatusCode::invalid_argument,
                             "bake_solid_texture: the mesh has no uv map (vt) to bake onto");
    if (mesh.positions == nullptr || mesh.indices == nullptr || mesh.triangle_count < 1)
        return Status::error(StatusCode::invalid_argument, "bake_solid_texture: empty mesh");
    if (dilate < 0 || dilate > 64)
        return Status::error(StatusCode::invalid_argument,
                             "bake_solid_texture: dilate must be in [0, 64] (got %d)", dilate);
    for (int k = 0; k < 3 * mesh.triangle_count; ++k)
        if (mesh.indices[k] >= std::uint32_t(mesh.vertex_count))
            return Status::error(StatusCode::invalid_argument,
                                 "bake_solid_texture: index %u out of range (%d vertices)",
                                 mesh.indices[k], mesh.vertex_count);
    out.resize(width, height, background);
    if (density) density->resize(width, height);
    std::vector<std::uint8_t> covered(std::size_t(width) * std::size_t(height), 0);
    const int report_every = std::max(1, mesh.triangle_count / 100);
    for (int t = 0; t < mesh.triangle_count; ++t) {
        const std::uint32_t* idx = mesh.indices + 3 * t;
        // uv -> texel space: x = u·W, y = (1 - v)·H (row 0 at the top).
        Vec2 q[3];
        Vec3 p[3];
        bool finite = true;
        for (int k = 0; k < 3; ++k) {
            const Vec2 uv = mesh.uvs[idx[k]];
            q[k] = Vec2{uv.x * float(width), (1.0f - uv.y) * float(height)};
            p[k] = mesh.positions[idx[k]];
            finite = finite && is_finite(q[k].x) && is_finite(q[k].y);
        }
        const float area = edge(q[0], q[1], q[2]);
        if (!finite || area == 0.0f) continue;  // no texels
        const int x0 = std::max(0, int(std::floor(std::min({q[0].x, q[1].x, q[2].x}))));
        const int x1 = std::min(width - 1, int(std::ceil(std::max({q[0].x, q[1].x, q[2].x}))));
        const int y0 = std::max(0, int(std::floor(std::min({q[0].y, q[1].y, q[2].y}))));
        const int y1 = std::min(height - 1, int(std::ceil(std::max({q[0].y, q[1].y, q[2].y}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const Vec2 c{float(x) + 0.5f, float(y) + 0.5f};
                // barycentric weights, sign-corrected so either winding works
                const float w0 = edge(q[1], q[2], c) / area, w1 = edge(q[2], q[0], c) / area,
                            w2 = edge(q[0], q[1], c) / area;
                if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
                const Vec3 object = p[0] * w0 + p[1] * w1 + p[2] * w2;
                const float g = solid_density(material, lattice, object_to_lattice(object, mapping));
                out.at(x, y) = to_rgb8(solid_density_color(material, g));
                if (density) density->at(x, y) = g;
                covered[std::size_t(y) * std::size_t(width) + std::size_t(x)] = 1;
            }
        if (t % report_every == 0) progress.report(float(t) / float(mesh.triangle_count));
    }
    dilate_rings(out, density, covered, dilate);
    if (density) fill_uncovered_density(*density, covered);
    progress.report(1.0f);
    return Status::success();
}

}  // namespace

Status bake_solid_texture(const MeshView& mesh, const LatticeView& lattice,
                          const SolidMaterial& material, const ObjectToLattice& mapping, int width,
                          int height, RgbImage& out, Rgb8 background, int dilate,
                          Progress progress) {
    return bake(mesh, lattice, material, mapping, width, height, out, nullptr, background, dilate,
                progress);
}

Status bake_solid_texture(const MeshView& mesh, const LatticeView& lattice,
                          const SolidMaterial& material, const ObjectToLattice& mapping, int width,
                          int height, RgbImage& out, FloatImage& density, Rgb8 background,
                          int dilate, Progress progress) {
    return bake(mesh, lattice, material, mapping, width, height, out, &density, background,
                dilate, progress);
}

Status render_solid_slice(const LatticeView& lattice, const SolidMaterial& material,
                          const SolidSlice& slice, int width, int height, RgbImage& out,
                          FloatImage* density, Progress progress) {
    SHITSUKAN_TRY(check_common(lattice, material, width, height, "render_solid_slice"));
    const float values[10] = {slice.origin.x, slice.origin.y, slice.origin.z, slice.u.x, slice.u.y,
                              slice.u.z,      slice.v.x,      slice.v.y,      slice.v.z, slice.extent};
    for (float v : values)
        if (!is_finite(v))
            return Status::error(StatusCode::invalid_argument,
                                 "render_solid_slice: origin, u, v and extent must be finite");
    if (!(slice.extent > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "render_solid_slice: extent must be > 0 (got %g)", double(slice.extent));
    out.resize(width, height);
    if (density) density->resize(width, height);
    const float du = slice.extent / float(width), dv = slice.extent / float(height);
    const int report_every = std::max(1, height / 100);
    // A row's points first, then D(P) for the whole row (turbulence_points), then eqs. (7)-(12).
    std::vector<Vec3> points(static_cast<std::size_t>(width));
    std::vector<float> d(static_cast<std::size_t>(width));
    for (int j = 0; j < height; ++j) {
        const float b = (float(height - 1 - j) + 0.5f) * dv;
        for (int i = 0; i < width; ++i) {
            const float a = (float(i) + 0.5f) * du;
            Vec3 p = slice.origin + slice.u * a + slice.v * b;
            if (slice.wrap) p = wrap_lattice_point(p, lattice.R);
            points[std::size_t(i)] = p;
        }
        turbulence_points(lattice, points.data(), points.size(), d.data());
        for (int i = 0; i < width; ++i) {
            const float g = solid_density_at(material, points[std::size_t(i)], d[std::size_t(i)]);
            out.at(i, j) = to_rgb8(solid_density_color(material, g));
            if (density) density->at(i, j) = g;
        }
        if (j % report_every == 0) progress.report(float(j) / float(height));
    }
    progress.report(1.0f);
    return Status::success();
}

}  // namespace shitsukan
