// hirota1998: the cracked bark as a seamless texture (see bark_texture.hpp).
#include "shitsukan/bark/bark_texture.hpp"

#include <algorithm>
#include <cmath>

#include "shitsukan/bark/crack_drawing.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {

constexpr std::uint32_t kStreamPlateTop = 41, kStreamPlateTone = 42;  // chosen here

// The periodic offset d in (-P/2, P/2].
float wrap_offset(float d, float period) { return d - period * std::floor(d / period + 0.5f); }
float wrap_into(float x, float period) { return x - period * std::floor(x / period); }

// A piece of a crack's centre line, a -> b, half-widths ra at a, rb at b.
struct CrackPiece {
    Vec2 a, ab;
    float ra, rb, reach;
};

// Cells over one period holding what reaches into them (CSR: begin per cell, items).
struct PeriodicGrid {
    int nx = 1, ny = 1;
    float cu = 1, cz = 1;
    std::vector<std::uint32_t> begin, items;
    int cell(float u, float z) const {
        const int x = std::min(nx - 1, int(u / cu)), y = std::min(ny - 1, int(z / cz));
        return y * nx + x;
    }
};

PeriodicGrid make_grid(float period_u, float period_z, float cell) {
    PeriodicGrid g;
    g.nx = std::max(1, int(period_u / cell));
    g.ny = std::max(1, int(period_z / cell));
    g.cu = period_u / float(g.nx);
    g.cz = period_z / float(g.ny);
    return g;
}

// Fills the grid with items whose boxes [lo, hi] (absolute, any period) cover cells.
template <class Box> void fill_grid(PeriodicGrid& g, int count, Box box) {
    g.begin.assign(std::size_t(g.nx * g.ny + 1), 0);
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<std::uint32_t> at;
        if (pass == 1) {
            for (std::size_t c = 1; c < g.begin.size(); ++c) g.begin[c] += g.begin[c - 1];
            g.items.resize(g.begin.back());
            at.assign(g.begin.begin(), g.begin.end() - 1);
        }
        for (int i = 0; i < count; ++i) {
            Vec2 lo, hi;
            box(i, &lo, &hi);
            const int x0 = int(std::floor(lo.x / g.cu)), x1 = int(std::floor(hi.x / g.cu));
            const int y0 = int(std::floor(lo.y / g.cz)), y1 = int(std::floor(hi.y / g.cz));
            for (int y = y0; y <= std::min(y1, y0 + g.ny - 1); ++y)
                for (int x = x0; x <= std::min(x1, x0 + g.nx - 1); ++x) {
                    const int c = ((y % g.ny + g.ny) % g.ny) * g.nx + (x % g.nx + g.nx) % g.nx;
                    if (pass == 0)
                        ++g.begin[std::size_t(c) + 1];
                    else
                        g.items[at[std::size_t(c)]++] = std::uint32_t(i);
                }
        }
    }
}

// Integral of the profile across a crack from its centre line to x >= 0 (bark_texture.hpp).
float profile_integral(float x, float r, float b, float top) {
    const float e = x - r;
    if (e <= 0.0f) return 0.0f;
    if (e < b) return top * (e * e / b - e * e * e / (3.0f * b * b));
    return top * (e - b / 3.0f);
}

float odd_integral(float x, float r, float b, float top) {
    return x < 0.0f ? -profile_integral(-x, r, b, top) : profile_integral(x, r, b, top);
}

struct Periods {
    float u, z;
};

// The cracks of each triangle (up to 3: its springs' faces meet at its centroid).
struct TriangleCracks {
    int count = 0;
    int ribbon[3] = {0, 0, 0};
    int side[3] = {0, 0, 0};  // which face end of the ribbon is this triangle's centroid
};

