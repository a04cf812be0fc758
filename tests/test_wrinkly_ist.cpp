// Tests for lib/shitsukan/wrinkly/ist_axis, ist_digits, ist_formula, ist_procedure:
// fujimoto2000 §2.2-2.3: the formulas equal the step-by-step procedure at every sub-interval,
// bijections, involutions (eqs. 8, 13), the number differences of §2.2.2(2), the real-valued
// forms (eqs. 9, 10, 14) and bad input.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <string>
#include <vector>

#include "shitsukan/core/prng.hpp"
#include "shitsukan/wrinkly/ist_axis.hpp"
#include "shitsukan/wrinkly/ist_digits.hpp"
#include "shitsukan/wrinkly/ist_formula.hpp"
#include "shitsukan/wrinkly/ist_procedure.hpp"

using namespace shitsukan;

namespace {

// The axes a test sweeps: unit for any N (B = 1 and B = 3), and for odd N the connected kinds
// on both kinds of ends.
std::vector<IstAxis> axes_for(int n, int k) {
    std::vector<IstAxis> out;
    IstAxis a;
    REQUIRE(ist_unit_axis(n, k, a).ok());
    out.push_back(a);
    REQUIRE(ist_unit_axis(n, k, 3, a).ok());
    out.push_back(a);
    if (n % 2 == 1) {
        for (IstEnds ends : {IstEnds::cyclic, IstEnds::translation}) {
            REQUIRE(ist_fully_connected_axis(n, k, 5, ends, a).ok());
            out.push_back(a);
            IstShuffle none;
            REQUIRE(ist_shuffle_none(n, none).ok());
            REQUIRE(ist_connected_axis(none, k, 4, ends, a).ok());
            out.push_back(a);
            if (n == 5) {
                for (const char* name : {"fig6b", "fig7a", "fig7c"}) {
                    IstShuffle s;
                    REQUIRE(ist_shuffle_named(name, 5, s).ok());
                    REQUIRE(ist_connected_axis(s, k, 6, ends, a).ok());
                    out.push_back(a);
                }
            }
        }
        // B = 1 and B = 2 on a cyclic axis: offsets wrap onto the same base intervals.
        REQUIRE(ist_fully_connected_axis(n, k, 1, IstEnds::cyclic, a).ok());
        out.push_back(a);
        REQUIRE(ist_fully_connected_axis(n, k, 2, IstEnds::cyclic, a).ok());
        out.push_back(a);
    }
    return out;
}

std::string describe(const IstAxis& a) {
    const char* kind = a.kind == IstKind::unit ? "unit"
                       : a.kind == IstKind::fully_connected ? "fully" : "connected";
    return std::string(kind) + " N=" + std::to_string(a.n) + " K=" + std::to_string(a.iterations) +
           " B=" + std::to_string(a.base_intervals) +
           (a.ends == IstEnds::cyclic ? " cyclic" : " translation") +
           " slots=" + [&] {
               std::string s;
               for (int g = 0; g < a.shuffle.n; ++g)
                   s += std::to_string(a.shuffle.offset[g]) + "/" +
                        std::to_string(a.shuffle.slot[g]) + " ";
               return s;
           }();
}

double midpoint(const IstAxis& axis, int base, std::uint64_t index, double offset = 0.5) {
    double count = double(ist_sub_interval_count(axis));
    return (double(base) + (double(index) + offset) / count) / double(axis.base_intervals);
}

// Formula (digits and real forms) against the procedure for one sub-interval, both ways.
void check_sub_interval(const IstAxis& axis, int base, std::uint64_t index) {
    IstDigits a, b, back, steps;
    ist_digits_from_index(axis, base, index, &a);
    ist_digits_forward(axis, a, &b);
    REQUIRE(b.base >= 0);
    REQUIRE(b.base < axis.base_intervals);
    ist_digits_forward_by_steps(axis, a, &steps);
    REQUIRE(steps.base == b.base);
    REQUIRE(ist_digits_index(axis, steps) == ist_digits_index(axis, b));
    ist_digits_inverse(axis, b, &back);
    REQUIRE(back.base == base);
    REQUIRE(ist_digits_index(axis, back) == index);

    const double u0 = midpoint(axis, base, index, 0.3);
    const double expected = midpoint(axis, b.base, ist_digits_index(axis, b), 0.3);
    const double tolerance = 1e-9;
    REQUIRE(std::fabs(ist_procedure_forward(axis, u0) - expected) < tolerance);
    REQUIRE(std::fabs(ist_forward_double(axis, u0) - expected) < tolerance);
    REQUIRE(std::fabs(ist_procedure_inverse(axis, expected) - u0) < tolerance);
    REQUIRE(std::fabs(ist_inverse_double(axis, expected) - u0) < tolerance);
}

}  // namespace

