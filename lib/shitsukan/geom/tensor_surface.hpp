// shitsukan/geom/tensor_surface.hpp — degree-n Bezier and uniform B-spline tensor-product
// surfaces over a grid of control values with any number of channels.
//
// Manual
//   // 4 x 4 control points, 3 channels (x, y, z), row-major: values[(row·cols + col)·3 + c]
//   float values[4 * 4 * 3];
//   for (int row = 0; row < 4; ++row)
//       for (int col = 0; col < 4; ++col) {
//           float* v = values + (row * 4 + col) * 3;
//           v[0] = float(col), v[1] = float(row), v[2] = float((row * col) % 3);
//       }
//   TensorGrid g{values, 4, 4, 3};
//   if (Status s = validate_tensor_grid(SurfaceBasis::bezier, 3, g); !s) return s;
//   float u = 0.5f, v = 0.25f;
//   float p[3], pu[3], pv[3];
//   evaluate_tensor_surface(SurfaceBasis::bezier, 3, g, u, v, p, pu, pv);  // u, v in [0, 1]
//
// The same call interpolates positions (3 channels), heights (1), colours (3), transparency
// (1) or any other per-control-point attribute: fujimoto2000 §3.1 step 1) ("continuous
// interpolation") applies one interpolation to all of them.
//   bezier:  cols = rows = degree + 1; one patch, S(u,v) = sum_ij B_i,n(u) B_j,n(v) P_ij.
//   bspline: cols, rows >= degree + 1; uniform knots, span_count = cols - degree spans along u
//            (rows - degree along v). The global parameter u in [0, 1] is mapped to
//            s = u·span_count; span = floor(s) (the last span owns s = span_count), t = s - span.
// Derivatives pu, pv (optional, nullptr to skip) are with respect to the global u and v.
// Degrees 1..kMaxBasisDegree. Parameters outside [0, 1] are clamped (NaN counts as 0).
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/basis.hpp"

namespace shitsukan {

enum class SurfaceBasis : std::uint8_t { bezier, bspline };

const char* surface_basis_name(SurfaceBasis basis);

struct TensorGrid {
    const float* values = nullptr;  // (row·cols + col)·channels + channel
    int cols = 0;                   // control points along u
    int rows = 0;                   // control points along v
    int channels = 0;
};

constexpr int kMaxTensorChannels = 16;

// Number of parameter spans (knot spans) along an axis with `points` control points.
int tensor_span_count(SurfaceBasis basis, int degree, int points);

// Degree in 1..kMaxBasisDegree, grid sizes fitting the basis, 1..kMaxTensorChannels channels,
// finite values.
Status validate_tensor_grid(SurfaceBasis basis, int degree, const TensorGrid& grid);

// Which span an axis parameter falls in and the local parameter there (s = u·spans).
void tensor_locate(int spans, float u, int* span, float* t);

// One axis parameter located in its knot span, with the basis functions there and their
// derivatives: the part of an evaluation that depends on that parameter alone. A grid of
// evaluations locates each column and row once (wrinkly/wr_tessellation.cpp) instead of once
// per point; evaluate_tensor_surface is exactly locate u, locate v, evaluate_tensor_located.
struct TensorBasisAt {
    int span = 0;        // first control point index of the span
    float scale = 1.0f;  // d(local t)/d(global parameter): 1 (Bezier) or the span count
    float b[kMaxBasisDegree + 1] = {};
    float db[kMaxBasisDegree + 1] = {};
};
TensorBasisAt locate_tensor_basis(SurfaceBasis basis, int degree, int points, float x);
void evaluate_tensor_located(int degree, const TensorGrid& grid, const TensorBasisAt& bu,
                             const TensorBasisAt& bv, float* out, float* du = nullptr,
                             float* dv = nullptr);

void evaluate_tensor_surface(SurfaceBasis basis, int degree, const TensorGrid& grid, float u,
                             float v, float* out, float* du = nullptr, float* dv = nullptr);

}  // namespace shitsukan
