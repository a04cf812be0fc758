// shitsukan/leather/relief.hpp — the relief of one scale (tokai1994 §3.2, fig. 12): height and
// normal at a point of a scale polygon from a Bezier cross-section swept around its centroid.
//
// Manual
//   const Vec2 poly[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // one scale, counter-clockwise
//   int n = 4;
//   Vec2 centroid{0.5f, 0.5f}, x{0.7f, 0.6f};                // its centroid m, a point in it
//   BezierChain section = table1_section(Table1Section::convex);   // fig. 13(a)
//   ReliefOptions opt;                                              // defaults below
//   ReliefSample s;
//   scale_relief(poly, n, centroid, x, section, opt, &s);           // s.height, s.normal, s.r
//
// The steps of §3.2 / fig. 12 for a point x inside a polygon with centroid m:
//   1. cast the ray from m through x; it leaves the polygon at the edge point p
//      (scale_edge_point: the nearest edge crossing at or beyond x, so it also works for
//      the slightly non-convex polygons of the perturbed pattern);
//   2. the relative distance rho = |x - m| / |p - m| (0 at m, 1 on the edge) gives the
//      section's first coordinate r = rho · opt.edge_r;
//   3. z(r) from the section (Bezier inversion, geom/bezier_curve.hpp);
//      height = z · S / edge_r · height_scale, with S = 2·area / perimeter of the polygon (its
//      inradius for a regular polygon): one height unit per scale, so a flat section gives
//      a flat top (scaling by the ray length |p - m| instead would tilt flat tops into
//      pyramids, since |p - m| grows toward the corners);
//   4. the normal of eq. (4): (n_x, n_y) = p - m, n_r = |p - m|, n_z = -dr·n_r / dz, written
//      here multiplied by -dz/n_r, i.e. n = (-dz·u, dr) with u = (p - m)/|p - m|: the same
//      direction, but it never divides by dz (dz = 0 on a flat top) and always points up.
// Beyond the section's last r (Table 1 sections end at 0.92-0.94 < 1) the height stays at
// the last z: the flat floor of the groove between scales (feature (4) of §2).
//
// eq. (4) is the exact normal of a section swept around m on a round scale. On a polygon
// the height field above is, inside the fan triangle (m, edge), z of the linear function
// rho = n_e·(x - m) / d_e (n_e the edge's outward unit normal, d_e the distance from m to
// the edge's line), so its exact normal is n = (-(S/d_e)·dz·n_e, dr). normal_rule =
// ReliefNormal::height_gradient uses that one (the normal map is then exactly the gradient
// of the height map); the default ReliefNormal::eq4 is the paper's.
//
// Options (defaults)
//   edge_r = 1.0        section r at the polygon edge. Chosen here: the README reading of
//                       Table 1 (r is the relative distance, the curve ends just inside the
//                       edge). edge_r = section_r_last(section) stretches the section to the
//                       edge instead (a V-shaped groove with no floor).
//   height_scale = 1.0  multiplies heights (and steepens normals accordingly).
//   normal_rule = eq4   or height_gradient (see above).
// Small-device: no allocation, float.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/bezier_curve.hpp"

namespace shitsukan {

// The three cross-sections of tokai1994 Table 1.
enum class Table1Section { convex, concave, two_segment };  // fig. 13(a), 14(a), 15(a)
BezierChain table1_section(Table1Section which);
const char* table1_section_name(Table1Section which);

enum class ReliefNormal { eq4, height_gradient };

struct ReliefOptions {
    float edge_r = 1.0f;        // chosen here, see the manual
    float height_scale = 1.0f;  // chosen here: the section's own proportions
    ReliefNormal normal_rule = ReliefNormal::eq4;
};

// Where the r axis of fig. 12 leaves the polygon.
struct EdgeHit {
    Vec2 p{0, 0};             // the edge point p
    Vec2 edge_normal{0, 0};   // outward unit normal of the crossed edge (n_e)
    float edge_distance = 0;  // distance from m to that edge's line (d_e)
    bool inside = false;      // false: no crossing at or beyond x (x outside the polygon)
};

struct ReliefSample {
    float height = 0;       // in the units of the polygon coordinates
    float scale_size = 0;   // S = 2·area / perimeter of the polygon
    Vec3 normal{0, 0, 1};   // unit, z up
    float rho = 0;          // relative distance |x - m| / |p - m|
    float r = 0;            // section coordinate
    Vec2 edge_point{0, 0};  // p
};

Status validate_relief_options(const ReliefOptions& options);

// p of fig. 12: where the ray from m through x leaves the polygon (n >= 3 vertices, any
// orientation). When x == m the ray is cast along +x. When no edge is crossed at or beyond x
// (x outside the polygon) hit.inside is false and p is the farthest crossing (or x).
EdgeHit scale_edge_point(const Vec2* polygon, int n, Vec2 m, Vec2 x);

// The same search in O(log n) for a polygon that is star-shaped from m (what the scale
// pattern guarantees): the vertices' angles around m, unwrapped, increase (counter-clockwise)
// or decrease (clockwise) through less than a full turn, so the edge the ray crosses is found
// by binary search on the ray's angle. make_angular_index fills angles[0 .. n) (caller
// memory) and returns false when the polygon is not star-shaped from m that way (then use
// scale_edge_point). scale_edge_point_indexed tests the found edge and its two neighbours and
// falls back to the full scan if none is crossed at or beyond x, so it returns the same hit.
bool make_angular_index(const Vec2* polygon, int n, Vec2 m, float* angles);
EdgeHit scale_edge_point_indexed(const Vec2* polygon, int n, Vec2 m, Vec2 x, const float* angles);

// S = 2·area / perimeter (the height unit of one scale).
float scale_size(const Vec2* polygon, int n);

// Relief at x for the polygon with centroid m. The section must have passed
// validate_section and the options validate_relief_options.
void scale_relief(const Vec2* polygon, int n, Vec2 m, Vec2 x, const BezierChain& section,
                  const ReliefOptions& options, ReliefSample* out);

// Steps 2-4 for a known relative distance rho, edge hit and scale size S (fig. 12 plots).
void relief_along_ray(float rho, Vec2 m, const EdgeHit& hit, float size, const BezierChain& section,
                      const ReliefOptions& options, ReliefSample* out);

}  // namespace shitsukan
