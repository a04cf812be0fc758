// paper_figures/fujimoto2000/terrain_mesh.hpp — the control mesh of fujimoto2000 fig. 21's
// terrain (chosen here: the paper does not print it), shared by the figure
// (fig21_terrain.cpp) and the web explorer's terrain panel (ports/web/api/api_fujimoto2000.cpp).
// Uses the library alone (no figure driver), so the WASM build compiles it as it is.
//
//   WrControlMesh m = terrain_control_mesh(0.55f);  // 10 x 10 points, delta 0.55 in the mountains
//   WrSurface s;  make_wr_surface(m, SurfaceBasis::bspline, 3, s);
#pragma once

#include "shitsukan/core/vec.hpp"
#include "shitsukan/wrinkly/control_mesh.hpp"

namespace shitsukan::fujimoto2000 {

// The "not superposed" delta of the green field (W^0 = 0.98: the sum is practically H).
constexpr float kTerrainDeltaGreen = 0.02f;
// The figure's camera: diagonal across the parameter grid, from above (fig21_terrain.cpp).
constexpr Vec3 kTerrainEye{5.4f, 4.6f, 5.4f}, kTerrainTarget{-0.3f, 0.3f, -0.3f};
constexpr float kTerrainFovDegrees = 41.0f;
// The figure's light, from above.
constexpr Vec3 kTerrainLight{0.25f, 1.0f, 0.45f};

// 1 in the field at the front right (as the figure's camera sees it), 0 in the mountains.
float terrain_green_mask(float x, float z);

// 10 x 10 control points (7 x 7 B-spline spans) on [-3, 3]^2: a massif at the back, a second
// range to the left, a low green field at the front right with delta kTerrainDeltaGreen;
// `delta` elsewhere. Colour per point from the height band, a hashed tint and a drift.
WrControlMesh terrain_control_mesh(float delta);

}  // namespace shitsukan::fujimoto2000
