#include "fujimoto2000/wr_figure_common.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

#include "shitsukan/core/scalar.hpp"
#include "driver/figure.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/core/detmath.hpp"

namespace shitsukan::fujimoto2000 {

using figures::fmt;

Camera shot_camera(const Shot& s, int width, int height) {
    return perspective_camera(s.eye, s.target, s.up, s.fov_degrees, width, height, 0.05f, 200.0f);
}

float shot_pixels_per_unit(const Shot& s, int height) {
    const float dist = length(s.eye - s.target);
    return 0.5f * float(height) / (det_tan(0.5f * s.fov_degrees * kPi / 180.0f) * dist);
}

Shot zoom_shot(const Shot& s, Vec3 target, float factor) {
    Shot z = s;
    z.eye = target + (s.eye - s.target);
    z.target = target;
    const float t = det_tan(0.5f * s.fov_degrees * kPi / 180.0f) / factor;
    z.fov_degrees = 2.0f * det_atan(t) * 180.0f / kPi;
    return z;
}

namespace {

Rgb8 to_rgb8(Vec3 c) {
    auto q = [](float x) { return std::uint8_t(clamp(x, 0.0f, 1.0f) * 255.0f + 0.5f); };
    return Rgb8{q(c.x), q(c.y), q(c.z)};
}

Vec3 from_rgb8(Rgb8 c) { return Vec3{c.r / 255.0f, c.g / 255.0f, c.b / 255.0f}; }

}  // namespace

Status render_opaque(const Camera& camera, const TriangleMesh& mesh, RgbView target,
                     const Shading& shading, RasterStats* stats) {
    FloatImage depth(target.width, target.height);
    FrameBand band = full_frame_band(target, depth.view());
    clear_band(band, shading.background);
    const Vec3 light = normalize(shading.light);
    const float ambient = shading.ambient;
    auto shader = [&](const Fragment& f) {
        const float lambert = std::fabs(dot(f.normal, light));  // two-sided: spikes flip
        return to_rgb8(f.color * (ambient + (1.0f - ambient) * lambert));
    };
    DrawOptions opt;
    opt.cull = CullMode::none;
    return draw_mesh(camera, band, mesh.view(), opt, shader, stats);
}

namespace {

// The triangles in ascending depth, ties in ascending index: the order std::sort gives the
// pairs (depth, index), found by a stable radix sort of the depths' order-preserving bit
// patterns (three passes of 11 bits) over the indices in ascending order. -0 counts as +0, as
// it compares equal in the pairs. Depths are finite.
std::vector<int> far_first_order(const std::vector<float>& depth) {
    const std::size_t n = depth.size();
    std::vector<std::uint32_t> key(n), key2(n);
    std::vector<int> index(n), index2(n);
    for (std::size_t i = 0; i < n; ++i) {
        const float z = depth[i] + 0.0f;  // -0 -> +0
        std::uint32_t b;
        std::memcpy(&b, &z, sizeof b);
        key[i] = (b & 0x80000000u) ? ~b : (b | 0x80000000u);
        index[i] = int(i);
    }
    for (int shift = 0; shift < 32; shift += 11) {
        std::size_t count[2049] = {0};
        for (std::size_t i = 0; i < n; ++i) ++count[((key[i] >> shift) & 2047u) + 1];
        for (int d = 0; d < 2048; ++d) count[d + 1] += count[d];
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t at = count[(key[i] >> shift) & 2047u]++;
            key2[at] = key[i];
            index2[at] = index[i];
        }
        key.swap(key2);
        index.swap(index2);
    }
    return index;
}

// The flame's edges against its core (TransparencySeen::edge_background): per image row, the
// covered span from the first to the last covered pixel; its outer tenth at either side is
// the edge, its middle half the core; the mean background share over each.
void measure_edge_fade(const std::vector<float>& background_share, int width, int height,
                       TransparencySeen* seen) {
    double edge = 0, edge_n = 0, core = 0, core_n = 0;
    for (int y = 0; y < height; ++y) {
        const float* row = &background_share[std::size_t(y) * std::size_t(width)];
        int x0 = 0, x1 = width - 1;
        while (x0 < width && row[x0] >= 1.0f) ++x0;
        while (x1 >= x0 && row[x1] >= 1.0f) --x1;
        const int span = x1 - x0 + 1;
        if (span < 20) continue;  // too few pixels to tell an edge from a core
        for (int x = x0; x <= x1; ++x) {
            const int from_side = std::min(x - x0, x1 - x);
            if (row[x] >= 1.0f) continue;
            if (from_side < span / 10) {
                edge += row[x];
                edge_n += 1;
            } else if (from_side >= span / 4) {
                core += row[x];
                core_n += 1;
            }
        }
    }
    seen->edge_background = edge_n > 0 ? edge / edge_n : 0.0;
    seen->core_background = core_n > 0 ? core / core_n : 0.0;
}

}  // namespace

