#include "shitsukan/leather/edge_perturbation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
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
    Vec2d a, u, nrm;  // canonical first end, unit chord, unit normal (left of a -> b)
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

}  // namespace

void midpoint_displacement(Vec2d a, Vec2d b, const PerturbationParams& prm, std::uint32_t seed,
                           double* f, const double* level_cap) {
    SHITSUKAN_ASSERT(prm.levels >= 0 && prm.levels <= kMaxPerturbationLevels);
    if (lex_less(b, a)) std::swap(a, b);
    const int n = 1 << prm.levels;
    std::uint64_t h = hash_start(seed, kStreamPerturbation);
    h = hash_add(h, bits_of(a.x));
    h = hash_add(h, bits_of(a.y));
    h = hash_add(h, bits_of(b.x));
    h = hash_add(h, bits_of(b.y));
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

Status perturb_subdivision(const PlanarSubdivision& sub, const PerturbationParams& prm,
                           std::uint32_t seed, float width, float height, ScalePattern* out,
                           PerturbationReport* report) {
    if (out == nullptr)
        return Status::error(StatusCode::invalid_argument, "perturb_subdivision: out is null");
    SHITSUKAN_TRY(check_params(prm));
    if (!(width > 0.0f && height > 0.0f) || !is_finite(width) || !is_finite(height))
        return Status::error(StatusCode::invalid_argument,
                             "perturb_subdivision: pattern size must be > 0 and finite (got %g x "
                             "%g)",
                             double(width), double(height));
    const int faces = sub.face_count();
    // centroid of every (convex) polygon before perturbation: the fan centre of the bound
    std::vector<Vec2d> centre(static_cast<std::size_t>(faces));
    std::vector<Vec2d> poly;
    for (int f = 0; f < faces; ++f) {
        poly.clear();
        for (int k = sub.face_offsets[std::size_t(f)]; k < sub.face_offsets[std::size_t(f) + 1];
             ++k)
            poly.push_back(
                sub.vertices[std::size_t(sub.face_vertex(sub.face_edges[std::size_t(k)]))]);
        centre[std::size_t(f)] = polygon_centroid(poly.data(), int(poly.size()));
    }
    // 1. Every interior edge gets its curve at the REQUESTED amplitude; an edge whose curve
    //    would leave its fan triangles or stop turning monotonically around a centre is scaled
    //    down (lambda < 1) just enough, the others keep p exactly.
    const int n = 1 << prm.levels;
    const std::size_t stride = std::size_t(n) + 1;
    const bool bend = prm.p > 0.0f && n > 1;
    std::vector<double> offsets(bend ? sub.edges.size() * stride : 0, 0.0);
    std::vector<double> lambda(sub.edges.size(), 0.0);
    std::vector<EdgeFrame> frame(sub.edges.size());
    PerturbationReport rep;
    double requested_sq = 0.0, realised_sq = 0.0;
    long samples = 0;
    for (std::size_t e = 0; e < sub.edges.size() && bend; ++e) {
        const PlanarSubdivision::Edge& edge = sub.edges[e];
        if (edge.right < 0) continue;  // the outer boundary stays straight
        Vec2d a = sub.vertices[std::size_t(edge.v0)], b = sub.vertices[std::size_t(edge.v1)];
        if (lex_less(b, a)) std::swap(a, b);
        EdgeFrame& fr = frame[e];
        fr.a = a;
        fr.l = length(b - a);
        fr.u = (b - a) / fr.l;
        fr.nrm = {-fr.u.y, fr.u.x};
        const Vec2d cl = centre[std::size_t(edge.left)], cr = centre[std::size_t(edge.right)];
        const bool left_up = cross(fr.u, cl - a) > 0.0;
        fr.centre[0] = left_up ? cl : cr;
        fr.centre[1] = left_up ? cr : cl;
        double* f = offsets.data() + e * stride;
        midpoint_displacement(a, b, prm, seed, f);
        lambda[e] = fitting_scale(fr, f, n, double(prm.safety));
        ++rep.edges;
    }
    // 2. Assemble the polygons; where one is not star-shaped from its own (float) centroid,
    //    the edges whose segments turn the wrong way are halved (all its bent edges if it is not
    //    counter-clockwise) and both their polygons are assembled again (straight, every
    //    polygon is convex: the loop ends).
    std::vector<std::vector<Vec2>> polys(static_cast<std::size_t>(faces));
    std::vector<int> seg_edge;  // per vertex of the polygon assembled last: its outgoing edge
    auto assemble = [&](int f_id) {
        std::vector<Vec2>& fpoly = polys[std::size_t(f_id)];
        fpoly.clear();
        seg_edge.clear();
        for (int k = sub.face_offsets[std::size_t(f_id)];
             k < sub.face_offsets[std::size_t(f_id) + 1]; ++k) {
            const int fe = sub.face_edges[std::size_t(k)];
            const std::size_t e = std::size_t(fe >= 0 ? fe : ~fe);
            const Vec2d start = sub.vertices[std::size_t(sub.face_vertex(fe))];
            fpoly.push_back(to_float(start));
            seg_edge.push_back(int(e));
            if (!(lambda[e] > 0.0)) continue;
            const EdgeFrame& fr = frame[e];
            const double* f = offsets.data() + e * stride;
            const double ds = fr.l / n;
            auto point = [&](int i) { return fr.a + fr.u * (ds * i) + fr.nrm * (lambda[e] * f[i]); };
            if (start == fr.a) {
                for (int i = 1; i < n; ++i) fpoly.push_back(to_float(point(i)));
            } else {
                for (int i = n - 1; i >= 1; --i) fpoly.push_back(to_float(point(i)));
            }
            seg_edge.resize(fpoly.size(), int(e));
        }
        // consecutive equal float points (a very short edge) collapse the same way on both sides
        std::size_t w = 0;
        for (std::size_t i = 0; i < fpoly.size(); ++i) {
            if (w > 0 && fpoly[i] == fpoly[w - 1]) {
                seg_edge[w - 1] = seg_edge[i];
                continue;
            }
            fpoly[w] = fpoly[i];
            seg_edge[w++] = seg_edge[i];
        }
        fpoly.resize(w);
        seg_edge.resize(w);
        while (fpoly.size() > 1 && fpoly.front() == fpoly.back()) {
            fpoly.pop_back();
            seg_edge.pop_back();
        }
    };
    // The edges whose segments do not turn counter-clockwise around the polygon's own float
    // centroid (all of them if the polygon is degenerate or clockwise).
    std::vector<int> offending;
    auto check = [&](int f_id) {
        offending.clear();
        const std::vector<Vec2>& fp = polys[std::size_t(f_id)];
        const int m = int(fp.size());
        const bool whole = m < 3 || !(polygon_area(fp.data(), m) > 0.0);
        const Vec2 cf = whole ? Vec2{0, 0} : to_float(polygon_centroid(fp.data(), m));
        const Vec2d c{cf.x, cf.y};
        for (int k = 0; k < m; ++k) {
            const Vec2d a{fp[std::size_t(k)].x, fp[std::size_t(k)].y};
            const Vec2d b{fp[std::size_t((k + 1) % m)].x, fp[std::size_t((k + 1) % m)].y};
            if (whole || !(cross(a - c, b - c) > 0.0)) offending.push_back(seg_edge[std::size_t(k)]);
        }
        if (whole)
            for (int k = sub.face_offsets[std::size_t(f_id)];
                 k < sub.face_offsets[std::size_t(f_id) + 1]; ++k) {
                const int fe = sub.face_edges[std::size_t(k)];
                offending.push_back(fe >= 0 ? fe : ~fe);
            }
        return offending.empty();
    };
    std::vector<int> todo;
    for (int f_id = 0; f_id < faces; ++f_id) todo.push_back(f_id);
    for (int round = 0; !todo.empty(); ++round) {
        std::vector<int> again;
        for (int f_id : todo) {
            assemble(f_id);
            if (check(f_id)) continue;
            std::sort(offending.begin(), offending.end());
            offending.erase(std::unique(offending.begin(), offending.end()), offending.end());
            for (int oe : offending) {
                const std::size_t e = std::size_t(oe);
                if (!(lambda[e] > 0.0)) continue;
                lambda[e] = round < 40 ? 0.8 * lambda[e] : 0.0;
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
    for (std::size_t e = 0; e < sub.edges.size() && bend; ++e) {
        if (sub.edges[e].right < 0) continue;
        const double* f = offsets.data() + e * stride;
        for (int i = 1; i < n; ++i) {
            requested_sq += f[i] * f[i];
            realised_sq += lambda[e] * lambda[e] * f[i] * f[i];
            rep.max_offset = std::max(rep.max_offset, std::fabs(lambda[e] * f[i]));
        }
        samples += n - 1;
        rep.shrunk += lambda[e] < 1.0;
    }
    if (samples > 0) {
        rep.requested_rms = std::sqrt(requested_sq / double(samples));
        rep.realised_rms = std::sqrt(realised_sq / double(samples));
    }
    out->width = width;
    out->height = height;
    out->vertices.clear();
    out->polygon_offsets.assign(1, 0);
    out->centroids.clear();
    for (int f_id = 0; f_id < faces; ++f_id) append_polygon(out, polys[std::size_t(f_id)]);
    if (report) *report = rep;
    return Status::success();
}

Status subdivision_to_pattern(const PlanarSubdivision& sub, float width, float height,
                              ScalePattern* out) {
    PerturbationParams none;
    none.p = 0.0f;
    return perturb_subdivision(sub, none, 0, width, height, out, nullptr);
}

}  // namespace shitsukan