TEST_CASE(
    "IST exhaustive: formula == procedure at every sub-interval, N in {1,2,3,4,5,7}, K <= 4") {
    for (int n : {1, 2, 3, 4, 5, 7}) {
        for (int k = 0; k <= 4; ++k) {
            for (const IstAxis& axis : axes_for(n, k)) {
                CAPTURE(describe(axis));
                const std::uint64_t count = ist_sub_interval_count(axis);
                for (int b = 0; b < axis.base_intervals; ++b)
                    for (std::uint64_t i = 0; i < count; ++i) check_sub_interval(axis, b, i);
            }
        }
    }
}

TEST_CASE("IST random samples up to K = 8: formula == procedure") {
    Pcg32 rng(2000u, 2u);
    for (int n : {1, 2, 3, 4, 5, 7}) {
        for (int k = 5; k <= 8; ++k) {
            for (const IstAxis& axis : axes_for(n, k)) {
                CAPTURE(describe(axis));
                const std::uint64_t count = ist_sub_interval_count(axis);
                for (int s = 0; s < 60; ++s) {
                    int b = int(rng.uniform_int(std::uint32_t(axis.base_intervals)));
                    std::uint64_t i = rng.next_u64() % count;
                    check_sub_interval(axis, b, i);
                }
            }
        }
    }
}

TEST_CASE("IST is a bijection of the sub-intervals; unit and fully-connected are involutions") {
    for (int n : {1, 2, 3, 4, 5, 7}) {
        for (int k = 1; k <= 3; ++k) {
            for (const IstAxis& axis : axes_for(n, k)) {
                CAPTURE(describe(axis));
                const std::uint64_t count = ist_sub_interval_count(axis);
                std::vector<char> hit(std::size_t(count) * std::size_t(axis.base_intervals), 0);
                const bool involution =
                    axis.kind == IstKind::unit ||
                    (axis.kind == IstKind::fully_connected && axis.ends == IstEnds::cyclic);
                for (int b = 0; b < axis.base_intervals; ++b) {
                    for (std::uint64_t i = 0; i < count; ++i) {
                        IstDigits a, f, ff;
                        ist_digits_from_index(axis, b, i, &a);
                        ist_digits_forward(axis, a, &f);
                        std::size_t slot = std::size_t(f.base) * std::size_t(count) +
                                           std::size_t(ist_digits_index(axis, f));
                        REQUIRE(hit[slot] == 0);
                        hit[slot] = 1;
                        if (involution) {
                            ist_digits_forward(axis, f, &ff);  // eqs. (8), (13)
                            REQUIRE(ff.base == b);
                            REQUIRE(ist_digits_index(axis, ff) == i);
                        }
                    }
                }
            }
        }
    }
}

TEST_CASE("unit-IST eq. (7): N = 5, K = 3, 124 -> 421 and back (the paper's example)") {
    IstAxis axis;
    REQUIRE(ist_unit_axis(5, 3, axis).ok());
    IstDigits a, b;
    ist_digits_from_index(axis, 0, 1 * 25 + 2 * 5 + 4, &a);
    ist_digits_forward(axis, a, &b);
    CHECK(b.digit[1] == 4);
    CHECK(b.digit[2] == 2);
    CHECK(b.digit[3] == 1);
    char text[32];
    CHECK(std::string(ist_digits_format(b, 0, text, sizeof text)) == "0.421");
    // The label through format_integer (no snprintf): signs, large sums, cut at the buffer.
    CHECK(std::string(ist_digits_format(b, -7, text, sizeof text)) == "-7.421");
    CHECK(std::string(ist_digits_format(b, 2147483647, text, sizeof text)) == "2147483647.421");
    CHECK(std::string(ist_digits_format(b, 12, text, 3)) == "12");
    CHECK(std::string(ist_digits_format(b, 12, text, 4)) == "12.");
    CHECK(std::string(ist_digits_format(b, 12, text, 5)) == "12.4");
    // eq. (22): one internal shuffle carries alpha_k to the front.
    IstDigits c = a;
    ist_internal_shuffle(axis, 3, &c);
    CHECK(std::string(ist_digits_format(c, 0, text, sizeof text)) == "0.412");
}

