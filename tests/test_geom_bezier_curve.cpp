// Tests for lib/shitsukan/geom/bezier_curve: eq. (2) end points, eq. (3) against finite
// differences, Table 1 sections, chains, inversion of r(t), bad sections.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <initializer_list>
#include <string>

#include "shitsukan/geom/bezier_curve.hpp"
#include "shitsukan/leather/relief.hpp"

using namespace shitsukan;

TEST_CASE("bezier: eq. (2) interpolates p0 and p3; eq. (3) gives 3(p1-p0), 3(p3-p2) at the ends") {
    CubicBezier2 c{{{0.1f, -0.2f}, {0.7f, 1.3f}, {1.9f, -0.4f}, {2.5f, 0.8f}}};
    CHECK(bezier_point(c, 0.0f).x == doctest::Approx(0.1f));
    CHECK(bezier_point(c, 0.0f).y == doctest::Approx(-0.2f));
    CHECK(bezier_point(c, 1.0f).x == doctest::Approx(2.5f));
    CHECK(bezier_point(c, 1.0f).y == doctest::Approx(0.8f));
    Vec2 d0 = bezier_derivative(c, 0.0f), d1 = bezier_derivative(c, 1.0f);
    CHECK(d0.x == doctest::Approx(3 * (0.7f - 0.1f)));
    CHECK(d0.y == doctest::Approx(3 * (1.3f + 0.2f)));
    CHECK(d1.x == doctest::Approx(3 * (2.5f - 1.9f)));
    CHECK(d1.y == doctest::Approx(3 * (0.8f + 0.4f)));
    // eq. (2) written out literally, at a few t.
    for (float t : {0.2f, 0.5f, 0.8f}) {
        float s = 1 - t;
        Vec2 lit = c.p[0] * (s * s * s) + c.p[1] * (3 * t * s * s) + c.p[2] * (3 * t * t * s) +
                   c.p[3] * (t * t * t);
        CHECK(bezier_point(c, t).x == doctest::Approx(lit.x).epsilon(1e-6));
        CHECK(bezier_point(c, t).y == doctest::Approx(lit.y).epsilon(1e-6));
    }
}

TEST_CASE("bezier: eq. (3) matches central finite differences (tolerance 1e-3 relative)") {
    CubicBezier2 c{{{0.0f, 0.03f}, {0.8f, 0.05f}, {0.9f, 0.25f}, {0.94f, 0.0f}}};
    const float h = 1e-3f;
    for (int k = 1; k < 20; ++k) {
        float t = float(k) / 20.0f;
        Vec2 fd = (bezier_point(c, t + h) - bezier_point(c, t - h)) / (2 * h);
        Vec2 d = bezier_derivative(c, t);
        // eq. (3) as printed: 3{-(t^2-2t+1)p0 + (3t^2-4t+1)p1 - (3t^2-2t)p2 + t^2 p3}.
        Vec2 printed = (c.p[0] * (-(t * t - 2 * t + 1)) + c.p[1] * (3 * t * t - 4 * t + 1) -
                        c.p[2] * (3 * t * t - 2 * t) + c.p[3] * (t * t)) *
                       3.0f;
        CHECK(d.x == doctest::Approx(fd.x).epsilon(1e-3).scale(1));
        CHECK(d.y == doctest::Approx(fd.y).epsilon(1e-3).scale(1));
        CHECK(d.x == doctest::Approx(printed.x).epsilon(1e-5));
        CHECK(d.y == doctest::Approx(printed.y).epsilon(1e-5));
    }
}

