#include "shitsukan/wrinkly/wr_tessellation.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>

#include "shitsukan/core/scalar.hpp"
#include "shitsukan/wrinkly/superposition.hpp"

namespace shitsukan {

std::vector<float> wr_grid_positions(const WrAxis& axis, int grid_level, int subdivisions, float lo,
                                     float hi) {
    const std::vector<float> x =
        hierarchical_sample_positions(axis.base_intervals, axis.division, grid_level);
    std::vector<float> g;
    g.push_back(lo);
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
        for (int s = 0; s < subdivisions; ++s) {
            const float p = x[i] + (x[i + 1] - x[i]) * float(s) / float(subdivisions);
            if (p > lo && p < hi) g.push_back(p);
        }
    }
    g.push_back(hi);
    return g;
}

namespace {

Status check_wr_grid_options(const WrSurface& surface, const HierarchicalSampling* sampling,
                             const WrTessellationOptions& o) {
    if (o.levels < 0 || o.levels > kMaxWrLevel || o.grid_level < 0 || o.grid_level > kMaxWrLevel)
        return Status::error(StatusCode::invalid_argument,
                             "levels K and grid level L must be in 0..%d (got %d, %d)", kMaxWrLevel,
                             o.levels, o.grid_level);
    if ((o.form == WrSurfaceForm::wr || o.form == WrSurfaceForm::superposed_direct) &&
        o.levels > surface.max_level())
        return Status::error(StatusCode::invalid_argument,
                             "levels K = %d exceeds the IST steps the surface's axes hold (%d): "
                             "build them with make_wr_ist_axis(..., max_level >= K, ...)",
                             o.levels, surface.max_level());
    if (o.subdivisions < 1 || o.subdivisions > 64)
        return Status::error(StatusCode::invalid_argument, "subdivisions must be in 1..64 (got %d)",
                             o.subdivisions);
    if (!(o.u0 >= 0 && o.u0 < o.u1 && o.u1 <= 1 && o.v0 >= 0 && o.v0 < o.v1 && o.v1 <= 1))
        return Status::error(StatusCode::invalid_argument,
                             "parameter window must satisfy 0 <= u0 < u1 <= 1, 0 <= v0 < v1 <= 1 "
                             "(got [%g, %g] x [%g, %g])",
                             double(o.u0), double(o.u1), double(o.v0), double(o.v1));
    if (!(o.tail_tolerance >= 0))
        return Status::error(StatusCode::invalid_argument, "tail_tolerance must be >= 0 (got %g)",
                             double(o.tail_tolerance));
    if (o.form == WrSurfaceForm::superposed && sampling == nullptr)
        return Status::error(StatusCode::invalid_argument,
                             "the superposed form (eq. 20) needs a HierarchicalSampling");
    const double est = double(surface.axis_u().base_intervals) *
                       det_pow(double(surface.axis_u().division), o.grid_level) *
                       double(surface.axis_v().base_intervals) *
                       det_pow(double(surface.axis_v().division), o.grid_level) *
                       double(o.subdivisions) * double(o.subdivisions);
    if (est > double(kMaxWrVertices))
        return Status::error(
            StatusCode::too_large,
            "grid level %d x %d subdivisions gives about %.0f vertices (limit %ld)", o.grid_level,
            o.subdivisions, est, kMaxWrVertices);
    return Status::success();
}

// The spline bases of one grid axis (they depend on u alone, or v alone): at the grid
// parameters themselves (index [i]) and at their IST inverses for the steps the form needs
// (index [i·(K + 1) + k]; step K only for eq. (15), every k for eq. (16)); for eq. (20) the
// sample weights of steps k = 1..K' of the sampling (index [i·K' + k - 1]).
struct WrAxisBases {
    std::vector<WrBasisAt> at, inverse;
    std::vector<SampleWeights> weights;
};

enum class Axis { u, v };

WrAxisBases locate_axis_bases(const WrSurface& surface, const HierarchicalSampling* sampling,
                              const std::vector<float>& g, Axis axis,
                              const WrTessellationOptions& o) {
    WrAxisBases r;
    const int steps = o.levels + 1;
    auto locate = [&](float x) {
        return axis == Axis::u ? surface.basis_u(x) : surface.basis_v(x);
    };
    auto inverse = [&](float x, int k) {
        return axis == Axis::u ? surface.inverse_u(x, k) : surface.inverse_v(x, k);
    };
    r.at.resize(g.size());
    for (std::size_t i = 0; i < g.size(); ++i) r.at[i] = locate(g[i]);
    if (o.form == WrSurfaceForm::wr || o.form == WrSurfaceForm::superposed_direct) {
        r.inverse.resize(g.size() * std::size_t(steps));
        for (std::size_t i = 0; i < g.size(); ++i)
            for (int k = o.form == WrSurfaceForm::wr ? o.levels : 0; k <= o.levels; ++k)
                r.inverse[i * std::size_t(steps) + std::size_t(k)] = locate(inverse(g[i], k));
    }
    if (o.form == WrSurfaceForm::superposed) {
        const int levels = sampling->levels();
        r.weights.resize(g.size() * std::size_t(levels));
        for (std::size_t i = 0; i < g.size(); ++i)
            for (int k = 1; k <= levels; ++k)
                r.weights[i * std::size_t(levels) + std::size_t(k - 1)] =
                    axis == Axis::u ? sampling->weights_u(k, g[i]) : sampling->weights_v(k, g[i]);
    }
    return r;
}

}  // namespace

