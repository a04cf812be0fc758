// Tests for lib/shitsukan/image/exr: the header says what the format requires, an uncompressed
// file holds the floats bit for bit where its offset table points, a zip file is smaller on a
// smooth map, bad arguments are refused. (The bit-exact read back through an independent
// reader, OpenImageIO, is in tests/cli/run.sh with tests/cli/exr_readback.py.)
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "shitsukan/image/exr.hpp"

using namespace shitsukan;

namespace {
std::string temp_path(const char* name) {
    return std::string("/tmp/shitsukan_exr_") + std::to_string(getpid()) + "_" + name;
}
std::vector<std::uint8_t> slurp(const std::string& path) {
    std::vector<std::uint8_t> b;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return b;
    int c;
    while ((c = std::fgetc(f)) != EOF) b.push_back(std::uint8_t(c));
    std::fclose(f);
    return b;
}
std::uint32_t u32(const std::vector<std::uint8_t>& b, std::size_t at) {
    return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
           std::uint32_t(b[at + 3]) << 24;
}
bool contains(const std::vector<std::uint8_t>& b, const char* text) {
    const std::string s(b.begin(), b.end());
    return s.find(text) != std::string::npos;
}
}  // namespace

TEST_CASE("write_exr: an uncompressed file holds every float bit for bit, channels B, G, R") {
    const int w = 7, h = 5;
    std::vector<float> rgb(std::size_t(w * h * 3));
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = float(i) * 0.37f - 3.0f;
    rgb[4] = std::nanf("");
    rgb[5] = -0.0f;
    ExrOptions none;
    none.compression = ExrCompression::none;
    const std::string path = temp_path("rgb.exr");
    REQUIRE(write_exr(path.c_str(), rgb.data(), w, h, 3, none));
    const std::vector<std::uint8_t> b = slurp(path);
    REQUIRE(b.size() > 8);
    CHECK(u32(b, 0) == 20000630u);  // 76 2f 31 01
    CHECK(u32(b, 4) == 2u);
    for (const char* name : {"channels", "chlist", "compression", "dataWindow", "displayWindow",
                             "lineOrder", "pixelAspectRatio", "screenWindowCenter",
                             "screenWindowWidth"})
        CHECK(contains(b, name));
    // the offset table follows the header's closing NUL: find it from the first chunk's offset
    const std::size_t table = b.size() - std::size_t(h) * (8 + 4 + 4 + std::size_t(w) * 12);
    for (int y = 0; y < h; ++y) {
        std::uint64_t offset = u32(b, table + 8 * std::size_t(y));
        CHECK(u32(b, offset) == std::uint32_t(y));
        CHECK(u32(b, offset + 4) == std::uint32_t(w * 12));
        for (int c = 0; c < 3; ++c)  // file order B, G, R
            for (int x = 0; x < w; ++x) {
                const float want = rgb[(std::size_t(y) * w + x) * 3 + std::size_t(2 - c)];
                std::uint32_t bits;
                std::memcpy(&bits, &want, 4);
                CHECK(u32(b, offset + 8 + 4 * (std::size_t(c) * w + x)) == bits);
            }
    }
    std::remove(path.c_str());
}

TEST_CASE("write_exr: zip compression shrinks a quantised height map (a 16-bit map as floats)") {
    const int w = 256, h = 256;
    std::vector<float> height(std::size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            height[std::size_t(y) * w + x] = std::round(1024.0f * std::sin(float(x) * 0.05f) * std::cos(float(y) * 0.03f)) / 1024.0f;
    ExrOptions none;
    none.compression = ExrCompression::none;
    const std::string raw = temp_path("raw.exr"), zip = temp_path("zip.exr");
    REQUIRE(write_exr(raw.c_str(), height.data(), w, h, 1, none));
    REQUIRE(write_exr(zip.c_str(), height.data(), w, h, 1));
    const std::vector<std::uint8_t> a = slurp(raw), z = slurp(zip);
    MESSAGE("256 x 256 float height: raw " << a.size() << " bytes, zip " << z.size());
    CHECK(z.size() < a.size() * 3 / 4);
    CHECK(contains(z, "compression"));
    std::remove(raw.c_str());
    std::remove(zip.c_str());
}

TEST_CASE("write_exr: refuses what it cannot write") {
    float v[4] = {0, 0, 0, 0};
    CHECK(write_exr("", v, 1, 1, 1).code() == StatusCode::invalid_argument);
    CHECK(write_exr("/tmp/x.exr", nullptr, 1, 1, 1).code() == StatusCode::invalid_argument);
    CHECK(write_exr("/tmp/x.exr", v, 0, 1, 1).code() == StatusCode::invalid_argument);
    CHECK(write_exr("/tmp/x.exr", v, 1, 1, 2).code() == StatusCode::invalid_argument);
    CHECK(!write_exr("/nonexistent_dir/x.exr", v, 2, 2, 1));
}
