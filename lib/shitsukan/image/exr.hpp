// shitsukan/image/exr.hpp — float maps as OpenEXR: the format game engines, compositors and
// texture painters take for height and other linear data, written by the library's own code
// (no OpenEXR library; the compression is the library's own deflate, image/deflate.hpp).
//
// Manual
//   int w = 16, h = 8;
//   std::vector<float> height(std::size_t(w * h), 0.5f);               // row 0 = the TOP row
//   Status s = write_exr("height.exr", height.data(), w, h, 1);        // one channel "Y"
//   std::vector<float> rgb(std::size_t(w * h * 3), 0.25f);             // r g b interleaved
//   ExrOptions zip;  zip.compression = ExrCompression::zip;
//   if (s) s = write_exr("normals.exr", rgb.data(), w, h, 3, zip);    // "R", "G", "B"
//   return s;
//
// Format (the OpenEXR 2.0 file layout, single part, scan lines): magic 76 2f 31 01, version 2
// with no flags, the required header attributes (channels, compression, dataWindow,
// displayWindow, lineOrder INCREASING_Y, pixelAspectRatio 1, screenWindowCenter (0, 0),
// screenWindowWidth 1), the line offset table (one 64-bit file offset a chunk), then the
// chunks: y, byte count, and the lines' samples channel by channel in the channels'
// alphabetical order (B, G, R), 32-bit FLOAT, little-endian. The samples are stored as given,
// bit for bit (NaN and infinities too).
// Compression: none (a chunk is one line) or zip (ZIP_COMPRESSION: 16 lines a chunk, the
// bytes split into even and odd halves, each byte stored as its difference from the one
// before plus 128, then a zlib stream; a chunk that does not shrink is stored raw, as the
// format allows). Chosen default: zip (lossless, never larger; float noise in the low mantissa bits
// compresses little, quantised heights much: tests/test_image_exr measures one).
// Channel names: 1 channel "Y" (a gray map), 3 channels "R", "G", "B", 4 add "A".
// Errors: empty path, null samples, sizes below 1 or above 65536, channels other than 1, 3
// or 4 -> invalid_argument; writes through core/output_file.hpp (a failed write names the
// reason and leaves no part of a file). Host side.
#pragma once

#include "shitsukan/core/status.hpp"

namespace shitsukan {

enum class ExrCompression { none, zip };

struct ExrOptions {
    ExrCompression compression = ExrCompression::zip;
};

Status write_exr(const char* path, const float* samples, int width, int height, int channels,
                 const ExrOptions& options = ExrOptions{});

}  // namespace shitsukan
