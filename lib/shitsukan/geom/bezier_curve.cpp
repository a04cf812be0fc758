// small-device: yes (no allocation, no exceptions)
#include "shitsukan/geom/bezier_curve.hpp"

#include <cmath>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/geom/basis.hpp"

namespace shitsukan {

Vec2 bezier_point(const CubicBezier2& curve, float t) {
    float b[4];
    bernstein_basis(3, t, b);  // (1-t)^3, 3t(1-t)^2, 3t^2(1-t), t^3: the weights of eq. (2)
    Vec2 q{0, 0};
    for (int i = 0; i < 4; ++i) q = q + curve.p[i] * b[i];
    return q;
}

Vec2 bezier_derivative(const CubicBezier2& curve, float t) {
    float b[4], db[4];
    bernstein_basis(3, t, b, db);  // db = eq. (3)'s weights: 3{-(1-t)^2, 3t^2-4t+1, ...}
    Vec2 q{0, 0};
    for (int i = 0; i < 4; ++i) q = q + curve.p[i] * db[i];
    return q;
}

SectionSample chain_point(const BezierChain& chain, int segment, float t) {
    SHITSUKAN_ASSERT(segment >= 0 && segment < chain.count);
    const CubicBezier2& c = chain.segments[segment];
    float b[4], db[4];
    bernstein_basis(3, t, b, db);  // eq. (2)'s weights and eq. (3)'s, in one call
    Vec2 q{0, 0}, d{0, 0};
    for (int i = 0; i < 4; ++i) {
        q = q + c.p[i] * b[i];
        d = d + c.p[i] * db[i];
    }
    SectionSample s;
    s.r = q.x;
    s.z = q.y;
    s.dr = d.x;
    s.dz = d.y;
    s.t = t;
    s.segment = segment;
    return s;
}

float section_r_first(const BezierChain& chain) {
    SHITSUKAN_ASSERT(chain.count >= 1);
    return chain.segments[0].p[0].x;
}

float section_r_last(const BezierChain& chain) {
    SHITSUKAN_ASSERT(chain.count >= 1);
    return chain.segments[chain.count - 1].p[3].x;
}

Status validate_section(const BezierChain& chain) {
    if (chain.count < 1 || chain.count > kMaxChainSegments)
        return Status::error(StatusCode::invalid_argument,
                             "section: segment count must be 1..%d (got %d)", kMaxChainSegments,
                             chain.count);
    for (int k = 0; k < chain.count; ++k)
        for (int i = 0; i < 4; ++i)
        {
            const Vec2 p = chain.segments[k].p[i];
            if (!is_finite(p))
                return Status::error(StatusCode::invalid_argument,
                                     "section: control point %d of segment %d is not finite", i, k);
            if (std::fabs(p.x) > kMaxSectionCoordinate || std::fabs(p.y) > kMaxSectionCoordinate)
                return Status::error(StatusCode::invalid_argument,
                                     "section: control point %d of segment %d is (%g, %g); "
                                     "coordinates must be within +-%g",
                                     i, k, double(p.x), double(p.y),
                                     double(kMaxSectionCoordinate));
        }
    for (int k = 0; k + 1 < chain.count; ++k) {
        Vec2 gap = chain.segments[k + 1].p[0] - chain.segments[k].p[3];
        if (length(gap) > 1e-5f)
            return Status::error(
                StatusCode::invalid_argument,
                "section: segment %d ends at (%g, %g) but segment %d starts at "
                "(%g, %g); a chain must be joined",
                k, double(chain.segments[k].p[3].x), double(chain.segments[k].p[3].y), k + 1,
                double(chain.segments[k + 1].p[0].x), double(chain.segments[k + 1].p[0].y));
    }
    // r'(t)/3 = a(1-t)^2 + 2b t(1-t) + c t^2 (Bernstein form of the derivative): it is >= 0 on
    // [0, 1] iff a >= 0, c >= 0 and either b >= 0 or the minimum, (ac - b^2)/(a - 2b + c), is
    // >= 0, i.e. b^2 <= ac. This is exact, so an accepted section has one z for each r.
    for (int k = 0; k < chain.count; ++k) {
        const CubicBezier2& s = chain.segments[k];
        double a = double(s.p[1].x) - double(s.p[0].x);
        double b = double(s.p[2].x) - double(s.p[1].x);
        double c = double(s.p[3].x) - double(s.p[2].x);
        bool monotone = a >= 0 && c >= 0 && (b >= 0 || b * b <= a * c);
        if (!monotone)
            return Status::error(StatusCode::invalid_argument,
                                 "section: r(t) decreases in segment %d (r steps %g, %g, %g): "
                                 "z(r) would be multi-valued; make r0 <= r1, r2 <= r3 and "
                                 "(r2 - r1)^2 <= (r1 - r0)(r3 - r2) when r2 < r1",
                                 k, a, b, c);
    }
    if (!(section_r_last(chain) > section_r_first(chain)))
        return Status::error(StatusCode::degenerate,
                             "section: r does not advance (first %g, last %g)",
                             double(section_r_first(chain)), double(section_r_last(chain)));
    return Status::success();
}

float invert_r(const CubicBezier2& segment, float r) {
    float r0 = segment.p[0].x, r1 = segment.p[1].x, r2 = segment.p[2].x, r3 = segment.p[3].x;
    if (!(r > r0)) return 0.0f;
    if (!(r < r3)) return 1.0f;
    // r(t) of eq. (2) in power form, r0 + t(c1 + t(c2 + t c3)), for cheap Newton steps.
    float c1 = 3.0f * (r1 - r0), c2 = 3.0f * (r2 - 2.0f * r1 + r0);
    float c3 = r3 - 3.0f * r2 + 3.0f * r1 - r0;
    // Bracket [lo, hi] with r(lo) <= r <= r(hi); Newton from the chord guess, falling back
    // to bisection whenever the step leaves the bracket (r'(t) may vanish at isolated t).
    float lo = 0.0f, hi = 1.0f;
    float t = (r - r0) / (r3 - r0);
    const float tolerance = 1e-7f * (std::fabs(r0) + std::fabs(r3) + 1.0f);
    for (int step = 0; step < 40; ++step) {
        float f = r0 + t * (c1 + t * (c2 + t * c3)) - r;
        if (std::fabs(f) <= tolerance) break;
        if (f < 0)
            lo = t;
        else
            hi = t;
        if (hi - lo <= 1e-7f) break;  // float resolution of t reached
        float d = c1 + t * (2.0f * c2 + 3.0f * c3 * t);
        float next = d > 0 ? t - f / d : -1.0f;
        if (!(next > lo && next < hi)) next = 0.5f * (lo + hi);
        if (next == t) break;
        t = next;
    }
    return t;
}

SectionSample section_at_r(const BezierChain& chain, float r) {
    SHITSUKAN_ASSERT(chain.count >= 1 && chain.count <= kMaxChainSegments);
    if (!(r > section_r_first(chain))) return chain_point(chain, 0, 0.0f);
    if (!(r < section_r_last(chain))) return chain_point(chain, chain.count - 1, 1.0f);
    // The segment whose r range holds r (the first one, at a shared end point).
    int k = 0;
    while (k + 1 < chain.count && r > chain.segments[k].p[3].x) ++k;
    return chain_point(chain, k, invert_r(chain.segments[k], r));
}

}  // namespace shitsukan
