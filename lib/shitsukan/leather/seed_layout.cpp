#include "shitsukan/leather/seed_layout.hpp"

#include <algorithm>
#include <cmath>

#include "shitsukan/core/hash.hpp"

namespace shitsukan {
namespace {

constexpr int kMaxSeedsPerLine = 4096;

Status check_common(const char* who, float width, float height, float D, float a) {
    if (!(width > 0.0f) || !(height > 0.0f) || !is_finite(width) || !is_finite(height))
        return Status::error(StatusCode::invalid_argument,
                             "%s: width and height must be > 0 (got %g x %g)", who, double(width),
                             double(height));
    if (!(D > 0.0f) || !is_finite(D))
        return Status::error(StatusCode::invalid_argument,
                             "%s: seed spacing D must be > 0 (got %g)", who, double(D));
    if (!(a >= 0.0f && a <= 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "%s: relative displacement a must be in [0, 1] (got %g)", who,
                             double(a));
    if (width / D > kMaxSeedsPerLine || height / D > kMaxSeedsPerLine)
        return Status::error(StatusCode::too_large,
                             "%s: %g x %g / D = %g gives more than %d seeds a line", who,
                             double(width), double(height), double(D), kMaxSeedsPerLine);
    return Status::success();
}

}  // namespace

float hashed_rnd(std::uint32_t seed, std::uint32_t stream, std::int32_t i, std::int32_t j) {
    return 2.0f * hash_uniform(seed, stream, i, j) - 1.0f;
}

Status square_lattice_seeds(float width, float height, float D, float a, std::uint32_t seed,
                            SeedLayout& out) {
    SHITSUKAN_TRY(check_common("square_lattice_seeds", width, height, D, a));
    out.original.clear();
    out.moved.clear();
    const int nx = int(std::ceil(width / D)), ny = int(std::ceil(height / D));
    for (int j = -1; j <= ny + 1; ++j)
        for (int i = -1; i <= nx + 1; ++i) {
            Vec2d p{i * double(D), j * double(D)};
            out.original.push_back(p);
            p.x += seed_displacement(D, a, hashed_rnd(seed, kStreamLatticeX, i, j));
            p.y += seed_displacement(D, a, hashed_rnd(seed, kStreamLatticeY, i, j));
            out.moved.push_back(p);
        }
    return Status::success();
}

Status triangular_lattice_seeds(float width, float height, float D, float a, std::uint32_t seed,
                                SeedLayout& out) {
    SHITSUKAN_TRY(check_common("triangular_lattice_seeds", width, height, D, a));
    out.original.clear();
    out.moved.clear();
    const double row = double(D) * std::sqrt(3.0) / 2.0;
    const int nx = int(std::ceil(width / D)), ny = int(std::ceil(height / row));
    for (int j = -1; j <= ny + 1; ++j)
        for (int i = -1; i <= nx + 1; ++i) {
            Vec2d p{(i + 0.5 * double(j & 1)) * double(D), j * row};
            out.original.push_back(p);
            p.x += seed_displacement(D, a, hashed_rnd(seed, kStreamLatticeX, i, j));
            p.y += seed_displacement(D, a, hashed_rnd(seed, kStreamLatticeY, i, j));
            out.moved.push_back(p);
        }
    return Status::success();
}

Status stage1_seeds(const Stage1SeedParams& prm, SeedLayout& out_layout) {
    const float width = prm.width, height = prm.height, D = prm.D, d = prm.d, a = prm.a;
    const std::uint32_t seed = prm.seed;
    SeedLayout* out = &out_layout;
    SHITSUKAN_TRY(check_common("stage1_seeds", width, height, D, a));
    if (!(d >= 0.0f) || !is_finite(d))
        return Status::error(StatusCode::invalid_argument,
                             "stage1_seeds: distance d from the centre line must be >= 0 (got %g)",
                             double(d));
    out->original.clear();
    out->moved.clear();
    const double xc = 0.5 * double(width);
    // processing 1: two rows parallel to y, at distance d on each side of the centre line, at
    // y = (j + 1/2) Dy, Dy = H / N (N = H / D rounded: the rows fill the height exactly)
    const int rows = std::max(1, int(std::lround(double(height) / double(D))));
    const double Dy = double(height) / rows;
    auto inside_row = [&](int j, int side, Vec2d* original, Vec2d* moved) {
        *original = {side == 0 ? xc - double(d) : xc + double(d), (j + 0.5) * Dy};
        *moved = *original;  // processing 2: move along y by eq. (1)
        moved->y += seed_displacement(D, a, hashed_rnd(seed, kStreamStage1, 2 * j + side, 0));
    };
    // two rows beyond each border: the mirror images of the first (last) two inside rows, so
    // the seeds are symmetric about y = 0 (y = H) there and the Voronoi edges run along the
    // border itself: the border rows are whole scales, never slivers
    for (int j = -2; j <= rows + 1; ++j)
        for (int side = 0; side < 2; ++side) {
            Vec2d original, moved;
            if (j < 0) {
                inside_row(-1 - j, side, &original, &moved);
                original.y = -original.y, moved.y = -moved.y;
            } else if (j >= rows) {
                inside_row(2 * rows - 1 - j, side, &original, &moved);
                original.y = 2.0 * double(height) - original.y;
                moved.y = 2.0 * double(height) - moved.y;
            } else {
                inside_row(j, side, &original, &moved);
            }
            out->original.push_back(original);
            out->moved.push_back(moved);
        }
    return Status::success();
}

float stage2_spacing(float width, float D, float edge_ratio, double x) {
    double u = std::fabs(x - 0.5 * double(width)) / (0.5 * double(width));
    if (u > 1.0) u = 1.0;
    return float(double(D) * (1.0 - (1.0 - double(edge_ratio)) * u * u));
}

namespace {

// The distances t_k of the columns from the centre line (and their spacings s_k) by the law:
// t_1 = s(0) / 2, then steps of s at the step's middle, until one column lies beyond the edge;
// all stretched by one common factor so that a column lies exactly on the edge (index
// `*on_edge`).
void columns_to_the_edge(float width, float D, float edge_ratio, std::vector<double>* t,
                         std::vector<double>* s, std::size_t* on_edge) {
    const double xc = 0.5 * double(width);
    t->assign(1, 0.5 * stage2_spacing(width, D, edge_ratio, xc));
    s->assign(1, double(stage2_spacing(width, D, edge_ratio, xc + t->front())));
    while (t->back() <= xc) {  // until one column lies beyond the edge
        double first = stage2_spacing(width, D, edge_ratio, xc + t->back());
        double step = stage2_spacing(width, D, edge_ratio, xc + t->back() + 0.5 * first);
        t->push_back(t->back() + step);
        s->push_back(stage2_spacing(width, D, edge_ratio, xc + t->back()));
    }
    std::size_t nearest = 0;
    for (std::size_t k = 0; k < t->size(); ++k)
        if (std::fabs((*t)[k] - xc) < std::fabs((*t)[nearest] - xc)) nearest = k;
    const double stretch = xc / (*t)[nearest];
    for (std::size_t k = 0; k < t->size(); ++k) {
        (*t)[k] *= stretch;
        (*s)[k] *= stretch;
    }
    *on_edge = nearest;
}

}  // namespace

Status stage2_columns(float width, float D, float edge_ratio, Stage2Columns& out) {
    SHITSUKAN_TRY(check_common("stage2_columns", width, width, D, 0.0f));
    if (!(edge_ratio > 0.05f && edge_ratio <= 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "stage2_columns: edge spacing ratio must be in (0.05, 1] (got %g)",
                             double(edge_ratio));
    const double xc = 0.5 * double(width);
    std::vector<double> t, s;
    std::size_t on_edge = 0;
    columns_to_the_edge(width, D, edge_ratio, &t, &s, &on_edge);
    // the column on the edge and those beyond it dropped; the rest stretched from the centre
    // line by one factor so that the edge lies midway between the last column and its mirror
    // image: the Voronoi edge between them is the border itself, so the edge scales are whole
    // (about s(1) wide, as their neighbours), never cut through their middle
    t.resize(std::max<std::size_t>(on_edge, 1));
    s.resize(t.size());
    if (on_edge == 0) t[0] = 0.5 * xc;  // W = D: one column a side, midway to the edge
    const double stretch = xc / (0.5 * (t.back() + xc));
    out.x.clear();
    out.spacing.clear();
    out.index.clear();
    const int n = int(t.size());
    for (int k = n - 1; k >= 0; --k) {
        out.x.push_back(xc - t[std::size_t(k)] * stretch);
        out.spacing.push_back(s[std::size_t(k)] * stretch);
        out.index.push_back(-(k + 1));
    }
    for (int k = 0; k < n; ++k) {
        out.x.push_back(xc + t[std::size_t(k)] * stretch);
        out.spacing.push_back(s[std::size_t(k)] * stretch);
        out.index.push_back(k + 1);
    }
    out.mirrored = true;
    out.left = 0.0;
    out.right = double(width);
    return Status::success();
}

Status stage2_row_seeds(const Stage2Columns& columns, float a, double row_y, int row_id,
                        std::uint32_t seed, SeedLayout& out, int side) {
    if (!(a >= 0.0f && a <= 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "stage2_row_seeds: relative displacement a must be in [0, 1] (got %g)",
                             double(a));
    if (!is_finite(row_y))
        return Status::error(StatusCode::invalid_argument, "stage2_row_seeds: row y is not finite");
    out.original.clear();
    out.moved.clear();
    const std::size_t n = columns.x.size();
    for (std::size_t k = 0; k < n; ++k) {
        if ((side < 0 && columns.index[k] > 0) || (side > 0 && columns.index[k] < 0)) continue;
        // processing 1: seeds on a row parallel to x; processing 2: moved along x
        Vec2d p{columns.x[k], row_y};
        out.original.push_back(p);
        p.x += seed_displacement(float(columns.spacing[k]), a,
                                 hashed_rnd(seed, kStreamStage2, row_id, columns.index[k]));
        out.moved.push_back(p);
        // the outermost seed's mirror image beyond the border (the seeds stay symmetric about
        // x = left and x = right there, so the border is a Voronoi edge of the row)
        const bool first = k == 0, last = k + 1 == n;
        if (columns.mirrored && (first || last)) {
            const double edge = first ? columns.left : columns.right;
            out.original.push_back({2.0 * edge - columns.x[k], row_y});
            out.moved.push_back({2.0 * edge - p.x, row_y});
        }
    }
    return Status::success();
}

}  // namespace shitsukan