TEST_CASE("bezier: Table 1 sections validate and reproduce their end control points") {
    for (Table1Section which :
         {Table1Section::convex, Table1Section::concave, Table1Section::two_segment}) {
        BezierChain s = table1_section(which);
        REQUIRE(validate_section(s).ok());
        const CubicBezier2& first = s.segments[0];
        const CubicBezier2& last = s.segments[s.count - 1];
        SectionSample a = section_at_r(s, section_r_first(s));
        SectionSample b = section_at_r(s, section_r_last(s));
        CHECK(a.z == first.p[0].y);
        CHECK(b.z == last.p[3].y);
        CHECK(b.z == 0.0f);  // every Table 1 section ends on the groove floor z = 0
    }
    BezierChain convex = table1_section(Table1Section::convex);
    CHECK(section_r_last(convex) == 0.92f);
    CHECK(section_r_last(table1_section(Table1Section::concave)) == 0.94f);
    CHECK(section_r_last(table1_section(Table1Section::two_segment)) == 0.9f);
}

TEST_CASE("bezier: section_at_r inverts r(t): r(t(r)) = r within 1e-6, z from the same t") {
    for (Table1Section which :
         {Table1Section::convex, Table1Section::concave, Table1Section::two_segment}) {
        BezierChain s = table1_section(which);
        float r0 = section_r_first(s), r1 = section_r_last(s);
        for (int k = 0; k <= 200; ++k) {
            float r = r0 + (r1 - r0) * float(k) / 200.0f;
            SectionSample q = section_at_r(s, r);
            CHECK(std::fabs(q.r - r) <= 1e-6f);
            Vec2 on = bezier_point(s.segments[q.segment], q.t);
            CHECK(on.y == q.z);
        }
        // Clamped outside the range.
        CHECK(section_at_r(s, r1 + 0.5f).z == s.segments[s.count - 1].p[3].y);
        CHECK(section_at_r(s, r0 - 0.5f).z == s.segments[0].p[0].y);
    }
}

TEST_CASE("bezier: inversion converges where r'(t) = 0 (b^2 = ac, a stationary point)") {
    // r steps a = 0.3, b = -0.3, c = 0.3: b^2 = ac, r'(t) vanishes at t = 0.5.
    CubicBezier2 c{{{0.0f, 0.0f}, {0.3f, 0.2f}, {0.0f, 0.4f}, {0.3f, 0.6f}}};
    BezierChain s;
    s.segments[0] = c;
    s.count = 1;
    REQUIRE(validate_section(s).ok());
    CHECK(bezier_derivative(c, 0.5f).x == doctest::Approx(0.0f).epsilon(1e-6).scale(1));
    for (int k = 0; k <= 100; ++k) {
        float r = 0.3f * float(k) / 100.0f;
        SectionSample q = section_at_r(s, r);
        CHECK(std::fabs(q.r - r) <= 2e-6f);
    }
}

TEST_CASE("bezier: a chain is continuous at the join (fig. 15), and z(r) too") {
    BezierChain s = table1_section(Table1Section::two_segment);
    SectionSample end0 = chain_point(s, 0, 1.0f), start1 = chain_point(s, 1, 0.0f);
    CHECK(end0.r == start1.r);
    CHECK(end0.z == start1.z);
    float join = s.segments[0].p[3].x;
    float below = section_at_r(s, join - 1e-4f).z, above = section_at_r(s, join + 1e-4f).z;
    CHECK(std::fabs(below - above) < 1e-3f);
    CHECK(section_at_r(s, join - 1e-4f).segment == 0);
    CHECK(section_at_r(s, join + 1e-4f).segment == 1);
}

