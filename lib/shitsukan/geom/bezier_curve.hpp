// shitsukan/geom/bezier_curve.hpp — cubic Bezier curves (tokai1994 eq. 2, 3) and chains of
// them used as a function z(r) (the scale cross-section of tokai1994 §3.2, fig. 11, 15).
//
// Manual
//   float t = 0.5f;
//   CubicBezier2 c{{{0.0f, 0.1f}, {0.51f, 0.1f}, {0.75f, 0.13f}, {0.92f, 0.0f}}};
//   Vec2 q  = bezier_point(c, t);          // eq. (2), t in [0, 1]
//   Vec2 dq = bezier_derivative(c, t);     // eq. (3): (dr/dt, dz/dt)
//
//   BezierChain s;                         // 1..kMaxChainSegments segments joined end to start
//   s.segments[0] = c; s.count = 1;
//   Status ok = validate_section(s);       // finite, joined, r(t) non-decreasing (see below)
//   SectionSample q = section_at_r(s, 0.4f);   // q.z = z(0.4), q.dr, q.dz = eq. (3) at that t
//
// A chain used as a section z(r) must have its first coordinate r non-decreasing along the
// whole chain, so that each r has one z. For one segment r'(t)/3 is the quadratic Bernstein
// polynomial with coefficients a = r1 - r0, b = r2 - r1, c = r3 - r2; it is >= 0 on [0, 1]
// exactly when a >= 0, c >= 0 and (b >= 0 or b^2 <= a·c). validate_section checks that
// exactly (no sampling), so a section is either accepted and invertible, or refused with the
// offending segment in the message. section_at_r then inverts r(t) by Newton steps kept
// inside a shrinking bisection bracket: it converges even where r'(t) = 0.
// Outside [r_first, r_last] section_at_r clamps to the end point (z continues flat).
// Everything here is float, allocation-free and exception-free (small-device).
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

// Four control points p0..p3 (position vectors in the plane; for a section: (r, z)).
struct CubicBezier2 {
    Vec2 p[4];
};

// tokai1994 eq. (2): P(t) = (1-t)^3 p0 + 3t(1-t)^2 p1 + 3t^2(1-t) p2 + t^3 p3.
Vec2 bezier_point(const CubicBezier2& curve, float t);
// tokai1994 eq. (3): dP/dt = 3{-(t^2-2t+1) p0 + (3t^2-4t+1) p1 - (3t^2-2t) p2 + t^2 p3}.
Vec2 bezier_derivative(const CubicBezier2& curve, float t);

constexpr int kMaxChainSegments = 4;

// Several cubic segments, segment k's p3 equal to segment k+1's p0 (fig. 15 uses two).
struct BezierChain {
    CubicBezier2 segments[kMaxChainSegments];
    int count = 0;
};

// A point of a chain, with the derivative of its segment at that parameter.
struct SectionSample {
    float r = 0, z = 0;    // the point on the curve
    float dr = 0, dz = 0;  // eq. (3) of the segment at t: (dr/dt, dz/dt)
    float t = 0;           // parameter within the segment
    int segment = 0;
};

// Point and derivative of segment `segment` at t (no validation: programmer's indices).
SectionSample chain_point(const BezierChain& chain, int segment, float t);

// Largest |coordinate| of a section's control point (chosen here: 1e15, far beyond any
// section a relief uses, and small enough that eq. (3)'s derivative, 3 x a difference of two
// points, and the products of two differences the monotonicity test and z(r) form stay
// finite in float: fuzz_bezier found dz = -inf at z = -1.7e38).
constexpr float kMaxSectionCoordinate = 1e15f;

// invalid_argument when: count outside 1..kMaxChainSegments, a control point is NaN/inf or
// beyond kMaxSectionCoordinate, consecutive segments do not join (|gap| > 1e-5), or r(t) decreases somewhere (the message
// names the segment and its a, b, c). degenerate when the whole chain has r_last <= r_first.
Status validate_section(const BezierChain& chain);

// z as a function of r for a validated section (tokai1994 §3.2: "the position (r0, z0) of a
// point q0 of the curve is computed by substituting t = t0 into eq. (2)"; here t0 is found
// from r0). r below the first / above the last control point clamps to that end.
SectionSample section_at_r(const BezierChain& chain, float r);

// The r range of a chain: first p0.x and last p3.x.
float section_r_first(const BezierChain& chain);
float section_r_last(const BezierChain& chain);

// Parameter t of one segment whose r(t) equals r, for a segment with non-decreasing r(t)
// and r inside [r(0), r(1)] (clamped otherwise). Newton steps inside a bisection bracket;
// stops at |r(t) - r| <= 1e-7·scale, a bracket narrower than 1e-7, or after 40 steps
// (2-3 Newton steps for the Table 1 sections).
float invert_r(const CubicBezier2& segment, float r);

}  // namespace shitsukan
