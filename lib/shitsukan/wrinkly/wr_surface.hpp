// shitsukan/wrinkly/wr_surface.hpp — the wrinkly (WR) surface of fujimoto2000 §3, eq. (15):
//
//   R(u, v) = P(u, v) + H(F_U^{-1}(u), F_V^{-1}(v)) · N(u, v)
//
// P is the base surface interpolating the positions x_i, H the height function interpolating
// h_i with the same basis (§3.1 step 1), F_U, F_V the ISTs on the two parameter axes (step 2)
// and N the unit normal of P (step 3: displacement mapping). With a Bezier base and a unit-IST
// this is the "IST-Bezier surface", with a uniform B-spline base whose knot spans are the
// connected IST's base intervals the "IST-B-spline surface" (§3.2). Colour, transparency and
// (figs. 22-23) a displacement vector h_i·d_i are carried through the IST the same way.
//
// Manual
//   WrControlMesh mesh = make_control_mesh(8, 8);     // control_mesh.hpp
//   for (int r = 0; r < 8; ++r)
//       for (int c = 0; c < 8; ++c)
//           mesh.at(c, r).position = {c / 7.0f, r / 7.0f, 0.0f}, mesh.at(c, r).height = 0.05f;
//   WrSurface s;
//   Status st = make_wr_surface(mesh, SurfaceBasis::bspline, 3, s);
//   WrAxis axis_u = identity_axis(s.spans_u()), axis_v = identity_axis(s.spans_v());
//   if (st) st = s.set_axes(axis_u, axis_v);  // WrAxis (wr_axis.hpp); default: identity
//   if (!st) return st;
//   float u = 0.3f, v = 0.6f;  int K = 2;
//   BasePoint b = s.base_point(u, v);    // P, N, dP/du, dP/dv, delta(u, v)
//   WrAttributes a = s.attributes(u, v); // H(u, v), colour, transparency, displacement vector
//   WrAttributes w = s.wr_attributes(u, v, K);  // the same at ((F_U^K)^-1(u), (F_V^K)^-1(v))
//   Vec3 r = s.wr_point(u, v, K);        // eq. (15)
// u, v in [0, 1] over the whole surface (clamped; NaN counts as 0). K in 0..s.max_level() (0 =
// plain surface; the axes' max_level: kMaxWrLevel for identity axes, what make_wr_ist_axis was
// given for ISTs).
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/basis.hpp"
#include "shitsukan/geom/tensor_surface.hpp"
#include "shitsukan/wrinkly/control_mesh.hpp"
#include "shitsukan/wrinkly/wr_axis.hpp"

namespace shitsukan {

// Where the height goes (§5: figs. 22 and 23 displace "in arbitrary directions").
enum class DisplacementMode : unsigned char {
    normal,     // eq. (15): H · N(u, v)
    direction,  // the interpolated vector sum_i B_i (h_i · d_i), d_i = WrControlPoint::direction
};

struct BasePoint {
    Vec3 position;  // P(u, v)
    Vec3 normal;    // N(u, v), unit
    Vec3 du, dv;    // dP/du, dP/dv
    float delta;    // the ratio function delta(u, v) of eq. (19), continuous interpolation
};

// Everything the IST carries from the control points (what §4 superposes and samples).
struct WrAttributes {
    float height = 0;        // H
    Vec3 color{1, 1, 1};     // C
    float transparency = 0;  // T
    Vec3 vector{0, 0, 0};    // sum_i B_i h_i d_i (used in DisplacementMode::direction)
};

constexpr int kWrAttributeChannels = 8;  // height, r, g, b, transparency, vx, vy, vz

// The attributes as the 8 interpolated channels, in the order above, and back.
void attributes_to_channels(const WrAttributes& a, float* channels);
WrAttributes attributes_from_channels(const float* channels);

// One surface parameter (u or v) located in its knot span with its basis functions
// (geom/tensor_surface.hpp): computed once per grid column and row by wr_tessellation.cpp.
using WrBasisAt = TensorBasisAt;

class WrSurface {
public:
    SurfaceBasis basis() const { return basis_; }
    int degree() const { return degree_; }
    int spans_u() const { return spans_u_; }
    int spans_v() const { return spans_v_; }
    const WrAxis& axis_u() const { return axis_u_; }
    const WrAxis& axis_v() const { return axis_v_; }
    DisplacementMode displacement() const { return mode_; }
    void set_displacement(DisplacementMode mode) { mode_ = mode; }
    float max_abs_height() const { return max_abs_height_; }  // max_i |h_i|: bounds |H|
    // Deepest IST step k both axes can evaluate: the k of wr_point, wr_attributes, inverse_u/v
    // must be in 0..max_level() (sample_hierarchy and tessellate_wr_surface check it).
    int max_level() const {
        return axis_u_.max_level < axis_v_.max_level ? axis_u_.max_level : axis_v_.max_level;
    }

    // The axes' base intervals must equal the knot spans (1 for Bezier), §3.2.
    Status set_axes(const WrAxis& u, const WrAxis& v);

    BasePoint base_point(float u, float v) const;
    WrAttributes attributes(float u, float v) const;
    // The same with the bases located once (basis_u(u), basis_v(v)); base_point needs u and v
    // too, for a collapsed edge's normal. Same bits as base_point(u, v) and attributes(u, v).
    WrBasisAt basis_u(float u) const;
    WrBasisAt basis_v(float v) const;
    BasePoint base_point(const WrBasisAt& bu, const WrBasisAt& bv, float u, float v) const;
    WrAttributes attributes(const WrBasisAt& bu, const WrBasisAt& bv) const;
    // Attributes at ((F_U^k)^{-1}(u), (F_V^k)^{-1}(v)): the IST-transformed functions.
    WrAttributes wr_attributes(float u, float v, int k) const;
    // (F^k)^{-1} in the surface parameter [0, 1] (axis coordinates scaled by the span count).
    float inverse_u(float u, int k) const;
    float inverse_v(float v, int k) const;
    // Adds a displacement of `a` (height or vector, by mode) to the base point.
    Vec3 displace(const BasePoint& b, const WrAttributes& a) const;
    Vec3 wr_point(float u, float v, int k) const;  // eq. (15) with K = k

private:
    friend Status make_wr_surface(const WrControlMesh&, SurfaceBasis, int, WrSurface&);
    SurfaceBasis basis_ = SurfaceBasis::bspline;
    int degree_ = 3;
    int cols_ = 0, rows_ = 0, spans_u_ = 1, spans_v_ = 1;
    WrAxis axis_u_, axis_v_;
    DisplacementMode mode_ = DisplacementMode::normal;
    float max_abs_height_ = 0;
    std::vector<float> geometry_;    // x, y, z, delta per control point
    std::vector<float> attributes_;  // kWrAttributeChannels per control point
};

Status make_wr_surface(const WrControlMesh& mesh, SurfaceBasis basis, int degree, WrSurface& out);

}  // namespace shitsukan