// The crack pieces around one triangle's centroid: two cracks meeting there are one groove
// joining their midpoints straight (widths linear between them); one crack ends there (its
// tip: width 0 at the centroid); three meet at the centroid (width there: their mean).
void triangle_pieces(const std::vector<CrackRibbon>& ribbons, const TriangleCracks& tc,
                     Periods P, float reach, std::vector<CrackPiece>* pieces) {
    auto mid = [&](int k) {
        const Vec3 m = ribbons[std::size_t(tc.ribbon[k])].midpoint;
        return Vec2{wrap_into(m.x, P.u), wrap_into(m.y, P.z)};
    };
    auto half = [&](int k) { return 0.5f * std::max(0.0f, ribbons[std::size_t(tc.ribbon[k])].width); };
    auto offset = [&](Vec2 from, Vec3 to) {
        return Vec2{wrap_offset(to.x - from.x, P.u), wrap_offset(to.y - from.y, P.z)};
    };
    if (tc.count == 2) {
        const Vec2 a = mid(0);
        const Vec3 m1 = ribbons[std::size_t(tc.ribbon[1])].midpoint;
        const float ra = half(0), rb = half(1);
        pieces->push_back({a, offset(a, m1), ra, rb, std::max(ra, rb) + reach});
        return;
    }
    float mean = 0.0f;
    for (int k = 0; k < tc.count; ++k) mean += half(k) / float(tc.count);
    const float rc = tc.count == 3 ? mean : 0.0f;
    for (int k = 0; k < tc.count; ++k) {
        const CrackRibbon& r = ribbons[std::size_t(tc.ribbon[k])];
        const Vec2 a = mid(k);
        pieces->push_back({a, offset(a, r.face[tc.side[k]]), half(k),
                           rc, std::max(half(k), rc) + reach});
    }
}

// The crack pieces of every broken (or weak) spring, triangle by triangle.
Status crack_pieces(const BarkCylinder& bark, float t, const Vec3* W, Periods P, float reach,
                    std::vector<CrackPiece>* pieces, BarkTexture* out) {
    std::vector<CrackRibbon> ribbons;
    SHITSUKAN_TRY(crack_ribbons(bark, t, W, ribbons, true));
    SHITSUKAN_TRY(check_memory_budget(
        budget_mul(budget_add(2 * ribbons.size(), bark.triangles.size()),
                   sizeof(CrackPiece) + sizeof(TriangleCracks)),
        "bark texture: crack pieces"));
    std::vector<TriangleCracks> per(bark.triangles.size());
    double broken_sum = 0;
    int broken = 0;
    for (std::size_t i = 0; i < ribbons.size(); ++i) {
        const CrackRibbon& r = ribbons[i];
        for (int k = 0; k < 2; ++k) {
            const std::int32_t tri = bark.spring_triangles[2 * std::size_t(r.spring) + k];
            if (tri < 0) continue;
            TriangleCracks& tc = per[std::size_t(tri)];
            tc.ribbon[tc.count] = int(i), tc.side[tc.count] = k, ++tc.count;
        }
        if (!r.weak) broken_sum += double(r.width), ++broken;
    }
    out->cracks = int(ribbons.size());
    out->mean_crack_width = broken ? float(broken_sum / broken) : 0.0f;
    pieces->clear();
    for (const TriangleCracks& tc : per)
        if (tc.count > 0) triangle_pieces(ribbons, tc, P, reach, pieces);
    return Status::success();
}

// Distance from q to the piece's centre line and the half-width there.
void piece_distance(const CrackPiece& c, Vec2 q, float* d, float* r) {
    const float len2 = c.ab.x * c.ab.x + c.ab.y * c.ab.y;
    float s = len2 > 0.0f ? (q.x * c.ab.x + q.y * c.ab.y) / len2 : 0.0f;
    s = clamp(s, 0.0f, 1.0f);
    const float dx = q.x - s * c.ab.x, dy = q.y - s * c.ab.y;
    *d = std::sqrt(dx * dx + dy * dy);
    *r = c.ra + s * (c.rb - c.ra);
}

// Per node: the plate's top (cm) and tone, from its region (or itself, outside any region).
void plate_looks(const BarkCylinder& bark, const RegionReport* regions,
                 const BarkTextureOptions& o, std::vector<Vec2>* looks, BarkTexture* out) {
    const int n = bark.net.node_count();
    looks->resize(std::size_t(n));
    const bool labelled = regions && int(regions->label.size()) == n;
    const std::int32_t offset = labelled ? std::int32_t(regions->regions.size()) : 0;
    out->plates = labelled ? int(regions->regions.size()) : n;
    const float D = bark.params.D;
    for (int p = 0; p < n; ++p) {
        const std::int32_t label = labelled ? regions->label[std::size_t(p)] : -1;
        const std::int32_t key = label >= 0 ? label : offset + p;
        const float top = D * (1.0f + o.relief * (hash_uniform(o.seed, kStreamPlateTop, key) - 0.5f));
        const float tone = 1.0f + o.tone * (hash_uniform(o.seed, kStreamPlateTone, key) - 0.5f);
        (*looks)[std::size_t(p)] = {top, tone};
    }
}

