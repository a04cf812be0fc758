// tokai1994 processing 4 on one subdivision (edge_perturbation.hpp: perturb_subdivision):
// every interior edge bent once, fitted to its fan triangles, polygons kept star-shaped.
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

// Processing 4 on one subdivision (perturb_subdivision): the curves of its interior edges.
struct SubdivisionCurves {
    const PlanarSubdivision& sub;
    const PerturbationParams& prm;
    std::uint32_t seed;
    int n;               // segments per curve, 2^levels
    std::size_t stride;  // n + 1 offsets per curve
    bool bend;           // p > 0 and at least one level
    std::vector<Vec2d> centre;     // each polygon's centroid before perturbation
    std::vector<double> offsets;   // edge -> f[0 .. n]
    std::vector<double> lambda;    // edge -> scale of its curve (0: straight)
    std::vector<EdgeFrame> frame;  // edge -> chord frame and fan centres
    std::vector<std::vector<Vec2>> polys;  // the assembled (float) polygons
    std::vector<int> seg_edge;  // per vertex of the polygon assembled last: its outgoing edge
    std::vector<int> offending;
    int edges = 0;

    SubdivisionCurves(const PlanarSubdivision& s, const PerturbationParams& p, std::uint32_t sd)
        : sub(s), prm(p), seed(sd), n(1 << p.levels), stride(std::size_t(n) + 1),
          bend(p.p > 0.0f && n > 1) {}
};

// The fan centres: the centroid of every (convex) polygon before perturbation.
void fan_centres(SubdivisionCurves& c) {
    const PlanarSubdivision& sub = c.sub;
    c.centre.assign(static_cast<std::size_t>(sub.face_count()), Vec2d{});
    std::vector<Vec2d> poly;
    for (int f = 0; f < sub.face_count(); ++f) {
        poly.clear();
        for (int k = sub.face_offsets[std::size_t(f)]; k < sub.face_offsets[std::size_t(f) + 1];
             ++k)
            poly.push_back(
                sub.vertices[std::size_t(sub.face_vertex(sub.face_edges[std::size_t(k)]))]);
        c.centre[std::size_t(f)] = polygon_centroid(poly.data(), int(poly.size()));
    }
}

// Step 1: every interior edge gets its curve at the REQUESTED amplitude (midpoint
// displacement); an edge whose curve would leave its fan triangles is scaled down (lambda < 1)
// just enough, the others keep p exactly.
void bend_interior_edges(SubdivisionCurves& c) {
    const PlanarSubdivision& sub = c.sub;
    c.offsets.assign(c.bend ? sub.edges.size() * c.stride : 0, 0.0);
    c.lambda.assign(sub.edges.size(), 0.0);
    c.frame.assign(sub.edges.size(), EdgeFrame{});
    for (std::size_t e = 0; e < sub.edges.size() && c.bend; ++e) {
        const PlanarSubdivision::Edge& edge = sub.edges[e];
        if (edge.right < 0) continue;  // the outer boundary stays straight
        Vec2d a = sub.vertices[std::size_t(edge.v0)], b = sub.vertices[std::size_t(edge.v1)];
        if (!edge_ends_in_order(a, b, c.prm)) std::swap(a, b);
        EdgeFrame& fr = c.frame[e];
        fr.a = a;
        fr.l = length(b - a);
        fr.u = (b - a) / fr.l;
        fr.nrm = {-fr.u.y, fr.u.x};
        const Vec2d cl = c.centre[std::size_t(edge.left)], cr = c.centre[std::size_t(edge.right)];
        const bool left_up = cross(fr.u, cl - a) > 0.0;
        fr.centre[0] = left_up ? cl : cr;
        fr.centre[1] = left_up ? cr : cl;
        double* f = c.offsets.data() + e * c.stride;
        midpoint_displacement(a, b, c.prm, c.seed, f);
        c.lambda[e] = fitting_scale(fr, f, c.n, double(c.prm.safety));
        ++c.edges;
    }
}

// Step 2a: polygon f_id's outline, each edge replaced by its (scaled) curve, rounded to float;
// c.seg_edge remembers which edge each segment belongs to.
void assemble_polygon(SubdivisionCurves& c, int f_id) {
    const PlanarSubdivision& sub = c.sub;
    const int n = c.n;
    std::vector<Vec2>& fpoly = c.polys[std::size_t(f_id)];
    std::vector<int>& seg_edge = c.seg_edge;
    fpoly.clear();
    seg_edge.clear();
    for (int k = sub.face_offsets[std::size_t(f_id)]; k < sub.face_offsets[std::size_t(f_id) + 1];
         ++k) {
        const int fe = sub.face_edges[std::size_t(k)];
        const std::size_t e = std::size_t(fe >= 0 ? fe : ~fe);
        const Vec2d start = sub.vertices[std::size_t(sub.face_vertex(fe))];
        fpoly.push_back(to_float(start));
        seg_edge.push_back(int(e));
        if (!(c.lambda[e] > 0.0)) continue;
        const EdgeFrame& fr = c.frame[e];
        const double* f = c.offsets.data() + e * c.stride;
        const double ds = fr.l / n;
        const double lam = c.lambda[e];
        auto point = [&](int i) { return fr.a + fr.u * (ds * i) + fr.nrm * (lam * f[i]); };
        if (start == fr.a) {
            for (int i = 1; i < n; ++i) fpoly.push_back(to_float(point(i)));
        } else {
            for (int i = n - 1; i >= 1; --i) fpoly.push_back(to_float(point(i)));
        }
        seg_edge.resize(fpoly.size(), int(e));
    }
    dedupe_closed(&fpoly, &seg_edge);
}

