// shitsukan/image/map_set.hpp — the map set a game or product artist drops into an engine:
// albedo, height (16-bit and float), normal, roughness and ambient occlusion, the last three
// derived from the height, written under one prefix with named suffixes.
//
// Manual
//   #include <vector>
//
//   const int w = 32, h = 32;
//   std::vector<float> height(w * h);                       // any units, top row first
//   std::vector<Rgb8> albedo(w * h, Rgb8{200, 190, 180});
//   for (int i = 0; i < w * h; ++i) height[i] = float((i % w) * (i / w) % 7);
//   MapSetOptions o;                                        // OpenGL normals, EXR float
//   o.strength = 4.0f;                                      // the full range is 4 pixels tall
//   o.wrap = true;                                          // a tileable map stays tileable
//   MapSetInput in{albedo.data(), height.data(), w, h};
//   std::vector<std::string> written;
//   Status s = write_map_set("/tmp/shitsukan_manual_stone", in, o, written);
//   // written: ..._albedo.png, _height16.png, _height.exr, _normal.png, _roughness.png, _ao.png
//   return s;
//
// Files (suffixes after the prefix): _albedo.png (8-bit sRGB, as given), _height16.png (16-bit
// gray, the heights' range [min, max] mapped to [0, 65535]), _height.exr and/or _height.pfm
// (the heights as given, float32, bit for bit; options.exr / options.pfm), _normal.png,
// _roughness.png and _ao.png (8-bit, linear). Every file is complete or absent
// (core/output_file.hpp; a caller's OutputSet makes the whole set appear together).
// Derived maps (chosen here; none of the five papers makes these maps), from h01 = the height
// normalised to [0, 1] like the 16-bit map, so they do not depend on the height's units:
// - normal: image/normal_map.hpp's height-field normal with `strength` pixels of relief for
//   the full range, differences across the borders when `wrap`. OpenGL convention (green =
//   +y, up the image); DirectX stores green' = 255 - green, the only channel that differs.
// - ambient occlusion: horizon-based: from each texel, 8 directions, heights at 1, 2, 4, ...
//   up to `ao_radius` pixels away; the highest elevation angle atan(strength·(h(q) - h(p))/d)
//   above the texel in each direction occludes sin(angle) of that direction; ao = 1 - the
//   mean over the 8 (1 on a flat map, lower in crevices and at the foot of ridges).
// - roughness: roughness_low + (roughness_high - roughness_low)·(1 - h01·ao): raised parts
//   are polished by wear and handling, low and occluded parts keep grime and stay rough
//   (the way polished stone, waxed wood and worn leather look). Defaults 0.3 and 0.8.
// Errors: null height, sizes below 1, a non-finite height (named with its texel), an empty
// prefix, no float format when a float is asked for -> invalid_argument; write failures as
// the writers report them. Host side (allocates the maps).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/image/image_view.hpp"

namespace shitsukan {

enum class NormalConvention { opengl, directx };

struct MapSetOptions {
    float strength = 4.0f;  // normal and AO: pixels of relief for the full height range
    NormalConvention normal = NormalConvention::opengl;
    bool wrap = false;          // tileable maps: differences and AO across the borders
    float ao_radius = 16.0f;    // pixels (chosen: the scale of a scale or a vein)
    float roughness_low = 0.3f, roughness_high = 0.8f;
    bool exr = true, pfm = false;  // the float height's formats
};

struct MapSetInput {
    const Rgb8* albedo = nullptr;  // may be null: no _albedo.png
    const float* height = nullptr;
    int width = 0, height_rows = 0;
};

// h01 = (h - min) / (max - min) (all 0 on a flat map); fails on a non-finite height.
Status normalise_heights(const float* height, int width, int rows, std::vector<float>& h01);

// 3 bytes a texel, the chosen convention.
Status derive_normal_map(const std::vector<float>& h01, int width, int rows,
                         const MapSetOptions& options, std::vector<Rgb8>& out);
// In [0, 1], 1 = unoccluded.
Status derive_ambient_occlusion(const std::vector<float>& h01, int width, int rows,
                                const MapSetOptions& options, std::vector<float>& out);
void derive_roughness(const std::vector<float>& h01, const std::vector<float>& ao,
                      const MapSetOptions& options, std::vector<float>& out);

Status write_map_set(const char* prefix, const MapSetInput& input, const MapSetOptions& options,
                     std::vector<std::string>& written);

}  // namespace shitsukan
