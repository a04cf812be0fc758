// shitsukan/wrinkly/control_mesh.hpp — the WR control mesh of fujimoto2000 §3.1: a square
// (regular quadrilateral) grid of WR control points, each carrying a 3D position x_i, a height
// h_i, a colour c_i, a transparency, a ratio value delta_i (§4.1) and, for the displacement in
// arbitrary directions of figs. 22-23 (§5), a direction.
//
// Manual
//   WrControlMesh mesh = make_control_mesh(8, 8);          // cols (along u) x rows (along v)
//   for (int r = 0; r < 8; ++r)
//       for (int c = 0; c < 8; ++c) mesh.at(c, r).position = {c / 7.0f, r / 7.0f, 0.0f};
//   mesh.at(2, 5).height = 0.3f;  mesh.at(2, 5).color = {1, 0, 0};
//   Status s = validate_control_mesh(mesh, SurfaceBasis::bspline, 3);
//   return s;
//
// Defaults per point: position (0,0,0), height 0, colour white, transparency 0 (opaque),
// delta 0.5, direction (0,0,0) = "along the base-surface normal N(u,v)" (eq. 15).
// Ranges: transparency in [0, 1]; delta in (0, 1) (eq. 17 requires 0 < delta < 1);
// a Bezier mesh has (n+1) x (n+1) points, a B-spline mesh at least (n+1) x (n+1).
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/tensor_surface.hpp"

namespace shitsukan {

struct WrControlPoint {
    Vec3 position{0, 0, 0};   // x_i
    float height = 0;         // h_i (displacement along N, or along `direction`)
    Vec3 color{1, 1, 1};      // c_i = (r, g, b) in [0, 1]
    float transparency = 0;   // 0 opaque .. 1 invisible
    float delta = 0.5f;       // ratio value delta_i of eq. (19)
    Vec3 direction{0, 0, 0};  // unit displacement direction; zero = the surface normal
};

struct WrControlMesh {
    int cols = 0;                        // along u
    int rows = 0;                        // along v
    std::vector<WrControlPoint> points;  // row-major: points[row·cols + col]

    WrControlPoint& at(int col, int row) { return points[std::size_t(row * cols + col)]; }
    const WrControlPoint& at(int col, int row) const {
        return points[std::size_t(row * cols + col)];
    }
};

constexpr long kMaxWrControlPoints = 1L << 20;  // cols·rows (about 50 MB of points)

// A cols x rows grid of default points. Sizes below 1 give an empty mesh and more than
// kMaxWrControlPoints points leave `points` empty (nothing is allocated): either way
// validate_control_mesh then reports the size.
WrControlMesh make_control_mesh(int cols, int rows);

// Largest |value| of a control point's position, height and direction components (chosen
// here: 1e5, far beyond the papers' scenes). It keeps every float product the evaluation
// forms finite for every accepted mesh: |dP/du| |dP/dv| <= 16 spans_u spans_v C^2 with
// spans_u spans_v <= kMaxWrControlPoints, so the normal's squared length stays below 3e34
// (fuzz_wr_tessellation found NaN positions and normals from a point at z = -3.4e35).
constexpr float kMaxWrCoordinate = 1e5f;

// Checks the grid shape against the base surface (the paper restricts WR surfaces to square
// meshes, §3.1 and §6), the point count, and every value's range (finite; positions, heights
// and directions within +-kMaxWrCoordinate). Returns a Status naming the offending point.
Status validate_control_mesh(const WrControlMesh& mesh, SurfaceBasis basis, int degree);

}  // namespace shitsukan