Status evaluate_wr_grid(const WrSurface& surface, const HierarchicalSampling* sampling,
                        const WrTessellationOptions& o, WrMesh& out) {
    SHITSUKAN_TRY(check_wr_grid_options(surface, sampling, o));
    const std::vector<float> gu =
        wr_grid_positions(surface.axis_u(), o.grid_level, o.subdivisions, o.u0, o.u1);
    const std::vector<float> gv =
        wr_grid_positions(surface.axis_v(), o.grid_level, o.subdivisions, o.v0, o.v1);
    const WrAxisBases bu = locate_axis_bases(surface, sampling, gu, Axis::u, o);
    const WrAxisBases bv = locate_axis_bases(surface, sampling, gv, Axis::v, o);
    const int nu = int(gu.size()), nv = int(gv.size());
    const std::size_t steps = std::size_t(o.levels) + 1;
    WrMesh m;
    m.grid_u = nu;
    m.grid_v = nv;
    TriangleMesh& t = m.mesh;
    t.positions.resize(std::size_t(nu) * std::size_t(nv));
    t.normals.resize(t.positions.size());
    t.uvs.resize(t.positions.size());
    t.colors.resize(t.positions.size());
    m.transparency.resize(t.positions.size());
    long levels_sum = 0;
    const int rows_per_report = nv > 100 ? nv / 100 : 1;  // about a hundred reports at most
    for (int j = 0; j < nv; ++j) {
        if (j % rows_per_report == 0) o.progress.report(float(j) / float(nv));
        for (int i = 0; i < nu; ++i) {
            const float u = gu[std::size_t(i)], v = gv[std::size_t(j)];
            const WrBasisAt &au = bu.at[std::size_t(i)], &av = bv.at[std::size_t(j)];
            const std::size_t id = std::size_t(j) * std::size_t(nu) + std::size_t(i);
            Vec3 p;
            WrAttributes a;
            if (o.form == WrSurfaceForm::superposed) {
                const std::size_t levels = std::size_t(sampling->levels());
                const SuperposedSample s = superposed_sampled(
                    surface, *sampling, au, av, bu.weights.data() + std::size_t(i) * levels,
                    bv.weights.data() + std::size_t(j) * levels, u, v, o.tail_tolerance);
                p = s.position;
                a = s.attributes;
                levels_sum += s.levels_used;
                if (s.levels_used > m.max_levels_used) m.max_levels_used = s.levels_used;
            } else {
                const BasePoint b = surface.base_point(au, av, u, v);
                // The inverses exist for the wr and superposed_direct forms only (no offset
                // from an empty vector's null data: fuzz_wr_tessellation, UBSan).
                const bool inverted = !bu.inverse.empty() && !bv.inverse.empty();
                const WrBasisAt* iu =
                    inverted ? bu.inverse.data() + std::size_t(i) * steps : nullptr;
                const WrBasisAt* iv =
                    inverted ? bv.inverse.data() + std::size_t(j) * steps : nullptr;
                if (o.form == WrSurfaceForm::wr)
                    a = surface.attributes(iu[o.levels], iv[o.levels]);  // eq. (15)
                else if (o.form == WrSurfaceForm::superposed_direct)
                    a = superposed_attributes_direct(surface, b.delta, iu, iv, o.levels);  // (16)
                else
                    a = surface.attributes(au, av);
                p = o.form == WrSurfaceForm::base ? b.position : surface.displace(b, a);
            }
            t.positions[id] = p;
            t.uvs[id] = {u, v};
            t.colors[id] = {clamp(a.color.x, 0.0f, 1.0f), clamp(a.color.y, 0.0f, 1.0f),
                            clamp(a.color.z, 0.0f, 1.0f)};
            m.transparency[id] = clamp(a.transparency, 0.0f, 1.0f);
        }
    }
    o.progress.report(1.0f);
    m.mean_levels_used = double(levels_sum) / double(t.positions.size());
    out = std::move(m);
    return Status::success();
}

