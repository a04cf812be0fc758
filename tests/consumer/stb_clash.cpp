// A program with its own stb_image_write implementation, linked with libshitsukan.a (which
// writes PNGs with stb_image_write too, compiled privately). It must link without "multiple
// definition of stbi_..." and both writers must work. Built by `make check-api`.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <cstdio>

#include "shitsukan/image/image_io.hpp"

int main(int argc, char** argv) {
    if (argc < 3) return std::fprintf(stderr, "usage: stb_clash own.png ours.png\n"), 2;
    stbi_write_tga_with_rle = 0;  // the program's own stb globals are its own
    const unsigned char pixels[2 * 2 * 3] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    if (!stbi_write_png(argv[1], 2, 2, 3, pixels, 6)) return 1;
    shitsukan::RgbImage image(2, 2, shitsukan::Rgb8{10, 20, 30});
    shitsukan::Status s = shitsukan::write_png(argv[2], image.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("stb_clash: own stb and shitsukan's both wrote their PNGs\n");
    return 0;
}
