// Tests for lib/shitsukan/image/image_io: PPM/PGM headers and bytes, PNG round trips through
// stb_image (its implementation is compiled in test_image_png16.cpp), error paths.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/png16.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

using namespace shitsukan;

namespace {

std::string read_file(const char* path) {
    std::string bytes;
    std::FILE* f = std::fopen(path, "rb");
    if (!f) return bytes;
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.append(buf, n);
    std::fclose(f);
    return bytes;
}

Rgb8 rgb_pattern(int x, int y) {
    return Rgb8{std::uint8_t(x * 37 + y), std::uint8_t(y * 53 ^ x), std::uint8_t((x * y) & 255)};
}

// Decodes an RGB PNG with stb_image and counts the pixels that differ from `expected`
// (a wrong size or channel count counts as every pixel wrong).
int rgb_png_pixels_wrong(const char* path, const RgbView& expected) {
    int w = 0, h = 0, n = 0;
    stbi_uc* back = stbi_load(path, &w, &h, &n, 0);
    if (back == nullptr) return expected.width * expected.height;
    int wrong = 0;
    if (w != expected.width || h != expected.height || n != 3) {
        wrong = expected.width * expected.height;
    } else {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const stbi_uc* p = back + 3 * (y * w + x);
                const Rgb8 e = expected.at(x, y);
                wrong += p[0] != e.r || p[1] != e.g || p[2] != e.b;
            }
    }
    stbi_image_free(back);
    return wrong;
}

}  // namespace

TEST_CASE("write_ppm: P6 header then raw RGB bytes, row by row, stride respected") {
    RgbImage big(9, 6);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 9; ++x) big.at(x, y) = rgb_pattern(x, y);
    RgbView window = big.view().subview(2, 1, 5, 4);
    const char* path = "build/test_image_io.ppm";
    REQUIRE(write_ppm(path, window).ok());
    std::string bytes = read_file(path);
    const std::string header = "P6\n5 4\n255\n";
    REQUIRE(bytes.size() == header.size() + 5 * 4 * 3);
    CHECK(bytes.compare(0, header.size(), header) == 0);
    std::size_t i = header.size();
    int wrong = 0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) {
            Rgb8 e = window.at(x, y);
            wrong += std::uint8_t(bytes[i]) != e.r || std::uint8_t(bytes[i + 1]) != e.g ||
                     std::uint8_t(bytes[i + 2]) != e.b;
            i += 3;
        }
    CHECK(wrong == 0);
    std::remove(path);
}

TEST_CASE("write_pgm: P5 header then raw gray bytes") {
    GrayImage img(7, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 7; ++x) img.at(x, y) = std::uint8_t(x * 40 + y);
    const char* path = "build/test_image_io.pgm";
    REQUIRE(write_pgm(path, img.view()).ok());
    std::string bytes = read_file(path);
    const std::string header = "P5\n7 3\n255\n";
    REQUIRE(bytes.size() == header.size() + 21);
    CHECK(bytes.compare(0, header.size(), header) == 0);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 7; ++x)
            CHECK(std::uint8_t(bytes[header.size() + std::size_t(y * 7 + x)]) == img.at(x, y));
    std::remove(path);
}

TEST_CASE("write_png 8-bit RGB and gray: stbi_load round trip of every byte") {
    RgbImage big(40, 30);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) big.at(x, y) = rgb_pattern(x, y);
    RgbView window = big.view().subview(5, 3, 31, 22);  // odd width, strided rows
    const char* path = "build/test_image_io.png";
    REQUIRE(write_png(path, window).ok());
    CHECK(rgb_png_pixels_wrong(path, window) == 0);

    GrayImage gray(13, 9);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 13; ++x) gray.at(x, y) = std::uint8_t(x * 19 + y * 7);
    REQUIRE(write_png(path, gray.view()).ok());
    int w = 0, h = 0, n = 0;
    stbi_uc* back = stbi_load(path, &w, &h, &n, 0);
    REQUIRE(back != nullptr);
    CHECK(n == 1);
    int wrong = 0;
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 13; ++x) wrong += back[y * 13 + x] != gray.at(x, y);
    CHECK(wrong == 0);
    stbi_image_free(back);
    std::remove(path);
}

TEST_CASE("image writers report errors: empty image, empty path, unwritable path") {
    RgbImage empty_rgb;
    GrayImage empty_gray;
    RgbImage rgb(2, 2);
    GrayImage gray(2, 2);
    const char* bad = "/nonexistent-dir/out";
    CHECK(write_ppm("build/never.ppm", empty_rgb.view()).code() == StatusCode::invalid_argument);
    CHECK(write_pgm("build/never.pgm", empty_gray.view()).code() == StatusCode::invalid_argument);
    CHECK(write_png("build/never.png", empty_rgb.view()).code() == StatusCode::invalid_argument);
    CHECK(write_png("build/never.png", empty_gray.view()).code() == StatusCode::invalid_argument);
    CHECK(write_ppm("", rgb.view()).code() == StatusCode::invalid_argument);
    CHECK(write_pgm(nullptr, gray.view()).code() == StatusCode::invalid_argument);
    Status s = write_ppm(bad, rgb.view());
    CHECK(s.code() == StatusCode::io_error);
    CHECK(std::string(s.message()).find(bad) != std::string::npos);
    CHECK(write_pgm(bad, gray.view()).code() == StatusCode::io_error);
    CHECK(write_png(bad, rgb.view()).code() == StatusCode::io_error);
    CHECK(write_png(bad, gray.view()).code() == StatusCode::io_error);
    // "Empty" includes a view with pixels but zero width.
    RgbView zero{rgb.data(), 0, 2, 2};
    CHECK(write_ppm("build/never.ppm", zero).code() == StatusCode::invalid_argument);
}

TEST_CASE("write_png's fallback encoder (no stb): stored deflate, stbi_load round trip") {
    // The encoder write_png uses when the library is built without stb_image_write.
    RgbImage big(40, 30);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) big.at(x, y) = rgb_pattern(x, y);
    RgbView window = big.view().subview(5, 3, 31, 22);
    const char* path = "build/test_image_io_fallback.png";
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(window.pixels);
    REQUIRE(detail::write_png8_stored(path, bytes, window.width, window.height, 3,
                                      std::size_t(window.stride) * 3, false)
                .ok());
    CHECK(rgb_png_pixels_wrong(path, window) == 0);
    // 8-bit samples: the file is the raw bytes (one filter byte a row) plus headers.
    CHECK(read_file(path).size() < std::size_t(22 * (1 + 31 * 3) + 100));
    CHECK(png_compressed());  // this build has stb_image_write (the Makefile installs it)
    std::remove(path);
}
