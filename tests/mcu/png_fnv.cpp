// tests/mcu/png_fnv.cpp — prints the FNV-1a 64 hash of a PNG's RGB bytes (rows top to bottom),
// the same digest ports/cortex-m/transcript.cpp writes for a band-rendered frame, so
// `make test-mcu` can check the device's fig. 10a against the host's paper figure PNG.
//   png_fnv FILE.png   ->   "WIDTHxHEIGHT rgb fnv 0123456789abcdef"
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb/stb_image.h>

#include <cinttypes>
#include <cstdint>
#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: png_fnv FILE.png\n");
        return 2;
    }
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(argv[1], &w, &h, &n, 3);
    if (!px) {
        std::fprintf(stderr, "png_fnv: cannot read %s: %s\n", argv[1], stbi_failure_reason());
        return 1;
    }
    std::uint64_t f = 0xcbf29ce484222325ull;
    for (long i = 0; i < long(w) * long(h) * 3; ++i) f = (f ^ px[i]) * 0x100000001b3ull;
    stbi_image_free(px);
    std::printf("%dx%d rgb fnv %016" PRIx64 "\n", w, h, f);
    return 0;
}