Status render_transparent(const Camera& camera, const WrMesh& wm, RgbView target,
                          const Shading& shading, RasterStats* stats, TransparencySeen* seen) {
    FloatImage depth(target.width, target.height);
    FrameBand band = full_frame_band(target, depth.view());
    clear_band(band, shading.background);
    // Painter's order: sort the triangles by the view depth of their centroids, far first.
    const TriangleMesh& m = wm.mesh;
    const int n = m.triangle_count();
    std::vector<float> depth_of(static_cast<std::size_t>(n));
    for (int t = 0; t < n; ++t) {
        Vec3 c{0, 0, 0};
        for (int e = 0; e < 3; ++e) c += m.positions[m.indices[std::size_t(3 * t + e)]];
        const Vec3 eye = transform_point(camera.view, c / 3.0f);
        depth_of[std::size_t(t)] = eye.z;  // eye looks down -z: more negative = farther
    }
    const std::vector<int> order = far_first_order(depth_of);
    TriangleMesh sorted;
    sorted.positions = m.positions;
    sorted.normals = m.normals;
    sorted.colors = m.colors;
    // The transparency rides in uv.x (the rasterizer interpolates uv perspective-correctly).
    sorted.uvs.resize(m.positions.size());
    for (std::size_t i = 0; i < sorted.uvs.size(); ++i) sorted.uvs[i] = {wm.transparency[i], 0};
    sorted.indices.reserve(m.indices.size());
    for (const int t : order)
        for (int e = 0; e < 3; ++e) sorted.indices.push_back(m.indices[std::size_t(3 * t + e)]);
    const Vec3 light = normalize(shading.light);
    // For `seen`: per pixel, the share of the colour still the background's, and the share
    // from surface layers behind the latest fragment.
    std::vector<float> background_share, behind_share;
    if (seen) {
        background_share.assign(std::size_t(target.width) * std::size_t(target.height), 1.0f);
        behind_share.assign(background_share.size(), 0.0f);
    }
    auto shader = [&](const Fragment& f) {
        const float lambert = std::fabs(dot(f.normal, light));
        const Vec3 c = shading.emissive
                           ? f.color * (0.85f + 0.25f * lambert)  // mostly emissive
                           : f.color * (shading.ambient + (1.0f - shading.ambient) * lambert);
        const float t = clamp(f.uv.x, 0.0f, 1.0f);
        const Vec3 dst = from_rgb8(target.at(f.x, f.y - band.y0));
        if (seen) {
            const std::size_t i =
                std::size_t(f.y - band.y0) * std::size_t(target.width) + std::size_t(f.x);
            behind_share[i] = t * (1.0f - background_share[i]);
            background_share[i] *= t;
        }
        return to_rgb8(c * (1.0f - t) + dst * t);  // "over" with opacity 1 - t
    };
    DrawOptions opt;
    opt.cull = CullMode::none;
    const Status st = draw_mesh(camera, band, sorted.view(), opt, shader, stats);
    if (seen && st) {
        double covered = 0, behind = 0, showing = 0, through = 0;
        for (std::size_t i = 0; i < background_share.size(); ++i)
            if (background_share[i] < 1.0f) {
                covered += 1;
                through += background_share[i];
                behind += behind_share[i];
                if (behind_share[i] > 0.15f) showing += 1;
            }
        seen->coverage = covered / double(background_share.size());
        seen->see_through = covered > 0 ? behind / covered : 0.0;
        seen->see_through_pixels = covered > 0 ? showing / covered : 0.0;
        seen->background = covered > 0 ? through / covered : 0.0;
        measure_edge_fade(background_share, target.width, target.height, seen);
    }
    return st;
}

