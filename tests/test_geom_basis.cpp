// Tests for lib/shitsukan/geom/basis: partition of unity, known values, derivatives.
#include <doctest/doctest.h>

#include <cmath>

#include "shitsukan/geom/basis.hpp"

using namespace shitsukan;

TEST_CASE("Bernstein and B-spline bases sum to 1 and derivatives match finite differences") {
    for (int n = 0; n <= kMaxBasisDegree; ++n) {
        for (int s = 0; s <= 20; ++s) {
            double t = s / 20.0, b[8], db[8], bp[8], bm[8];
            const double h = 1e-6;
            bernstein_basis(n, t, b, db);
            double sum = 0;
            for (int i = 0; i <= n; ++i) sum += b[i];
            CHECK(sum == doctest::Approx(1.0).epsilon(1e-12));
            bernstein_basis(n, t + h, bp);
            bernstein_basis(n, t - h, bm);
            for (int i = 0; i <= n; ++i)
                CHECK(db[i] == doctest::Approx((bp[i] - bm[i]) / (2 * h)).epsilon(1e-5));
            bspline_basis(n, t, b, db);
            sum = 0;
            for (int i = 0; i <= n; ++i) {
                CHECK(b[i] >= 0.0);
                sum += b[i];
            }
            CHECK(sum == doctest::Approx(1.0).epsilon(1e-12));
            bspline_basis(n, t + h, bp);
            bspline_basis(n, t - h, bm);
            for (int i = 0; i <= n; ++i)
                CHECK(db[i] == doctest::Approx((bp[i] - bm[i]) / (2 * h)).epsilon(1e-5));
        }
    }
}

TEST_CASE("known values: cubic B-spline (1, 4, 1)/6 at a knot, Bernstein endpoints") {
    float b[8];
    bspline_basis(3, 0.0f, b);
    CHECK(b[0] == doctest::Approx(1.0f / 6));
    CHECK(b[1] == doctest::Approx(4.0f / 6));
    CHECK(b[2] == doctest::Approx(1.0f / 6));
    CHECK(b[3] == doctest::Approx(0.0f));
    bernstein_basis(3, 1.0f, b);
    CHECK(b[3] == 1.0f);
    CHECK(b[0] == 0.0f);
    // C2 continuity across spans: the span's end weights equal the next span's start weights.
    double e[8], s[8], de[8], ds[8];
    bspline_basis(3, 1.0, e, de);
    bspline_basis(3, 0.0, s, ds);
    for (int i = 0; i < 3; ++i) {
        CHECK(e[i + 1] == doctest::Approx(s[i]));
        CHECK(de[i + 1] == doctest::Approx(ds[i]));
    }
}
