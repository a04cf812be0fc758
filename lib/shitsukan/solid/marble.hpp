// shitsukan/solid/marble.hpp — okada1987 §4.1 marble: layers as trapezoids with exponential
// skirts (eq. (8)), displaced along z by the turbulence (eq. (9)).
//
// Manual
//   FractalLattice lattice;                              // lattice_store.hpp
//   Status s = lattice.build(FractalParams{});
//   if (!s) return s;
//   Vec3 p{32.0f, 30.0f, 21.5f};                          // a point in lattice units
//   const MarbleStripe stripes[] = {{20.0f, 3.0f, 0.8f}, {44.0f, 1.5f, 1.2f}};  // c, w, alpha
//   MarbleParams m{stripes, 2, 16.0f};                   // k = 16 (okada1987 §4.4)
//   s = validate_marble(m);
//   float g  = marble_original(p.z, stripes, 2);         // G(P), eq. (8)
//   float gp = marble_texture(p, turbulence(lattice.view(), p), m);  // G(P + k·D(P)·(0,0,1))
//   float density = marble_density(p, turbulence(lattice.view(), p), m);  // 1 - min(gp, 1)
//   return s;
//   #include "shitsukan/solid/lattice_store.hpp"
//   #include "shitsukan/solid/turbulence.hpp"
//
// Units: the same as P (lattice units in the figures). One stripe j: centre c_j (z of the
// layer's middle), width w_j > 0 of the flat top, decay alpha_j > 0 of the skirt:
//   d_j = |z - c_j| - w_j/2 (distance from the stripe's edge),
//   g_j = 1 inside (d_j <= 0), e^{-alpha_j·d_j} outside.
// okada1989 eq. (8) is the single-stripe case (count = 1). G can exceed 1 where skirts of
// two stripes overlap; lookup_color() clamps G' to [0, 1].
// small-device: yes (no allocation)
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct MarbleStripe {
    float c = 0.0f;      // z of the stripe's centre
    float w = 1.0f;      // width of the flat top, > 0
    float alpha = 1.0f;  // decay of the exponential skirt, > 0
};

struct MarbleParams {
    const MarbleStripe* stripes = nullptr;
    int count = 0;
    float k = 16.0f;  // contribution of the turbulence (okada1987: 16)
};

// okada1987 eq. (8), one term: the trapezoid with exponential skirt g_j(z).
float trapezoid_skirt(float z, const MarbleStripe& stripe);
// okada1987 eq. (8): G(P) = sum_j g_j(z).
float marble_original(float z, const MarbleStripe* stripes, int count);
// The marble texture at P: G(P') with P' = P + k·D(P)·(0, 0, 1) (eqs. (7), (9) as pixel shift).
float marble_texture(Vec3 p, float d, const MarbleParams& params);
// The density G' = 1 - min(G(P + k·D·(0, 0, 1)), 1) of the layered marble, D = d (see
// solid_material.hpp: what solid_density_at gives a marble material without a layer period).
// A firmware that draws only marble calls this and links no wood code.
float marble_density(Vec3 p, float d, const MarbleParams& params);

Status validate_marble_stripe(const MarbleStripe& stripe);
Status validate_marble(const MarbleParams& params);

}  // namespace shitsukan