void draw_control_mesh(RgbView target, const Camera& camera, const WrControlMesh& mesh,
                       const WrSurface& surface, bool sticks, Rgb8 background) {
    RasterCanvas canvas(target);
    canvas.clear(background);
    auto screen = [&](Vec3 p) {
        const Vec3 s = project(camera, p);
        return Vec2{s.x, s.y};
    };
    const Rgb8 grid{90, 90, 90};
    for (int r = 0; r < mesh.rows; ++r)
        for (int c = 0; c < mesh.cols; ++c) {
            const Vec3 p = mesh.at(c, r).position;
            if (c + 1 < mesh.cols)
                canvas.line(screen(p), screen(mesh.at(c + 1, r).position), grid, 1.2f);
            if (r + 1 < mesh.rows)
                canvas.line(screen(p), screen(mesh.at(c, r + 1).position), grid, 1.2f);
        }
    const float dot_size = std::max(3.0f, float(target.width) / 64.0f);
    for (int r = 0; r < mesh.rows; ++r)
        for (int c = 0; c < mesh.cols; ++c) {
            const WrControlPoint& p = mesh.at(c, r);
            const Rgb8 col = to_rgb8(p.color);
            if (sticks) {
                // Direction of the stick: d_i, or the control polygon's normal at the point.
                Vec3 d = p.direction;
                if (surface.displacement() == DisplacementMode::normal || length_squared(d) == 0) {
                    // The base surface normal where the point acts most: u = c/n (Bezier),
                    // the centre of its cubic basis s = c - (n-1)/2 (uniform B-spline).
                    const float half = surface.basis() == SurfaceBasis::bezier
                                           ? 0.0f
                                           : 0.5f * float(surface.degree() - 1);
                    const float du = surface.basis() == SurfaceBasis::bezier
                                         ? float(surface.degree())
                                         : float(surface.spans_u());
                    const float dv = surface.basis() == SurfaceBasis::bezier
                                         ? float(surface.degree())
                                         : float(surface.spans_v());
                    d = surface
                            .base_point(clamp((float(c) - half) / du, 0.0f, 1.0f),
                                        clamp((float(r) - half) / dv, 0.0f, 1.0f))
                            .normal;
                }
                const Vec3 tip = p.position + d * p.height;
                canvas.line(screen(p.position), screen(tip), Rgb8{30, 30, 30}, 1.5f);
                canvas.marker(screen(tip), MarkerShape::dot, dot_size, Rgb8{20, 20, 20});
            }
            canvas.marker(screen(p.position), MarkerShape::dot, dot_size * 1.2f, col);
            canvas.marker(screen(p.position), MarkerShape::circle, dot_size * 1.2f,
                          Rgb8{40, 40, 40});
        }
}

Vec3 span_color(int i, int j) {
    // A fixed, well-separated palette; neighbours always differ.
    static const float pal[][3] = {
        {0.90f, 0.25f, 0.20f}, {0.95f, 0.75f, 0.15f}, {0.30f, 0.70f, 0.30f}, {0.20f, 0.55f, 0.90f},
        {0.65f, 0.35f, 0.85f}, {0.95f, 0.55f, 0.70f}, {0.35f, 0.85f, 0.85f}};
    const int k = ((i % 7) + 7 + 3 * ((j % 7) + 7)) % 7;
    return {pal[k][0], pal[k][1], pal[k][2]};
}

void color_by_source_span(WrMesh* m, const WrSurface& surface, int k) {
    for (std::size_t i = 0; i < m->mesh.positions.size(); ++i) {
        const Vec2 uv = m->mesh.uvs[i];
        int su = 0, sv = 0;
        float t = 0;
        tensor_locate(surface.spans_u(), surface.inverse_u(uv.x, k), &su, &t);
        tensor_locate(surface.spans_v(), surface.inverse_v(uv.y, k), &sv, &t);
        m->mesh.colors[i] = span_color(su, sv);
    }
}

Status make_axes(const WrSurface& surface, IstKind kind, const char* shuffle_name, int n,
                 int max_level, AxisPair* out) {
    IstAxis iu, iv;
    if (kind == IstKind::unit) {
        SHITSUKAN_TRY(ist_unit_axis(n, 1, surface.spans_u(), iu));
        SHITSUKAN_TRY(ist_unit_axis(n, 1, surface.spans_v(), iv));
    } else if (kind == IstKind::fully_connected) {
        SHITSUKAN_TRY(ist_fully_connected_axis(n, 1, surface.spans_u(), IstEnds::translation, iu));
        SHITSUKAN_TRY(ist_fully_connected_axis(n, 1, surface.spans_v(), IstEnds::translation, iv));
    } else {
        IstShuffle sh;
        SHITSUKAN_TRY(ist_shuffle_named(shuffle_name, n, sh));
        SHITSUKAN_TRY(ist_connected_axis(sh, 1, surface.spans_u(), IstEnds::translation, iu));
        SHITSUKAN_TRY(ist_connected_axis(sh, 1, surface.spans_v(), IstEnds::translation, iv));
    }
    SHITSUKAN_TRY(make_wr_ist_axis(iu, max_level, out->u));
    SHITSUKAN_TRY(make_wr_ist_axis(iv, max_level, out->v));
    return Status::success();
}

