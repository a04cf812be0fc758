// shitsukan/image/png_row_filters.hpp — 8-bit image rows PNG-filtered as stb_image_write
// filters them (public domain): per row the filter (None, Sub, Up, Average, Paeth; PNG spec
// §9) whose filtered bytes, read as signed, have the smallest sum of magnitudes (ties: the
// lower type), written as that type's byte and the filtered row. The same bytes as stb's own,
// in one pass over each row instead of six; write_png compresses them (fixed_huffman_zlib).
//
// Manual
//   const unsigned char pixels[2 * 3 * 2] = {10, 20, 30, 11, 21, 31,   // 2 x 2 RGB
//                                            10, 20, 30, 11, 21, 31};
//   unsigned char rows[2 * (1 + 2 * 3)];
//   png_filter_rows_like_stb(pixels, 2 * 3, 2, 2, 3, rows);
//   // row 0: Sub (1, then 10 20 30 1 1 1); row 1: Up (2, then six zeros)
//   if (rows[0] != 1 || rows[7] != 2) return Status::error(StatusCode::io_error, "filters");
//
// Row 0 has no row above: Up, Average and Paeth there filter against zeros, as in the spec.
#pragma once

namespace shitsukan {

// pixels: height rows of width·channels bytes, stride_bytes apart. out: height·(1 +
// width·channels) bytes, each row its filter type byte and its filtered bytes.
void png_filter_rows_like_stb(const unsigned char* pixels, int stride_bytes, int width,
                              int height, int channels, unsigned char* out);

}  // namespace shitsukan
