// tokai1994 processing 4 in the paper's stage order (edge_perturbation.hpp: perturb_two_stage):
// the stage-1 curves, the stage-2 junctions moved onto them, the stage-2 curves, the tiling
// kept over both levels.
#include "shitsukan/leather/edge_perturbation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <vector>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/leather/perturbation_tiling.hpp"

namespace shitsukan {
using namespace perturbation_tiling;

namespace {

// Processing 4 in the paper's stage order (perturb_two_stage): the stage-1 curves, the stage-2
// junctions moved onto them, the stage-2 curves, and the check over both pattern levels.
// Curve groups: g < e1 a stage-1 edge, g = e1 + e the final edge e's own curve.
struct TwoStageCurves {
    const PlanarSubdivision& s1;
    const PlanarSubdivision& cells;
    const std::vector<int>& cell_stage1;
    const PerturbationParams& prm;
    std::uint32_t seed;
    int n;
    std::size_t stride;
    bool bend;
    std::size_t e1, e2, groups;
    int f1, f2;  // faces 0 .. f1-1: stage-1 polygons (fig. 5); f1 ..: final polygons (fig. 7)
    std::vector<double> offsets;    // group -> f[0 .. n]
    std::vector<double> lambda;     // group -> scale of its curve
    std::vector<EdgeFrame> frame1;  // stage-1 edge -> chord frame
    std::unordered_map<std::uint64_t, int> stage1_edge_of;  // (face, face) -> stage-1 edge
    std::vector<int> parent;        // final edge -> the stage-1 edge it is a piece of, or -1
    std::vector<char> own;          // final edge -> 1 if it is a stage-2 edge (its own curve)
    std::vector<int> vertex_edge;   // final vertex -> the stage-1 edge it lies on, or -1
    std::vector<double> vertex_s;   // its chord parameter there
    std::vector<Vec2d> moved;       // final vertices, junctions moved onto the curves
    std::vector<std::vector<Vec2>> polys;   // assembled faces (both levels)
    std::vector<std::vector<int>> tags;     // segment -> curve group
    std::vector<std::vector<int>> touched;  // group -> faces to assemble again when it shrinks

