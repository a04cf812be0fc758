// cli/preview.hpp — `--preview FILE.png`: a map set (image/map_set.hpp) as an artist first
// checks it, on a lit sphere and on a plane, drawn by the library's rasterizer
// (raster/rasterizer.hpp), 1024 x 512. A tileable set (options.wrap) goes twice around the
// sphere and 2 x 2 on the plane, so a seam or a crease would show; any other set once.
//
//   MapSetInput maps{albedo, heights, w, h};
//   Status s = write_map_preview("preview.png", maps, map_set_options(flags, tileable));
//
// Shading (chosen: what an engine's default material does with the maps, in plain terms):
// the albedo taken as sRGB and lit in linear light; the normal map's tangent-space normal
// (the OpenGL one, whatever convention is written) turned into the surface's frame (u, v,
// n); one directional light from the upper left, Lambert diffuse, a Blinn-Phong highlight
// whose exponent falls with the roughness map, 2/r^4 - 2, and an ambient term times the AO.
// Texel lookups are bilinear and wrap. Host side.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/image/map_set.hpp"

namespace shitsukan::cli {

Status write_map_preview(const char* path, const MapSetInput& maps, const MapSetOptions& options);

}  // namespace shitsukan::cli
