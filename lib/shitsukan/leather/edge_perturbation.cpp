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

// Largest slope G the curve of chord a -> b may have next to the face with centroid c.
double slope_bound(Vec2d a, Vec2d b, Vec2d c) {
    const double inf = std::numeric_limits<double>::infinity();
    Vec2d ab = b - a;
    double l = length(ab);
    Vec2d u = ab / l;
    double h = std::fabs(cross(u, c - a));           // distance from c to the chord's line
    double da = dot(u, c - a), db = dot(-u, c - b);  // c's foot seen from a and from b
    double tan_a = da > 0.0 ? h / da : inf;          // base angles of the fan triangle (a, b, c)
    double tan_b = db > 0.0 ? h / db : inf;
    // Star-shaped from c: at chord parameter s the curve point must satisfy
    // |s - s0| G + |f(s)| < h with |f(s)| <= G min(s, l - s) (s0: c's foot). The left side is
    // piecewise linear in s with breaks at s0 and l/2, so its maximum is at one of them or at
    // an end.
    double s0 = std::min(std::max(da, 0.0), l);
    double worst = 0.0;
    for (double s : {0.0, l, 0.5 * l, s0})
        worst = std::max(worst, std::fabs(s - da) + std::min(s, l - s));
    double star = h / worst;
    return std::min(std::min(tan_a, tan_b), star);
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
    const int n = 1 << prm.levels;
    std::vector<int> curve_offset(sub.edges.size() + 1, 0);
    std::vector<Vec2d> curve;  // interior points of each edge, from its canonical first end
    std::vector<double> f(static_cast<std::size_t>(n) + 1);
    PerturbationReport rep;
    for (std::size_t e = 0; e < sub.edges.size(); ++e) {
        const PlanarSubdivision::Edge& edge = sub.edges[e];
        if (edge.right >= 0 && prm.p > 0.0f && n > 1) {
            Vec2d a = sub.vertices[std::size_t(edge.v0)], b = sub.vertices[std::size_t(edge.v1)];
            if (lex_less(b, a)) std::swap(a, b);
            double l = length(b - a), ds = l / n;
            // the slope budget G, shared by the levels: level k (half-segment l / 2^k) may use
            // w_k = 2^-k / (1 - 2^-L) of it, so the coarse bends keep most of their amplitude
            double bound =
                double(prm.safety) * std::min(slope_bound(a, b, centre[std::size_t(edge.left)]),
                                              slope_bound(a, b, centre[std::size_t(edge.right)]));
            double cap[kMaxPerturbationLevels];
            double half = 0.5 * l, weight_sum = 1.0 - std::ldexp(1.0, -prm.levels);
            bool capped = false;
            double amplitude = double(prm.p);
            for (int k = 0; k < prm.levels; ++k, half *= 0.5, amplitude *= double(prm.decay)) {
                cap[k] = bound * (std::ldexp(1.0, -(k + 1)) / weight_sum) * half;
                capped = capped || amplitude > cap[k];
            }
            rep.clamped += capped;
            midpoint_displacement(a, b, prm, seed, f.data(), cap);
            double slope = 0.0;
            for (int i = 0; i < n; ++i)
                slope = std::max(slope, std::fabs(f[std::size_t(i) + 1] - f[std::size_t(i)]) / ds);
            SHITSUKAN_ASSERT(slope <= bound * (1.0 + 1e-9));  // the sum of the caps' slopes
            Vec2d u = (b - a) / l, nrm{-u.y, u.x};
            for (int i = 1; i < n; ++i) {
                double off = f[std::size_t(i)];
                rep.max_offset = std::max(rep.max_offset, std::fabs(off));
                curve.push_back(a + u * (ds * i) + nrm * off);
            }
            ++rep.edges;
        }
        curve_offset[e + 1] = int(curve.size());
    }
    // Assemble each polygon: its corners and, between them, its edges' curves.
    out->width = width;
    out->height = height;
    out->vertices.clear();
    out->polygon_offsets.assign(1, 0);
    out->centroids.clear();
    std::vector<Vec2> fpoly;
    for (int f_id = 0; f_id < faces; ++f_id) {
        fpoly.clear();
        for (int k = sub.face_offsets[std::size_t(f_id)];
             k < sub.face_offsets[std::size_t(f_id) + 1]; ++k) {
            int fe = sub.face_edges[std::size_t(k)];
            int e = fe >= 0 ? fe : ~fe;
            Vec2d start = sub.vertices[std::size_t(sub.face_vertex(fe))];
            fpoly.push_back(to_float(start));
            int c0 = curve_offset[std::size_t(e)], c1 = curve_offset[std::size_t(e) + 1];
            Vec2d other = sub.vertices[std::size_t(fe >= 0 ? sub.edges[std::size_t(e)].v1
                                                           : sub.edges[std::size_t(e)].v0)];
            if (lex_less(start, other)) {
                for (int i = c0; i < c1; ++i) fpoly.push_back(to_float(curve[std::size_t(i)]));
            } else {
                for (int i = c1 - 1; i >= c0; --i) fpoly.push_back(to_float(curve[std::size_t(i)]));
            }
        }
        append_polygon(out, fpoly);
    }
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
