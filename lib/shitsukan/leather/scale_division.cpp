#include "shitsukan/leather/scale_division.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/geom/predicates.hpp"
#include "shitsukan/geom/voronoi.hpp"

namespace shitsukan {
namespace {

// A stage-2 vertex and the stage-1 edges (global ids) it lies on.
struct TaggedVertex {
    Vec2d p;
    int on[2];
};

int common_edge(const TaggedVertex& a, const TaggedVertex& b) {
    for (int i = 0; i < 2; ++i)
        if (a.on[i] >= 0 && (a.on[i] == b.on[0] || a.on[i] == b.on[1])) return a.on[i];
    return -1;
}

// Non-empty cells of a Voronoi division, as polygons with area.
void collect_cells(const VoronoiCells& cells, std::vector<Vec2d>* verts, std::vector<int>* offsets,
                   std::vector<int>* site) {
    for (int i = 0; i < cells.cell_count(); ++i) {
        int k;
        const Vec2d* v = cells.cell(i, &k);
        if (k < 3 || !(polygon_area(v, k) > 0.0)) continue;
        verts->insert(verts->end(), v, v + k);
        offsets->push_back(int(verts->size()));
        if (site) site->push_back(i);
    }
}

// The stage-2 columns of a tileable belly's tile, repeated across the region (tile k's shifted
// by k periods, their indices and so their random numbers the tile's own). The tile's edge is
// a joint like its centre line (where the left half of one tile meets the right half of the
// next): stage2_columns already puts it midway between the last column and its mirror image,
// and in the repeated layout that image is the next tile's first column (so no mirror seeds:
// the scales along the seam are whole, about s(1) wide, as along the centre line).
Status periodic_stage2_columns(const ScaleParams& prm, float period, Stage2Columns& out) {
    Stage2Columns tile;
    SHITSUKAN_TRY(stage2_columns(period, prm.D, prm.edge_ratio, tile));
    const int tiles = std::max(1, int(std::lround(double(prm.width) / double(period))));
    out.x.clear();
    out.spacing.clear();
    out.index.clear();
    out.mirrored = false;
    for (int k = 0; k < tiles; ++k)
        for (std::size_t c = 0; c < tile.x.size(); ++c) {
            out.x.push_back(tile.x[c] + double(k) * double(period));
            out.spacing.push_back(tile.spacing[c]);
            out.index.push_back(tile.index[c]);
        }
    return Status::success();
}

}  // namespace

Status check_scale_params(const ScaleParams& prm) {
    if (!(prm.width > 0.0f && prm.height > 0.0f) || !is_finite(prm.width) || !is_finite(prm.height))
        return Status::error(StatusCode::invalid_argument,
                             "scale pattern: width and height must be > 0 (got %g x %g)",
                             double(prm.width), double(prm.height));
    if (!(prm.D > 0.0f) || !is_finite(prm.D))
        return Status::error(StatusCode::invalid_argument,
                             "scale pattern: seed spacing D must be > 0 (got %g)", double(prm.D));
    // subnormal sizes lose their digits in the float pattern: cells with gaps (fuzz finding)
    for (float v : {prm.width, prm.height, prm.D})
        if (!std::isnormal(v))
            return Status::error(StatusCode::invalid_argument,
                                 "scale pattern: width, height and D must be normal floats "
                                 "(>= %g; got %g x %g, D %g)",
                                 double(std::numeric_limits<float>::min()), double(prm.width),
                                 double(prm.height), double(prm.D));
    // chosen: at least one seed spacing across each side; a region thinner than one scale
    // (aspect 5e22 under D) left the stage-2 rows without cells (fuzz finding)
    if (prm.D > std::min(prm.width, prm.height))
        return Status::error(StatusCode::invalid_argument,
                             "scale pattern: seed spacing D = %g must fit the region %g x %g "
                             "(D <= the shorter side)",
                             double(prm.D), double(prm.width), double(prm.height));
    if (!(prm.d >= 0.0f) || !is_finite(prm.d))
        return Status::error(StatusCode::invalid_argument,
                             "scale pattern: distance d from the centre line must be >= 0 (got %g)",
                             double(prm.d));
    // chosen: two stage-1 rows closer than 1e-6 of the pattern (a thousand weld distances) put
    // their Voronoi vertices within the stage-1 weld and the joint collapses (fuzz finding:
    // d = 1.8e-15 on a 1.3 x 1 pattern gave cells with a one-sided edge); d = 0 is one row
    const double min_d = 1e3 * kWeldRelative * std::max(double(prm.width), double(prm.height));
    // chosen: the rows at most half a width outside the rectangle (d <= W); far beyond it the
    // stage-1 joint is a bisector of points d away, rounded by ulps of d, which can exceed the
    // pattern itself (fuzz finding: d = 1.8e-15 on a 1e-30 pattern: a one-sided edge)
    if (prm.d > prm.width)
        return Status::error(StatusCode::invalid_argument,
                             "scale pattern: distance d = %g from the centre line must be at most "
                             "the width %g",
                             double(prm.d), double(prm.width));
    if (prm.d > 0.0f && double(prm.d) < min_d)
        return Status::error(StatusCode::invalid_argument,
                             "scale pattern: distance d = %g from the centre line must be 0 (one "
                             "row) or at least %g (1e-6 of the pattern's longer side)",
                             double(prm.d), min_d);
    if (!(prm.a >= 0.0f && prm.a <= 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "scale pattern: relative displacement a must be in [0, 1] (got %g)",
                             double(prm.a));
    if (!(prm.perturbation.p >= 0.0f) || !is_finite(prm.perturbation.p))
        return Status::error(StatusCode::invalid_argument,
                             "scale pattern: perturbation p must be >= 0 (got %g)",
                             double(prm.perturbation.p));
    return Status::success();
}

std::uint64_t scale_pattern_bytes(const ScaleParams& prm) {
    const double D = double(prm.D), r = std::min(1.0, std::max(0.05, double(prm.edge_ratio)));
    // columns per side: the integral of 1 / s(u) over the half width (seed_layout.hpp's law)
    const double k = r < 1.0 ? std::atanh(std::sqrt(1.0 - r)) / std::sqrt(1.0 - r) : 1.0;
    const double columns = (0.5 * double(prm.width) / D * k + 2.0) * (prm.d > 0.0f ? 1.0 : 2.0);
    const double rows = 2.0 * (std::ceil(double(prm.height) / D) + 3.0);
    const int levels = std::max(0, std::min(prm.perturbation.levels, kMaxPerturbationLevels));
    const double per_scale = 1024.0 + 128.0 * double(1 << levels);
    const double bytes = rows * columns * per_scale;
    return bytes < 1.8e19 ? std::uint64_t(bytes) : UINT64_MAX;
}

Status divide_single_stage(const Vec2d* seeds, int count, float width, float height,
                           PlanarSubdivision& out, std::vector<int>* face_site) {
    if (!(width > 0.0f && height > 0.0f) || !is_finite(width) || !is_finite(height))
        return Status::error(StatusCode::invalid_argument,
                             "divide_single_stage: empty region %g x %g", double(width),
                             double(height));
    const Vec2d region[4] = {
        {0, 0}, {double(width), 0}, {double(width), double(height)}, {0, double(height)}};
    VoronoiCells cells;
    SHITSUKAN_TRY(voronoi_cells(seeds, count, region, 4, cells));
    std::vector<Vec2d> verts;
    std::vector<int> offsets(1, 0);
    if (face_site) face_site->clear();
    collect_cells(cells, &verts, &offsets, face_site);
    return build_planar_subdivision(verts.data(), offsets.data(), int(offsets.size()) - 1, out);
}

namespace {

// The stage-2 cells of every stage-1 polygon, their vertices tagged with the stage-1 edges they
// lie on, and the points each stage-1 edge carries (both sides' junctions).
struct Stage2Cells {
    std::vector<std::vector<TaggedVertex>> cells;  // every stage-2 cell
    std::vector<std::vector<Vec2d>> on_edge;       // stage-1 edge -> points on it
    std::vector<std::vector<double>> on_edge_t;    // their chord parameters (after welding)
};

// Stage 2, processings 1-2 (§3.1 (2)): the row of seeds parallel to x through the stage-1
// polygon's own (moved) seed, on the columns of its own half (its scales end at the centre-line
// joint; with d = 0 both rows sit on the centre line and every polygon spans both halves),
// moved along x (the outermost seeds mirrored about the left and right borders).
Status stage2_row_for_polygon(const ScaleParams& prm, int f, ScaleDivision& out, SeedLayout& row) {
    const int site = out.stage1_site[std::size_t(f)];
    const Vec2d own = out.stage1_seeds.original[std::size_t(site)];
    const int row_id =
        out.stage1_row_id.empty() ? site : out.stage1_row_id[std::size_t(site)];
    const bool periodic = out.column_period > 0.0f;
    const int side = !(prm.d > 0.0f) ? 0
                     : periodic      ? ((row_id & 1) ? 1 : -1)
                                     : (own.x < 0.5 * double(prm.width) ? -1 : 1);
    SHITSUKAN_TRY(stage2_row_seeds(out.columns, prm.a, out.stage1_seeds.moved[std::size_t(site)].y,
                                   row_id, prm.seed, row, side));
    out.stage2_seeds.original.insert(out.stage2_seeds.original.end(), row.original.begin(),
                                     row.original.end());
    out.stage2_seeds.moved.insert(out.stage2_seeds.moved.end(), row.moved.begin(),
                                  row.moved.end());
    out.stage2_row.insert(out.stage2_row.end(), row.moved.size(), f);
    return Status::success();
}

// Distance from p to the segment a-b.
double distance_to_segment(Vec2d p, Vec2d a, Vec2d b) {
    const Vec2d ab = b - a;
    const double l2 = dot(ab, ab);
    double t = l2 > 0.0 ? dot(p - a, ab) / l2 : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return length(p - (a + ab * t));
}

// One vertex of a stage-2 cell, tagged with the stage-1 edges (global ids) it lies on; a corner
// of the stage-1 polygon takes the corner's exact bits, shared by all sides.
TaggedVertex tag_stage2_vertex(const VoronoiCells& vc, int c, int i, const Vec2d* v,
                               const std::vector<Vec2d>& region, const PlanarSubdivision& s1,
                               int e0, double weld) {
    const int m = int(region.size());
    TaggedVertex t{v[i], {-1, -1}};
    const int base = vc.offsets[std::size_t(c)];
    int r0 = vc.on_region_edge[std::size_t(2 * (base + i))];
    int r1 = vc.on_region_edge[std::size_t(2 * (base + i) + 1)];
    if (r0 >= 0 && r1 >= 0) {
        int lo = std::min(r0, r1), hi = std::max(r0, r1);
        int corner = (hi == lo + 1) ? hi : ((lo == 0 && hi == m - 1) ? 0 : -1);
        if (corner >= 0 && orient2d(region[std::size_t((corner + m - 1) % m)],
                                    region[std::size_t(corner)],
                                    region[std::size_t((corner + 1) % m)]) > 0.0)
            t.p = region[std::size_t(corner)];
    }
    for (int j = 0; j < 2; ++j) {
        int r = j == 0 ? r0 : r1;
        if (r < 0) continue;
        // Only the region edges whose SEGMENT holds the point (fuzz finding 7): a stage-1
        // polygon may have collinear neighbouring edges (with a ~ 0 four stage-1 seeds are
        // cocircular and the Voronoi vertex splits into two an ulp apart), and a clip point on
        // the long edge then lies on the tiny edge's line too. Tagged with the tiny edge, its
        // T junctions were looked up there and the other side's were never inserted: the
        // final cells did not share that edge, and the perturbed scales did not tile.
        const Vec2d a = region[std::size_t(r)], b = region[std::size_t((r + 1) % m)];
        if (!(distance_to_segment(t.p, a, b) <= weld)) continue;
        int fe = s1.face_edges[std::size_t(e0 + r)];
        t.on[j] = fe >= 0 ? fe : ~fe;
    }
    return t;
}

// Stage 2, processing 3: the row's Voronoi division clipped to stage-1 polygon f; its cells,
// tagged, join `st` (and each vertex on a stage-1 edge joins that edge's point list).
Status stage2_divide_polygon(const PlanarSubdivision& s1, int f, const SeedLayout& row,
                             double weld, VoronoiCells& vc, std::vector<Vec2d>& region,
                             Stage2Cells& st, std::vector<int>& cell_stage1) {
    const int e0 = s1.face_offsets[std::size_t(f)], m = s1.face_offsets[std::size_t(f) + 1] - e0;
    region.clear();
    for (int k = 0; k < m; ++k)
        region.push_back(
            s1.vertices[std::size_t(s1.face_vertex(s1.face_edges[std::size_t(e0 + k)]))]);
    SHITSUKAN_TRY(voronoi_cells(row.moved.data(), int(row.moved.size()), region.data(), m, vc));
    for (int c = 0; c < vc.cell_count(); ++c) {
        int k;
        const Vec2d* v = vc.cell(c, &k);
        if (k < 3 || !(polygon_area(v, k) > 0.0)) continue;
        std::vector<TaggedVertex> cell;
        for (int i = 0; i < k; ++i)
            cell.push_back(tag_stage2_vertex(vc, c, i, v, region, s1, e0, weld));
        for (const TaggedVertex& t : cell)
            for (int g : t.on)
                if (g >= 0) st.on_edge[std::size_t(g)].push_back(t.p);
        st.cells.push_back(std::move(cell));
        cell_stage1.push_back(f);
    }
    return Status::success();
}

// T-junction stitching, part 1: the points on each stage-1 edge sorted along it, and points
// closer than kWeldRelative * max(W, H) welded into one (the edge's own end point if it is
// among them): with a = 0 the columns line up across a stage-1 edge and the two sides compute
// the same junction with different rounding (1e-14 apart). Every cell vertex takes its welded
// point.
void weld_stage1_edge_points(const PlanarSubdivision& s1, double weld, Stage2Cells& st) {
    st.on_edge_t.assign(s1.edges.size(), {});
    // the stage-2 vertices on each stage-1 edge (not a scan of every cell per edge: that was
    // O(edges x cells), 1.4 s at D = 0.005)
    struct VertexRef {
        std::size_t cell, vertex;
    };
    std::vector<std::vector<VertexRef>> refs(s1.edges.size());
    for (std::size_t c = 0; c < st.cells.size(); ++c)
        for (std::size_t i = 0; i < st.cells[c].size(); ++i)
            for (int g : st.cells[c][i].on)
                if (g >= 0) refs[std::size_t(g)].push_back({c, i});
    for (std::size_t g = 0; g < s1.edges.size(); ++g) {
        Vec2d a = s1.vertices[std::size_t(s1.edges[g].v0)],
              b = s1.vertices[std::size_t(s1.edges[g].v1)];
        std::vector<Vec2d>& pts = st.on_edge[g];
        auto t_of = [&](Vec2d p) { return dot(p - a, b - a); };
        auto before = [&](Vec2d p, Vec2d q) {
            double tp = t_of(p), tq = t_of(q);
            if (tp != tq) return tp < tq;
            return p.x < q.x || (p.x == q.x && p.y < q.y);
        };
        std::sort(pts.begin(), pts.end(), before);
        pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
        std::vector<Vec2d> canonical(pts.size());
        for (std::size_t i = 0; i < pts.size();) {
            std::size_t j = i;
            while (j + 1 < pts.size() && length(pts[j + 1] - pts[i]) <= weld) ++j;
            Vec2d c = pts[i];
            for (std::size_t k = i; k <= j; ++k)
                if (pts[k] == a || pts[k] == b) c = pts[k];
            for (std::size_t k = i; k <= j; ++k) canonical[k] = c;
            i = j + 1;
        }
        for (const VertexRef& r : refs[g]) {
            TaggedVertex& t = st.cells[r.cell][r.vertex];
            auto it = std::lower_bound(pts.begin(), pts.end(), t.p, before);
            if (it != pts.end() && *it == t.p) t.p = canonical[std::size_t(it - pts.begin())];
        }
        canonical.erase(std::unique(canonical.begin(), canonical.end()), canonical.end());
        pts = canonical;
        for (Vec2d p : pts) st.on_edge_t[g].push_back(t_of(p));
    }
}

// The points of stage-1 edge g strictly between pa and pb (both on g), in that direction.
void insert_points_between(const PlanarSubdivision& s1, const Stage2Cells& st, int g, Vec2d pa,
                           Vec2d pb, std::vector<Vec2d>& verts) {
    const std::vector<Vec2d>& pts = st.on_edge[std::size_t(g)];
    const std::vector<double>& ts = st.on_edge_t[std::size_t(g)];
    const Vec2d e0 = s1.vertices[std::size_t(s1.edges[std::size_t(g)].v0)];
    const Vec2d e1 = s1.vertices[std::size_t(s1.edges[std::size_t(g)].v1)];
    const double ta = dot(pa - e0, e1 - e0), tb = dot(pb - e0, e1 - e0);
    if (ta < tb) {
        for (std::size_t j = 0; j < pts.size(); ++j)
            if (ts[j] > ta && ts[j] < tb && pts[j] != pa && pts[j] != pb) verts.push_back(pts[j]);
    } else {
        for (std::size_t j = pts.size(); j-- > 0;)
            if (ts[j] < ta && ts[j] > tb && pts[j] != pa && pts[j] != pb) verts.push_back(pts[j]);
    }
}

// Where stage-1 edge g sits in polygon f's edge loop (-1: not an edge of f).
int loop_position(const PlanarSubdivision& s1, int f, int g) {
    for (int k = s1.face_offsets[std::size_t(f)]; k < s1.face_offsets[std::size_t(f) + 1]; ++k) {
        const int fe = s1.face_edges[std::size_t(k)];
        if ((fe >= 0 ? fe : ~fe) == g) return k - s1.face_offsets[std::size_t(f)];
    }
    return -1;
}

// A cell side from a (on one stage-1 edge) to b (on the next one) that skipped the stage-1
// polygon's vertex between them: the clip drops a region vertex where the region is straight
// to rounding (a near-degenerate stage-1 vertex, fuzz finding 7's sibling: d and a ~ 0 put the
// four-cell vertex as two vertices 1e-7 apart on a straight line). Walks polygon f's loop from
// a's edge to b's (at most 2 steps) and inserts the vertices and T junctions passed.
void stitch_across_stage1_vertex(const PlanarSubdivision& s1, const Stage2Cells& st, int f,
                                 const TaggedVertex& a, const TaggedVertex& b, double weld,
                                 std::vector<Vec2d>& verts) {
    const int base = s1.face_offsets[std::size_t(f)];
    const int m = s1.face_offsets[std::size_t(f) + 1] - base;
    int best = 3, ka = -1;
    for (int ga : a.on)
        for (int gb : b.on) {
            if (ga < 0 || gb < 0) continue;
            const int pa = loop_position(s1, f, ga), pb = loop_position(s1, f, gb);
            if (pa < 0 || pb < 0) continue;
            const int steps = (pb - pa + m) % m;
            if (steps > 0 && steps < best) best = steps, ka = pa;
        }
    if (ka < 0) return;
    // only a side that runs along the boundary: every skipped stage-1 vertex lies on it (a
    // bisector crossing the polygon from one edge to another is not such a side)
    for (int step = 0; step < best; ++step) {
        const Vec2d v = s1.vertices[std::size_t(
            s1.face_vertex(s1.face_edges[std::size_t(base + (ka + step + 1) % m)]))];
        if (!(distance_to_segment(v, a.p, b.p) <= weld)) return;
    }
    Vec2d from = a.p;
    for (int step = 0; step <= best; ++step) {
        const int k = (ka + step) % m;
        const int fe = s1.face_edges[std::size_t(base + k)];
        const int g = fe >= 0 ? fe : ~fe;
        const Vec2d end = s1.vertices[std::size_t(s1.face_vertex(
            s1.face_edges[std::size_t(base + (k + 1) % m)]))];
        const Vec2d to = step == best ? b.p : end;
        insert_points_between(s1, st, g, from, to, verts);
        if (step < best) verts.push_back(end);
        from = end;
    }
}

// T-junction stitching, part 2: one stage-2 cell's outline with every point of the other side
// that lies between two of its vertices on a stage-1 edge inserted (T junctions become
// vertices). Appends to verts; false when the cell collapsed (a corner snapped onto its
// neighbour left fewer than 3 points or no area).
bool stitch_t_junctions(const PlanarSubdivision& s1, const Stage2Cells& st, int f, double weld,
                        const std::vector<TaggedVertex>& cell, std::vector<Vec2d>& verts) {
    const std::size_t n = cell.size();
    const std::size_t first = verts.size();
    for (std::size_t i = 0; i < n; ++i) {
        const TaggedVertex& a = cell[i];
        const TaggedVertex& b = cell[(i + 1) % n];
        verts.push_back(a.p);
        const int g = common_edge(a, b);
        if (g >= 0)
            insert_points_between(s1, st, g, a.p, b.p, verts);
        else if ((a.on[0] >= 0 || a.on[1] >= 0) && (b.on[0] >= 0 || b.on[1] >= 0))
            stitch_across_stage1_vertex(s1, st, f, a, b, weld, verts);
    }
    // drop repeats (a corner snapped onto its neighbour)
    std::size_t w = first;
    for (std::size_t i = first; i < verts.size(); ++i)
        if (w == first || verts[i] != verts[w - 1]) verts[w++] = verts[i];
    verts.resize(w);
    while (verts.size() - first > 1 && verts[first] == verts.back()) verts.pop_back();
    if (verts.size() - first < 3 ||
        !(polygon_area(verts.data() + first, int(verts.size() - first)) > 0.0)) {
        verts.resize(first);
        return false;
    }
    return true;
}

// T-junction stitching, part 3: every cell stitched, the final planar subdivision built.
Status stitch_final_cells(const PlanarSubdivision& s1, const Stage2Cells& st, double weld,
                          ScaleDivision& out) {
    std::vector<Vec2d> verts;
    std::vector<int> offsets(1, 0);
    std::vector<int> kept_stage1;
    for (std::size_t c = 0; c < st.cells.size(); ++c) {
        if (!stitch_t_junctions(s1, st, out.cell_stage1[c], weld, st.cells[c], verts)) continue;
        offsets.push_back(int(verts.size()));
        kept_stage1.push_back(out.cell_stage1[c]);
    }
    out.cell_stage1 = kept_stage1;
    Status s = build_planar_subdivision(verts.data(), offsets.data(), int(offsets.size()) - 1,
                                        out.cells);
    if (!s)
        return Status::error(StatusCode::degenerate, "divide_scales: stage-2 cells do not fit: %s",
                             s.message());
    return Status::success();
}

}  // namespace

Stage1SeedParams stage1_seed_params(const ScaleParams& prm) {
    Stage1SeedParams sp;
    sp.width = prm.width;
    sp.height = prm.height;
    sp.D = prm.D;
    sp.d = prm.d;
    sp.a = prm.a;
    sp.seed = prm.seed;
    return sp;
}

namespace {

// Stage-1 vertices closer than `weld` merged into one (fuzz finding 7's root cause): with
// a ~ 0 the stage-1 seeds of both rows lie on common circles, and each Voronoi vertex where
// four cells meet comes out as two vertices an ulp apart joined by an ulp-long edge, collinear
// with its neighbours. Stage 2 then tagged clip points with the wrong (tiny) stage-1 edge and
// the T junctions of the other side were never inserted: the final cells did not share that
// edge and the perturbed scales did not tile. Merged, the four cells meet at one vertex.
// Polygons and their order are kept (a polygon left with < 3 vertices cannot occur: the
// polygons are a scale across); a subdivision without close vertices is returned unchanged.
Status weld_close_stage1_vertices(double weld, ScaleDivision& out) {
    const PlanarSubdivision& s1 = out.stage1;
    const std::size_t nv = s1.vertices.size();
    std::vector<int> order(nv);
    for (std::size_t i = 0; i < nv; ++i) order[i] = int(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return s1.vertices[std::size_t(a)].x < s1.vertices[std::size_t(b)].x;
    });
    std::vector<int> rep(nv);
    for (std::size_t i = 0; i < nv; ++i) rep[i] = int(i);
    bool merged = false;
    for (std::size_t i = 0; i < nv; ++i)
        for (std::size_t j = i + 1; j < nv; ++j) {
            const Vec2d a = s1.vertices[std::size_t(order[i])], b = s1.vertices[std::size_t(order[j])];
            if (b.x - a.x > weld) break;
            if (length(b - a) > weld) continue;
            int ra = order[i], rb = order[j];  // union of the two groups, by their roots
            while (rep[std::size_t(ra)] != ra) ra = rep[std::size_t(ra)];
            while (rep[std::size_t(rb)] != rb) rb = rep[std::size_t(rb)];
            if (ra != rb) rep[std::size_t(std::max(ra, rb))] = std::min(ra, rb);
            merged = true;
        }
    if (!merged) return Status::success();
    std::vector<Vec2d> verts;
    std::vector<int> offsets(1, 0);
    for (int f = 0; f < s1.face_count(); ++f) {
        const std::size_t first = verts.size();
        for (int k = s1.face_offsets[std::size_t(f)]; k < s1.face_offsets[std::size_t(f) + 1];
             ++k) {
            int v = s1.face_vertex(s1.face_edges[std::size_t(k)]);
            while (rep[std::size_t(v)] != v) v = rep[std::size_t(v)];
            const Vec2d p = s1.vertices[std::size_t(v)];
            if (verts.size() == first || verts.back() != p) verts.push_back(p);
        }
        while (verts.size() - first > 1 && verts[first] == verts.back()) verts.pop_back();
        if (verts.size() - first < 3)
            return Status::error(StatusCode::degenerate,
                                 "divide_scales: stage-1 polygon %d collapsed when its vertices "
                                 "closer than %g were merged",
                                 f, weld);
        offsets.push_back(int(verts.size()));
    }
    PlanarSubdivision welded;
    SHITSUKAN_TRY(build_planar_subdivision(verts.data(), offsets.data(), int(offsets.size()) - 1,
                                           welded));
    out.stage1 = std::move(welded);
    return Status::success();
}

}  // namespace

Status stage1_vertical_division(const ScaleParams& prm, ScaleDivision& out) {
    SHITSUKAN_TRY(divide_single_stage(out.stage1_seeds.moved.data(),
                                      int(out.stage1_seeds.moved.size()), prm.width, prm.height,
                                      out.stage1, &out.stage1_site));
    return weld_close_stage1_vertices(
        kWeldRelative * std::max(double(prm.width), double(prm.height)), out);
}

Status stage2_horizontal_division(const ScaleParams& prm, ScaleDivision& out) {
    const PlanarSubdivision& s1 = out.stage1;
    if (out.column_period > 0.0f)
        SHITSUKAN_TRY(periodic_stage2_columns(prm, out.column_period, out.columns));
    else
        SHITSUKAN_TRY(stage2_columns(prm.width, prm.D, prm.edge_ratio, out.columns));
    out.stage2_seeds.original.clear();
    out.stage2_seeds.moved.clear();
    out.stage2_row.clear();
    out.cell_stage1.clear();
    Stage2Cells st;
    st.on_edge.resize(s1.edges.size());
    SeedLayout row;
    VoronoiCells vc;
    std::vector<Vec2d> region;
    const double weld = kWeldRelative * std::max(double(prm.width), double(prm.height));
    for (int f = 0; f < s1.face_count(); ++f) {
        SHITSUKAN_TRY(stage2_row_for_polygon(prm, f, out, row));  // processings 1-2
        SHITSUKAN_TRY(                                             // processing 3
            stage2_divide_polygon(s1, f, row, weld, vc, region, st, out.cell_stage1));
    }
    // T junctions: both sides of a stage-1 edge get all points on it
    weld_stage1_edge_points(s1, weld, st);
    return stitch_final_cells(s1, st, weld, out);
}

Status divide_scales(const ScaleParams& prm, ScaleDivision& out) {
    SHITSUKAN_TRY(check_scale_params(prm));
    SHITSUKAN_TRY(check_memory_budget(scale_pattern_bytes(prm), "scale pattern (divide_scales)"));
    // ---- Stage 1 (§3.1 (1)): vertical division, processings 1-3 ---------------------------
    SHITSUKAN_TRY(stage1_seeds(stage1_seed_params(prm), out.stage1_seeds));
    out.stage1_row_id.clear();
    SHITSUKAN_TRY(stage1_vertical_division(prm, out));
    // ---- Stage 2 (§3.1 (2)): horizontal division inside each stage-1 polygon -------------
    return stage2_horizontal_division(prm, out);
}

Status generate_scale_pattern(const ScaleParams& prm, ScalePattern& pattern, ScaleDivision* steps,
                              Progress progress) {
    ScaleDivision local;
    ScaleDivision* div = steps ? steps : &local;
    SHITSUKAN_TRY(check_scale_params(prm));
    SHITSUKAN_TRY(check_memory_budget(scale_pattern_bytes(prm),
                                      "scale pattern (generate_scale_pattern)"));
    SHITSUKAN_TRY(stage1_seeds(stage1_seed_params(prm), div->stage1_seeds));
    div->stage1_row_id.clear();
    SHITSUKAN_TRY(stage1_vertical_division(prm, *div));
    progress.report(0.05f);
    SHITSUKAN_TRY(stage2_horizontal_division(prm, *div));
    progress.report(0.5f);
    // processing 4 in the paper's order: the stage-1 curves first, the stage-2 cells in them
    SHITSUKAN_TRY(perturb_two_stage(div->stage1, div->cells, div->cell_stage1, prm.perturbation,
                                    prm.seed, prm.width, prm.height, div->stage1_pattern,
                                    pattern, &div->perturbation));
    progress.report(0.95f);
    // The contract, checked once more: the final polygons' areas sum to the rectangle's. A
    // pattern that fails it is refused rather than returned wrong (found by make fuzz: p = 0.1
    // with rows far closer than D).
    double area = 0.0;
    for (int f = 0; f < pattern.polygon_count(); ++f) {
        int n = 0;
        const Vec2* v = pattern.polygon(f, &n);
        area += polygon_area(v, n);
    }
    const double want = double(prm.width) * double(prm.height);
    if (!(std::fabs(area - want) <= 1e-6 * want)) {
        const int polygons = pattern.polygon_count();
        pattern = ScalePattern{};
        return Status::error(StatusCode::degenerate,
                             "generate_scale_pattern: the perturbed scales do not tile the %g x "
                             "%g rectangle (their areas sum to %.9g of %.9g over %d polygons); "
                             "lower the perturbation p (%g)",
                             double(prm.width), double(prm.height), area, want, polygons,
                             double(prm.perturbation.p));
    }
    progress.report(1.0f);
    return Status::success();
}

}  // namespace shitsukan
