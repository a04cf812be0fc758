// Tests for lib/shitsukan/image/png16: checksums against known values, the file layout,
// and round trips through stb_image's independent 16-bit decoder (stbi_load_16).
#include <doctest/doctest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "shitsukan/image/png16.hpp"

// stb_image (libstb-dev) is the reference decoder; its implementation lives in this test
// file only. Its own code is not ours to make warning-free.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

using namespace shitsukan;

namespace {

std::vector<unsigned char> read_file(const char* path) {
    std::vector<unsigned char> bytes;
    std::FILE* f = std::fopen(path, "rb");
    if (!f) return bytes;
    unsigned char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.insert(bytes.end(), buf, buf + n);
    std::fclose(f);
    return bytes;
}

std::uint32_t be32(const unsigned char* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
           std::uint32_t(p[3]);
}

// A deterministic test pattern covering 0, 65535 and byte-order-sensitive values.
std::uint16_t pattern(int x, int y, int c) {
    std::uint32_t v = (std::uint32_t(x) * 2654435761u) ^ (std::uint32_t(y) * 40503u) ^
                      (std::uint32_t(c) * 977u);
    if ((x + y) % 17 == 0) return 0;
    if ((x + y) % 19 == 0) return 65535;
    return std::uint16_t(v ^ (v >> 16));
}

}  // namespace

TEST_CASE("CRC-32 and Adler-32 match their published check values") {
    const char* check = "123456789";
    const auto* p = reinterpret_cast<const std::uint8_t*>(check);
    CHECK(detail::crc32(p, 9) == 0xCBF43926u);  // the standard CRC-32 check value
    CHECK(detail::crc32(p, 0) == 0u);
    const char* wiki = "Wikipedia";
    CHECK(detail::adler32(reinterpret_cast<const std::uint8_t*>(wiki), 9) == 0x11E60398u);
    CHECK(detail::adler32(p, 0) == 1u);
    // Incremental = one shot.
    std::uint32_t a = detail::adler32_update(1u, p, 4);
    CHECK(detail::adler32_update(a, p + 4, 5) == detail::adler32(p, 9));
    // Many 0xFF bytes exercise the modulo.
    std::vector<std::uint8_t> ff(100000, 0xFF);
    std::uint64_t s1 = 1, s2 = 0;
    for (std::uint8_t b : ff) {
        s1 = (s1 + b) % 65521;
        s2 = (s2 + s1) % 65521;
    }
    CHECK(detail::adler32(ff.data(), ff.size()) == std::uint32_t((s2 << 16) | s1));
}

TEST_CASE("write_png16 gray: layout and stbi_load_16 round trip of every sample") {
    // 300 x 200: 120 KB of samples, several stored deflate blocks, a block edge inside a row.
    const int W = 300, H = 200;
    Gray16Image img(W, H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) img.at(x, y) = pattern(x, y, 0);
    const char* path = "build/test_png16_gray.png";
    REQUIRE(write_png16(path, img.view()).ok());

    std::vector<unsigned char> bytes = read_file(path);
    REQUIRE(bytes.size() > 8 + 25 + 12);
    const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    CHECK(std::memcmp(bytes.data(), sig, 8) == 0);
    CHECK(be32(&bytes[8]) == 13);
    CHECK(std::memcmp(&bytes[12], "IHDR", 4) == 0);
    CHECK(be32(&bytes[16]) == W);
    CHECK(be32(&bytes[20]) == H);
    CHECK(bytes[24] == 16);
    CHECK(bytes[25] == 0);
    CHECK(be32(&bytes[29]) == detail::crc32(&bytes[12], 17));
    // Every chunk's CRC is right, and the chunks are IHDR, IDAT, IEND.
    std::vector<std::string> types;
    std::size_t pos = 8;
    while (pos + 12 <= bytes.size()) {
        std::uint32_t len = be32(&bytes[pos]);
        REQUIRE(pos + 12 + len <= bytes.size());
        types.push_back(std::string(reinterpret_cast<const char*>(&bytes[pos + 4]), 4));
        CHECK(be32(&bytes[pos + 8 + len]) == detail::crc32(&bytes[pos + 4], len + 4));
        pos += 12 + len;
    }
    CHECK(pos == bytes.size());
    CHECK(types == std::vector<std::string>{"IHDR", "IDAT", "IEND"});
    // Size: never more than raw samples + filter bytes + zlib framing of stored blocks (the
    // encoder keeps the stored form when deflate does not shrink the data).
    std::size_t raw = std::size_t(H) * (1 + 2 * W);
    std::size_t blocks = (raw + 65534) / 65535;
    CHECK(bytes.size() <= 8 + 25 + (12 + 2 + raw + 5 * blocks + 4) + 12);

    int w = 0, h = 0, channels = 0;
    stbi_us* back = stbi_load_16(path, &w, &h, &channels, 0);
    REQUIRE(back != nullptr);
    CHECK(w == W);
    CHECK(h == H);
    CHECK(channels == 1);
    int wrong = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) wrong += back[y * W + x] != img.at(x, y);
    CHECK(wrong == 0);
    stbi_image_free(back);
    std::remove(path);
}