TEST_CASE("fully-connected eq. (12) on 6.123, N = 5, K = 3") {
    IstDigits a, b;
    a.base = 6;
    a.count = 3;
    a.digit[1] = 1;
    a.digit[2] = 2;
    a.digit[3] = 3;
    ist_scale_reverse_fully_connected(5, a, &b);
    // alpha_0 = 6 + (1-2) + (2-2) + (3-2) = 6; digits (4-3)(4-2)(4-1) = 1 2 3.
    CHECK(b.base == 6);
    CHECK(b.digit[1] == 1);
    CHECK(b.digit[2] == 2);
    CHECK(b.digit[3] == 3);
    a.digit[1] = 4;
    a.digit[2] = 4;
    a.digit[3] = 0;
    ist_scale_reverse_fully_connected(5, a, &b);
    CHECK(b.base == 6 + 2 + 2 - 2);
    CHECK(b.digit[1] == 4);
    CHECK(b.digit[2] == 0);
    CHECK(b.digit[3] == 0);
}

namespace {

// The number found at each position of u^3 (the origin of the sub-interval there) as an
// integer in units of N^-K: base·N^K + index. Differences of these are the paper's "number
// differences" (integer part decimal, fraction base N).
std::vector<long> numbers_on_last_axis(const IstAxis& axis, int base) {
    const std::uint64_t count = ist_sub_interval_count(axis);
    std::vector<long> numbers;
    for (std::uint64_t i = 0; i < count; ++i) {
        IstDigits position, origin;
        ist_digits_from_index(axis, base, i, &position);
        ist_digits_inverse(axis, position, &origin);
        numbers.push_back(long(origin.base) * long(count) + long(ist_digits_index(axis, origin)));
    }
    return numbers;
}

// Differences between neighbouring ranges of size N^(level-1) inside every range of size
// N^level, as N^-K units; checks they equal expected[t] for the step t -> t + 1.
void check_differences(const std::vector<long>& numbers, int n, int level, const long* expected) {
    long range = 1;
    for (int l = 1; l < level; ++l) range *= n;
    const long enclosing = range * n;
    for (long start = 0; start < long(numbers.size()); start += enclosing)
        for (int t = 0; t + 1 < n; ++t)
            for (long j = 0; j < range; ++j) {
                long a = numbers[std::size_t(start + t * range + j)];
                long b = numbers[std::size_t(start + (t + 1) * range + j)];
                CAPTURE(level);
                CAPTURE(t);
                REQUIRE(b - a == expected[t]);
            }
}

}  // namespace

TEST_CASE("fig 6a: number differences 0.400 / 0.440 / 0.444 on u^3 (§2.2.2(2))") {
    IstAxis axis;
    REQUIRE(ist_fully_connected_axis(5, 3, 15, IstEnds::cyclic, axis).ok());
    // Base 7 of 15: numbers come from at most K·M = 6 base intervals away, never across the wrap.
    std::vector<long> numbers = numbers_on_last_axis(axis, 7);
    // In units of 5^-3: 0.400 = 100, 0.440 = 120, 0.444 = 124.
    const long level1[4] = {100, 100, 100, 100};
    const long level2[4] = {120, 120, 120, 120};
    const long level3[4] = {124, 124, 124, 124};
    check_differences(numbers, 5, 1, level1);
    check_differences(numbers, 5, 2, level2);
    check_differences(numbers, 5, 3, level3);
}

TEST_CASE("fig 6b: the inferred shuffle reproduces all three levels of differences") {
    IstAxis axis;
    REQUIRE(ist_connected_axis(ist_shuffle_fig6b(), 3, 15, IstEnds::cyclic, axis).ok());
    std::vector<long> numbers = numbers_on_last_axis(axis, 7);
    // 0.200 = 50, 0.100 = 25 | 0.420 = 110, 0.010 = 5 | 0.442 = 122, 0.001 = 1 (units 5^-3)
    const long level1[4] = {50, 25, 25, 50};
    const long level2[4] = {110, 5, 5, 110};
    const long level3[4] = {122, 1, 1, 122};
    check_differences(numbers, 5, 1, level1);
    check_differences(numbers, 5, 2, level2);
    check_differences(numbers, 5, 3, level3);
    // ... and fully-connected does not (the test can fail).
    IstAxis fully;
    REQUIRE(ist_fully_connected_axis(5, 3, 15, IstEnds::cyclic, fully).ok());
    std::vector<long> other = numbers_on_last_axis(fully, 7);
    CHECK(other[1] - other[0] != level1[0]);
}

