// shitsukan/wrinkly/terrain_maps.hpp — a WR or superposed surface (fujimoto2000 eqs. (15),
// (20)) written out as maps: the height H at every pixel (the displacement along the base
// surface's normal; for a flat shell, the terrain's height) and the carried colour C.
//
// Manual
//   WrControlMesh mesh = make_control_mesh(8, 8);     // control_mesh.hpp
//   for (int r = 0; r < 8; ++r)
//       for (int c = 0; c < 8; ++c)
//           mesh.at(c, r).position = {c / 7.0f, 0.0f, r / 7.0f},
//           mesh.at(c, r).height = 0.1f * float((c * 3 + r * 5) % 7);
//   WrSurface surface;
//   Status s = make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface);
//   HierarchicalOptions ho;  ho.levels = 2;
//   HierarchicalSampling hs;
//   if (s) s = sample_hierarchy(surface, ho, hs);     // identity axes: plain sums
//   TerrainMapOptions o;  o.width = o.height = 32;  o.form = WrSurfaceForm::superposed;
//   TerrainMaps maps;
//   if (s) s = make_terrain_maps(surface, &hs, o, maps);   // maps.heights, maps.color
//   return s;
//   #include "shitsukan/wrinkly/hierarchical_sampling.hpp"
//
// Pixel (x, y) is the parameter point u = (x + 1/2)/width, v = (y + 1/2)/height (row 0 at
// v = 0). form plain: H(u, v); wr: H((F_U^K)^-1(u), (F_V^K)^-1(v)) (eq. 15, K = levels);
// superposed: eq. (20) with every sampled step (hierarchical_sampling.hpp; eq. (18) on the
// finite sum), the colour averaged with the same weights.
// Periodic (a wrapped control mesh, terrain_mesh.hpp, whose u, v in [0, 1) is one period):
// the sampled steps H^k are interpolated cyclically over their centre samples (i + 1/2)/M,
// sample M - 1 next to sample 0 (the boundary samples at 0 and 1 of an open surface,
// fig. 20, would be two different values at one point of the tiling: a seam); linear or
// Hermite (Catmull-Rom tangents) as the sampling says. With cyclic IST axes
// (IstEnds::cyclic) the map then tiles: its seam is one more column of samples.
// Errors: sizes outside [1, 16384], form superposed without hs, form base, levels outside
// 0..max_level -> invalid_argument; the maps over the memory budget -> too_large.
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/wr_surface.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"

namespace shitsukan {

struct TerrainMapOptions {
    int width = 512, height = 512;
    WrSurfaceForm form = WrSurfaceForm::superposed;
    int levels = 3;         // K of the wr form
    bool periodic = false;  // cyclic interpolation of the superposed steps
};

struct TerrainMaps {
    int width = 0, height = 0;
    std::vector<float> heights;  // row-major, row 0 at v = 0
    std::vector<Vec3> color;    // [0, 1]
    float lo = 0, hi = 0;       // range of the heights
};

Status make_terrain_maps(const WrSurface& surface, const HierarchicalSampling* hs,
                         const TerrainMapOptions& options, TerrainMaps& out);

}  // namespace shitsukan
