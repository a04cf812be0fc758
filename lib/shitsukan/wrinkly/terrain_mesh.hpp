// shitsukan/wrinkly/terrain_mesh.hpp — the "shell" of fujimoto2000 §3.1 from a height map: a
// WR control mesh whose heights h_i come from the map and whose colours c_i from a colour
// ramp over the heights; a periodic control mesh (one period of a tiling terrain) wrapped so
// a uniform B-spline over it tiles; the map read from a 16-bit PNG or a PFM by
// image/height_map.hpp's read_height_map.
//
// Manual
//   std::vector<float> h(32 * 32);
//   for (int i = 0; i < 32 * 32; ++i) h[std::size_t(i)] = float((i % 32) * (i / 32)) / 961.0f;
//   TerrainMeshOptions o;  o.points = 8;  o.periodic = true;
//   Status s = parse_color_ramp("terrain", o.ramp);       // or "0:0.2,0.4,0.1;1:1,1,1"
//   WrControlMesh mesh;                                   // 8 + 3 points a side (wrapped)
//   if (s) s = control_mesh_from_height_map(h.data(), 32, 32, o, mesh);
//   WrSurface surface;
//   if (s) s = make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface);   // 8 x 8 spans
//   return s;
//   #include "shitsukan/wrinkly/wr_surface.hpp"
//
// Layout (chosen here, as fig. 21's terrain): the points lie on the x-z plane over
// [-extent/2, extent/2]^2 (column c along +x, row r along -z, image row 0 at z = extent/2,
// so dP/du x dP/dv = +y), y up; each point's height h_i = height_scale·(map value), displaced
// along the plane's normal, +y. The map is resampled to points x points: each point takes
// the mean of the map over its cell (1/points of the map a side; pixels weighted by the area
// they share with the cell, so a map smaller than the mesh works too).
// Open (periodic = false): points x points control points, spaced extent/(points - 1); point
// c's cell is [c, c + 1)/points of the map.
// Periodic: the cell is centred on the point the B-spline's u = c/points is centred on, and
// wraps; the output maps (terrain_maps.hpp) then keep the input's pixels where they were.
// Periodic: the map is one period of a tiling terrain. A uniform B-spline of degree n repeats
// with period m when its (m + n) x (m + n) control points repeat with period m; so the m x m
// points (spaced extent/m) are wrapped (wrap_control_mesh): m x m spans, one period of extent.
// Colour ramps: stops "t:r,g,b" separated by ';' (t in [0, 1] of the map's range, ascending;
// r, g, b in [0, 1]), or a name: "terrain" (fig. 21's bands: grass, rock, snow), "grey", "sand".
// Errors: null map, sizes < 1, points outside [4, 1024], extent or height_scale not finite and
// > 0 (height_scale >= 0), delta outside (0, 1), a bad ramp -> invalid_argument naming it.
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/wrinkly/control_mesh.hpp"

namespace shitsukan {

struct ColorRamp {
    static constexpr int kMaxStops = 8;
    int count = 0;
    float at[kMaxStops] = {};
    Vec3 color[kMaxStops];
};

Status parse_color_ramp(const char* text, ColorRamp& out);
// The colour at t (clamped to the first and last stop; linear between stops).
Vec3 color_ramp_at(const ColorRamp& ramp, float t);

struct TerrainMeshOptions {
    int points = 16;            // control points a side (chosen here: 16, a shell of 13-16 spans)
    float extent = 6.0f;        // world side (fig. 21: [-3, 3])
    float height_scale = 1.5f;  // world height of the map's 1 (fig. 21's massif: about 2)
    float delta = 0.5f;         // ratio value delta_i of eq. (19) for every point
    bool periodic = false;
    int degree = 3;             // of the B-spline the mesh is for (periodic padding)
    ColorRamp ramp;             // empty: every point white
};

Status control_mesh_from_height_map(const float* map, int width, int height,
                                    const TerrainMeshOptions& options, WrControlMesh& out);

// One period of m_u x m_v points -> (m_u + degree) x (m_v + degree), point (c, r) a copy of
// (c mod m_u, r mod m_v) moved by whole periods: period_u·(c div m_u) + period_v·(r div m_v).
// The uniform B-spline of that degree over it has m_u x m_v spans and repeats with the period.
Status wrap_control_mesh(const WrControlMesh& period, int degree, Vec3 period_u, Vec3 period_v,
                         WrControlMesh& out);

}  // namespace shitsukan
