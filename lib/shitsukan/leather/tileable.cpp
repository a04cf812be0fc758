#include "shitsukan/leather/tileable.hpp"

#include <algorithm>
#include <cmath>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/geom/polygon.hpp"

namespace shitsukan {
namespace {

// The block: the kept tile with `margin` tiles on each side along each periodic axis, at least
// kMarginCells cells (chosen: processing 4's shrink loop reaches a few cells from the block's
// straight outer border; measured: one tile of 3 rows, D = 0.33 and a = 0.5, was not enough).
constexpr int kMarginCells = 6;

int margin_tiles(int cells_per_tile) {
    return std::max(1, (kMarginCells + cells_per_tile - 1) / cells_per_tile);
}

int wrap_index(int i, int n) { return ((i % n) + n) % n; }

// Lattice columns and rows closing the tile (see the header).
void lattice_counts(const TileParams& prm, int* nx, int* ny) {
    const ScaleParams& sp = prm.scales;
    const bool tri = prm.layout == TileLayout::triangular_lattice;
    *nx = std::max(1, int(std::lround(double(sp.width) / double(sp.D))));
    const double Dx = double(sp.width) / *nx;
    *ny = tri ? 2 * std::max(1, int(std::lround(double(sp.height) / (Dx * std::sqrt(3.0)))))
              : std::max(1, int(std::lround(double(sp.height) / double(sp.D))));
}

int belly_rows(const ScaleParams& sp) {
    return std::max(1, int(std::lround(double(sp.height) / double(sp.D))));
}

// The lattice closing the tile (see the header) and its seeds over the 3 x 3 block, each copy
// moved by the displacement of its wrapped indices (processings 1-2 of fig. 3).
void lattice_block_seeds(const TileParams& prm, int bx, int by, TileReport& rep,
                         std::vector<Vec2d>& seeds) {
    const ScaleParams& sp = prm.scales;
    const double W = sp.width, H = sp.height;
    const bool tri = prm.layout == TileLayout::triangular_lattice;
    int nx, ny;
    lattice_counts(prm, &nx, &ny);
    const double Dx = W / nx, Dy = H / ny;
    rep.columns = nx;
    rep.rows = ny;
    rep.Dx = float(Dx);
    rep.Dy = float(Dy);
    seeds.clear();
    // one ring of seeds outside the block, as the plain lattices (the border cuts cells)
    for (int j = -1; j <= by * ny; ++j)
        for (int i = -1; i <= bx * nx; ++i) {
            const int iw = wrap_index(i, nx), jw = wrap_index(j, ny);
            const double shift = tri ? 0.5 * double(jw & 1) : 0.0;
            Vec2d p{(i + 0.5 + shift) * Dx, (j + 0.5) * Dy};
            p.x += double(seed_displacement(float(Dx), sp.a,
                                            hashed_rnd(sp.seed, kStreamLatticeX, iw, jw)));
            p.y += double(seed_displacement(float(Dy), sp.a,
                                            hashed_rnd(sp.seed, kStreamLatticeY, iw, jw)));
            seeds.push_back(p);
        }
}

// The belly's stage-1 seeds over the bx x by block (fig. 4 in every tile, wrapped row
// indices), and the wrapped row id of each for stage 2's random numbers.
void belly_block_seeds(const ScaleParams& sp, int bx, int by, TileReport& rep,
                       ScaleDivision& div) {
    const int ny = belly_rows(sp);
    const double Dy = double(sp.height) / ny, xc = 0.5 * double(sp.width);
    rep.columns = 0;
    rep.rows = ny;
    rep.Dx = sp.D;
    rep.Dy = float(Dy);
    div.stage1_seeds.original.clear();
    div.stage1_seeds.moved.clear();
    div.stage1_row_id.clear();
    for (int j = -1; j <= by * ny; ++j)
        for (int k = 0; k < 2 * bx; ++k) {
            const int side = k & 1, tile = k / 2;
            const int jw = wrap_index(j, ny);
            // processing 1: two rows parallel to y at distance d from each tile's centre line
            const double cx = xc + double(tile) * double(sp.width);
            Vec2d p{side == 0 ? cx - double(sp.d) : cx + double(sp.d), (j + 0.5) * Dy};
            div.stage1_seeds.original.push_back(p);
            // processing 2: moved along y by eq. (1), the wrapped row's random number
            p.y += double(seed_displacement(float(Dy), sp.a,
                                            hashed_rnd(sp.seed, kStreamStage1, 2 * jw + side, 0)));
            div.stage1_seeds.moved.push_back(p);
            div.stage1_row_id.push_back(2 * jw + side);
        }
}

// The middle tile's scales of the block pattern, shifted to the tile: the polygons whose
// centroid lies in [mx W, (mx + 1) W) x [my H, (my + 1) H) (periodic axes only).
void keep_middle_tile(const ScalePattern& block, float W, float H, int mx, int my,
                      ScalePattern& out) {
    const bool wx = mx > 0, wy = my > 0;
    out = ScalePattern{};
    out.width = W;
    out.height = H;
    out.wrap_x = wx;
    out.wrap_y = wy;
    out.polygon_offsets.assign(1, 0);
    const float ox = float(mx) * W, oy = float(my) * H;
    for (int f = 0; f < block.polygon_count(); ++f) {
        const Vec2 c = block.centroids[std::size_t(f)];
        if (wx && !(c.x >= ox && c.x < ox + W)) continue;
        if (wy && !(c.y >= oy && c.y < oy + H)) continue;
        int n;
        const Vec2* v = block.polygon(f, &n);
        for (int k = 0; k < n; ++k) out.vertices.push_back(Vec2{v[k].x - ox, v[k].y - oy});
        out.polygon_offsets.push_back(int(out.vertices.size()));
        out.centroids.push_back(Vec2{c.x - ox, c.y - oy});
    }
}

Status check_torus_area(const ScalePattern& out) {
    double area = 0.0;
    for (int f = 0; f < out.polygon_count(); ++f) {
        int n;
        const Vec2* v = out.polygon(f, &n);
        area += polygon_area(v, n);
    }
    const double want = double(out.width) * double(out.height);
    if (!(std::fabs(area - want) <= 1e-5 * want))
        return Status::error(StatusCode::degenerate,
                             "tileable pattern: the scales of one tile do not tile the torus "
                             "(their areas sum to %.9g of %.9g over %d polygons); lower the "
                             "perturbation p or raise the tile",
                             area, want, out.polygon_count());
    return Status::success();
}

}  // namespace

Status generate_tileable_pattern(const TileParams& prm, ScalePattern& out, TileReport* report,
                                 Progress progress) {
    SHITSUKAN_TRY(check_scale_params(prm.scales));
    const ScaleParams& sp = prm.scales;
    const bool belly = prm.layout == TileLayout::belly;
    int nx = 0, ny = belly_rows(sp);
    if (belly) {  // the belly's columns per tile (stage 2), for the block's margin along x
        Stage2Columns columns;
        SHITSUKAN_TRY(stage2_columns(sp.width, sp.D, sp.edge_ratio, columns));
        nx = std::max(1, int(columns.x.size()));  // a scale per column
    } else {
        lattice_counts(prm, &nx, &ny);
    }
    const int mx = margin_tiles(nx), my = margin_tiles(ny);
    const int bx = 2 * mx + 1, by = 2 * my + 1;
    // the block's tiles (a lattice has about as many cells as the belly has scales)
    SHITSUKAN_TRY(check_memory_budget(budget_mul(scale_pattern_bytes(sp), std::uint64_t(bx * by)),
                                      "tileable scale pattern (the block of tiles)"));
    TileReport rep;
    PerturbationParams pp = sp.perturbation;
    ScalePattern block;
    if (belly) {
        ScaleParams bp = sp;  // the bx x by block of tiles
        bp.width = float(bx) * sp.width;
        bp.height = float(by) * sp.height;
        bp.D = float(double(sp.height) / ny);
        ScaleDivision div;
        div.column_period = sp.width;  // stage 2: the tile's columns, repeated
        belly_block_seeds(sp, bx, by, rep, div);
        SHITSUKAN_TRY(stage1_vertical_division(bp, div));
        SHITSUKAN_TRY(stage2_horizontal_division(bp, div));
        progress.report(0.05f);
        pp.period_x = sp.width;
        pp.period_y = sp.height;
        SHITSUKAN_TRY(perturb_two_stage(div.stage1, div.cells, div.cell_stage1, pp, sp.seed,
                                        bp.width, bp.height, div.stage1_pattern, block,
                                        &rep.perturbation));
    } else {
        std::vector<Vec2d> seeds;
        lattice_block_seeds(prm, bx, by, rep, seeds);
        const float bw = float(bx) * sp.width, bh = float(by) * sp.height;
        PlanarSubdivision sub;
        SHITSUKAN_TRY(divide_single_stage(seeds.data(), int(seeds.size()), bw, bh, sub));
        progress.report(0.05f);
        pp.period_x = sp.width;
        pp.period_y = sp.height;
        SHITSUKAN_TRY(perturb_subdivision(sub, pp, sp.seed, bw, bh, block, &rep.perturbation));
    }
    progress.report(0.9f);
    keep_middle_tile(block, sp.width, sp.height, mx, my, out);
    Status s = check_torus_area(out);
    if (!s) {
        out = ScalePattern{};
        return s;
    }
    rep.polygons = out.polygon_count();
    if (report) *report = rep;
    progress.report(1.0f);
    return Status::success();
}

Status torus_cover(const ScalePattern& torus, ScalePattern& out) {
    if (!(torus.width > 0.0f && torus.height > 0.0f) || !is_finite(torus.width) ||
        !is_finite(torus.height))
        return Status::error(StatusCode::invalid_argument, "torus_cover: pattern is %g x %g",
                             double(torus.width), double(torus.height));
    if (torus.polygon_offsets.empty() || torus.polygon_offsets.front() != 0 ||
        std::size_t(torus.polygon_offsets.back()) != torus.vertices.size() ||
        torus.centroids.size() + 1 != torus.polygon_offsets.size())
        return Status::error(StatusCode::invalid_argument,
                             "torus_cover: polygon_offsets / centroids do not match the %d "
                             "vertices",
                             int(torus.vertices.size()));
    ScalePattern cover;
    cover.width = torus.width;
    cover.height = torus.height;
    cover.polygon_offsets.assign(1, 0);
    const float W = torus.width, H = torus.height;
    const int rx = torus.wrap_x ? 1 : 0, ry = torus.wrap_y ? 1 : 0;
    for (int f = 0; f < torus.polygon_count(); ++f) {
        int n;
        const Vec2* v = torus.polygon(f, &n);
        if (n < 1) continue;
        Vec2 lo = v[0], hi = v[0];
        for (int k = 1; k < n; ++k) {
            lo = Vec2{std::min(lo.x, v[k].x), std::min(lo.y, v[k].y)};
            hi = Vec2{std::max(hi.x, v[k].x), std::max(hi.y, v[k].y)};
        }
        for (int sy = -ry; sy <= ry; ++sy)
            for (int sx = -rx; sx <= rx; ++sx) {
                const float dx = float(sx) * W, dy = float(sy) * H;
                if (hi.x + dx < 0.0f || lo.x + dx > W || hi.y + dy < 0.0f || lo.y + dy > H)
                    continue;
                for (int k = 0; k < n; ++k) cover.vertices.push_back(Vec2{v[k].x + dx, v[k].y + dy});
                cover.polygon_offsets.push_back(int(cover.vertices.size()));
                const Vec2 c = torus.centroids[std::size_t(f)];
                cover.centroids.push_back(Vec2{c.x + dx, c.y + dy});
            }
    }
    out = std::move(cover);
    return Status::success();
}

}  // namespace shitsukan
