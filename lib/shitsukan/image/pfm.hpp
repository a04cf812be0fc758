// shitsukan/image/pfm.hpp — float maps as PFM (Portable Float Map): heights and densities
// without quantisation, read by image tools and game engines' importers.
//
// Manual
//   int w = 16, h = 8;
//   std::vector<float> height(std::size_t(w * h), 0.5f);          // row 0 = the TOP row
//   std::vector<float> rgb(std::size_t(w * h * 3), 0.25f);
//   Status s = write_pfm("height.pfm", height.data(), w, h, 1);   // "Pf": gray
//   if (s) s = write_pfm("normals.pfm", rgb.data(), w, h, 3);     // "PF": r g b interleaved
//   PfmImage back;
//   if (s) s = read_pfm("height.pfm", back);                      // the same floats, bit for bit
//   return s;
//
// Format: a text header "PF\n" (3 channels) or "Pf\n" (1), "width height\n", a scale
// "-1.0\n" (negative = little-endian), then the float32 samples row by row from the BOTTOM
// row up (the format's convention; the functions here take and give the top row first).
// Errors: empty image, channels other than 1 or 3, non-finite samples are allowed (PFM
// stores any float); unreadable or malformed files -> io_error / invalid_argument with the
// path; sizes above 65536 a side -> too_large. read_pfm parses the header with bounds (a
// size of more than 6 digits is malformed) and checks its size against the bytes the file
// holds before allocating (a short file is refused at once; a pipe is read a row at a time).
// Written through core/output_file.hpp (a failed write names the reason and leaves no part of
// a file). Host side.
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"

namespace shitsukan {

struct PfmImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float> data;  // width·height·channels, top row first
};

Status write_pfm(const char* path, const float* samples, int width, int height, int channels);
Status read_pfm(const char* path, PfmImage& out);

}  // namespace shitsukan
