// shitsukan/leather/scale_pattern.hpp — the hand-off from the scale pattern (tokai1994 §3.1)
// to the relief (tokai1994 §3.2): the final polygons that tile the pattern rectangle.
//
// Manual
//   ScaleParams prm;
//   ScalePattern pattern;                       // filled by the two-stage division
//   Status s = generate_scale_pattern(prm, pattern);   // scale_division.hpp
//   for (int i = 0; i < pattern.polygon_count(); ++i) {
//       int n; const Vec2* v = pattern.polygon(i, &n);   // n vertices, counter-clockwise
//       Vec2 m = pattern.centroids[std::size_t(i)];      // area centroid ("m" in fig. 12)
//   }
//   return s;
//   #include "shitsukan/leather/scale_division.hpp"
// The polygons tile [0, width] x [0, height] (no gaps, no overlaps) and may be non-convex
// after edge perturbation, but each is star-shaped from its centroid (the relief casts a ray
// from m through x to the boundary point p).
#pragma once

#include <vector>

#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct ScalePattern {
    float width = 1.0f, height = 1.0f;
    std::vector<Vec2> vertices;        // all polygons' vertices, concatenated
    std::vector<int> polygon_offsets;  // polygon i = vertices[offsets[i] .. offsets[i + 1])
    std::vector<Vec2> centroids;       // one per polygon
    // Tileable patterns (tileable.hpp): the polygons tile the torus [0, W) x [0, H) instead of
    // the rectangle; a polygon may cross the border and continues on the other side (its copy
    // one period away). torus_cover() turns such a pattern into one covering the rectangle.
    bool wrap_x = false, wrap_y = false;

    int polygon_count() const {
        return polygon_offsets.empty() ? 0 : int(polygon_offsets.size()) - 1;
    }
    const Vec2* polygon(int i, int* count) const {
        *count = polygon_offsets[std::size_t(i) + 1] - polygon_offsets[std::size_t(i)];
        return vertices.data() + polygon_offsets[std::size_t(i)];
    }
};

}  // namespace shitsukan
