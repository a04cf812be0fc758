// shitsukan/image/png16.hpp — 16-bit PNG output (height maps, high-precision gray/RGB).
//
// Manual
//   Gray16Image height(512, 512);                  // 0 .. 65535 per sample
//   Status s = write_png16("height.png", height.view());
//   Rgb16Image rgb(256, 256, Rgb16{65535, 0, 0});
//   if (s) s = write_png16("normals.png", rgb.view());
//   return s;
// stb_image_write only writes 8-bit PNGs, so this is a small encoder of its own, following
// the PNG specification (ISO/IEC 15948): the 8-byte signature, then chunks
// (length, type, data, CRC-32 of type + data): IHDR (size, bit depth 16, colour type 0 =
// gray or 2 = RGB, no interlace), one IDAT holding a zlib stream (RFC 1950: header 78 01,
// the deflate data, the Adler-32 of the raw bytes) and IEND. The deflate data (RFC 1951)
// is compressed by the library's own deflate (image/deflate.hpp: LZ77 + dynamic Huffman
// codes, no dependency): each row is first filtered (None, Sub, Up, Average or Paeth,
// whichever gives the smallest sum of |residual|, PNG spec 12.8; for 16-bit rows the residual
// of each sample is read as one signed 16-bit value, so a carry between its bytes does not
// count as a large residual), then the whole image is deflated (lazy matching), kept only
// when smaller than the stored form (noise does not shrink). Measured at 4096 x 4096 (33.6 MB
// raw): the `shitsukan leather --size 4096` height map -> 12.38 MB (2.71x; 2.64x with byte
// sums and greedy matching), a smooth sine map -> 8.64 MB (3.89x), a linear ramp -> 0.24 MB
// (139x). zlib -9 on the same filtered rows gives 12.10 MB (2.77x): PNG's byte-wise filters
// have no planar predictor (a + b - c, whose residuals would carry 3.9 bits a pixel here), so
// the low bytes of a curved slope stay near-random and 3x is out of reach for this relief.
// The stored
// form, the 8-bit fallback of write_png, is made of uncompressed blocks of at most 65535
// bytes, streamed through a one-row buffer. Views with a stride are handled.
// Errors: empty image or path -> invalid_argument; an image whose data would not fit one
// PNG chunk (2^31 - 1 bytes) -> too_large; open or write failures -> io_error (the path
// and the reason are in the message; the file is written through core/output_file.hpp:
// complete or not there). Host side (stdio).
#pragma once

#include <cstddef>
#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/image/image.hpp"

namespace shitsukan {

struct Rgb16 {
    std::uint16_t r = 0, g = 0, b = 0;
};
inline bool operator==(Rgb16 a, Rgb16 b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
inline bool operator!=(Rgb16 a, Rgb16 b) { return !(a == b); }

using Rgb16View = ImageView<Rgb16>;
using Rgb16Image = Image<Rgb16>;

Status write_png16(const char* path, const Gray16View& image);
Status write_png16(const char* path, const Rgb16View& image);

namespace detail {
// The two checksums, exposed for the tests (known vectors).
std::uint32_t crc32_update(std::uint32_t crc, const std::uint8_t* data, std::size_t size);
std::uint32_t crc32(const std::uint8_t* data, std::size_t size);     // PNG / zlib CRC-32
std::uint32_t adler32_update(std::uint32_t adler, const std::uint8_t* data, std::size_t size);
std::uint32_t adler32(const std::uint8_t* data, std::size_t size);   // zlib Adler-32
// The same encoder at bit depth 8 (stored deflate blocks): write_png's fallback when the
// library is built without stb_image_write (image_io.hpp).
Status write_png8_stored(const char* path, const std::uint8_t* pixels, int width, int height,
                         int channels, std::size_t row_stride_bytes, bool empty);
}  // namespace detail

}  // namespace shitsukan
