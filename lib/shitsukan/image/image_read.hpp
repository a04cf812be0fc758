// shitsukan/image/image_read.hpp — reading images (PNG 8 and 16 bit, JPEG, BMP, TGA, PGM/PPM)
// through stb_image, compiled privately like stb_image_write (no stbi_* symbol leaves the
// library); its GIF, PSD, PIC and HDR readers are left out (floats come as PFM, image/pfm.hpp).
//
// Manual
//   RgbImage photo(8, 8, Rgb8{10, 20, 30});
//   Status s = write_png("photo.png", photo.view());  // (image_io.hpp) something to read
//   LoadedImage img;
//   bool ok = image_reading_available();              // false in a build without stb_image.h
//   if (s && ok) s = read_image("photo.png", img);    // img.width, height, channels (1..4), bits
//   if (s && ok) {
//       std::uint16_t v = img.sample(1, 2, 0);        // 0..255 (bits 8) or 0..65535 (bits 16)
//   }
//   return s;
//   #include "shitsukan/image/image_io.hpp"
//
// 16-bit PNGs keep their 16 bits (bits = 16); every other file is read as 8-bit.
// The file is read whole within the memory budget and checked before stb_image decodes it.
// Errors: a missing file -> io_error with the C library's reason; an undecodable one -> io_error
// with stb_image's reason; a header that claims more samples than kImageMaxExpansion times the
// file's size, a PNG chunk past the file's end, over 2^31 - 1 bytes or no IEND, a JPEG segment
// past the end, a Huffman table over 256 codes or no EOI (a truncated or broken file) ->
// invalid_argument, and more than the memory budget -> too_large, all before
// decoding; a build without the stb_image header -> not_supported. Host side.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"

namespace shitsukan {

struct LoadedImage {
    int width = 0, height = 0, channels = 0, bits = 8;
    std::vector<std::uint16_t> samples;  // width·height·channels, top row first
    std::uint16_t sample(int x, int y, int c) const {
        return samples[(std::size_t(y) * std::size_t(width) + std::size_t(x)) *
                           std::size_t(channels) +
                       std::size_t(c)];
    }
};

// Decoded bytes one byte of file can hold, at most (chosen here: deflate's limit, 1032:1, as in
// a PNG of one colour, rounded up; JPEG and the RLE formats pack less). An LZW GIF can pack
// more; no height map needs such a GIF.
constexpr std::uint64_t kImageMaxExpansion = 1100;

Status read_image(const char* path, LoadedImage& out);
bool image_reading_available();

}  // namespace shitsukan