TEST_CASE("real forms eqs. (9), (10), (14): offset kept, continuous inside, u = 1 rule") {
    for (int n : {2, 3, 5}) {
        IstAxis unit, fully;
        REQUIRE(ist_unit_axis(n, 3, unit).ok());
        if (n % 2 == 1) REQUIRE(ist_fully_connected_axis(n, 3, 4, IstEnds::cyclic, fully).ok());
        for (const IstAxis* axis : {&unit, &fully}) {
            if (axis == &fully && n % 2 == 0) continue;
            CAPTURE(describe(*axis));
            const double count = double(ist_sub_interval_count(*axis)) * axis->base_intervals;
            const double width = 1.0 / count;
            Pcg32 rng(31u, std::uint64_t(n));
            for (int s = 0; s < 500; ++s) {
                double u = rng.uniform_double();
                IstLocation where;
                ist_locate(*axis, u, &where);
                CHECK(std::fabs(ist_position(*axis, where) - u) < 1e-12);
                double v = ist_forward_double(*axis, u);
                IstLocation image;
                ist_locate(*axis, v, &image);
                IstDigits expected;
                ist_digits_forward(*axis, where.alpha, &expected);
                // u^K lies in the right sub-interval with the same offset Δu (eq. 10).
                CHECK(image.alpha.base == expected.base);
                CHECK(ist_digits_index(*axis, image.alpha) == ist_digits_index(*axis, expected));
                CHECK(std::fabs(image.offset - where.offset) < 1e-6);
                // Continuity inside the sub-interval: slope 1.
                double inside = (where.offset < 0.5 ? 0.25 : -0.25) * width;
                CHECK(std::fabs(ist_forward_double(*axis, u + inside) - (v + inside)) < 1e-12);
                // float version agrees to float precision.
                CHECK(std::fabs(double(ist_forward(*axis, float(u))) - v) < 4e-6);
            }
            // u = 1 belongs to the last sub-interval: its image's right end.
            IstDigits last, image;
            ist_digits_from_index(*axis, axis->base_intervals - 1,
                                  ist_sub_interval_count(*axis) - 1, &last);
            ist_digits_forward(*axis, last, &image);
            double expected_end = midpoint(*axis, image.base, ist_digits_index(*axis, image), 1.0);
            CHECK(ist_forward_double(*axis, 1.0) == doctest::Approx(expected_end).epsilon(1e-12));
            CHECK(ist_procedure_forward(*axis, 1.0) ==
                  doctest::Approx(expected_end).epsilon(1e-12));
            // u = 0: the first sub-interval, offset 0 ([u_a, u_b) holds u_a).
            IstDigits first, first_image;
            ist_digits_from_index(*axis, 0, 0, &first);
            ist_digits_forward(*axis, first, &first_image);
            CHECK(ist_forward_double(*axis, 0.0) ==
                  doctest::Approx(midpoint(*axis, first_image.base,
                                           ist_digits_index(*axis, first_image), 0.0)));
        }
    }
}

TEST_CASE("procedure with unequal base intervals (fig 6 draws base 6 wider) stays a bijection") {
    IstAxis axis;
    REQUIRE(ist_fully_connected_axis(5, 2, 5, IstEnds::translation, axis).ok());
    const double edges[6] = {0.0, 0.15, 0.3, 0.7, 0.85, 1.0};
    REQUIRE(ist_check_edges(axis, edges).ok());
    Pcg32 rng(5u, 5u);
    for (int s = 0; s < 2000; ++s) {
        double u = rng.uniform_double();
        double v = ist_procedure_forward(axis, u, edges);
        REQUIRE(v >= 0.0);
        REQUIRE(v <= 1.0);
        REQUIRE(std::fabs(ist_procedure_inverse(axis, v, edges) - u) < 1e-12);
        // The sub-interval keeps its base interval's digits: same digit map as equal widths.
        IstPoint p;
        ist_procedure_start(axis, edges, u, &p);
        int origin_base = p.base;
        for (int k = 1; k <= axis.iterations; ++k) {
            ist_divide_and_shuffle_internally(axis, edges, &p);
            ist_shuffle_externally(axis, edges, &p);
        }
        double rel0 = (u - edges[origin_base]) / (edges[origin_base + 1] - edges[origin_base]);
        double equal_u = (origin_base + rel0) / 5.0;
        double equal_v = ist_forward_double(axis, equal_u);
        int equal_base = int(equal_v * 5.0);
        if (equal_base > 4) equal_base = 4;
        CHECK(p.base == equal_base);
        double rel = (v - edges[p.base]) / (edges[p.base + 1] - edges[p.base]);
        CHECK(rel == doctest::Approx(equal_v * 5.0 - equal_base).epsilon(1e-9));
    }
    const double bad[6] = {0.0, 0.3, 0.2, 0.7, 0.85, 1.0};
    CHECK_FALSE(ist_check_edges(axis, bad).ok());
}

