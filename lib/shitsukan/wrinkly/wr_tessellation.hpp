// shitsukan/wrinkly/wr_tessellation.hpp — polygonising WR surfaces (fujimoto2000 §4.2, §5:
// "after polygonising the surface by adaptive sampling, render with a Z-buffer").
//
// Manual
//   WrControlMesh mesh = make_control_mesh(8, 8);          // control_mesh.hpp
//   for (int r = 0; r < 8; ++r)
//       for (int c = 0; c < 8; ++c)
//           mesh.at(c, r).position = {c / 7.0f, r / 7.0f, 0.0f}, mesh.at(c, r).height = 0.05f;
//   WrSurface surface;
//   Status s = make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface);
//   if (!s) return s;
//   HierarchicalOptions ho;  ho.levels = 3;
//   HierarchicalSampling sampling;                   // hierarchical_sampling.hpp
//   s = sample_hierarchy(surface, ho, sampling);
//   WrTessellationOptions o;
//   o.form = WrSurfaceForm::superposed;    // base | plain | wr | superposed_direct | superposed
//   o.levels = 3;                          // K of eq. (15) / (16)
//   o.grid_level = 3;  o.subdivisions = 1; // vertices at the step-3 sample positions
//   WrMesh m;
//   if (s) s = tessellate_wr_surface(surface, &sampling, o, m);   // sampling: for `superposed`
//   // m.mesh (positions, normals, uv = (u, v), colours), m.transparency (one per vertex)
//   float pixels_per_unit = 200.0f;
//   AdaptiveLevels a = choose_adaptive_levels(surface, mesh, pixels_per_unit, 1.5f, 0.5f, 5);
//   return s;
//
// The vertex grid along each axis is the step-L sample positions of hierarchical_sampling.hpp
// (0, the small-interval midpoints, 1), each interval cut into `subdivisions` pieces, clipped
// to the parameter window [u0, u1] x [v0, v1] (zooms). For odd N every coarser step's sample
// lies on this grid, so linear H^k (k <= L) is represented exactly at the vertices.
// Adaptive sampling (the paper's ref. 13 is not available; this is our reading of §4.2):
//   - the vertex grid level L is the first whose cells project to at most `cell_pixels`;
//   - the superposition stops, per vertex, once the rest of the sum, delta(u,v)^k·max|h|,
//     projects below `tolerance_pixels` (WrTessellationOptions::tail_tolerance, world units).
// Ranges: levels 0..surface.max_level() (<= kMaxWrLevel), grid_level 0..kMaxWrLevel,
// subdivisions 1..64, 0 <= u0 < u1 <= 1 (same for v), at most kMaxWrVertices vertices.
#pragma once

#include <vector>

#include "shitsukan/core/progress.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/wr_surface.hpp"

namespace shitsukan {

enum class WrSurfaceForm : unsigned char {
    base,               // P(u, v): the base surface alone
    plain,              // P + H(u, v) N: the conventional surface ("(c)" panels, no IST)
    wr,                 // eq. (15) with F^K
    superposed_direct,  // eq. (16) summed to K, no sampling (staircase, fig. 19b)
    superposed,         // eq. (20) with the hierarchical sampling (needs a HierarchicalSampling)
};

constexpr long kMaxWrVertices = 6L * 1000 * 1000;

struct WrTessellationOptions {
    WrSurfaceForm form = WrSurfaceForm::superposed;
    int levels = 3;        // K for wr / superposed_direct (superposed: the sampling's levels)
    int grid_level = 3;    // L
    int subdivisions = 1;  // vertices per sample interval
    float u0 = 0, u1 = 1, v0 = 0, v1 = 1;
    float tail_tolerance = 0;  // superposed: world-unit bound on the omitted rest of the sum
    Progress progress;         // evaluate_wr_grid's rows done, 0 .. 1 (core/progress.hpp)
};

struct WrMesh {
    TriangleMesh mesh;                // uv = surface parameter (u, v); colours per vertex
    std::vector<float> transparency;  // per vertex
    int grid_u = 0, grid_v = 0;       // vertices along u and v
    int max_levels_used = 0;          // superposed: deepest step added anywhere
    double mean_levels_used = 0;      // superposed: mean over vertices
};

// Both steps below: sample the surface at the grid points, then build the polygons.
Status tessellate_wr_surface(const WrSurface& surface, const HierarchicalSampling* sampling,
                             const WrTessellationOptions& options, WrMesh& out);
// Step 1 (the paper's "sampling" stage of Tables 2-4): points, colours, uv, transparency.
Status evaluate_wr_grid(const WrSurface& surface, const HierarchicalSampling* sampling,
                        const WrTessellationOptions& options, WrMesh& out);
// Step 2 ("polygonisation"): vertex normals of the displaced grid and two triangles per cell.
void polygonise_wr_grid(const WrSurface& surface, WrMesh* mesh);

// Grid positions along one axis (used by tessellate_wr_surface; exposed for tests).
std::vector<float> wr_grid_positions(const WrAxis& axis, int grid_level, int subdivisions, float lo,
                                     float hi);

struct AdaptiveLevels {
    int grid_level = 0;         // L: cells project to <= cell_pixels
    int sum_levels = 0;         // K: delta_max^(K+1)·max|h| projects below tolerance_pixels
    float world_tolerance = 0;  // tolerance_pixels / pixels_per_unit
};

// pixels_per_unit: how many pixels one world unit covers near the surface (the figure measures
// it with its camera). max_level caps both answers.
AdaptiveLevels choose_adaptive_levels(const WrSurface& surface, const WrControlMesh& mesh,
                                      float pixels_per_unit, float cell_pixels,
                                      float tolerance_pixels, int max_level);

}  // namespace shitsukan
