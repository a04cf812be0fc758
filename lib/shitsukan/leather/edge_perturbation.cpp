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

namespace shitsukan {
namespace {

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

Status perturb_two_stage(const PlanarSubdivision& s1, const PlanarSubdivision& cells,
                         const std::vector<int>& cell_stage1, const PerturbationParams& prm,
                         std::uint32_t seed, float width, float height, ScalePattern* stage1_out,
                         ScalePattern* out, PerturbationReport* report) {
    if (out == nullptr || stage1_out == nullptr)
        return Status::error(StatusCode::invalid_argument, "perturb_two_stage: out is null");
    SHITSUKAN_TRY(check_params(prm));
    if (!(width > 0.0f && height > 0.0f) || !is_finite(width) || !is_finite(height))
        return Status::error(StatusCode::invalid_argument,
                             "perturb_two_stage: pattern size must be > 0 and finite (got %g x %g)",
                             double(width), double(height));
    if (int(cell_stage1.size()) != cells.face_count())
        return Status::error(StatusCode::invalid_argument,
                             "perturb_two_stage: %d stage-1 labels for %d cells",
                             int(cell_stage1.size()), cells.face_count());
    const int n = 1 << prm.levels;
    const std::size_t stride = std::size_t(n) + 1;
    const bool bend = prm.p > 0.0f && n > 1;
    const std::size_t e1 = s1.edges.size(), e2 = cells.edges.size();
    const std::size_t groups = e1 + e2;  // a curve: a stage-1 edge, or a stage-2 edge
    std::vector<double> offsets(bend ? groups * stride : 0, 0.0);
    std::vector<double> lambda(groups, 0.0);
    std::vector<EdgeFrame> frame1(e1);

    // ---- stage-1 curves (fig. 5), fitted to the stage-1 polygons' fan triangles ----------
    auto face_centroid = [](const PlanarSubdivision& sub, int f, const std::vector<Vec2d>* moved) {
        std::vector<Vec2d> poly;
        for (int k = sub.face_offsets[std::size_t(f)]; k < sub.face_offsets[std::size_t(f) + 1];
             ++k) {
            const int v = sub.face_vertex(sub.face_edges[std::size_t(k)]);
            poly.push_back(moved ? (*moved)[std::size_t(v)] : sub.vertices[std::size_t(v)]);
        }
        return polygon_centroid(poly.data(), int(poly.size()));
    };
    auto make_frame = [](Vec2d a, Vec2d b, Vec2d cl, Vec2d cr) {
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
    };
    std::vector<Vec2d> centre1(static_cast<std::size_t>(s1.face_count()));
    for (int f = 0; f < s1.face_count(); ++f) centre1[std::size_t(f)] = face_centroid(s1, f, nullptr);
    std::unordered_map<std::uint64_t, int> stage1_edge_of;  // (face, face) -> stage-1 edge
    auto pair_key = [](int a, int b) {
        return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
    };
    for (std::size_t g = 0; g < e1; ++g) {
        const PlanarSubdivision::Edge& edge = s1.edges[g];
        Vec2d a = s1.vertices[std::size_t(edge.v0)], b = s1.vertices[std::size_t(edge.v1)];
        if (lex_less(b, a)) std::swap(a, b);
        if (edge.right < 0) {
            frame1[g] = make_frame(a, b, a, b);
            continue;
        }
        stage1_edge_of[pair_key(edge.left, edge.right)] = int(g);
        frame1[g] = make_frame(a, b, centre1[std::size_t(edge.left)],
                               centre1[std::size_t(edge.right)]);
        if (!bend) continue;
        double* f = offsets.data() + g * stride;
        midpoint_displacement(a, b, prm, seed, f);
        lambda[g] = fitting_scale(frame1[g], f, n, double(prm.safety));
    }

    // ---- the final edges: pieces of stage-1 edges (parent), or stage-2 edges of their own --
    std::vector<int> parent(e2, -1);
    std::vector<char> own(e2, 0);
    std::vector<int> vertex_edge(cells.vertices.size(), -1);  // stage-1 edge a vertex lies on
    std::vector<double> vertex_s(cells.vertices.size(), 0.0);
    for (std::size_t e = 0; e < e2; ++e) {
        const PlanarSubdivision::Edge& edge = cells.edges[e];
        if (edge.right < 0) continue;
        const int fa = cell_stage1[std::size_t(edge.left)], fb = cell_stage1[std::size_t(edge.right)];
        if (fa == fb) {
            own[e] = 1;
            continue;
        }
        auto it = stage1_edge_of.find(pair_key(fa, fb));
        if (it == stage1_edge_of.end())
            return Status::error(StatusCode::degenerate,
                                 "perturb_two_stage: cells of stage-1 polygons %d and %d meet "
                                 "where no stage-1 edge runs",
                                 fa, fb);
        parent[e] = it->second;
        for (int v : {edge.v0, edge.v1}) {
            const EdgeFrame& fr = frame1[std::size_t(it->second)];
            const Vec2d p = cells.vertices[std::size_t(v)];
            vertex_edge[std::size_t(v)] = it->second;
            vertex_s[std::size_t(v)] = chord_s(fr, p);
        }
    }
    // where a vertex on a stage-1 edge goes: onto that edge's curve (its ends stay)
    std::vector<Vec2d> moved(cells.vertices);
    auto move_vertex = [&](std::size_t v) {
        const int g = vertex_edge[v];
        moved[v] = cells.vertices[v];
        if (g < 0 || !bend || !(lambda[std::size_t(g)] > 0.0)) return;
        const EdgeFrame& fr = frame1[std::size_t(g)];
        const double s = vertex_s[v];
        if (!(s > 0.0 && s < fr.l)) return;
        const double off = offset_at(offsets.data() + std::size_t(g) * stride, n, fr.l, s);
        moved[v] = cells.vertices[v] + fr.nrm * (lambda[std::size_t(g)] * off);
    };
    for (std::size_t v = 0; v < moved.size(); ++v) move_vertex(v);
    // stage-2 curves: hashed from the straight end points, laid along the moved chord
    std::vector<Vec2d> centre2(static_cast<std::size_t>(cells.face_count()));
    for (int f = 0; f < cells.face_count(); ++f) centre2[std::size_t(f)] = face_centroid(cells, f, &moved);
    auto own_ends = [&](std::size_t e, int* first, int* second) {
        const PlanarSubdivision::Edge& edge = cells.edges[e];
        const bool fwd = !lex_less(cells.vertices[std::size_t(edge.v1)],
                                   cells.vertices[std::size_t(edge.v0)]);
        *first = fwd ? edge.v0 : edge.v1;
        *second = fwd ? edge.v1 : edge.v0;
    };
    for (std::size_t e = 0; e < e2 && bend; ++e) {
        if (!own[e]) continue;
        int va, vb;
        own_ends(e, &va, &vb);
        double* f = offsets.data() + (e1 + e) * stride;
        midpoint_displacement(cells.vertices[std::size_t(va)], cells.vertices[std::size_t(vb)], prm,
                              seed, f);
        const PlanarSubdivision::Edge& edge = cells.edges[e];
        EdgeFrame fr = make_frame(moved[std::size_t(va)], moved[std::size_t(vb)],
                                  centre2[std::size_t(edge.left)], centre2[std::size_t(edge.right)]);
        lambda[e1 + e] = fitting_scale(fr, f, n, double(prm.safety));
    }

    // ---- assembly and the check loop over both pattern levels ----------------------------
    // faces 0 .. F1-1: stage-1 polygons (fig. 5); F1 ..: final polygons (fig. 7)
    const int f1 = s1.face_count(), f2 = cells.face_count();
    std::vector<std::vector<Vec2>> polys(std::size_t(f1 + f2));
    std::vector<std::vector<int>> tags(std::size_t(f1 + f2));  // segment -> curve group
    auto stage1_point = [&](std::size_t g, int i) {
        const EdgeFrame& fr = frame1[g];
        const double ds = fr.l / n;
        return fr.a + fr.u * (ds * i) + fr.nrm * (lambda[g] * offsets[g * stride + std::size_t(i)]);
    };
    auto assemble = [&](int face) {
        std::vector<Vec2>& fp = polys[std::size_t(face)];
        std::vector<int>& tag = tags[std::size_t(face)];
        fp.clear();
        tag.clear();
        const bool first_level = face < f1;
        const PlanarSubdivision& sub = first_level ? s1 : cells;
        const int fid = first_level ? face : face - f1;
        for (int k = sub.face_offsets[std::size_t(fid)]; k < sub.face_offsets[std::size_t(fid) + 1];
             ++k) {
            const int fe = sub.face_edges[std::size_t(k)];
            const std::size_t e = std::size_t(fe >= 0 ? fe : ~fe);
            const int vs = sub.face_vertex(fe);
            const int ve = fe >= 0 ? sub.edges[e].v1 : sub.edges[e].v0;
            const Vec2d start = first_level ? s1.vertices[std::size_t(vs)] : moved[std::size_t(vs)];
            fp.push_back(to_float(start));
            if (!bend) {
                tag.push_back(-1);
                continue;
            }
            if (first_level || parent[e] >= 0) {  // a stage-1 curve, or a piece of it
                const std::size_t g = first_level ? e : std::size_t(parent[e]);
                tag.push_back(int(g));
                if (!(lambda[g] > 0.0)) continue;
                const double ds = frame1[g].l / n;
                double sa = 0.0, sb = frame1[g].l;
                bool up = first_level && s1.vertices[std::size_t(vs)] == frame1[g].a;
                if (!first_level) {  // (a corner's vertex_s may be on another stage-1 edge)
                    sa = chord_s(frame1[g], cells.vertices[std::size_t(vs)]);
                    sb = chord_s(frame1[g], cells.vertices[std::size_t(ve)]);
                    up = sa < sb;
                }
                const double lo = std::min(sa, sb), hi = std::max(sa, sb);
                if (up) {
                    for (int i = 1; i < n; ++i)
                        if (ds * i > lo && ds * i < hi) fp.push_back(to_float(stage1_point(g, i)));
                } else {
                    for (int i = n - 1; i >= 1; --i)
                        if (ds * i > lo && ds * i < hi) fp.push_back(to_float(stage1_point(g, i)));
                }
            } else if (own[e]) {
                const std::size_t g = e1 + e;
                tag.push_back(int(g));
                if (!(lambda[g] > 0.0)) continue;
                int va, vb;
                own_ends(e, &va, &vb);
                const Vec2d a = moved[std::size_t(va)], b = moved[std::size_t(vb)];
                const double l = length(b - a);
                if (!(l > 0.0)) continue;
                const Vec2d u = (b - a) / l, nrm{-u.y, u.x};
                auto point = [&](int i) {
                    return a + u * (l * i / n) + nrm * (lambda[g] * offsets[g * stride + std::size_t(i)]);
                };
                if (vs == va) {
                    for (int i = 1; i < n; ++i) fp.push_back(to_float(point(i)));
                } else {
                    for (int i = n - 1; i >= 1; --i) fp.push_back(to_float(point(i)));
                }
            } else {
                tag.push_back(-1);  // the outer boundary stays straight
                continue;
            }
            tag.resize(fp.size(), tag.back());
        }
        dedupe_closed(&fp, &tag);
    };
    // which polygons a curve's scale touches: its own faces, and for a stage-1 curve every
    // final polygon with a vertex on it (their junctions move with it)
    std::vector<std::vector<int>> touched(groups);
    for (std::size_t g = 0; g < e1; ++g) {
        touched[g].push_back(s1.edges[g].left);
        if (s1.edges[g].right >= 0) touched[g].push_back(s1.edges[g].right);
    }
    for (std::size_t e = 0; e < e2; ++e) {
        const PlanarSubdivision::Edge& edge = cells.edges[e];
        const std::size_t g = parent[e] >= 0 ? std::size_t(parent[e]) : e1 + e;
        touched[g].push_back(f1 + edge.left);
        if (edge.right >= 0) touched[g].push_back(f1 + edge.right);
    }
    for (int f = 0; f < f2; ++f)
        for (int k = cells.face_offsets[std::size_t(f)]; k < cells.face_offsets[std::size_t(f) + 1];
             ++k) {
            const int g = vertex_edge[std::size_t(cells.face_vertex(cells.face_edges[std::size_t(k)]))];
            if (g >= 0) touched[std::size_t(g)].push_back(f1 + f);
        }
    for (auto& t : touched) {
        std::sort(t.begin(), t.end());
        t.erase(std::unique(t.begin(), t.end()), t.end());
    }
    std::vector<int> todo(std::size_t(f1 + f2)), bad;
    for (int f = 0; f < f1 + f2; ++f) todo[std::size_t(f)] = f;
    for (int round = 0; !todo.empty(); ++round) {
        std::vector<int> again;
        std::vector<std::size_t> shrink;
        for (int face : todo) {
            assemble(face);
            offending_segments(polys[std::size_t(face)], &bad);
            for (int k : bad) {
                const int g = tags[std::size_t(face)][std::size_t(k)];
                if (g >= 0 && lambda[std::size_t(g)] > 0.0) shrink.push_back(std::size_t(g));
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
            lambda[g] = round < 40 ? 0.8 * lambda[g] : 0.0;
            again.insert(again.end(), touched[g].begin(), touched[g].end());
        }
        if (!shrink.empty())
            for (std::size_t v = 0; v < moved.size(); ++v) move_vertex(v);
        std::sort(again.begin(), again.end());
        again.erase(std::unique(again.begin(), again.end()), again.end());
        if (round > 100)
            return Status::error(StatusCode::degenerate,
                                 "perturb_two_stage: %d polygons still not star-shaped",
                                 int(again.size()));
        todo.swap(again);
    }
    // ---- report and output ------------------------------------------------------------------
    PerturbationReport rep;
    double requested_sq = 0.0, realised_sq = 0.0;
    long samples = 0;
    for (std::size_t g = 0; g < groups && bend; ++g) {
        const bool curve = g < e1 ? s1.edges[g].right >= 0 : own[g - e1] != 0;
        if (!curve) continue;
        ++rep.edges;
        rep.shrunk += lambda[g] < 1.0;
        for (int i = 1; i < n; ++i) {
            const double v = offsets[g * stride + std::size_t(i)];
            requested_sq += v * v;
            realised_sq += lambda[g] * lambda[g] * v * v;
            rep.max_offset = std::max(rep.max_offset, std::fabs(lambda[g] * v));
        }
        samples += n - 1;
    }
    if (samples > 0) {
        rep.requested_rms = std::sqrt(requested_sq / double(samples));
        rep.realised_rms = std::sqrt(realised_sq / double(samples));
    }
    for (ScalePattern* p : {stage1_out, out}) {
        p->width = width;
        p->height = height;
        p->vertices.clear();
        p->polygon_offsets.assign(1, 0);
        p->centroids.clear();
    }
    for (int f = 0; f < f1; ++f) append_polygon(stage1_out, polys[std::size_t(f)]);
    for (int f = 0; f < f2; ++f) append_polygon(out, polys[std::size_t(f1 + f)]);
    if (report) *report = rep;
    return Status::success();
}

}  // namespace shitsukan