TEST_CASE("IST bad input: clear status, no crash") {
    IstAxis axis;
    Status s = ist_unit_axis(0, 2, axis);
    CHECK_FALSE(s.ok());
    CHECK(std::string(s.message()).find("N must be in [1, 32] (got 0)") != std::string::npos);
    s = ist_fully_connected_axis(4, 2, 5, IstEnds::cyclic, axis);
    CHECK_FALSE(s.ok());
    CHECK(std::string(s.message()).find("odd") != std::string::npos);
    s = ist_unit_axis(3, 36, axis);
    CHECK_FALSE(s.ok());
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::string(s.message()).find("K <= 33") != std::string::npos);
    CHECK(ist_unit_axis(3, 33, axis).ok());
    s = ist_unit_axis(3, 41, axis);
    CHECK_FALSE(s.ok());
    CHECK(ist_unit_axis(1, 40, axis).ok());   // N = 1: no transformation (fig 4a), any K
    s = ist_unit_axis(3, -1, axis);
    CHECK_FALSE(s.ok());
    s = ist_fully_connected_axis(3, 2, 0, IstEnds::cyclic, axis);
    CHECK_FALSE(s.ok());
    CHECK(std::string(s.message()).find("got 0") != std::string::npos);

    REQUIRE(ist_unit_axis(3, 2, axis).ok());
    float out = -1.0f;
    s = ist_forward_checked(axis, 1.5f, out);
    CHECK(s.code() == StatusCode::out_of_range);
    CHECK(std::string(s.message()).find("1.5") != std::string::npos);
    CHECK(out == -1.0f);
    CHECK_FALSE(ist_inverse_checked(axis, -0.25f, out).ok());
    CHECK_FALSE(ist_forward_checked(axis, std::nanf(""), out).ok());
    CHECK(ist_forward_checked(axis, 1.0f, out).ok());
    CHECK(out == 1.0f);
    // The unchecked forms clamp instead of failing.
    CHECK(ist_forward(axis, 7.0f) == 1.0f);
    CHECK(ist_forward(axis, std::nanf("")) == 0.0f);

    // Shuffle tables that are not bijections.
    IstShuffle table;
    const int offsets[3] = {-1, 0, 1};
    const int twice[3] = {2, 1, 2};
    s = ist_shuffle_from_table(3, offsets, twice, table);
    CHECK_FALSE(s.ok());
    CHECK(std::string(s.message()).find("slot 2 is filled twice") != std::string::npos);
    const int outside[3] = {2, 1, 3};
    CHECK_FALSE(ist_shuffle_from_table(3, offsets, outside, table).ok());
    const int even_offsets[2] = {0, 0}, even_slots[2] = {0, 1};
    CHECK_FALSE(ist_shuffle_from_table(2, even_offsets, even_slots, table).ok());
    // A permutation that is not an exchange: fine on a cyclic axis, refused on a translation one.
    const int shift[3] = {1, 1, 1}, same[3] = {0, 1, 2};
    REQUIRE(ist_shuffle_from_table(3, shift, same, table).ok());
    CHECK(ist_connected_axis(table, 2, 4, IstEnds::cyclic, axis).ok());
    s = ist_connected_axis(table, 2, 4, IstEnds::translation, axis);
    CHECK_FALSE(s.ok());
    CHECK(std::string(s.message()).find("exchange") != std::string::npos);
    // A hand-made axis is rechecked.
    IstAxis broken;
    broken.kind = IstKind::connected;
    broken.n = 3;
    broken.shuffle.n = 3;  // all slots 0
    CHECK_FALSE(ist_validate(broken).ok());
    CHECK_FALSE(ist_shuffle_named("fig6b", 3, table).ok());
    s = ist_shuffle_named("zigzag", 5, table);
    CHECK(std::string(s.message()).find("known: fully, none, fig6b") != std::string::npos);
    // Digit strings from users.
    REQUIRE(ist_unit_axis(3, 2, axis).ok());
    IstDigits d, e;
    d.count = 2;
    d.digit[1] = 3;
    CHECK_FALSE(ist_digits_forward_checked(axis, d, e).ok());
    d.digit[1] = 2;
    d.base = 1;
    CHECK_FALSE(ist_digits_forward_checked(axis, d, e).ok());
    d.base = 0;
    CHECK(ist_digits_forward_checked(axis, d, e).ok());
    // Formatting an unchecked string: no read past the digit table or the digit array, no
    // signed overflow of the label, truncation to the buffer.
    IstDigits wild;
    wild.base = 2147483000;
    wild.count = 1000;  // more than the kIstMaxIterations digits the array holds
    for (int i = 1; i <= kIstMaxIterations; ++i) wild.digit[i] = std::uint8_t(i == 2 ? 200 : 7);
    char text[128];
    const std::string printed = ist_digits_format(wild, 1000, text, sizeof text);
    CHECK(printed.substr(0, 13) == "2147484000.7?");
    CHECK(printed.size() == 11 + std::size_t(kIstMaxIterations));
    char tiny[4];
    CHECK(std::string(ist_digits_format(wild, 0, tiny, sizeof tiny)) == "214");
}

