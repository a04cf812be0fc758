// shitsukan/leather/scale_statistics.hpp — numbers behind the claims of tokai1994 §2 / fig. 7:
// (1) scales are nearly quadrilateral, (3) they narrow from the centre toward the edges.
//
// Manual
//   ScaleParams prm;
//   ScaleDivision steps;  Status s = divide_scales(prm, steps);    // scale_division.hpp
//   ScaleStatistics st;
//   if (s) s = measure_scale_statistics(steps.cells, prm.width, prm.height, st);
//   // st.mean_corners     ~4 for the fig. 7 settings
//   // st.edge_to_centre   < 1: edge scales narrower than centre scales
//   return s;
//   #include "shitsukan/leather/scale_division.hpp"
//
// Measured on the straight polygons (before perturbation). A corner is a vertex where the
// boundary turns (|sin| of the turn > 1e-9): T junctions of a neighbour's edge, which lie on
// a straight edge, do not count. Cells cut by the top or bottom edge are left out. Width =
// the cell's extent in x. "Centre" cells have their middle 0.1-0.2 W from the centre line
// (clear of the joint), "edge" cells 0.3-0.45 W from it and do not touch the left or right
// edge (chosen bands).
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/planar_subdivision.hpp"

namespace shitsukan {

struct ScaleStatistics {
    int cells = 0;              // cells measured (not cut by the top or bottom edge)
    double mean_corners = 0.0;  // mean corner count
    int centre_cells = 0, edge_cells = 0;
    double centre_width = 0.0;    // mean x extent in the centre bands
    double edge_width = 0.0;      // mean x extent in the edge bands
    double edge_to_centre = 0.0;  // edge_width / centre_width
};

Status measure_scale_statistics(const PlanarSubdivision& cells, float width, float height,
                                ScaleStatistics& out);

}  // namespace shitsukan
