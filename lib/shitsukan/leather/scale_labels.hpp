// shitsukan/leather/scale_labels.hpp — the label image of a scale pattern: pixel -> polygon id.
//
// Manual
//   ScaleParams prm;  ScalePattern pattern;
//   Status s = generate_scale_pattern(prm, pattern);     // scale_division.hpp
//   int w = 128, h = 128, i = 10, j = 20;
//   std::vector<int32_t> labels(size_t(w) * h);
//   if (s) s = rasterize_scale_labels(pattern, w, h, labels.data());  // row-major, w per row
//   int id = labels[size_t(j) * w + i];   // the polygon holding pixel (i, j)'s centre
//   return s;
//   #include "shitsukan/leather/scale_division.hpp"
//
// Pixel (i, j) is the point ((i + 1/2) W / w, (j + 1/2) H / h) of the pattern (row 0 at y = 0,
// no flip). Each polygon is scan-converted with the half-open crossing rule: an edge covers
// scanlines y in [ymin, ymax), its crossing x is computed from its lower end point, and a
// pixel centre at x belongs to the span [x_in, x_out). Two polygons sharing an edge share its
// end points bit for bit (ScalePattern guarantees it), hence the same crossing x, so every
// pixel gets exactly one label. A pattern that does not tile (a gap or an overlap at some pixel
// centre) returns a Status naming the first such pixel.
// A pattern with a non-finite size or vertex, or polygon_offsets outside its vertices, is
// refused with a Status before anything is drawn. Cost: O(sum over polygons of rows x edges).
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/leather/scale_pattern.hpp"

namespace shitsukan {

Status rasterize_scale_labels(const ScalePattern& pattern, int width, int height,
                              std::int32_t* labels);

}  // namespace shitsukan