void polygonise_wr_grid(const WrSurface& surface, WrMesh* m) {
    TriangleMesh& t = m->mesh;
    const int nu = m->grid_u, nv = m->grid_v;
    // Normals of the displaced surface from central differences on the grid (the wrinkles'
    // own normals, not N(u, v) of the base surface).
    auto at = [&](int i, int j) {
        return t.positions[std::size_t(j) * std::size_t(nu) + std::size_t(i)];
    };
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
            const Vec3 du = at(i < nu - 1 ? i + 1 : i, j) - at(i > 0 ? i - 1 : i, j);
            const Vec3 dv = at(i, j < nv - 1 ? j + 1 : j) - at(i, j > 0 ? j - 1 : j);
            Vec3 n = cross(du, dv);
            const float l = length(n);
            const Vec2 uv = t.uvs[std::size_t(j) * std::size_t(nu) + std::size_t(i)];
            n = l > 0 && is_finite(l) ? n / l : surface.base_point(uv.x, uv.y).normal;
            t.normals[std::size_t(j) * std::size_t(nu) + std::size_t(i)] = n;
        }
    }
    // Two counter-clockwise triangles per grid cell (front = the side dP/du x dP/dv points to).
    t.indices.clear();
    t.indices.reserve(std::size_t(nu - 1) * std::size_t(nv - 1) * 6);
    for (int j = 0; j + 1 < nv; ++j) {
        for (int i = 0; i + 1 < nu; ++i) {
            const std::uint32_t a = std::uint32_t(j * nu + i), b = a + 1;
            const std::uint32_t c = a + std::uint32_t(nu), d = c + 1;
            t.add_triangle(a, b, d);
            t.add_triangle(a, d, c);
        }
    }
}

Status tessellate_wr_surface(const WrSurface& surface, const HierarchicalSampling* sampling,
                             const WrTessellationOptions& options, WrMesh& out) {
    SHITSUKAN_TRY(evaluate_wr_grid(surface, sampling, options, out));
    polygonise_wr_grid(surface, &out);
    return Status::success();
}

AdaptiveLevels choose_adaptive_levels(const WrSurface& surface, const WrControlMesh& mesh,
                                      float pixels_per_unit, float cell_pixels,
                                      float tolerance_pixels, int max_level) {
    AdaptiveLevels r;
    if (!(pixels_per_unit > 0) || !(cell_pixels > 0) || !(tolerance_pixels > 0)) return r;
    max_level = clamp(max_level, 0, kMaxWrLevel);
    // World length of one base interval: the control polygon's length along each axis, per span.
    double len_u = 0, len_v = 0;
    for (int r2 = 0; r2 < mesh.rows; ++r2)
        for (int c = 0; c + 1 < mesh.cols; ++c)
            len_u += length(mesh.at(c + 1, r2).position - mesh.at(c, r2).position);
    for (int c = 0; c < mesh.cols; ++c)
        for (int r2 = 0; r2 + 1 < mesh.rows; ++r2)
            len_v += length(mesh.at(c, r2 + 1).position - mesh.at(c, r2).position);
    len_u /= double(mesh.rows) * double(surface.spans_u());
    len_v /= double(mesh.cols) * double(surface.spans_v());
    const double span = len_u > len_v ? len_u : len_v;
    const int n = surface.axis_u().division > surface.axis_v().division ? surface.axis_u().division
                                                                        : surface.axis_v().division;
    double cell = span * pixels_per_unit;
    r.grid_level = 0;
    while (cell > cell_pixels && r.grid_level < max_level && n > 1) {
        cell /= n;
        ++r.grid_level;
    }
    // The largest delta on the mesh bounds the tail everywhere.
    float dmax = 0;
    for (const WrControlPoint& p : mesh.points) dmax = p.delta > dmax ? p.delta : dmax;
    double tail = double(dmax) * surface.max_abs_height() * pixels_per_unit;  // step 1 onwards
    r.sum_levels = 0;
    while (tail >= tolerance_pixels && r.sum_levels < max_level) {
        ++r.sum_levels;
        tail *= dmax;
    }
    r.world_tolerance = tolerance_pixels / pixels_per_unit;
    return r;
}

}  // namespace shitsukan
