// small-device: yes (no allocation, no exceptions)
#include "shitsukan/leather/relief.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>

#include "shitsukan/core/assert.hpp"

namespace shitsukan {

BezierChain table1_section(Table1Section which) {
    // tokai1994 Table 1: control points (r, z) of the sectional shapes.
    BezierChain c;
    switch (which) {
        case Table1Section::convex:  // fig. 13(a)
            c.segments[0] = {{{0.0f, 0.1f}, {0.51f, 0.1f}, {0.75f, 0.13f}, {0.92f, 0.0f}}};
            c.count = 1;
            break;
        case Table1Section::concave:  // fig. 14(a)
            c.segments[0] = {{{0.0f, 0.03f}, {0.8f, 0.05f}, {0.9f, 0.25f}, {0.94f, 0.0f}}};
            c.count = 1;
            break;
        case Table1Section::two_segment:  // fig. 15(a)
            c.segments[0] = {{{0.0f, 0.25f}, {0.23f, 0.07f}, {0.47f, 0.07f}, {0.6f, 0.25f}}};
            c.segments[1] = {{{0.6f, 0.25f}, {0.73f, 0.2f}, {0.85f, 0.13f}, {0.9f, 0.0f}}};
            c.count = 2;
            break;
    }
    return c;
}

const char* table1_section_name(Table1Section which) {
    switch (which) {
        case Table1Section::convex:
            return "convex (fig. 13a)";
        case Table1Section::concave:
            return "concave (fig. 14a)";
        case Table1Section::two_segment:
            return "two segments (fig. 15a)";
    }
    return "?";
}

Status validate_relief_options(const ReliefOptions& options) {
    if (!(options.edge_r > 0.0f) || !is_finite(options.edge_r))
        return Status::error(StatusCode::invalid_argument,
                             "relief: edge_r must be a finite value > 0 (got %g)",
                             double(options.edge_r));
    if (!(options.height_scale >= 0.0f) || !is_finite(options.height_scale))
        return Status::error(StatusCode::invalid_argument,
                             "relief: height_scale must be finite and >= 0 (got %g)",
                             double(options.height_scale));
    return Status::success();
}

namespace {

// Crossing of the ray m + s·d with edge i (a + w·(b - a), w in [0, 1]); false if none.
bool ray_edge(const Vec2* polygon, int n, int i, Vec2 m, Vec2 d, float* s_out) {
    Vec2 a = polygon[i], e = polygon[i + 1 < n ? i + 1 : 0] - a;
    float denom = cross(d, e);
    if (denom == 0.0f) return false;  // parallel to the ray
    Vec2 am = a - m;
    float s = cross(am, e) / denom;
    float w = cross(am, d) / denom;
    if (w < -1e-6f || w > 1.0f + 1e-6f || !(s > 0.0f)) return false;
    *s_out = s;
    return true;
}

// x itself is s = 1 on the ray, so the boundary bounding x's side is the nearest crossing
// with s >= 1 (a little tolerance for x exactly on the edge).
constexpr float kSMin = 1.0f - 1e-5f;

EdgeHit make_hit(const Vec2* polygon, int n, Vec2 m, Vec2 d, int edge, float s, bool inside) {
    EdgeHit hit;
    hit.inside = inside;
    hit.p = m + d * s;
    Vec2 a = polygon[edge], e = polygon[edge + 1 < n ? edge + 1 : 0] - a;
    Vec2 normal = normalize(Vec2{e.y, -e.x});
    float dist = dot(a - m, normal);
    if (dist < 0.0f) {
        normal = -normal;
        dist = -dist;
    }  // the side facing away from m
    hit.edge_normal = normal;
    hit.edge_distance = dist;
    return hit;
}

Vec2 ray_direction(Vec2 m, Vec2 x) {
    Vec2 d = x - m;
    if (d.x == 0.0f && d.y == 0.0f) d = {1.0f, 0.0f};  // at m: any direction will do
    return d;
}

}  // namespace

EdgeHit scale_edge_point(const Vec2* polygon, int n, Vec2 m, Vec2 x) {
    SHITSUKAN_ASSERT(n >= 3);
    Vec2 d = ray_direction(m, x);
    float best = INFINITY, farthest = -1.0f;
    int best_edge = -1, far_edge = -1;
    for (int i = 0; i < n; ++i) {
        float s;
        if (!ray_edge(polygon, n, i, m, d, &s)) continue;
        if (s >= kSMin && s < best) {
            best = s;
            best_edge = i;
        }
        if (s > farthest) {
            farthest = s;
            far_edge = i;
        }
    }
    if (best_edge >= 0) return make_hit(polygon, n, m, d, best_edge, best, true);
    if (far_edge >= 0) return make_hit(polygon, n, m, d, far_edge, farthest, false);
    EdgeHit none;
    none.p = x;
    return none;
}

bool make_angular_index(const Vec2* polygon, int n, Vec2 m, float* angles) {
    SHITSUKAN_ASSERT(n >= 3);
    // Unwrapped angles of the vertices around m; a star-shaped counter-clockwise polygon
    // turns by +2π in total, a clockwise one by -2π, each step strictly one way.
    float sign = 0.0f;
    for (int i = 0; i < n; ++i) {
        Vec2 v = polygon[i] - m;
        if (v.x == 0.0f && v.y == 0.0f) return false;
        float a = det_atan2(v.y, v.x);
        if (i > 0) {
            float step = a - angles[i - 1];
            while (step > kPi) step -= kTwoPi;
            while (step <= -kPi) step += kTwoPi;
            if (step == 0.0f) return false;
            if (sign == 0.0f) sign = step > 0.0f ? 1.0f : -1.0f;
            if (step * sign <= 0.0f) return false;
            a = angles[i - 1] + step;
        }
        angles[i] = a;
    }
    // Closing the loop must complete exactly one turn.
    float closing = det_atan2(polygon[0].y - m.y, polygon[0].x - m.x) - angles[n - 1];
    while (closing * sign <= 0.0f) closing += sign * kTwoPi;
    float total = angles[n - 1] - angles[0] + closing;
    return std::fabs(total * sign - kTwoPi) < 1e-3f;
}

EdgeHit scale_edge_point_indexed(const Vec2* polygon, int n, Vec2 m, Vec2 x, const float* angles) {
    SHITSUKAN_ASSERT(n >= 3);
    Vec2 d = ray_direction(m, x);
    float theta = det_atan2(d.y, d.x);
    bool ccw = angles[n - 1] > angles[0];
    // Search in increasing order: negate the angles of a clockwise polygon.
    float first = ccw ? angles[0] : -angles[0];
    float t = ccw ? theta : -theta;
    while (t < first) t += kTwoPi;
    while (t >= first + kTwoPi) t -= kTwoPi;
    int lo = 0, hi = n - 1;  // largest i with angle_i <= t
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        float a = ccw ? angles[mid] : -angles[mid];
        if (a <= t)
            lo = mid;
        else
            hi = mid - 1;
    }
    // Edge lo (counter-clockwise) or lo - 1 (clockwise, edges run the other way) spans the
    // ray's angle; its neighbours cover rounding at a vertex.
    int centre = ccw ? lo : (lo - 1 + n) % n;
    float best = INFINITY;
    int best_edge = -1;
    for (int k = -1; k <= 1; ++k) {
        int i = (centre + k + n) % n;
        float s;
        if (ray_edge(polygon, n, i, m, d, &s) && s >= kSMin && s < best) {
            best = s;
            best_edge = i;
        }
    }
    if (best_edge >= 0) return make_hit(polygon, n, m, d, best_edge, best, true);
    return scale_edge_point(polygon, n, m, x);
}