TEST_CASE("write_png16 RGB from a strided window: stbi_load_16 round trip") {
    const int W = 97, H = 61;
    Rgb16Image big(W + 10, H + 4);
    for (int y = 0; y < big.height(); ++y)
        for (int x = 0; x < big.width(); ++x)
            big.at(x, y) = Rgb16{pattern(x, y, 0), pattern(x, y, 1), pattern(x, y, 2)};
    Rgb16View window = big.view().subview(3, 2, W, H);
    const char* path = "build/test_png16_rgb.png";
    REQUIRE(write_png16(path, window).ok());
    int w = 0, h = 0, channels = 0;
    stbi_us* back = stbi_load_16(path, &w, &h, &channels, 0);
    REQUIRE(back != nullptr);
    CHECK(w == W);
    CHECK(h == H);
    CHECK(channels == 3);
    int wrong = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const stbi_us* p = back + 3 * (y * W + x);
            Rgb16 e = window.at(x, y);
            wrong += p[0] != e.r || p[1] != e.g || p[2] != e.b;
        }
    CHECK(wrong == 0);
    stbi_image_free(back);
    std::remove(path);
    // A 1 x 1 image is the smallest valid file.
    Rgb16Image one(1, 1, Rgb16{1, 256, 65535});
    REQUIRE(write_png16(path, one.view()).ok());
    back = stbi_load_16(path, &w, &h, &channels, 0);
    REQUIRE(back != nullptr);
    CHECK(back[0] == 1);
    CHECK(back[1] == 256);
    CHECK(back[2] == 65535);
    stbi_image_free(back);
    std::remove(path);
}

TEST_CASE("write_png16 errors: empty image, empty path, unwritable path, too large") {
    Gray16Image empty;
    Status s = write_png16("build/never.png", empty.view());
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("empty") != std::string::npos);
    Gray16Image one(2, 2, 7);
    CHECK(write_png16("", one.view()).code() == StatusCode::invalid_argument);
    CHECK(write_png16(nullptr, one.view()).code() == StatusCode::invalid_argument);
    s = write_png16("/nonexistent-dir/h.png", one.view());
    CHECK(s.code() == StatusCode::io_error);
    CHECK(std::string(s.message()).find("/nonexistent-dir/h.png") != std::string::npos);
    // A view that claims 40000 x 40000 RGB samples (9.6 GB) is refused before any access.
    Rgb16 pixel;
    Rgb16View huge{&pixel, 40000, 40000, 40000};
    s = write_png16("build/never.png", huge);
    CHECK(s.code() == StatusCode::too_large);
    std::FILE* f = std::fopen("build/never.png", "rb");
    CHECK(f == nullptr);
    if (f) std::fclose(f);
}