std::uint8_t srgb_byte(float v) { return std::uint8_t(clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

struct Scene {
    Periods P;
    float bevel, px;
    const std::vector<CrackPiece>* pieces;
    const PeriodicGrid* piece_grid;
    const PeriodicGrid* node_grid;
    const std::vector<Vec2>* nodes;  // wrapped positions at t
    const std::vector<Vec2>* looks;  // per node: top, tone
};

// The nearest node to q (the plate the pixel belongs to): the 3 x 3 cells around it.
int nearest_node(const Scene& s, Vec2 q) {
    const PeriodicGrid& g = *s.node_grid;
    const int cx = std::min(g.nx - 1, int(q.x / g.cu)), cy = std::min(g.ny - 1, int(q.y / g.cz));
    int best = 0;
    float best_d = INFINITY;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int c = ((cy + dy + g.ny) % g.ny) * g.nx + (cx + dx + g.nx) % g.nx;
            for (std::uint32_t k = g.begin[std::size_t(c)]; k < g.begin[std::size_t(c) + 1]; ++k) {
                const std::uint32_t p = g.items[k];
                const Vec2 x = (*s.nodes)[p];
                const float du = wrap_offset(q.x - x.x, s.P.u), dz = wrap_offset(q.y - x.y, s.P.z);
                const float d = du * du + dz * dz;
                if (d < best_d || (d == best_d && int(p) < best)) best_d = d, best = int(p);
            }
        }
    return best;
}

// One pixel at q: height (cm), its share of the plate's top and the plate's tone.
void shade_pixel(const Scene& s, Vec2 q, float* height, float* share, float* tone) {
    const Vec2 look = (*s.looks)[std::size_t(nearest_node(s, q))];
    const float top = look.x, b = s.bevel * top, half = 0.5f * s.px;
    float h = top;
    const PeriodicGrid& g = *s.piece_grid;
    const int c = g.cell(q.x, q.y);
    for (std::uint32_t k = g.begin[std::size_t(c)]; k < g.begin[std::size_t(c) + 1]; ++k) {
        const CrackPiece& piece = (*s.pieces)[g.items[k]];
        const Vec2 rel{wrap_offset(q.x - piece.a.x, s.P.u), wrap_offset(q.y - piece.a.y, s.P.z)};
        float d, r;
        piece_distance(piece, rel, &d, &r);
        if (d >= piece.reach) continue;
        const float f =
            (odd_integral(d + half, r, b, top) - odd_integral(d - half, r, b, top)) / s.px;
        h = std::min(h, f);
    }
    *height = std::max(0.0f, h);
    *share = *height / top;
    *tone = look.y;
}

Status check_options(const BarkCylinder& bark, const Vec3* W, const BarkTextureOptions& o) {
    if (!W) return Status::error(StatusCode::invalid_argument, "bark texture: null W");
    if (!bark.periodic_along)
        return Status::error(StatusCode::invalid_argument,
                             "bark texture: the lattice must be periodic along the axis "
                             "(build_cylinder(params, true, ...))");
    if (o.width < 8 || o.width > 16384 || o.height < 8 || o.height > 16384)
        return Status::error(StatusCode::invalid_argument,
                             "bark texture: size %d x %d outside [8, 16384]", o.width, o.height);
    if (!(o.bevel > 0.0f && o.bevel <= 4.0f) || !(o.relief >= 0.0f && o.relief <= 1.0f) ||
        !(o.tone >= 0.0f && o.tone <= 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "bark texture: bevel %g must be in (0, 4], relief %g and tone %g "
                             "in [0, 1]",
                             double(o.bevel), double(o.relief), double(o.tone));
    const std::uint64_t pixels = budget_mul(std::uint64_t(o.width), std::uint64_t(o.height));
    return check_memory_budget(budget_mul(pixels, sizeof(float) + 3), "bark texture maps");
}

}  // namespace

BarkTextureColors bark_texture_colors(Species species) {
    BarkTextureColors c;
    if (species == Species::camphor) c.plate = {0.46f, 0.40f, 0.34f}, c.crack = {0.09f, 0.07f, 0.05f};
    if (species == Species::chinese_tallow) c.plate = {0.56f, 0.53f, 0.48f}, c.crack = {0.12f, 0.10f, 0.08f};
    if (species == Species::pine) c.plate = {0.55f, 0.36f, 0.25f}, c.crack = {0.10f, 0.06f, 0.04f};
    return c;
}

float bark_crack_profile(float x, float r, float b, float top, float px) {
    return (odd_integral(x + 0.5f * px, r, b, top) - odd_integral(x - 0.5f * px, r, b, top)) / px;
}

Status make_bark_texture(const BarkCylinder& bark, float t, const Vec3* W,
                         const RegionReport* regions, const BarkTextureOptions& o,
                         BarkTexture& out) {
    SHITSUKAN_TRY(check_options(bark, W, o));
    out = BarkTexture{};
    const CylinderParams& p = bark.params;
    const Periods P{bark.circumference * (1.0f + hoop_strain(p, t)),
                    float(p.N_H) * p.species.L0 * (1.0f + axial_strain(p, t))};
    out.width = o.width, out.height = o.height, out.period_u = P.u, out.period_z = P.z;
    out.cm_per_pixel = std::max(P.u / float(o.width), P.z / float(o.height));
    const float bevel_cm = o.bevel * p.D * (1.0f + 0.5f * o.relief);
    std::vector<CrackPiece> pieces;
    SHITSUKAN_TRY(crack_pieces(bark, t, W, P, bevel_cm + out.cm_per_pixel, &pieces, &out));
    const float cell = 1.25f * p.species.L0 * (1.0f + std::max(0.0f, axial_strain(p, t)));
    PeriodicGrid piece_grid = make_grid(P.u, P.z, std::max(cell, 2.0f * out.cm_per_pixel));
    fill_grid(piece_grid, int(pieces.size()), [&](int i, Vec2* lo, Vec2* hi) {
        const CrackPiece& c = pieces[std::size_t(i)];
        const Vec2 b{c.a.x + c.ab.x, c.a.y + c.ab.y};
        *lo = {std::min(c.a.x, b.x) - c.reach, std::min(c.a.y, b.y) - c.reach};
        *hi = {std::max(c.a.x, b.x) + c.reach, std::max(c.a.y, b.y) + c.reach};
    });
    const int n = bark.net.node_count();
    std::vector<Vec2> nodes(static_cast<std::size_t>(n)), looks;
    for (int i = 0; i < n; ++i) {
        const Vec3 x = node_position(bark, std::uint32_t(i), t, W);
        nodes[std::size_t(i)] = {wrap_into(x.x, P.u), wrap_into(x.y, P.z)};
    }
    PeriodicGrid node_grid = make_grid(P.u, P.z, cell);
    fill_grid(node_grid, n, [&](int i, Vec2* lo, Vec2* hi) { *lo = *hi = nodes[std::size_t(i)]; });
    plate_looks(bark, regions, o, &looks, &out);
    const Scene scene{P, o.bevel, out.cm_per_pixel, &pieces, &piece_grid, &node_grid, &nodes, &looks};
    out.height_cm.resize(std::size_t(o.width) * std::size_t(o.height));
    out.albedo.resize(3 * out.height_cm.size());
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            const Vec2 q{(float(x) + 0.5f) * P.u / float(o.width),
                         P.z - (float(y) + 0.5f) * P.z / float(o.height)};
            float h, m, tone;
            shade_pixel(scene, q, &h, &m, &tone);
            const std::size_t i = std::size_t(y) * std::size_t(o.width) + std::size_t(x);
            out.height_cm[i] = h;
            out.max_height = std::max(out.max_height, h);
            const Vec3 c = lerp(o.colors.crack, o.colors.plate * tone, m);
            out.albedo[3 * i] = srgb_byte(c.x);
            out.albedo[3 * i + 1] = srgb_byte(c.y);
            out.albedo[3 * i + 2] = srgb_byte(c.z);
        }
    return Status::success();
}

}  // namespace shitsukan
