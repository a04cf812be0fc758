// Tests for lib/shitsukan/geom/tensor_surface: Bezier and uniform B-spline tensor surfaces.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "shitsukan/geom/tensor_surface.hpp"

using namespace shitsukan;

namespace {
std::vector<float> wavy_grid(int cols, int rows) {
    std::vector<float> g;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            g.insert(g.end(),
                     {float(c), float(r), std::sin(0.9f * float(c)) * std::cos(0.7f * float(r))});
    return g;
}
}  // namespace

TEST_CASE("Bezier patch interpolates its corner control points") {
    std::vector<float> g = wavy_grid(4, 4);
    TensorGrid grid{g.data(), 4, 4, 3};
    REQUIRE(validate_tensor_grid(SurfaceBasis::bezier, 3, grid));
    float p[3];
    evaluate_tensor_surface(SurfaceBasis::bezier, 3, grid, 0, 0, p);
    CHECK(p[2] == doctest::Approx(g[2]).epsilon(1e-6));
    evaluate_tensor_surface(SurfaceBasis::bezier, 3, grid, 1, 1, p);
    CHECK(p[2] == doctest::Approx(g[(3 * 4 + 3) * 3 + 2]).epsilon(1e-6));
}

TEST_CASE("B-spline surface reproduces a linear function and its derivatives") {
    // x = col and y = row are linear in the control index: a uniform B-spline reproduces them
    // with x(u) = (degree - 1)/2 + spans·u, so dx/du = span count (tolerance 1e-4).
    std::vector<float> g = wavy_grid(8, 6);
    TensorGrid grid{g.data(), 8, 6, 3};
    REQUIRE(validate_tensor_grid(SurfaceBasis::bspline, 3, grid));
    for (float u : {0.0f, 0.13f, 0.5f, 0.77f, 1.0f}) {
        float p[3], pu[3], pv[3];
        evaluate_tensor_surface(SurfaceBasis::bspline, 3, grid, u, 0.4f, p, pu, pv);
        CHECK(p[0] == doctest::Approx(1.0f + u * 5.0f).epsilon(1e-4));
        CHECK(pu[0] == doctest::Approx(5.0f).epsilon(1e-4));
        CHECK(pv[1] == doctest::Approx(3.0f).epsilon(1e-4));
        // z derivative against central differences
        if (u > 0.01f && u < 0.99f) {
            float a[3], b[3];
            const float h = 1e-3f;
            evaluate_tensor_surface(SurfaceBasis::bspline, 3, grid, u + h, 0.4f, a);
            evaluate_tensor_surface(SurfaceBasis::bspline, 3, grid, u - h, 0.4f, b);
            CHECK(pu[2] == doctest::Approx((a[2] - b[2]) / (2 * h)).epsilon(2e-2));
        }
    }
}

TEST_CASE("tensor grid validation rejects bad sizes and NaN") {
    std::vector<float> g = wavy_grid(4, 4);
    CHECK(!validate_tensor_grid(SurfaceBasis::bezier, 3, TensorGrid{g.data(), 4, 3, 3}));
    CHECK(!validate_tensor_grid(SurfaceBasis::bspline, 4, TensorGrid{g.data(), 4, 4, 3}));
    CHECK(!validate_tensor_grid(SurfaceBasis::bspline, 0, TensorGrid{g.data(), 4, 4, 3}));
    g[5] = std::nanf("");
    Status s = validate_tensor_grid(SurfaceBasis::bspline, 3, TensorGrid{g.data(), 4, 4, 3});
    CHECK(!s);
    CHECK(s.code() == StatusCode::invalid_argument);
}

TEST_CASE("parameters outside [0, 1] are clamped and NaN counts as 0 (no span index from NaN)") {
    std::vector<float> g = wavy_grid(7, 5);
    const TensorGrid bs{g.data(), 7, 5, 3};
    std::vector<float> gb = wavy_grid(4, 4);
    const TensorGrid bz{gb.data(), 4, 4, 3};
    for (SurfaceBasis basis : {SurfaceBasis::bspline, SurfaceBasis::bezier}) {
        const TensorGrid& grid = basis == SurfaceBasis::bspline ? bs : bz;
        float a[3], b[3];
        evaluate_tensor_surface(basis, 3, grid, std::nanf(""), 0.4f, a);
        evaluate_tensor_surface(basis, 3, grid, 0.0f, 0.4f, b);
        for (int c = 0; c < 3; ++c) CHECK(a[c] == b[c]);
        evaluate_tensor_surface(basis, 3, grid, 5.0f, -INFINITY, a);
        evaluate_tensor_surface(basis, 3, grid, 1.0f, 0.0f, b);
        for (int c = 0; c < 3; ++c) CHECK(a[c] == b[c]);
    }
    int span = -1;
    float t = -1;
    tensor_locate(4, std::nanf(""), &span, &t);
    CHECK(span == 0);
    CHECK(t == 0.0f);
}
