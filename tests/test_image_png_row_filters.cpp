// Tests for lib/shitsukan/image/png_row_filters (and write_png's PNG built from it): the rows
// and the whole file the same bytes as stb_image_write's own (compiled here, without the
// library's hooks) on images that make each filter win.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/png_row_filters.hpp"

// stb_image_write's reference encoder, private to this file. Its own code is not ours to make
// warning-free.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

using namespace shitsukan;

namespace {

std::vector<unsigned char> file_bytes(const char* path) {
    std::vector<unsigned char> bytes;
    std::FILE* f = std::fopen(path, "rb");
    if (!f) return bytes;
    unsigned char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.insert(bytes.end(), buf, buf + n);
    std::fclose(f);
    return bytes;
}

std::vector<unsigned char> stb_png(const unsigned char* pixels, int stride, int w, int h, int n) {
    int length = 0;
    unsigned char* png = stbi_write_png_to_mem(pixels, stride, w, h, n, &length);
    std::vector<unsigned char> v(png, png + length);
    std::free(png);
    return v;
}

// Pixel patterns: noise (None or Sub), horizontal ramps (Sub), vertical ramps (Up), smooth
// 2D gradients (Average, Paeth), flat areas; byte wrap-around everywhere.
unsigned char pattern(int kind, int x, int y, int c, std::uint32_t& s) {
    s = s * 1664525u + 1013904223u;
    switch (kind) {
        case 0: return static_cast<unsigned char>(s >> 24);
        case 1: return static_cast<unsigned char>(x * 7 + c * 50);
        case 2: return static_cast<unsigned char>(y * 9 + c * 30);
        case 3: return static_cast<unsigned char>((x * x + y * y) / 7 + c);
        case 4: return static_cast<unsigned char>(x * 3 + y * 5 + ((s >> 28) & 1));
        default: return static_cast<unsigned char>((x / 16 + y / 16) % 2 ? 240 : 17);
    }
}

}  // namespace

TEST_CASE("png_filter_rows_like_stb and write_png: stb's bytes, row filters and whole files") {
    const char* path = "build/test_png_row_filters.png";
    for (int kind = 0; kind < 6; ++kind)
        for (const int size : {1, 2, 37}) {
            const int w = size * 3 + kind, h = size * 2 + 1;
            std::uint32_t s = std::uint32_t(kind * 100 + size);
            RgbImage big(w + 5, h);
            GrayImage gray(w, h);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w + 5; ++x) {
                    big.at(x, y) = Rgb8{pattern(kind, x, y, 0, s), pattern(kind, x, y, 1, s),
                                        pattern(kind, x, y, 2, s)};
                    if (x < w) gray.at(x, y) = pattern(kind, x, y, 1, s);
                }
            const RgbView rgb = big.view().subview(2, 0, w, h);  // a stride wider than the row
            const auto* rgb_bytes = reinterpret_cast<const unsigned char*>(rgb.pixels);
            REQUIRE(write_png(path, rgb).ok());
            CHECK(file_bytes(path) == stb_png(rgb_bytes, rgb.stride * 3, w, h, 3));
            REQUIRE(write_png(path, gray.view()).ok());
            const auto* gray_bytes = reinterpret_cast<const unsigned char*>(gray.view().pixels);
            CHECK(file_bytes(path) == stb_png(gray_bytes, gray.view().stride, w, h, 1));
        }
    std::remove(path);
}

TEST_CASE("png_filter_rows_like_stb: each row's type is the one with the least sum of |byte|") {
    // Row 0 a ramp along x (Sub leaves ones), row 1 the same ramp (Up leaves zeros).
    unsigned char pixels[2 * 8];
    for (int x = 0; x < 8; ++x) pixels[x] = pixels[8 + x] = static_cast<unsigned char>(100 + x);
    unsigned char rows[2 * 9];
    png_filter_rows_like_stb(pixels, 8, 8, 2, 1, rows);
    CHECK(rows[0] == 1);
    CHECK(rows[1] == 100);
    for (int x = 1; x < 8; ++x) CHECK(rows[1 + x] == 1);
    CHECK(rows[9] == 2);
    for (int x = 0; x < 8; ++x) CHECK(rows[10 + x] == 0);
}
