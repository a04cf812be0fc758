#include "shitsukan/leather/edge_perturbation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <vector>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/leather/seed_layout.hpp"

namespace shitsukan {
namespace {

bool lex_less(Vec2d a, Vec2d b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

std::uint64_t bits_of(double v) {
    if (v == 0.0) v = 0.0;
    std::uint64_t b;
    std::memcpy(&b, &v, 8);
    return b;
}

// The two faces' centres of an edge and what the curve may do next to each (see the header).
struct EdgeFrame {
    Vec2d a, b, u, nrm;  // canonical ends, unit chord, unit normal (left of a -> b)
    double l;         // chord length
    Vec2d centre[2];  // centre[0] on the normal's side (> 0), centre[1] on the other
};

// Height of the fan triangle (a, b, c) above the chord at chord parameter s (c at distance h
// from the chord's line, its foot at da from a).
double fan_height(double s, double l, double h, double da) {
    const double db = l - da;
    double v = std::numeric_limits<double>::infinity();
    if (da > 0.0) v = std::min(v, s * h / da);
    if (db > 0.0) v = std::min(v, (l - s) * h / db);
    return v;
}

// Does the curve with offsets lambda * f stay strictly inside the safety share of its two fan
// triangles? Then it cannot cross or touch any other edge's curve (see the header).
bool curve_fits(const EdgeFrame& e, const double* f, int n, double lambda, double safety) {
    double h[2], da[2];
    for (int k = 0; k < 2; ++k) {
        h[k] = std::fabs(cross(e.u, e.centre[k] - e.a));
        da[k] = dot(e.u, e.centre[k] - e.a);
    }
    const double ds = e.l / n;
    for (int i = 1; i < n; ++i) {
        const double off = lambda * f[i];
        const int k = off > 0.0 ? 0 : 1;
        if (!(std::fabs(off) < safety * fan_height(ds * i, e.l, h[k], da[k]))) return false;
    }
    return true;
}

// The largest lambda in [0, 1] (1 if it fits, else by bisection to 2^-20) for which the curve
// fits; 0 keeps the edge straight.
double fitting_scale(const EdgeFrame& e, const double* f, int n, double safety) {
    if (curve_fits(e, f, n, 1.0, safety)) return 1.0;
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 20; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (curve_fits(e, f, n, mid, safety))
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

Status check_params(const PerturbationParams& prm) {
    if (!(prm.p >= 0.0f) || !is_finite(prm.p))
        return Status::error(StatusCode::invalid_argument, "perturbation p must be >= 0 (got %g)",
                             double(prm.p));
    if (prm.levels < 0 || prm.levels > kMaxPerturbationLevels)
        return Status::error(StatusCode::invalid_argument,
                             "perturbation levels must be in [0, %d] (got %d)",
                             kMaxPerturbationLevels, prm.levels);
    if (!(prm.decay > 0.0f && prm.decay <= 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "perturbation decay must be in (0, 1] (got %g)", double(prm.decay));
    if (!(prm.safety > 0.0f && prm.safety < 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "perturbation safety must be in (0, 1) (got %g)", double(prm.safety));
    if (!(prm.period_x >= 0.0f && prm.period_y >= 0.0f) || !is_finite(prm.period_x) ||
        !is_finite(prm.period_y))
        return Status::error(StatusCode::invalid_argument,
                             "perturbation periods must be >= 0 and finite (got %g, %g)",
                             double(prm.period_x), double(prm.period_y));
    return Status::success();
}

void append_polygon(ScalePattern* out, std::vector<Vec2>& poly) {
    // consecutive equal float points (a very short edge) collapse the same way on both sides
    std::size_t w = 0;
    for (std::size_t i = 0; i < poly.size(); ++i)
        if (w == 0 || poly[i] != poly[w - 1]) poly[w++] = poly[i];
    poly.resize(w);
    while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
    out->vertices.insert(out->vertices.end(), poly.begin(), poly.end());
    out->polygon_offsets.push_back(int(out->vertices.size()));
    Vec2d m = polygon_centroid(poly.data(), int(poly.size()));
    out->centroids.push_back(to_float(m));
}


// Offset of the curve f (n segments over a chord of length l) at chord parameter s, linear
// between the samples (the curve is drawn as that polyline).
double offset_at(const double* f, int n, double l, double s) {
    const double t = s / l * n;
    if (!(t > 0.0)) return 0.0;
    if (!(t < n)) return 0.0;
    const int i = std::min(int(t), n - 1);
    const double frac = t - i;
    return f[i] + frac * (f[i + 1] - f[i]);
}

// The polygons of a subdivision-like structure are checked the same way everywhere: counter-
// clockwise, every segment turning counter-clockwise around the polygon's own float centroid,
// the angle winding once. Those polygons are simple, and polygons that share their edges point
// for point then tile the union of their outlines (the sum of their winding numbers is the
// outline's). Returns the positions k of the offending segments (all of them if degenerate).
void offending_segments(const std::vector<Vec2>& fp, std::vector<int>* bad) {
    bad->clear();
    const int m = int(fp.size());
    const bool whole = m < 3 || !(polygon_area(fp.data(), m) > 0.0);
    const Vec2 cf = whole ? Vec2{0, 0} : to_float(polygon_centroid(fp.data(), m));
    const Vec2d c{cf.x, cf.y};
    int wraps = 0;
    for (int k = 0; k < m && !whole; ++k) {
        const Vec2d a = Vec2d{fp[std::size_t(k)].x, fp[std::size_t(k)].y} - c;
        const Vec2d b = Vec2d{fp[std::size_t((k + 1) % m)].x, fp[std::size_t((k + 1) % m)].y} - c;
        if (!(cross(a, b) > 0.0)) bad->push_back(k);
        const bool a_low = a.y < 0.0 || (a.y == 0.0 && a.x < 0.0);
        const bool b_low = b.y < 0.0 || (b.y == 0.0 && b.x < 0.0);
        wraps += a_low && !b_low;
    }
    if (whole || (bad->empty() && wraps != 1))
        for (int k = 0; k < m; ++k) bad->push_back(k);
}

// Chord parameter of a point on the edge (its ends exactly 0 and l).
double chord_s(const EdgeFrame& fr, Vec2d p) {
    if (p == fr.a) return 0.0;
    if (p == fr.b) return fr.l;
    return dot(p - fr.a, fr.u);
}

void dedupe_closed(std::vector<Vec2>* fp, std::vector<int>* tag) {
    std::size_t w = 0;
    for (std::size_t i = 0; i < fp->size(); ++i) {
        if (w > 0 && (*fp)[i] == (*fp)[w - 1]) {
            (*tag)[w - 1] = (*tag)[i];
            continue;
        }
        (*fp)[w] = (*fp)[i];
        (*tag)[w++] = (*tag)[i];
    }
    fp->resize(w);
    tag->resize(w);
    while (fp->size() > 1 && fp->front() == fp->back()) {
        fp->pop_back();
        tag->pop_back();
    }
}

}  // namespace

namespace {

constexpr double kKeyQuanta = 16777216.0;  // 2^24 per period (see PerturbationParams)

bool wrapped_keys(const PerturbationParams& prm) {
    return prm.period_x > 0.0f || prm.period_y > 0.0f;
}

// The period of an axis for the key: its own, or the other axis's when it is not wrapped.
double key_period(const PerturbationParams& prm, int axis) {
    const float own = axis == 0 ? prm.period_x : prm.period_y;
    return double(own > 0.0f ? own : (axis == 0 ? prm.period_y : prm.period_x));
}

// A coordinate in quanta of its period, wrapped when the axis is periodic. The offset 0.37
// keeps lattice-aligned points (halves, quarters of the period) away from rounding ties.
std::int64_t wrapped_quanta(double v, const PerturbationParams& prm, int axis) {
    const double q = std::floor(v / key_period(prm, axis) * kKeyQuanta + 0.37);
    const bool wraps = (axis == 0 ? prm.period_x : prm.period_y) > 0.0f;
    if (!wraps) return std::int64_t(q);
    const double m = q - kKeyQuanta * std::floor(q / kKeyQuanta);
    return std::int64_t(m);
}

std::int64_t direction_quanta(double d, const PerturbationParams& prm, int axis) {
    return std::int64_t(std::floor(d / key_period(prm, axis) * kKeyQuanta + 0.5));
}

}  // namespace

bool edge_ends_in_order(Vec2d a, Vec2d b, const PerturbationParams& prm) {
    if (!wrapped_keys(prm)) return !lex_less(b, a);
    const std::int64_t dx = direction_quanta(b.x - a.x, prm, 0);
    const std::int64_t dy = direction_quanta(b.y - a.y, prm, 1);
    if (dx != 0) return dx > 0;
    if (dy != 0) return dy > 0;
    return !lex_less(b, a);
}

void midpoint_displacement(Vec2d a, Vec2d b, const PerturbationParams& prm, std::uint32_t seed,
                           double* f, const double* level_cap) {
    SHITSUKAN_ASSERT(prm.levels >= 0 && prm.levels <= kMaxPerturbationLevels);
    if (!edge_ends_in_order(a, b, prm)) std::swap(a, b);
    const int n = 1 << prm.levels;
    std::uint64_t h = hash_start(seed, kStreamPerturbation);
    if (wrapped_keys(prm)) {  // tileable: the same key for the edge and its periodic copies
        const Vec2d m = (a + b) * 0.5;
        h = hash_add(h, std::uint64_t(wrapped_quanta(m.x, prm, 0)));
        h = hash_add(h, std::uint64_t(wrapped_quanta(m.y, prm, 1)));
        h = hash_add(h, std::uint64_t(direction_quanta(b.x - a.x, prm, 0)));
        h = hash_add(h, std::uint64_t(direction_quanta(b.y - a.y, prm, 1)));
    } else {
        h = hash_add(h, bits_of(a.x));
        h = hash_add(h, bits_of(a.y));
        h = hash_add(h, bits_of(b.x));
        h = hash_add(h, bits_of(b.y));
    }
    f[0] = 0.0;
    f[n] = 0.0;
    double amplitude = double(prm.p);
    int level = 0;
    for (int step = n; step >= 2; step /= 2, ++level) {
        double amp = level_cap ? std::min(amplitude, level_cap[level]) : amplitude;
        for (int i = 0; i < n; i += step) {
            int mid = i + step / 2;
            double rnd = 2.0 * double(uniform_from_bits(hash_add(h, std::uint64_t(mid)))) - 1.0;
            f[mid] = 0.5 * (f[i] + f[i + step]) + amp * rnd;
        }
        amplitude *= double(prm.decay);
    }
}

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

void start_pattern(ScalePattern* p, float width, float height) {
    p->width = width;
    p->height = height;
    p->vertices.clear();
    p->polygon_offsets.assign(1, 0);
    p->centroids.clear();
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
        append_polygon(&out, curves.polys[std::size_t(f_id)]);
    if (report) *report = subdivision_report(curves);
    return Status::success();
}

Status subdivision_to_pattern(const PlanarSubdivision& sub, float width, float height,
                              ScalePattern& out) {
    PerturbationParams none;
    none.p = 0.0f;
    return perturb_subdivision(sub, none, 0, width, height, out, nullptr);
}


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
    for (int f = 0; f < c.f1; ++f) append_polygon(&stage1_out, c.polys[std::size_t(f)]);
    for (int f = 0; f < c.f2; ++f) append_polygon(&out, c.polys[std::size_t(c.f1 + f)]);
    if (report) *report = two_stage_report(c);
    return Status::success();
}

}  // namespace shitsukan
