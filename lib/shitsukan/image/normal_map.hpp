// shitsukan/image/normal_map.hpp — a tangent-space normal map from any height map: the normal
// of the height field z = s·h(x, y), (-s ∂h/∂x, -s ∂h/∂y, 1) / |.|, the same height-field
// normal that Blinn's bump mapping uses (raster/bump_mapping.hpp) and that the leather maps
// store (leather/maps.hpp), encoded the same way (OpenGL convention, green = +y).
//
// Manual
//   #include <vector>
//
//   const int w = 64, h_rows = 32;
//   std::vector<float> h(w * h_rows);            // heights in [0, 1], top row first
//   for (int i = 0; i < w * h_rows; ++i) h[i] = float(i % w) / float(w);   // a ramp along x
//   HeightNormalOptions o;  o.strength = 8.0f;   // the full height range is 8 pixels tall
//   std::vector<Vec3> n(h.size());
//   Status s = height_map_normals(h.data(), w, h_rows, o, n.data());
//   if (!s) return s;
//   std::vector<std::uint8_t> rgb(3 * h.size());
//   encode_normal_rgb8(n.data(), n.size(), rgb.data());   // rgb = (n + 1) / 2 · 255
//
// Image axes: x to the right, rows from the top; the normal's y points up (to the previous
// row), as in the leather normal maps. Derivatives are central differences over one pixel,
// (h(x + 1) - h(x - 1)) / 2; at the border one-sided ones, or, with wrap, differences across
// the opposite border, so a tileable height map gives a tileable normal map. strength: the
// height, in pixels, of a height difference of 1 (the full range of a 16-bit or 8-bit map).
// Errors: null pointers, sizes below 1, a strength that is not finite, a height that is not
// finite (NaN, inf: named with its pixel) -> invalid_argument; a slope s·dh that overflows a
// float (heights near ±3e38, or a huge strength) -> out_of_range. Any finite slope gives a
// unit normal (nearly horizontal for a steep one).
// Host or device: allocates nothing, float only.
#pragma once

#include <cstddef>
#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct HeightNormalOptions {
    float strength = 1.0f;  // pixels per unit of height
    bool wrap = false;      // differences across the borders (tileable maps)
};

Status height_map_normals(const float* heights, int width, int height,
                          const HeightNormalOptions& options, Vec3* out);

// rgb = round((n + 1) / 2 · 255) per component, 3 bytes a normal, in the order given.
void encode_normal_rgb8(const Vec3* normals, std::size_t count, std::uint8_t* rgb);

}  // namespace shitsukan
