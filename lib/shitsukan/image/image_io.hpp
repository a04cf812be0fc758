// shitsukan/image/image_io.hpp — write images as PNG (stb_image_write) or PPM/PGM.
//
// Manual
//   RgbImage img(64, 32, Rgb8{255, 128, 0});
//   GrayImage gray(64, 32);
//   Status s = write_png("out.png", img.view());        // RgbView or GrayView
//   if (s) s = write_ppm("out.ppm", img.view());        // binary P6
//   if (s) s = write_pgm("out.pgm", gray.view());       // binary P5
//   return s;
// Failures (empty image, unwritable path, a failed write) come back as a Status with the path
// and the reason in the message; nothing is silent. Files are written through
// core/output_file.hpp: complete under their name, or not there (an old file is kept). Views with a stride are handled.
// PNG: compressed by stb_image_write when the library was built with its header (compiled
// privately, no stbi_* symbol leaves the library); otherwise by the library's own encoder
// in stored (uncompressed) deflate blocks: same pixels, bigger files. png_compressed() says
// which. Host side: PNG encoding allocates.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/image/image.hpp"

namespace shitsukan {

Status write_png(const char* path, const RgbView& image);
Status write_png(const char* path, const GrayView& image);
Status write_ppm(const char* path, const RgbView& image);
Status write_pgm(const char* path, const GrayView& image);
// True when write_png compresses (built with stb_image_write), false for the fallback.
bool png_compressed();

}  // namespace shitsukan
