// fujimoto2000 §3.1: a WR control mesh from a height map (see terrain_mesh.hpp).
#include "shitsukan/wrinkly/terrain_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {

struct NamedRamp {
    const char* name;
    const char* stops;
};
// chosen here: "terrain" follows fig. 21's control-point colours (grass, rock, snow by height);
// "sand" a dune's ochres; "grey" plain.
const NamedRamp kRamps[] = {
    {"terrain", "0:0.30,0.50,0.22;0.3:0.46,0.50,0.30;0.5:0.50,0.45,0.40;0.72:0.60,0.52,0.45;"
                "0.85:0.96,0.96,0.98;1:0.98,0.98,1"},
    {"grey", "0:0.15,0.15,0.15;1:0.95,0.95,0.95"},
    {"sand", "0:0.55,0.42,0.26;0.6:0.80,0.66,0.44;1:0.93,0.84,0.64"},
};

bool parse_float(const char*& p, float* out) {
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p || !std::isfinite(v)) return false;
    *out = float(v);
    p = end;
    return true;
}

Status ramp_error(const char* text, const char* why) {
    return Status::error(StatusCode::invalid_argument,
                         "colour ramp \"%s\": %s (stops t:r,g,b;... with t ascending in [0, 1] "
                         "and r, g, b in [0, 1], or terrain|grey|sand)",
                         text, why);
}

// Mean of the map over [x0, x1) x [y0, y1) (continuous pixel coordinates, pixel x covering
// [x, x + 1)), each pixel weighted by the area it shares with the box: clamped at the
// borders, or wrapped (a periodic map).
float box_mean(const float* map, int w, int h, float x0, float x1, float y0, float y1,
               bool wrap) {
    const int ix0 = int(std::floor(x0)), ix1 = int(std::ceil(x1)) - 1;
    const int iy0 = int(std::floor(y0)), iy1 = int(std::ceil(y1)) - 1;
    double sum = 0, weight = 0;
    for (int y = iy0; y <= iy1; ++y) {
        const double wy = std::fmin(double(y) + 1.0, double(y1)) - std::fmax(double(y), double(y0));
        for (int x = ix0; x <= ix1; ++x) {
            const double wx =
                std::fmin(double(x) + 1.0, double(x1)) - std::fmax(double(x), double(x0));
            const int cx = wrap ? (x % w + w) % w : clamp(x, 0, w - 1);
            const int cy = wrap ? (y % h + h) % h : clamp(y, 0, h - 1);
            sum += wx * wy * double(map[std::size_t(cy) * std::size_t(w) + std::size_t(cx)]);
            weight += wx * wy;
        }
    }
    return weight > 0 ? float(sum / weight) : map[0];
}

}  // namespace

Status parse_color_ramp(const char* text, ColorRamp& out) {
    if (!text) return ramp_error("", "null");
    for (const NamedRamp& r : kRamps)
        if (std::strcmp(text, r.name) == 0) return parse_color_ramp(r.stops, out);
    ColorRamp ramp;
    const char* p = text;
    while (*p) {
        if (ramp.count == ColorRamp::kMaxStops) return ramp_error(text, "more than 8 stops");
        float t, c[3];
        if (!parse_float(p, &t) || *p++ != ':') return ramp_error(text, "a stop is t:r,g,b");
        for (int k = 0; k < 3; ++k)
            if (!parse_float(p, &c[k]) || (k < 2 && *p++ != ','))
                return ramp_error(text, "a stop is t:r,g,b");
        if (*p == ';') ++p;
        else if (*p) return ramp_error(text, "stops are separated by ';'");
        const bool ascending = ramp.count == 0 || t > ramp.at[ramp.count - 1];
        if (!(t >= 0.0f && t <= 1.0f) || !ascending)
            return ramp_error(text, "t must ascend within [0, 1]");
        for (float v : c)
            if (!(v >= 0.0f && v <= 1.0f)) return ramp_error(text, "a colour is outside [0, 1]");
        ramp.at[ramp.count] = t;
        ramp.color[ramp.count++] = {c[0], c[1], c[2]};
    }
    if (ramp.count == 0) return ramp_error(text, "no stops");
    out = ramp;
    return Status::success();
}

