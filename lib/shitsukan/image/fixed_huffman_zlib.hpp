// shitsukan/image/fixed_huffman_zlib.hpp — the zlib stream write_png puts in a PNG's IDAT:
// byte for byte the stream of stb_image_write's stbi_zlib_compress (public domain), found in
// a fraction of its time. image_io.cpp hands it to stb as STBIW_ZLIB_COMPRESS.
//
// Manual
//   const unsigned char data[] = "a row, a row, a row of bytes";
//   int size = 0;
//   unsigned char* z = fixed_huffman_zlib(data, int(sizeof data), &size, 8);  // stb's quality 8
//   if (z == nullptr) return Status::error(StatusCode::too_large, "out of memory");
//   bool zlib_header = size > 6 && z[0] == 0x78;  // z[0 .. size): the zlib stream
//   std::free(z);
//   return zlib_header ? Status::success() : Status::error(StatusCode::io_error, "no stream");
//
// The stream (RFC 1950/1951): header 78 5E, one block with the fixed Huffman codes (BTYPE 1),
// Adler-32; stored blocks instead when that would be longer. The matches are stb's: each
// position's 3 bytes hash (stb's hash) into one of 16384 buckets holding the positions last
// inserted there (at most 2 x quality; when full the older half is dropped); the longest
// match among them within 32 KiB wins (ties: the newest), 3..258 bytes; a match is given up
// for a literal when one at the next position is longer (lazy matching); only the positions
// where a literal or a match starts are inserted. Faster, the same choices: a candidate is
// ruled out by the one byte that decides it before it is compared in full, and bytes are
// compared eight at a time.
// Host side: allocates the bucket table and the output (malloc: stb frees it).
#pragma once

namespace shitsukan {

// data[0 .. size) compressed as stbi_zlib_compress(data, size, out_size, quality) does, in a
// buffer from std::malloc (the caller frees it); nullptr when out of memory or size < 0.
// quality below 5 counts as 5, as in stb.
unsigned char* fixed_huffman_zlib(const unsigned char* data, int size, int* out_size, int quality);

}  // namespace shitsukan