TEST_CASE("connected IST with an exchange table is an involution, on both kinds of axis") {
    // Noticed here, not stated in the paper: an exchange (slot an involution, offsets opposite
    // in each pair) makes D(D(alpha)) = alpha as eqs. (8) and (13), even with the skipped moves
    // at the ends of a translation axis.
    for (const char* name : {"fully", "none", "fig6b", "fig7a", "fig7c"}) {
        for (IstEnds ends : {IstEnds::cyclic, IstEnds::translation}) {
            for (int k = 1; k <= 4; ++k) {
                IstShuffle s;
                REQUIRE(ist_shuffle_named(name, 5, s).ok());
                IstAxis axis;
                REQUIRE(ist_connected_axis(s, k, 6, ends, axis).ok());
                CAPTURE(describe(axis));
                const std::uint64_t count = ist_sub_interval_count(axis);
                for (int b = 0; b < 6; ++b)
                    for (std::uint64_t i = 0; i < count; ++i) {
                        IstDigits a, f, ff;
                        ist_digits_from_index(axis, b, i, &a);
                        ist_digits_forward(axis, a, &f);
                        ist_digits_forward(axis, f, &ff);
                        REQUIRE(ff.base == b);
                        REQUIRE(ist_digits_index(axis, ff) == i);
                    }
            }
        }
    }
}

TEST_CASE("on a cyclic axis any table has a closed scale reverse form like eq. (12)") {
    // alpha^K_0 = alpha^0_0 + sum_k offset[alpha^0_k] (mod B), alpha^K_i = slot[alpha^0_{K-i+1}]:
    // the in-shf never touches the digits behind the k-th, so each digit meets the external
    // shuffle exactly once, as the first digit. The step algorithm must agree.
    IstShuffle shift;
    const int offsets[5] = {2, -1, 0, 1, 3}, slots[5] = {1, 3, 0, 4, 2};  // not an exchange
    REQUIRE(ist_shuffle_from_table(5, offsets, slots, shift).ok());
    for (int k = 1; k <= 4; ++k) {
        IstAxis axis;
        REQUIRE(ist_connected_axis(shift, k, 7, IstEnds::cyclic, axis).ok());
        const std::uint64_t count = ist_sub_interval_count(axis);
        for (int b = 0; b < 7; ++b)
            for (std::uint64_t i = 0; i < count; ++i) {
                IstDigits a, f;
                ist_digits_from_index(axis, b, i, &a);
                ist_digits_forward(axis, a, &f);
                int base = b;
                for (int j = 1; j <= k; ++j) base += offsets[a.digit[j]];
                base = ((base % 7) + 7) % 7;
                REQUIRE(f.base == base);
                for (int j = 1; j <= k; ++j) REQUIRE(f.digit[j] == slots[a.digit[k - j + 1]]);
            }
    }
}

TEST_CASE("procedure steps == digit steps at every u^k and u^{k.5} (eqs. 25, 26)") {
    for (int n : {3, 5}) {
        for (const char* name : {"fully", "none", "fig6b"}) {
            if (n != 5 && std::string(name) == "fig6b") continue;
            for (IstEnds ends : {IstEnds::cyclic, IstEnds::translation}) {
                IstShuffle s;
                REQUIRE(ist_shuffle_named(name, n, s).ok());
                IstAxis axis;
                REQUIRE(ist_connected_axis(s, 3, 5, ends, axis).ok());
                CAPTURE(describe(axis));
                const std::uint64_t count = ist_sub_interval_count(axis);
                for (int b = 0; b < 5; ++b)
                    for (std::uint64_t i = 0; i < count; ++i) {
                        IstDigits alpha;
                        ist_digits_from_index(axis, b, i, &alpha);
                        IstPoint p;
                        ist_procedure_start(axis, nullptr, midpoint(axis, b, i), &p);
                        for (int k = 1; k <= 3; ++k) {
                            ist_internal_shuffle(axis, k, &alpha);  // -> u^{(k-1).5}
                            ist_divide_and_shuffle_internally(axis, nullptr, &p);
                            REQUIRE(p.u == doctest::Approx(midpoint(
                                               axis, alpha.base, ist_digits_index(axis, alpha))));
                            ist_external_shuffle(axis, &alpha);  // -> u^k
                            ist_shuffle_externally(axis, nullptr, &p);
                            REQUIRE(p.u == doctest::Approx(midpoint(
                                               axis, alpha.base, ist_digits_index(axis, alpha))));
                            REQUIRE(p.base == alpha.base);
                        }
                    }
            }
        }
    }
}