Vec3 color_ramp_at(const ColorRamp& ramp, float t) {
    if (ramp.count == 0) return {1, 1, 1};
    if (!(t > ramp.at[0])) return ramp.color[0];
    for (int i = 1; i < ramp.count; ++i)
        if (t <= ramp.at[i])
            return lerp(ramp.color[i - 1], ramp.color[i],
                        (t - ramp.at[i - 1]) / (ramp.at[i] - ramp.at[i - 1]));
    return ramp.color[ramp.count - 1];
}

Status wrap_control_mesh(const WrControlMesh& period, int degree, Vec3 period_u, Vec3 period_v,
                         WrControlMesh& out) {
    const int mu = period.cols, mv = period.rows;
    if (mu < 1 || mv < 1 || int(period.points.size()) != mu * mv || degree < 1 || degree > 7)
        return Status::error(StatusCode::invalid_argument,
                             "wrap_control_mesh: a %d x %d mesh of %zu points, degree %d", mu, mv,
                             period.points.size(), degree);
    WrControlMesh m = make_control_mesh(mu + degree, mv + degree);
    if (m.points.empty())
        return Status::error(StatusCode::too_large, "wrap_control_mesh: %d x %d points",
                             mu + degree, mv + degree);
    for (int r = 0; r < m.rows; ++r)
        for (int c = 0; c < m.cols; ++c) {
            WrControlPoint q = period.at(c % mu, r % mv);
            q.position = q.position + period_u * float(c / mu) + period_v * float(r / mv);
            m.at(c, r) = q;
        }
    out = std::move(m);
    return Status::success();
}

Status control_mesh_from_height_map(const float* map, int w, int h, const TerrainMeshOptions& o,
                                    WrControlMesh& out) {
    if (!map || w < 1 || h < 1)
        return Status::error(StatusCode::invalid_argument, "height map: empty (%d x %d)", w, h);
    if (o.points < 4 || o.points > 1024 || !(o.extent > 0.0f && std::isfinite(o.extent)) ||
        !(o.height_scale >= 0.0f && std::isfinite(o.height_scale)) ||
        !(o.delta > 0.0f && o.delta < 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "terrain mesh: points %d must be in [4, 1024], extent %g > 0, "
                             "height scale %g >= 0, delta %g in (0, 1)",
                             o.points, double(o.extent), double(o.height_scale), double(o.delta));
    float lo = map[0], hi = map[0];
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i) {
        if (!std::isfinite(map[i]))
            return Status::error(StatusCode::invalid_argument,
                                 "height map: pixel (%zu, %zu) is not finite", i % std::size_t(w),
                                 i / std::size_t(w));
        lo = std::min(lo, map[i]), hi = std::max(hi, map[i]);
    }
    const int n = o.points;
    // Open: point c stands for the cell [c, c + 1)/n of the map. Periodic: for the point c
    // on which the B-spline's u = c/n is centred (c - degree/2 of the wrapped mesh), the cell
    // centred on it, wrapped: the output map's pixels then sit where the input's did.
    const int shift = o.periodic ? o.degree / 2 : 0;
    const float step = o.extent / float(o.periodic ? n : n - 1);
    const float sx = float(w) / float(n), sy = float(h) / float(n);
    const float centre = o.periodic ? 0.5f : 0.0f;
    WrControlMesh period = make_control_mesh(n, n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const int i = (c - shift + n) % n, j = (r - shift + n) % n;
            const float x0 = (float(i) - centre) * sx, y0 = (float(j) - centre) * sy;
            const float v = box_mean(map, w, h, x0, x0 + sx, y0, y0 + sy, o.periodic);
            WrControlPoint& q = period.at(c, r);
            q.position = {-0.5f * o.extent + step * float(c - shift), 0.0f,
                          0.5f * o.extent - step * float(r - shift)};
            q.height = o.height_scale * v;
            q.color = color_ramp_at(o.ramp, hi > lo ? (v - lo) / (hi - lo) : 0.0f);
            q.delta = o.delta;
        }
    if (!o.periodic) {
        out = std::move(period);
        return Status::success();
    }
    return wrap_control_mesh(period, o.degree, {o.extent, 0, 0}, {0, 0, -o.extent}, out);
}

}  // namespace shitsukan