float scale_size(const Vec2* polygon, int n) {
    SHITSUKAN_ASSERT(n >= 3);
    float area2 = 0.0f, perimeter = 0.0f;
    for (int i = 0; i < n; ++i) {
        Vec2 a = polygon[i], b = polygon[i + 1 < n ? i + 1 : 0];
        area2 += cross(a, b);
        perimeter += length(b - a);
    }
    return perimeter > 0.0f ? std::fabs(area2) / perimeter : 0.0f;  // 2·area / perimeter
}

// normalize(n), also for a slope so steep that the squared length overflows a float (a
// component past 1.8e19, or infinite: a tiny edge distance or a huge height_scale), and for an
// n so short that its squared length is lost below float's range (fuzz_maps: a section whose
// dr and dz are both near 1e-20 gave a normal of length 0.7). Such an n is first scaled by its
// largest component, in double so the scale itself neither overflows nor rounds away; an
// infinite component stands for the limit of the normal as the slope grows (the horizontal
// direction of the infinite components); n = 0 has no direction and is taken as straight up
// (chosen here: the flat groove floor's normal).
namespace {
Vec3 steep_normalize(Vec3 n) {
    const float squared = n.x * n.x + n.y * n.y + n.z * n.z;
    if (is_finite(squared) && squared >= 1e-30f) return normalize(n);
    if (!is_finite(n.x) || !is_finite(n.y) || !is_finite(n.z)) {
        for (int c = 0; c < 3; ++c) n[c] = is_finite(n[c]) ? 0.0f : (n[c] > 0.0f ? 1.0f : -1.0f);
        return normalize(n);
    }
    double m = std::fabs(double(n.x)) > std::fabs(double(n.y)) ? std::fabs(double(n.x))
                                                                : std::fabs(double(n.y));
    m = std::fabs(double(n.z)) > m ? std::fabs(double(n.z)) : m;
    if (m == 0.0) return Vec3{0, 0, 1};
    return normalize(Vec3{float(double(n.x) / m), float(double(n.y) / m), float(double(n.z) / m)});
}
}  // namespace

