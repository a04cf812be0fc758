// shitsukan/wrinkly/wr_ist_axis.hpp — plugs an IST (ist_axis.hpp, ist_formula.hpp) into a WR
// surface axis: WrAxis::inverse_at(s, k) = (F^k)^{-1}(s) for every step k = 0..max_level,
// which eq. (15) (k = K) and eqs. (16), (20) (all k) need.
//
// Manual
//   WrControlMesh mesh = make_control_mesh(8, 8);          // control_mesh.hpp
//   for (int r = 0; r < 8; ++r)
//       for (int c = 0; c < 8; ++c)
//           mesh.at(c, r).position = {c / 7.0f, r / 7.0f, 0.0f}, mesh.at(c, r).height = 0.05f;
//   WrSurface surface;
//   Status s = make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface);
//   if (!s) return s;
//   IstAxis ist;
//   s = ist_fully_connected_axis(3, 4, surface.spans_u(), IstEnds::translation, ist);   // K unused
//   WrIstAxis au, av;
//   if (s) s = make_wr_ist_axis(ist, 6, au);    // F^0 .. F^6
//   if (s) s = make_wr_ist_axis(ist, 6, av);
//   if (s) s = surface.set_axes(au.axis(), av.axis());
//   return s;
//   #include "shitsukan/wrinkly/wr_surface.hpp"
// The WrAxis returned by axis() points at this object: keep the WrIstAxis alive and in place
// (do not move or copy it) while the surface uses it.
// IST-Bezier (§3.2): ist_unit_axis(N, K, ist) (one base interval). IST-B-spline: a connected
// or fully-connected IST with one base interval per knot span, translation ends (the surface
// is open, fig. 9).
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/wrinkly/ist_axis.hpp"
#include "shitsukan/wrinkly/wr_axis.hpp"

namespace shitsukan {

class WrIstAxis {
public:
    WrIstAxis() = default;
    WrIstAxis(const WrIstAxis&) = delete;
    WrIstAxis& operator=(const WrIstAxis&) = delete;

    WrAxis axis() const;
    int max_level() const { return int(steps_.size()) - 1; }
    const IstAxis& step(int k) const { return steps_[std::size_t(k)]; }

private:
    friend Status make_wr_ist_axis(const IstAxis& ist, int max_level, WrIstAxis& out);
    static float inverse(const void* self, float s, int k);
    std::vector<IstAxis> steps_;  // steps_[k] = the IST with K = k
};

Status make_wr_ist_axis(const IstAxis& ist, int max_level, WrIstAxis& out);

}  // namespace shitsukan