namespace {
// Figures run in parallel (the driver's --jobs): the store is shared, so it is locked.
std::mutex& stage_store_mutex() {
    static std::mutex mutex;
    return mutex;
}
std::map<std::string, StageTimes>& stage_store() {
    static std::map<std::string, StageTimes> store;
    return store;
}
}  // namespace

void record_stage_times(const std::string& key, const StageTimes& t) {
    std::lock_guard<std::mutex> lock(stage_store_mutex());
    stage_store()[key] = t;
}

bool find_stage_times(const std::string& key, StageTimes* t) {
    std::lock_guard<std::mutex> lock(stage_store_mutex());
    auto it = stage_store().find(key);
    if (it == stage_store().end()) return false;
    *t = it->second;
    return true;
}

double mean_offset(const WrSurface& surface, const WrMesh& m) {
    double sum = 0;
    long n = 0;
    for (std::size_t i = 0; i < m.mesh.positions.size(); i += 7) {
        const Vec2 uv = m.mesh.uvs[i];
        sum += double(length(m.mesh.positions[i] - surface.base_point(uv.x, uv.y).position));
        ++n;
    }
    return n ? sum / double(n) : 0.0;
}

std::string format_seconds(double s) {
    // Small stages (polygonisation takes milliseconds here) keep their digits: never "0.00 s".
    if (s >= 1.0) return fmt("%.2f s", s);
    if (s >= 0.01) return fmt("%.3f s", s);
    return fmt("%.2f ms", 1e3 * s);
}

void downsample_into(const RgbView& src, RgbView dst) {
    // Box filter: each destination pixel is the mean of the source pixels it covers.
    for (int y = 0; y < dst.height; ++y) {
        const int y0 = int(std::int64_t(y) * src.height / dst.height);
        const int y1 = std::max(y0 + 1, int(std::int64_t(y + 1) * src.height / dst.height));
        for (int x = 0; x < dst.width; ++x) {
            const int x0 = int(std::int64_t(x) * src.width / dst.width);
            const int x1 = std::max(x0 + 1, int(std::int64_t(x + 1) * src.width / dst.width));
            unsigned r = 0, g = 0, b = 0, n = 0;
            for (int sy = y0; sy < y1; ++sy)
                for (int sx = x0; sx < x1; ++sx) {
                    const Rgb8 c = src.at(sx, sy);
                    r += c.r;
                    g += c.g;
                    b += c.b;
                    ++n;
                }
            dst.at(x, y) = Rgb8{std::uint8_t((r + n / 2) / n), std::uint8_t((g + n / 2) / n),
                                std::uint8_t((b + n / 2) / n)};
        }
    }
}

std::string stage_table(const std::vector<std::string>& names, const std::vector<StageTimes>& ours,
                        const std::vector<std::array<const char*, 4>>& paper) {
    std::string md = "| | ";
    for (const std::string& n : names) md += n + " paper | " + n + " ours | ";
    md += "\n|---|";
    for (std::size_t i = 0; i < names.size(); ++i) md += "---|---|";
    md += "\n";
    const char* rows[4] = {"sam.", "pol.", "ren.", "total"};
    for (int r = 0; r < 4; ++r) {
        md += std::string("| ") + rows[r] + " | ";
        for (std::size_t i = 0; i < names.size(); ++i) {
            const StageTimes& t = ours[i];
            const double v = r == 0   ? t.sampling
                             : r == 1 ? t.polygonisation
                             : r == 2 ? t.rendering
                                      : t.sampling + t.polygonisation + t.rendering;
            md += std::string(paper[i][std::size_t(r)]) + " | " + format_seconds(v) + " | ";
        }
        md += "\n";
    }
    md += "| triangles |";
    for (std::size_t i = 0; i < names.size(); ++i)
        md += " | " + fmt("%ld", ours[i].triangles) + " |";
    md += "\n";
    return md;
}

std::string stage_table(const std::string& figure, const std::vector<PaperTimes>& rows,
                        const std::map<std::string, StageTimes>& times) {
    std::vector<std::string> names;
    std::vector<StageTimes> ours;
    std::vector<std::array<const char*, 4>> paper;
    for (const PaperTimes& r : rows) {
        StageTimes t;
        const auto it = times.find(r.label);
        if (it != times.end())
            t = it->second;
        else
            find_stage_times(figure + r.label, &t);
        names.push_back(r.label);
        ours.push_back(t);
        paper.push_back(r.paper);
    }
    return stage_table(names, ours, paper);
}

void label_panel(RgbView target, const std::string& text, Rgb8 color) {
    RasterCanvas canvas(target);
    const int scale = target.width >= 400 ? 2 : 1;
    canvas.text(Vec2{6.0f, 6.0f}, text, color, scale);
}

}  // namespace shitsukan::fujimoto2000