// Step 2b: the edges whose segments do not turn counter-clockwise around the polygon's own
// float centroid (all of them if the polygon is degenerate or clockwise). True when none.
bool star_shaped_check(SubdivisionCurves& c, int f_id) {
    const PlanarSubdivision& sub = c.sub;
    c.offending.clear();
    const std::vector<Vec2>& fp = c.polys[std::size_t(f_id)];
    const int m = int(fp.size());
    const bool whole = m < 3 || !(polygon_area(fp.data(), m) > 0.0);
    const Vec2 cf = whole ? Vec2{0, 0} : to_float(polygon_centroid(fp.data(), m));
    const Vec2d ctr{cf.x, cf.y};
    for (int k = 0; k < m; ++k) {
        const Vec2d a{fp[std::size_t(k)].x, fp[std::size_t(k)].y};
        const Vec2d b{fp[std::size_t((k + 1) % m)].x, fp[std::size_t((k + 1) % m)].y};
        if (whole || !(cross(a - ctr, b - ctr) > 0.0))
            c.offending.push_back(c.seg_edge[std::size_t(k)]);
    }
    if (whole)
        for (int k = sub.face_offsets[std::size_t(f_id)];
             k < sub.face_offsets[std::size_t(f_id) + 1]; ++k) {
            const int fe = sub.face_edges[std::size_t(k)];
            c.offending.push_back(fe >= 0 ? fe : ~fe);
        }
    return c.offending.empty();
}

// Step 2: assemble every polygon; where one is not star-shaped from its own (float) centroid,
// the edges whose segments turn the wrong way are scaled by 0.8 (all its bent edges if it is
// not counter-clockwise) and both their polygons are assembled again (straight, every polygon
// is convex: the loop ends).
Status shrink_until_star_shaped(SubdivisionCurves& c) {
    const PlanarSubdivision& sub = c.sub;
    const int faces = sub.face_count();
    c.polys.assign(static_cast<std::size_t>(faces), {});
    std::vector<int> todo;
    for (int f_id = 0; f_id < faces; ++f_id) todo.push_back(f_id);
    for (int round = 0; !todo.empty(); ++round) {
        std::vector<int> again;
        for (int f_id : todo) {
            assemble_polygon(c, f_id);
            if (star_shaped_check(c, f_id)) continue;
            std::sort(c.offending.begin(), c.offending.end());
            c.offending.erase(std::unique(c.offending.begin(), c.offending.end()),
                              c.offending.end());
            for (int oe : c.offending) {
                const std::size_t e = std::size_t(oe);
                if (!(c.lambda[e] > 0.0)) continue;
                c.lambda[e] = round < 40 ? 0.8 * c.lambda[e] : 0.0;
                const PlanarSubdivision::Edge& edge = sub.edges[e];
                again.push_back(edge.left);  // both sides share the curve
                if (edge.right >= 0) again.push_back(edge.right);
            }
        }
        std::sort(again.begin(), again.end());
        again.erase(std::unique(again.begin(), again.end()), again.end());
        if (round > 80)  // cannot happen: all edges straight after round 40
            return Status::error(StatusCode::degenerate,
                                 "perturb_subdivision: %d polygons not star-shaped even straight",
                                 int(again.size()));
        todo.swap(again);
    }
    return Status::success();
}

// The report: requested and realised RMS offset over the curves' inner samples.
PerturbationReport subdivision_report(const SubdivisionCurves& c) {
    PerturbationReport rep;
    rep.edges = c.edges;
    double requested_sq = 0.0, realised_sq = 0.0;
    long samples = 0;
    const int n = c.n;
    for (std::size_t e = 0; e < c.sub.edges.size() && c.bend; ++e) {
        if (c.sub.edges[e].right < 0) continue;
        const double* f = c.offsets.data() + e * c.stride;
        for (int i = 1; i < n; ++i) {
            requested_sq += f[i] * f[i];
            realised_sq += c.lambda[e] * c.lambda[e] * f[i] * f[i];
            rep.max_offset = std::max(rep.max_offset, std::fabs(c.lambda[e] * f[i]));
        }
        samples += n - 1;
        rep.shrunk += c.lambda[e] < 1.0;
    }
    if (samples > 0) {
        rep.requested_rms = std::sqrt(requested_sq / double(samples));
        rep.realised_rms = std::sqrt(realised_sq / double(samples));
    }
    return rep;
}

}  // namespace

Status perturb_subdivision(const PlanarSubdivision& sub, const PerturbationParams& prm,
                           std::uint32_t seed, float width, float height, ScalePattern& out,
                           PerturbationReport* report) {
    SHITSUKAN_TRY(check_params(prm));
    if (!(width > 0.0f && height > 0.0f) || !is_finite(width) || !is_finite(height))
        return Status::error(StatusCode::invalid_argument,
                             "perturb_subdivision: pattern size must be > 0 and finite (got %g x "
                             "%g)",
                             double(width), double(height));
    SubdivisionCurves curves(sub, prm, seed);
    fan_centres(curves);
    bend_interior_edges(curves);                     // 1. the curves, fitted to their fans
    SHITSUKAN_TRY(shrink_until_star_shaped(curves));  // 2. every polygon star-shaped
    start_pattern(&out, width, height);
    for (int f_id = 0; f_id < sub.face_count(); ++f_id)
        append_polygon(&out, &curves.polys[std::size_t(f_id)]);
    if (report) *report = subdivision_report(curves);
    return Status::success();
}

Status subdivision_to_pattern(const PlanarSubdivision& sub, float width, float height,
                              ScalePattern& out) {
    PerturbationParams none;
    none.p = 0.0f;
    return perturb_subdivision(sub, none, 0, width, height, out, nullptr);
}

}  // namespace shitsukan
