// shitsukan/image/deflate.hpp — a zlib stream (RFC 1950) of DEFLATE data (RFC 1951) with
// LZ77 matches and dynamic Huffman codes: the compressor of the 16-bit PNGs (png16.hpp).
//
// Manual
//   const std::uint8_t data[] = "a row, a row, a row of bytes";
//   std::vector<std::uint8_t> z;
//   Status s = zlib_deflate(data, sizeof data, z);   // any zlib inflater reads it back
//
// How (RFC 1951 §3.2): LZ77 over a 32 KiB window, candidates from a hash chain of 3-byte
// prefixes (at most kDeflateChain tried per position, chosen: 32; 128 gains 1.5 % on a
// height map at 1.4x the time), the longest match (3..258 bytes) taken lazily: a match shorter
// than kDeflateLazy is given up for a literal when the next position starts a longer one.
// Every 65536 symbols form one
// block with dynamic Huffman codes (BTYPE 2): code lengths from the block's frequencies,
// limited to 15 bits (7 for the code-length code) by halving the frequencies until they fit
// (chosen: simple, a fraction of a percent above optimal), the code lengths run-length coded
// with symbols 16, 17, 18. zlib header 78 9C, Adler-32 trailer.
// Errors: null data with a size, more than 2^31 bytes -> invalid_argument / too_large.
// Host side (allocates the window tables and the output).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"

namespace shitsukan {

// RFC 1951 §3.2.5: the base and extra bits of length codes 257..285 and distance codes 0..29,
// shared by the two compressors (zlib_deflate here, fixed_huffman_zlib.hpp).
namespace detail {
inline constexpr int kLenBase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                     31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
inline constexpr int kLenExtra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                      2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
inline constexpr int kDistBase[30] = {1,    2,    3,    4,    5,    7,    9,    13,    17,    25,
                                      33,   49,   65,   97,   129,  193,  257,  385,   513,   769,
                                      1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
inline constexpr int kDistExtra[30] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                       6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
}  // namespace detail


constexpr int kDeflateChain = 32;
constexpr int kDeflateLazy = 32;  // a match this long is taken without looking one byte on

Status zlib_deflate(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>& out);

}  // namespace shitsukan