TEST_CASE("bezier: bad sections get a clear status, no crash") {
    BezierChain s = table1_section(Table1Section::convex);
    SUBCASE("r goes backwards") {
        s.segments[0].p[1].x = 0.6f;      // r steps a = 0.6, b = -0.3, c = 0.62:
        s.segments[0].p[2].x = 0.3f;      // b^2 = 0.09 <= ac = 0.372, so r(t) still increases
        CHECK(validate_section(s).ok());  // r dips in the control polygon but not in r(t)
        s.segments[0].p[3].x = 0.2f;      // c = -0.1 < 0: r(t) decreases near t = 1
        Status st = validate_section(s);
        CHECK(!st.ok());
        CHECK(st.code() == StatusCode::invalid_argument);
        CHECK(std::strstr(st.message(), "decreases") != nullptr);
    }
    SUBCASE("NaN control point") {
        s.segments[0].p[1].y = NAN;
        Status st = validate_section(s);
        CHECK(!st.ok());
        CHECK(std::strstr(st.message(), "not finite") != nullptr);
    }
    SUBCASE("gap in a chain") {
        BezierChain t = table1_section(Table1Section::two_segment);
        t.segments[1].p[0] = {0.61f, 0.25f};
        Status st = validate_section(t);
        CHECK(!st.ok());
        CHECK(std::strstr(st.message(), "joined") != nullptr);
    }
    SUBCASE("segment count") {
        s.count = 0;
        CHECK(!validate_section(s).ok());
        s.count = kMaxChainSegments + 1;
        CHECK(!validate_section(s).ok());
    }
    SUBCASE("no r advance") {
        for (int i = 0; i < 4; ++i) s.segments[0].p[i].x = 0.5f;
        Status st = validate_section(s);
        CHECK(st.code() == StatusCode::degenerate);
    }
}

TEST_CASE("bezier: a vertical segment makes a step in z(r) (§3.2: discontinuous sections)") {
    // §3.2: joining several curves "handles more complex shapes, including discontinuous
    // sections". A segment with constant r (a = b = c = 0 in validate_section) is a cliff:
    // z jumps there, and section_at_r never inverts r(t) on it (r0 == r3: no division).
    BezierChain s;
    s.segments[0] = {{{0.0f, 0.2f}, {0.2f, 0.2f}, {0.4f, 0.2f}, {0.5f, 0.2f}}};
    s.segments[1] = {{{0.5f, 0.2f}, {0.5f, 0.16f}, {0.5f, 0.13f}, {0.5f, 0.1f}}};  // the cliff
    s.segments[2] = {{{0.5f, 0.1f}, {0.7f, 0.1f}, {0.85f, 0.05f}, {0.9f, 0.0f}}};
    s.count = 3;
    REQUIRE(validate_section(s).ok());
    SectionSample before = section_at_r(s, 0.5f - 1e-4f), at = section_at_r(s, 0.5f);
    SectionSample after = section_at_r(s, 0.5f + 1e-4f);
    CHECK(before.segment == 0);
    CHECK(at.segment == 0);  // the shared end point belongs to the first segment
    CHECK(after.segment == 2);
    CHECK(before.z == doctest::Approx(0.2f).epsilon(1e-4));
    CHECK(after.z == doctest::Approx(0.1f).epsilon(1e-3));
    for (int k = 0; k <= 100; ++k) {
        SectionSample q = section_at_r(s, 0.9f * float(k) / 100.0f);
        CHECK(std::isfinite(q.z));
        CHECK(std::isfinite(q.t));
        CHECK(q.segment != 1);
    }
}

TEST_CASE("fuzz_bezier finding: a section with a control point near FLT_MAX is refused") {
    // fuzz/corpus/fuzz_bezier/finding_section_dz_overflow: z = -1.7e38 was accepted and
    // section_at_r returned dz = -inf (eq. (3)'s 3 (p1 - p0) overflows float).
    BezierChain chain;
    chain.count = 1;
    chain.segments[0].p[0] = {0.0f, 0.0f};
    chain.segments[0].p[1] = {0.3f, -1.7e38f};
    chain.segments[0].p[2] = {0.6f, 1.0f};
    chain.segments[0].p[3] = {1.0f, 0.0f};
    Status s = validate_section(chain);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("within +-1e+15") != std::string::npos);
    // At the limit the derivative stays finite.
    chain.segments[0].p[1] = {0.3f, -kMaxSectionCoordinate};
    chain.segments[0].p[2] = {0.6f, kMaxSectionCoordinate};
    REQUIRE(validate_section(chain).ok());
    for (float r = 0.0f; r <= 1.0f; r += 0.125f) {
        SectionSample q = section_at_r(chain, r);
        CHECK(std::isfinite(q.z));
        CHECK(std::isfinite(q.dz));
        CHECK(std::isfinite(q.dr));
    }
}