void relief_along_ray(float rho, Vec2 m, const EdgeHit& hit, float size, const BezierChain& section,
                      const ReliefOptions& options, ReliefSample* out) {
    SHITSUKAN_ASSERT(section.count >= 1 && options.edge_r > 0.0f);
    Vec2 mp = hit.p - m;
    float n_r = length(mp);  // eq. (4): n_r = sqrt(n_x^2 + n_y^2), the ray's length |p - m|
    rho = clamp(rho, 0.0f, 1.0f);
    float r = rho * options.edge_r;
    // Step 3: z(r) from the section, continued flat past its last point (the groove floor).
    SectionSample q = section_at_r(section, r);
    float k = options.height_scale;
    out->rho = rho;
    out->r = r;
    out->edge_point = hit.p;
    out->scale_size = size;
    out->height = q.z * size / options.edge_r * k;
    if (r >= section_r_last(section) || n_r == 0.0f || rho == 0.0f || (q.dr == 0 && q.dz == 0)) {
        // The flat groove floor, or the centroid itself where the r direction is undefined.
        out->normal = {0, 0, 1};
        return;
    }
    Vec3 n;
    if (options.normal_rule == ReliefNormal::height_gradient && hit.edge_distance > 0.0f) {
        // Exact gradient of the height field in the fan triangle: rho = n_e·(x - m)/d_e.
        float g = k * size / hit.edge_distance;
        const float gz = q.dz == 0.0f ? 0.0f : g * q.dz;  // a flat top stays flat at g = inf
        n = {-gz * hit.edge_normal.x, -gz * hit.edge_normal.y, q.dr};
    } else {
        // Step 4, eq. (4) multiplied by -dz/n_r: n = (-dz·u, dr), u = (p - m)/|p - m|.
        Vec2 u = mp / n_r;
        n = {-k * q.dz * u.x, -k * q.dz * u.y, q.dr};
    }
    out->normal = steep_normalize(n);
}

void scale_relief(const Vec2* polygon, int n, Vec2 m, Vec2 x, const BezierChain& section,
                  const ReliefOptions& options, ReliefSample* out) {
    // Step 1 (fig. 12): the r axis from m through x to the edge point p.
    EdgeHit hit = scale_edge_point(polygon, n, m, x);
    // Step 2: relative distance along the r axis.
    float mp = length(hit.p - m);
    float rho = mp > 0.0f ? length(x - m) / mp : 0.0f;
    // Steps 3-4: z(r) and the normal.
    relief_along_ray(rho, m, hit, scale_size(polygon, n), section, options, out);
}

}  // namespace shitsukan
