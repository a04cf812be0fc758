// The tiling kept while the edges bend (perturbation_tiling.hpp).
#include "shitsukan/leather/perturbation_tiling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "shitsukan/geom/polygon.hpp"

namespace shitsukan {
namespace perturbation_tiling {

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

void append_polygon(ScalePattern* out, std::vector<Vec2>* poly_ptr) {
    std::vector<Vec2>& poly = *poly_ptr;
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

void start_pattern(ScalePattern* p, float width, float height) {
    p->width = width;
    p->height = height;
    p->vertices.clear();
    p->polygon_offsets.assign(1, 0);
    p->centroids.clear();
}

}  // namespace perturbation_tiling
}  // namespace shitsukan
