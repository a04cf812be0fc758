// shitsukan/solid/wood.hpp — okada1987 §4.2 wood: a radial sine (eq. (10)) displaced along
// the radius by the turbulence (eq. (11); okada1989 eqs. (10), (11)).
//
// Manual
//   FractalLattice store;                                // lattice_store.hpp
//   Status s = store.build(FractalParams{});
//   if (!s) return s;
//   LatticeView lattice = store.view();
//   Vec3 p{30.0f, 12.0f, 40.0f};
//   WoodParams w;  w.x0 = 10; w.y0 = 20; w.k2 = 1.0f; w.k = 1.6f;   // k = 1.6 (okada1987)
//   s = validate_wood(w);
//   float g  = wood_original(p, w);                    // sin(k2·r), in [-1, 1]
//   float gp = wood_texture(p, turbulence(lattice, p), w);  // G(P + k·D(P)·u_radial)
//   float t  = wood_unit_range(gp);                    // [0, 1] for lookup_color (eq. (12))
//   Vec3 u;
//   if (s) s = wood_radial_direction(p, w, u);         // degenerate on the axis (r = 0)
//   return s;
//   #include "shitsukan/solid/lattice_store.hpp"
//   #include "shitsukan/solid/turbulence.hpp"
//
// The axis of the tree is the line x = x0, y = y0 (parallel to z); r is the distance from
// it and k2 sets the ring spacing 2·pi/k2. Units are those of P (lattice units in the
// figures). On the axis (r = 0) the radial direction is undefined: u = (0, 0, 0) is used
// there (chosen here: the point is not displaced; G = sin(0) = 0 is the limit of the rings
// shrinking to the axis), and wood_radial_direction() reports it with a degenerate status.
// sin range: G lies in [-1, 1] but eq. (12) interpolates with G' in [0, 1]; chosen here:
// G' = (G + 1)/2, a linear map that keeps the sine's shape (G' = 1 at the ring crest,
// I_max, 0 in the trough, I_min), so each period 2·pi/k2 holds one light and one dark band.
// sin: std::sin on float (correctly rounded in glibc; other libms may differ in the last bit).
// small-device: yes (no allocation)
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct WoodParams {
    float x0 = 0.0f, y0 = 0.0f;  // the axis (okada1987: "木目中心")
    float k2 = 1.0f;             // ring frequency: rings every 2·pi/k2
    float k = 1.6f;              // contribution of the turbulence (okada1987: 1.6)
};

// okada1987 eq. (10): G(P) = sin(k2·r), r = sqrt((x - x0)^2 + (y - y0)^2).
float wood_original(Vec3 p, const WoodParams& params);
// okada1987 eq. (11): u = ((x - x0)/r, (y - y0)/r, 0); degenerate status and u = 0 at r = 0.
Status wood_radial_direction(Vec3 p, const WoodParams& params, Vec3& u);
// The wood texture at P: G(P + k·D(P)·u) (okada1989 eq. (7) with u of eq. (11)).
float wood_texture(Vec3 p, float d, const WoodParams& params);
// [-1, 1] -> [0, 1]: (G + 1)/2 (chosen here, see above).
inline float wood_unit_range(float g) { return (g + 1.0f) * 0.5f; }

Status validate_wood(const WoodParams& params);

}  // namespace shitsukan
