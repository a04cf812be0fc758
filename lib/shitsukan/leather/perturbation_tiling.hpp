// shitsukan/leather/perturbation_tiling.hpp — what keeps the tiling while tokai1994's
// processing 4 bends the edges (edge_perturbation.hpp): not the paper's step, the engineering
// around it. A curve may use a share (`safety`) of the fan triangle (chord, face centroid) on
// each side of its chord; a polygon must stay counter-clockwise and star-shaped from its own
// float centroid. perturb_subdivision (perturb_subdivision.cpp) and perturb_two_stage
// (perturb_two_stage.cpp) share these pieces.
//
// Manual
//   using namespace shitsukan::perturbation_tiling;
//   EdgeFrame e;                                   // the edge (0, 0)-(1, 0) and its two fans
//   e.a = {0, 0}; e.b = {1, 0}; e.u = {1, 0}; e.nrm = {0, 1}; e.l = 1.0;
//   e.centre[0] = {0.5, 0.5}; e.centre[1] = {0.5, -0.5};   // the faces' centroids
//   const double f[5] = {0, 0.1, 0.2, 0.1, 0};               // offsets along nrm, 4 segments
//   double lambda = fitting_scale(e, f, 4, 0.6);             // 1: the curve fits as it is
//   std::vector<Vec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
//   std::vector<int> bad;
//   offending_segments(square, &bad);                        // empty: star-shaped from c
//   if (lambda != 1.0 || !bad.empty()) return Status::error(StatusCode::degenerate, "fit");
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/leather/edge_perturbation.hpp"
#include "shitsukan/leather/scale_pattern.hpp"

namespace shitsukan {
namespace perturbation_tiling {

// The two faces' centres of an edge and what the curve may do next to each.
struct EdgeFrame {
    Vec2d a, b, u, nrm;  // canonical ends, unit chord, unit normal (left of a -> b)
    double l = 0.0;      // chord length
    Vec2d centre[2];     // centre[0] on the normal's side (> 0), centre[1] on the other
};

// Height of the fan triangle (a, b, c) above the chord at chord parameter s (c at distance h
// from the chord's line, its foot at da from a).
double fan_height(double s, double l, double h, double da);
// Does the curve with offsets lambda * f (n segments) stay strictly inside the safety share of
// its two fan triangles? Then it cannot cross or touch any other edge's curve.
bool curve_fits(const EdgeFrame& e, const double* f, int n, double lambda, double safety);
// The largest lambda in [0, 1] (1 if it fits, else by bisection to 2^-20) for which the curve
// fits; 0 keeps the edge straight.
double fitting_scale(const EdgeFrame& e, const double* f, int n, double safety);
// Offset of the curve f (n segments over a chord of length l) at chord parameter s, linear
// between the samples (the curve is drawn as that polyline).
double offset_at(const double* f, int n, double l, double s);
// Chord parameter of a point on the edge (its ends exactly 0 and l).
double chord_s(const EdgeFrame& fr, Vec2d p);

// The checks every polygon passes: counter-clockwise, every segment turning counter-clockwise
// around the polygon's own float centroid, the angle winding once. *bad: the positions k of
// the offending segments (all of them if degenerate); empty when the polygon passes.
void offending_segments(const std::vector<Vec2>& fp, std::vector<int>* bad);
// Consecutive equal points of a closed polygon dropped (*tag, one per point, kept in step).
void dedupe_closed(std::vector<Vec2>* fp, std::vector<int>* tag);

// The PerturbationParams' ranges (a Status naming the bad value).
Status check_params(const PerturbationParams& prm);
// An empty pattern of the given size; a polygon appended (consecutive equal float points
// collapsed the same way on both sides of an edge; *poly is changed so), with its centroid.
void start_pattern(ScalePattern* p, float width, float height);
void append_polygon(ScalePattern* out, std::vector<Vec2>* poly);

}  // namespace perturbation_tiling
}  // namespace shitsukan