    TwoStageCurves(const PlanarSubdivision& a, const PlanarSubdivision& b,
                   const std::vector<int>& labels, const PerturbationParams& p, std::uint32_t sd)
        : s1(a), cells(b), cell_stage1(labels), prm(p), seed(sd), n(1 << p.levels),
          stride(std::size_t(n) + 1), bend(p.p > 0.0f && n > 1), e1(a.edges.size()),
          e2(b.edges.size()), groups(e1 + e2), f1(a.face_count()), f2(b.face_count()) {}
};

std::uint64_t pair_key(int a, int b) {
    return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
}

Vec2d face_centroid(const PlanarSubdivision& sub, int f, const std::vector<Vec2d>* moved) {
    std::vector<Vec2d> poly;
    for (int k = sub.face_offsets[std::size_t(f)]; k < sub.face_offsets[std::size_t(f) + 1]; ++k) {
        const int v = sub.face_vertex(sub.face_edges[std::size_t(k)]);
        poly.push_back(moved ? (*moved)[std::size_t(v)] : sub.vertices[std::size_t(v)]);
    }
    return polygon_centroid(poly.data(), int(poly.size()));
}

EdgeFrame make_frame(Vec2d a, Vec2d b, Vec2d cl, Vec2d cr) {
    EdgeFrame fr;
    fr.a = a;
    fr.b = b;
    fr.l = length(b - a);
    fr.u = (b - a) / fr.l;
    fr.nrm = {-fr.u.y, fr.u.x};
    const bool left_up = cross(fr.u, cl - a) > 0.0;
    fr.centre[0] = left_up ? cl : cr;
    fr.centre[1] = left_up ? cr : cl;
    return fr;
}

// Stage 1, processing 4 (fig. 5): each stage-1 edge bent once, fitted to the stage-1 polygons'
// fan triangles.
void bend_stage1_edges(TwoStageCurves& c) {
    const PlanarSubdivision& s1 = c.s1;
    c.offsets.assign(c.bend ? c.groups * c.stride : 0, 0.0);
    c.lambda.assign(c.groups, 0.0);
    c.frame1.assign(c.e1, EdgeFrame{});
    std::vector<Vec2d> centre1(static_cast<std::size_t>(s1.face_count()));
    for (int f = 0; f < s1.face_count(); ++f) centre1[std::size_t(f)] = face_centroid(s1, f, nullptr);
    for (std::size_t g = 0; g < c.e1; ++g) {
        const PlanarSubdivision::Edge& edge = s1.edges[g];
        Vec2d a = s1.vertices[std::size_t(edge.v0)], b = s1.vertices[std::size_t(edge.v1)];
        if (!edge_ends_in_order(a, b, c.prm)) std::swap(a, b);
        if (edge.right < 0) {
            c.frame1[g] = make_frame(a, b, a, b);
            continue;
        }
        c.stage1_edge_of[pair_key(edge.left, edge.right)] = int(g);
        c.frame1[g] = make_frame(a, b, centre1[std::size_t(edge.left)],
                                 centre1[std::size_t(edge.right)]);
        if (!c.bend) continue;
        double* f = c.offsets.data() + g * c.stride;
        midpoint_displacement(a, b, c.prm, c.seed, f);
        c.lambda[g] = fitting_scale(c.frame1[g], f, c.n, double(c.prm.safety));
    }
}

// The final edges: pieces of stage-1 edges (parent), or stage-2 edges of their own; the
// vertices of the pieces remember where on their stage-1 edge they lie.
Status find_stage1_pieces(TwoStageCurves& c) {
    const PlanarSubdivision& cells = c.cells;
    c.parent.assign(c.e2, -1);
    c.own.assign(c.e2, 0);
    c.vertex_edge.assign(cells.vertices.size(), -1);
    c.vertex_s.assign(cells.vertices.size(), 0.0);
    for (std::size_t e = 0; e < c.e2; ++e) {
        const PlanarSubdivision::Edge& edge = cells.edges[e];
        if (edge.right < 0) continue;
        const int fa = c.cell_stage1[std::size_t(edge.left)],
                  fb = c.cell_stage1[std::size_t(edge.right)];
        if (fa == fb) {
            c.own[e] = 1;
            continue;
        }
        auto it = c.stage1_edge_of.find(pair_key(fa, fb));
        if (it == c.stage1_edge_of.end())
            return Status::error(StatusCode::degenerate,
                                 "perturb_two_stage: cells of stage-1 polygons %d and %d meet "
                                 "where no stage-1 edge runs",
                                 fa, fb);
        c.parent[e] = it->second;
        for (int v : {edge.v0, edge.v1}) {
            const EdgeFrame& fr = c.frame1[std::size_t(it->second)];
            const Vec2d p = cells.vertices[std::size_t(v)];
            c.vertex_edge[std::size_t(v)] = it->second;
            c.vertex_s[std::size_t(v)] = chord_s(fr, p);
        }
    }
    return Status::success();
}

// The T junctions follow the bend: a final vertex on a stage-1 edge goes onto that edge's
// (scaled) curve; the edge's ends stay.
void move_junctions_onto_curves(TwoStageCurves& c) {
    c.moved.resize(c.cells.vertices.size());
    for (std::size_t v = 0; v < c.moved.size(); ++v) {
        const int g = c.vertex_edge[v];
        c.moved[v] = c.cells.vertices[v];
        if (g < 0 || !c.bend || !(c.lambda[std::size_t(g)] > 0.0)) continue;
        const EdgeFrame& fr = c.frame1[std::size_t(g)];
        const double s = c.vertex_s[v];
        if (!(s > 0.0 && s < fr.l)) continue;
        const double off = offset_at(c.offsets.data() + std::size_t(g) * c.stride, c.n, fr.l, s);
        c.moved[v] = c.cells.vertices[v] + fr.nrm * (c.lambda[std::size_t(g)] * off);
    }
}

// A stage-2 edge's ends in canonical (lexicographic, straight) order.
void own_ends(const TwoStageCurves& c, std::size_t e, int* first, int* second) {
    const PlanarSubdivision::Edge& edge = c.cells.edges[e];
    const bool fwd = edge_ends_in_order(c.cells.vertices[std::size_t(edge.v0)],
                                        c.cells.vertices[std::size_t(edge.v1)], c.prm);
    *first = fwd ? edge.v0 : edge.v1;
    *second = fwd ? edge.v1 : edge.v0;
}

// Stage 2, processing 4: each stage-2 edge's curve, hashed from its straight end points, laid
// along the moved chord and fitted to the moved cells' fan triangles.
void bend_stage2_edges(TwoStageCurves& c) {
    const PlanarSubdivision& cells = c.cells;
    std::vector<Vec2d> centre2(static_cast<std::size_t>(cells.face_count()));
    for (int f = 0; f < cells.face_count(); ++f)
        centre2[std::size_t(f)] = face_centroid(cells, f, &c.moved);
    for (std::size_t e = 0; e < c.e2 && c.bend; ++e) {
        if (!c.own[e]) continue;
        int va, vb;
        own_ends(c, e, &va, &vb);
        double* f = c.offsets.data() + (c.e1 + e) * c.stride;
        midpoint_displacement(cells.vertices[std::size_t(va)], cells.vertices[std::size_t(vb)],
                              c.prm, c.seed, f);
        const PlanarSubdivision::Edge& edge = cells.edges[e];
        EdgeFrame fr = make_frame(c.moved[std::size_t(va)], c.moved[std::size_t(vb)],
                                  centre2[std::size_t(edge.left)], centre2[std::size_t(edge.right)]);
        c.lambda[c.e1 + e] = fitting_scale(fr, f, c.n, double(c.prm.safety));
    }
}

Vec2d stage1_point(const TwoStageCurves& c, std::size_t g, int i) {
    const EdgeFrame& fr = c.frame1[g];
    const double ds = fr.l / c.n;
    return fr.a + fr.u * (ds * i) + fr.nrm * (c.lambda[g] * c.offsets[g * c.stride + std::size_t(i)]);
}

// Assembly of one segment that lies on stage-1 curve g (a whole stage-1 edge of a stage-1
// polygon, or the piece of it between two junctions of a final polygon): the curve's inner
// samples strictly between the segment's ends, in the segment's direction.
void append_stage1_piece(const TwoStageCurves& c, bool first_level, std::size_t g, int vs, int ve,
                         std::vector<Vec2>& fp) {
    const double ds = c.frame1[g].l / c.n;
    double sa = 0.0, sb = c.frame1[g].l;
    bool up = first_level && c.s1.vertices[std::size_t(vs)] == c.frame1[g].a;
    if (!first_level) {  // (a corner's vertex_s may be on another stage-1 edge)
        sa = chord_s(c.frame1[g], c.cells.vertices[std::size_t(vs)]);
        sb = chord_s(c.frame1[g], c.cells.vertices[std::size_t(ve)]);
        up = sa < sb;
    }
    const double lo = std::min(sa, sb), hi = std::max(sa, sb);
    if (up) {
        for (int i = 1; i < c.n; ++i)
            if (ds * i > lo && ds * i < hi) fp.push_back(to_float(stage1_point(c, g, i)));
    } else {
        for (int i = c.n - 1; i >= 1; --i)
            if (ds * i > lo && ds * i < hi) fp.push_back(to_float(stage1_point(c, g, i)));
    }
}

// Assembly of a stage-2 edge's own curve (group g) from polygon vertex vs onward.
void append_stage2_curve(const TwoStageCurves& c, std::size_t e, std::size_t g, int vs,
                         std::vector<Vec2>& fp) {
    int va, vb;
    own_ends(c, e, &va, &vb);
    const Vec2d a = c.moved[std::size_t(va)], b = c.moved[std::size_t(vb)];
    const double l = length(b - a);
    if (!(l > 0.0)) return;
    const Vec2d u = (b - a) / l, nrm{-u.y, u.x};
    const int n = c.n;
    auto point = [&](int i) {
        return a + u * (l * i / n) + nrm * (c.lambda[g] * c.offsets[g * c.stride + std::size_t(i)]);
    };
    if (vs == va) {
        for (int i = 1; i < n; ++i) fp.push_back(to_float(point(i)));
    } else {
        for (int i = n - 1; i >= 1; --i) fp.push_back(to_float(point(i)));
    }
}

// One face of either level assembled from its curves, each segment tagged with its group.
void assemble_face(TwoStageCurves& c, int face) {
    std::vector<Vec2>& fp = c.polys[std::size_t(face)];
    std::vector<int>& tag = c.tags[std::size_t(face)];
    fp.clear();
    tag.clear();
    const bool first_level = face < c.f1;
    const PlanarSubdivision& sub = first_level ? c.s1 : c.cells;
    const int fid = first_level ? face : face - c.f1;
    for (int k = sub.face_offsets[std::size_t(fid)]; k < sub.face_offsets[std::size_t(fid) + 1];
         ++k) {
        const int fe = sub.face_edges[std::size_t(k)];
        const std::size_t e = std::size_t(fe >= 0 ? fe : ~fe);
        const int vs = sub.face_vertex(fe);
        const int ve = fe >= 0 ? sub.edges[e].v1 : sub.edges[e].v0;
        const Vec2d start = first_level ? c.s1.vertices[std::size_t(vs)] : c.moved[std::size_t(vs)];
        fp.push_back(to_float(start));
        if (!c.bend) {
            tag.push_back(-1);
            continue;
        }
        if (first_level || c.parent[e] >= 0) {  // a stage-1 curve, or a piece of it
            const std::size_t g = first_level ? e : std::size_t(c.parent[e]);
            tag.push_back(int(g));
            if (!(c.lambda[g] > 0.0)) continue;
            append_stage1_piece(c, first_level, g, vs, ve, fp);
        } else if (c.own[e]) {
            const std::size_t g = c.e1 + e;
            tag.push_back(int(g));
            if (!(c.lambda[g] > 0.0)) continue;
            append_stage2_curve(c, e, g, vs, fp);
        } else {
            tag.push_back(-1);  // the outer boundary stays straight
            continue;
        }
        tag.resize(fp.size(), tag.back());
    }
    dedupe_closed(&fp, &tag);
}

// Which polygons a curve's scale touches: its own faces, and for a stage-1 curve every final
// polygon with a vertex on it (their junctions move with it).
void collect_touched_faces(TwoStageCurves& c) {
    const PlanarSubdivision& s1 = c.s1;
    const PlanarSubdivision& cells = c.cells;
    c.touched.assign(c.groups, {});
    for (std::size_t g = 0; g < c.e1; ++g) {
        c.touched[g].push_back(s1.edges[g].left);
        if (s1.edges[g].right >= 0) c.touched[g].push_back(s1.edges[g].right);
    }
    for (std::size_t e = 0; e < c.e2; ++e) {
        const PlanarSubdivision::Edge& edge = cells.edges[e];
        const std::size_t g = c.parent[e] >= 0 ? std::size_t(c.parent[e]) : c.e1 + e;
        c.touched[g].push_back(c.f1 + edge.left);
        if (edge.right >= 0) c.touched[g].push_back(c.f1 + edge.right);
    }
    for (int f = 0; f < c.f2; ++f)
        for (int k = cells.face_offsets[std::size_t(f)]; k < cells.face_offsets[std::size_t(f) + 1];
             ++k) {
            const int g =
                c.vertex_edge[std::size_t(cells.face_vertex(cells.face_edges[std::size_t(k)]))];
            if (g >= 0) c.touched[std::size_t(g)].push_back(c.f1 + f);
        }
    for (auto& t : c.touched) {
        std::sort(t.begin(), t.end());
        t.erase(std::unique(t.begin(), t.end()), t.end());
    }
}

// The tiling check over both pattern levels: every face assembled; a curve with a segment that
// breaks a face's star shape is scaled by 0.8 (a stage-1 curve in both levels at once, its
// junctions moved with it) and the faces it touches are assembled again.
Status shrink_until_tiling(TwoStageCurves& c) {
    c.polys.assign(std::size_t(c.f1 + c.f2), {});
    c.tags.assign(std::size_t(c.f1 + c.f2), {});
    std::vector<int> todo(std::size_t(c.f1 + c.f2)), bad;
    for (int f = 0; f < c.f1 + c.f2; ++f) todo[std::size_t(f)] = f;
    for (int round = 0; !todo.empty(); ++round) {
        std::vector<int> again;
        std::vector<std::size_t> shrink;
        for (int face : todo) {
            assemble_face(c, face);
            offending_segments(c.polys[std::size_t(face)], &bad);
            for (int k : bad) {
                const int g = c.tags[std::size_t(face)][std::size_t(k)];
                if (g >= 0 && c.lambda[std::size_t(g)] > 0.0) shrink.push_back(std::size_t(g));
            }
            if (!bad.empty() && shrink.empty() && round > 80)
                return Status::error(StatusCode::degenerate,
                                     "perturb_two_stage: polygon %d is not star-shaped even "
                                     "straight",
                                     face);
        }
        std::sort(shrink.begin(), shrink.end());
        shrink.erase(std::unique(shrink.begin(), shrink.end()), shrink.end());
        for (std::size_t g : shrink) {
            c.lambda[g] = round < 40 ? 0.8 * c.lambda[g] : 0.0;
            again.insert(again.end(), c.touched[g].begin(), c.touched[g].end());
        }
        if (!shrink.empty()) move_junctions_onto_curves(c);
        std::sort(again.begin(), again.end());
        again.erase(std::unique(again.begin(), again.end()), again.end());
        if (round > 100)
            return Status::error(StatusCode::degenerate,
                                 "perturb_two_stage: %d polygons still not star-shaped",
                                 int(again.size()));
        todo.swap(again);
    }
    return Status::success();
}

PerturbationReport two_stage_report(const TwoStageCurves& c) {
    PerturbationReport rep;
    double requested_sq = 0.0, realised_sq = 0.0;
    long samples = 0;
    for (std::size_t g = 0; g < c.groups && c.bend; ++g) {
        const bool curve = g < c.e1 ? c.s1.edges[g].right >= 0 : c.own[g - c.e1] != 0;
        if (!curve) continue;
        ++rep.edges;
        rep.shrunk += c.lambda[g] < 1.0;
        for (int i = 1; i < c.n; ++i) {
            const double v = c.offsets[g * c.stride + std::size_t(i)];
            requested_sq += v * v;
            realised_sq += c.lambda[g] * c.lambda[g] * v * v;
            rep.max_offset = std::max(rep.max_offset, std::fabs(c.lambda[g] * v));
        }
        samples += c.n - 1;
    }
    if (samples > 0) {
        rep.requested_rms = std::sqrt(requested_sq / double(samples));
        rep.realised_rms = std::sqrt(realised_sq / double(samples));
    }
    return rep;
}

}  // namespace

Status perturb_two_stage(const PlanarSubdivision& s1, const PlanarSubdivision& cells,
                         const std::vector<int>& cell_stage1, const PerturbationParams& prm,
                         std::uint32_t seed, float width, float height, ScalePattern& stage1_out,
                         ScalePattern& out, PerturbationReport* report) {
    SHITSUKAN_TRY(check_params(prm));
    if (!(width > 0.0f && height > 0.0f) || !is_finite(width) || !is_finite(height))
        return Status::error(StatusCode::invalid_argument,
                             "perturb_two_stage: pattern size must be > 0 and finite (got %g x %g)",
                             double(width), double(height));
    if (int(cell_stage1.size()) != cells.face_count())
        return Status::error(StatusCode::invalid_argument,
                             "perturb_two_stage: %d stage-1 labels for %d cells",
                             int(cell_stage1.size()), cells.face_count());
    TwoStageCurves c(s1, cells, cell_stage1, prm, seed);
    bend_stage1_edges(c);                  // fig. 5: the stage-1 curves
    SHITSUKAN_TRY(find_stage1_pieces(c));  // which final edges are pieces of them
    move_junctions_onto_curves(c);         // the stage-2 cells fill the bent polygons
    bend_stage2_edges(c);                  // fig. 7: the stage-2 curves
    collect_touched_faces(c);
    SHITSUKAN_TRY(shrink_until_tiling(c));  // both levels star-shaped, sharing every edge
    start_pattern(&stage1_out, width, height);
    start_pattern(&out, width, height);
    for (int f = 0; f < c.f1; ++f) append_polygon(&stage1_out, &c.polys[std::size_t(f)]);
    for (int f = 0; f < c.f2; ++f) append_polygon(&out, &c.polys[std::size_t(c.f1 + f)]);
    if (report) *report = two_stage_report(c);
    return Status::success();
}

}  // namespace shitsukan
