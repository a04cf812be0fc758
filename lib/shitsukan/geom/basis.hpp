// shitsukan/geom/basis.hpp — Bernstein and uniform B-spline basis functions, any degree.
//
// Manual
//   float t = 0.25f;
//   float b[kMaxBasisDegree + 1], db[kMaxBasisDegree + 1];
//   bernstein_basis(3, t, b, db);        // B_{i,3}(t), i = 0..3, and dB/dt; t in [0, 1]
//   bspline_basis(3, t, b, db);          // uniform B-spline of degree 3 on one knot span:
//                                        // the weights of the n + 1 control points that
//                                        // influence the span, local t in [0, 1]
// Degrees 0..kMaxBasisDegree (7). db may be nullptr. Programmer bugs (degree out of range)
// assert; callers validate user degrees first.
//   Bezier curve of degree n:  C(t) = sum_i B_{i,n}(t) P_i          (tokai1994 eq. 2)
//   Bezier patch:              S(u,v) = sum_i sum_j B_{i,n}(u) B_{j,n}(v) P_ij  (tokai1994 eq. 5)
//   Uniform B-spline span s:   C(t) = sum_{i=0..n} N_i(t) P_{s+i}
#pragma once

namespace shitsukan {

constexpr int kMaxBasisDegree = 7;

// B_{i,n}(t) = C(n,i) t^i (1-t)^(n-i); derivative n(B_{i-1,n-1} - B_{i,n-1}).
void bernstein_basis(int degree, float t, float* b, float* db = nullptr);
void bernstein_basis(int degree, double t, double* b, double* db = nullptr);

// Uniform B-spline blending functions on one span (Cox-de Boor on knots ..., -1, 0, 1, 2, ...).
void bspline_basis(int degree, float t, float* b, float* db = nullptr);
void bspline_basis(int degree, double t, double* b, double* db = nullptr);

}  // namespace shitsukan
