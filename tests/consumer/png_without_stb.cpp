// Linked with image_io.cpp compiled with -DSHITSUKAN_NO_STB (as a build without libstb-dev
// gets it) ahead of libshitsukan.a: write_png must still write a PNG, with the library's own
// encoder. Built by `make check-api`.
#include <cstdio>
#include <cstring>

#include "shitsukan/image/image_io.hpp"

int main(int argc, char** argv) {
    if (argc < 2) return std::fprintf(stderr, "usage: png_without_stb out.png\n"), 2;
    if (shitsukan::png_compressed()) return std::fprintf(stderr, "stb was compiled in\n"), 1;
    shitsukan::RgbImage image(3, 2, shitsukan::Rgb8{10, 20, 30});
    shitsukan::Status s = shitsukan::write_png(argv[1], image.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    unsigned char head[8] = {0};
    std::FILE* f = std::fopen(argv[1], "rb");
    const bool read = f && std::fread(head, 1, 8, f) == 8;
    if (f) std::fclose(f);
    const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (!read || std::memcmp(head, png, 8) != 0) return std::fprintf(stderr, "not a PNG\n"), 1;
    std::printf("png_without_stb: write_png works without stb_image_write (own encoder)\n");
    return 0;
}