// Regression: inverse(forward(u)) missed u by up to the whole axis on about 25 % of the
// sub-interval left ends (u = 0 included): split() floored u B N^K, which rounds just below
// an integer at many left ends, so the inverse read the neighbouring sub-interval.
TEST_CASE("IST round trip is exact on every sub-interval left end (a regression)") {
    long checked = 0;
    for (int n = 1; n <= 7; ++n)
        for (int k = 0; k <= 6; ++k)
            for (int b = 1; b <= 6; ++b)
                for (int kind = 0; kind < 3; ++kind)
                    for (IstEnds ends : {IstEnds::cyclic, IstEnds::translation}) {
                        IstAxis axis;
                        Status s;
                        if (kind == 0) {
                            if (ends == IstEnds::translation) continue;
                            s = ist_unit_axis(n, k, b, axis);
                        } else if (kind == 1) {
                            s = ist_fully_connected_axis(n, k, b, ends, axis);
                        } else {
                            IstShuffle sh;
                            if (!ist_shuffle_named("fig7c", n, sh)) continue;
                            s = ist_connected_axis(sh, k, b, ends, axis);
                        }
                        if (!s) continue;
                        const std::uint64_t count = ist_sub_interval_count(axis);
                        if (count * std::uint64_t(b) > 4000) continue;
                        for (int base = 0; base < b; ++base)
                            for (std::uint64_t i = 0; i < count; ++i) {
                                IstLocation at;
                                ist_digits_from_index(axis, base, i, &at.alpha);
                                const double u = ist_position(axis, at);  // a left end
                                const double v = ist_forward_double(axis, u);
                                REQUIRE(ist_inverse_double(axis, v) == u);
                                REQUIRE(ist_forward_double(axis, ist_inverse_double(axis, u)) ==
                                        u);
                                REQUIRE(v < 1.0);
                                // float: no jump to another sub-interval (float(u) may lie
                                // an ulp left of the float left end: a few ulps allowed)
                                const float uf = float(u);
                                CHECK(std::fabs(ist_inverse(axis, ist_forward(axis, uf)) - uf) <=
                                      4e-7f);
                                ++checked;
                            }
                    }
    CHECK(checked > 100000);
    IstAxis axis;  // u = 0, the first left end, on the case the probe reported
    REQUIRE(ist_fully_connected_axis(3, 2, 1, IstEnds::cyclic, axis).ok());
    CHECK(ist_inverse_double(axis, ist_forward_double(axis, 0.0)) == 0.0);
}

TEST_CASE("IST interior points: forward stays in the image sub-interval, round trip to ulps") {
    IstAxis axis;
    REQUIRE(ist_fully_connected_axis(5, 4, 7, IstEnds::cyclic, axis).ok());
    std::uint32_t x = 12345;
    for (int r = 0; r < 20000; ++r) {
        x = x * 1664525u + 1013904223u;
        const double u = double(x) / 4294967296.0;
        const double v = ist_forward_double(axis, u);
        REQUIRE((v >= 0.0 && v < 1.0));
        REQUIRE(std::fabs(ist_inverse_double(axis, v) - u) < 1e-12);
    }
}

// fuzz_ist finding: with B N^K beyond double's 2^53 (N = 3, K = 33, B = 4) the last left
// ends rounded up to 1, so forward() returned 1 for u < 1. Points below 1 now stay below 1.
TEST_CASE("IST beyond double resolution: values below 1 stay below 1 (fuzz_ist regression)") {
    IstAxis axis;
    REQUIRE(ist_fully_connected_axis(3, 33, 4, IstEnds::cyclic, axis).ok());
    for (double u : {0.0, 0.25, 0.5, 0.75, 0.999999, 1.0 - 1e-16}) {
        const double v = ist_forward_double(axis, u), w = ist_inverse_double(axis, u);
        CHECK(v >= 0.0);
        CHECK(v < 1.0);
        CHECK(w < 1.0);
    }
    CHECK(ist_forward_double(axis, 1.0) <= 1.0);
}

