// shitsukan/image/height_map.hpp — a height map read from a file: one float per pixel, from a
// 16-bit or 8-bit PNG (or any image read_image takes: its first channel) or a PFM, for the
// tools that build a surface from a map (fujimoto2000's shell from a terrain, wrinkly's
// control_mesh_from_height_map).
//
// Manual
//   std::vector<float> ramp = {0.0f, 0.25f, 0.5f, 1.0f};
//   Status s = write_pfm("ramp.pfm", ramp.data(), 2, 2, 1);      // (pfm.hpp) something to read
//   std::vector<float> h;
//   int width = 0, height = 0;
//   if (s) s = read_height_map("ramp.pfm", h, width, height);    // 2 x 2: 0, 0.25 / 0.5, 1
//   return s;
//   #include "shitsukan/image/pfm.hpp"
//
// Values: a PNG's samples / 65535 (16-bit) or / 255 (8-bit), in [0, 1]; a PFM's first channel
// as stored. Row 0 is the top row, width·height values.
// Errors: the readers' (io_error naming the file, invalid_argument for a malformed one), a
// non-finite PFM sample -> invalid_argument naming the file and the pixel; on error the
// outputs are left as they were. Host side.
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"

namespace shitsukan {

Status read_height_map(const char* path, std::vector<float>& out, int& width, int& height);

}  // namespace shitsukan
