// shitsukan/leather/maps.hpp — the leather texture of tokai1994 §3.2 for a whole scale
// pattern: a height map and a normal map, and their exports (16-bit height, RGB normal map,
// relief mesh for OBJ).
//
// Manual
//   ScaleParams prm;  ScalePattern pattern;
//   Status s = generate_scale_pattern(prm, pattern);    // scale_division.hpp
//   int w = 256, h = 256;
//   LeatherMaps maps;                               // one call: labels, then the maps
//   if (s) s = make_leather_maps(pattern, w, h, table1_section(Table1Section::convex),
//                                ReliefOptions{}, maps);
//   if (!s) return s;
//   Vec2 uv{1.7f, -0.4f};
//   Vec3 n = mirrored_normal_at(maps, uv);           // tiled by mirroring: any (u, v)
//   #include "shitsukan/leather/scale_division.hpp"
//
//   std::vector<int> labels(w * h);                 // pixel -> polygon id, from the pattern's
//   ...                                             // label function (leather/scale_pattern)
//   LeatherMaps maps;
//   Status s = make_leather_maps(pattern, labels.data(), w, h,
//                                table1_section(Table1Section::convex), ReliefOptions{}, maps);
//   Vec3 n = normal_at(maps, {x, y});                // bilinear, in pattern units, unit length
//   std::vector<uint16_t> h16(w * h);  encode_height16(maps, h16.data());   // top row = +y
//   std::vector<uint8_t> rgb(3 * w * h); encode_normal_rgb(maps, rgb.data());
//   TriangleMesh mesh; make_relief_mesh(maps, 4, 1.0f, mesh);  write_obj("relief.obj", mesh);
//
// Conventions
//   Pixel (i, j) of the maps is the pattern point ((i + 0.5)·W/w, (j + 0.5)·H/h): row 0 is
//   y = 0 (pattern y up, as the paper's x-y plane). labels[j·w + i] is the polygon id of that
//   point, or -1 for "no polygon" (treated as groove floor: height 0, normal up).
//   Heights are in pattern units: section z times the scale's size S = 2·area / perimeter
//   (divided by edge_r, times height_scale; see relief.hpp step 3).
//   Normals are in the pattern frame (x, y, z up), unit length.
//   Exports flip rows so the image's top row is the largest y (image "up" = +y), and the
//   normal map uses the common OpenGL-style encoding rgb = (n + 1)/2 · 255 with green = +y.
//   The 16-bit height map stores height / max_height · 65535 (max_height = maps.max_height
//   unless given): one unit of the PNG is max_height / 65535 pattern units.
// Host side (std::vector); the per-point relief (relief.hpp) is small-device.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/progress.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/bezier_curve.hpp"
#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/leather/relief.hpp"
#include "shitsukan/leather/scale_pattern.hpp"

namespace shitsukan {

struct LeatherMaps {
    int width = 0, height = 0;                    // pixels
    float pattern_width = 1, pattern_height = 1;  // pattern units covered by the maps
    std::vector<float> heights;                   // width·height, row j <-> y = (j+0.5)·H/h
    std::vector<Vec3> normals;                    // width·height, unit, pattern frame
    float max_height = 0;                         // largest height in the map

    float at_height(int i, int j) const {
        return heights[std::size_t(j) * std::size_t(width) + std::size_t(i)];
    }
    Vec3 at_normal(int i, int j) const {
        return normals[std::size_t(j) * std::size_t(width) + std::size_t(i)];
    }
};

// Builds the maps: for every pixel, scale_relief of its polygon at the pixel centre (with
// S and the angular edge index of relief.hpp computed once per polygon).
// invalid_argument for sizes outside 1..16384, a label outside -1..polygon_count-1 (the
// message gives the pixel), an invalid section or options, or a pattern without polygons;
// out_of_range when the heights could pass kMaxReliefHeight (a tiny edge_r or a huge
// height_scale).
// `progress` (core/progress.hpp) hears the share of rows done, about 100 times. For a tileable
// (wrapped) pattern pass its torus_cover (tileable.hpp) and that cover's labels.
// Largest height a map may hold (chosen here: 1e30, far above any relief, far below a
// float's 3.4e38 so the encodings' sums and units stay finite).
constexpr float kMaxReliefHeight = 1e30f;

Status make_leather_maps(const ScalePattern& pattern, const int* labels, int width, int height,
                         const BezierChain& section, const ReliefOptions& options,
                         LeatherMaps& out, Progress progress = {});

// The same in one call: the label image (rasterize_scale_labels, scale_labels.hpp) at
// width x height, then the maps above. Same errors; the sizes are checked before the label
// image is allocated. A tileable pattern (wrap_x / wrap_y, tileable.hpp) is first covered by
// its copies across the border (torus_cover), so the maps repeat with no seam.
// `progress`: 0.1 once the labels are drawn, then the rows as above (0.1 .. 1).
Status make_leather_maps(const ScalePattern& pattern, int width, int height,
                         const BezierChain& section, const ReliefOptions& options,
                         LeatherMaps& out, Progress progress = {});

// Bilinear normal at a pattern point (clamped to the map), renormalised.
Vec3 normal_at(const LeatherMaps& maps, Vec2 pattern_point);
// Bilinear height at a pattern point (clamped to the map).
float height_at(const LeatherMaps& maps, Vec2 pattern_point);

// Tiling for texturing a surface larger than the pattern: the maps repeated by mirroring
// (copy, mirror image, copy, ... in x and in y), so scales continue across every seam. In
// a mirrored copy the normal's x (or y) is negated, so the bumps stay consistent. Any point
// of the plane, in pattern units (e.g. a mesh's uv scaled by the pattern size).
Vec3 mirrored_normal_at(const LeatherMaps& maps, Vec2 point);
float mirrored_height_at(const LeatherMaps& maps, Vec2 point);

// 16-bit height image, width·height values, top row = largest y. max_height <= 0 means
// maps.max_height.
void encode_height16(const LeatherMaps& maps, std::uint16_t* out, float max_height = 0.0f);
// RGB normal map, 3·width·height bytes, top row = largest y.
void encode_normal_rgb(const LeatherMaps& maps, std::uint8_t* out);

// A grid mesh of the relief: every `step`-th pixel centre becomes a vertex
// (x, y, height · z_scale) with the map's normal and uv = (x/W, y/H). invalid_argument for
// step < 1 or a map smaller than 2x2 samples.
Status make_relief_mesh(const LeatherMaps& maps, int step, float z_scale, TriangleMesh& out);

}  // namespace shitsukan