// The procedure equals the formula at the ends of sub-intervals too (fujimoto2000 §2.3.1: a
// sub-interval with ends u_a, u_b holds u_a <= u < u_b, u = 1 the last one). Every axis with
// N <= 9, K <= 8, B <= 9 (unit for every N; fully connected for odd N, cyclic and translation
// ends), at u in {0, 1/4, 1/3, 1/2, 1} and at the left end of every sub-interval (a spread of
// them where B N^K is large). Both directions: procedure forward == formula forward, procedure
// inverse == formula inverse, and the procedure's inverse undoes the formula's forward.
// (The rounding of the procedure's slot and part boundaries put a point lying on a boundary
// into the part before it: N = 3, K = 1, B = 2 cyclic fully connected sent 0 to 5/6 and 5/6
// back to 5/6.)
TEST_CASE("IST procedure == formula at every grid point, sub-interval ends included") {
    long checked = 0, wrong = 0;
    std::string first_wrong;
    auto check = [&](const IstAxis& axis, double u, double tolerance) {
        const double v = ist_forward_double(axis, u);
        const double pf = ist_procedure_forward(axis, u);
        const double pi = ist_procedure_inverse(axis, v);
        const double pi_u = ist_procedure_inverse(axis, u);
        const double fi_u = ist_inverse_double(axis, u);
        ++checked;
        // u = 1 maps to the right end of an image, which is the left end of another when that
        // image is not the last: the round trip is asked of u < 1 only.
        const bool round_trip = u == 1.0 || std::fabs(pi - u) <= tolerance;
        if (std::fabs(pf - v) <= tolerance && round_trip && std::fabs(pi_u - fi_u) <= tolerance)
            return;
        if (wrong++ == 0) {
            char text[400];
            std::snprintf(text, sizeof text,
                          " u=%.17g: formula F(u)=%.17g procedure F(u)=%.17g, procedure "
                          "F^-1(F(u))=%.17g, F^-1(u): formula %.17g procedure %.17g",
                          u, v, pf, pi, fi_u, pi_u);
            first_wrong = describe(axis) + text;
        }
    };
    for (int n = 1; n <= 9; ++n)
        for (int k = 0; k <= 8; ++k)
            for (int b = 1; b <= 9; ++b) {
                std::vector<IstAxis> axes;
                IstAxis a;
                REQUIRE(ist_unit_axis(n, k, b, a).ok());
                axes.push_back(a);
                if (n % 2 == 1)
                    for (IstEnds ends : {IstEnds::cyclic, IstEnds::translation}) {
                        REQUIRE(ist_fully_connected_axis(n, k, b, ends, a).ok());
                        axes.push_back(a);
                    }
                for (const IstAxis& axis : axes) {
                    const std::uint64_t count = ist_sub_interval_count(axis);
                    const double total = double(count) * double(b);
                    // A hundredth of the smallest sub-interval: a point sent to the wrong
                    // sub-interval misses by more.
                    const double tolerance = 0.01 / total;
                    // 1/3 is no double: where it is an end of the grid, the grid point is the
                    // end as eq. (9) computes it (Δ = 0), not the double nearest 1/3, which lies
                    // 2e-17 below the end and so, exactly read, in the sub-interval before it.
                    for (double u : {0.0, 0.25, 1.0 / 3.0, 0.5, 1.0}) {
                        const double at = std::floor(u * total + 0.5);
                        if (u < 1.0 && std::fabs(at - u * total) < 1e-6)
                            u = midpoint(axis, int(at / double(count)),
                                         std::uint64_t(at) % count, 0.0);
                        check(axis, u, tolerance);
                    }
                    const std::uint64_t stride = count <= 729 ? 1 : count / 97 + 1;
                    for (int base = 0; base < b; ++base)
                        for (std::uint64_t i = 0; i < count; i += stride) {
                            check(axis, midpoint(axis, base, i, 0.0), tolerance);
                            if (i + 1 < count && stride > 1)  // both sides of a strided end
                                check(axis, midpoint(axis, base, i + 1, 0.0), tolerance);
                        }
                }
            }
    INFO(first_wrong);
    INFO("checked ", checked, " points, wrong ", wrong);
    CHECK(wrong == 0);
    CHECK(checked > 100000);
}
