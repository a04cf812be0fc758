// Tests for lib/shitsukan/image/height_map: a height map read from a 16-bit PNG, an 8-bit PNG
// and a PFM, the values and rows where they were written; a non-finite PFM sample and a
// missing file refused with the outputs untouched.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "shitsukan/image/height_map.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/image_read.hpp"
#include "shitsukan/image/pfm.hpp"
#include "shitsukan/image/png16.hpp"

using namespace shitsukan;

TEST_CASE("read_height_map: a 16-bit PNG's samples / 65535, row 0 at the top") {
    if (!image_reading_available()) return;  // a build without stb_image.h reads PFM only
    Gray16Image img(4, 2);
    for (int i = 0; i < 8; ++i) img.data()[i] = std::uint16_t(i * 9000);
    const std::string png = "test_image_height_map_16.png";
    REQUIRE(write_png16(png.c_str(), img.view()));
    std::vector<float> h;
    int w = 0, rows = 0;
    REQUIRE(read_height_map(png.c_str(), h, w, rows));
    CHECK(w == 4);
    CHECK(rows == 2);
    REQUIRE(h.size() == 8);
    for (int i = 0; i < 8; ++i) CHECK(h[std::size_t(i)] == float(i * 9000) * (1.0f / 65535.0f));
    std::remove(png.c_str());
}

TEST_CASE("read_height_map: an 8-bit PNG's first channel / 255") {
    if (!image_reading_available()) return;
    RgbImage img(3, 2, Rgb8{0, 0, 0});
    img.at(2, 1) = Rgb8{255, 10, 10};
    img.at(1, 0) = Rgb8{51, 200, 200};
    const std::string png = "test_image_height_map_8.png";
    REQUIRE(write_png(png.c_str(), img.view()));
    std::vector<float> h;
    int w = 0, rows = 0;
    REQUIRE(read_height_map(png.c_str(), h, w, rows));
    REQUIRE(h.size() == 6);
    CHECK(h[5] == 1.0f);
    CHECK(h[1] == 51.0f * (1.0f / 255.0f));
    CHECK(h[0] == 0.0f);
    std::remove(png.c_str());
}

TEST_CASE("read_height_map: a PFM as stored; a non-finite sample or a missing file refused") {
    const std::string pfm = "test_image_height_map.pfm";
    const float values[4] = {0.5f, -2.0f, 3.25f, 1e-3f};
    REQUIRE(write_pfm(pfm.c_str(), values, 2, 2, 1));
    std::vector<float> h;
    int w = 0, rows = 0;
    REQUIRE(read_height_map(pfm.c_str(), h, w, rows));
    CHECK(w == 2);
    CHECK(rows == 2);
    for (int i = 0; i < 4; ++i) CHECK(h[std::size_t(i)] == values[i]);

    const float bad[4] = {0.5f, 1.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f};
    REQUIRE(write_pfm(pfm.c_str(), bad, 2, 2, 1));
    const Status s = read_height_map(pfm.c_str(), h, w, rows);
    CHECK(!s);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("(0, 1)") != std::string::npos);
    CHECK(h.size() == 4);
    CHECK(h[2] == 3.25f);  // left as it was
    CHECK(!read_height_map("/nonexistent/h.pfm", h, w, rows));
    CHECK(!read_height_map(nullptr, h, w, rows));
    std::remove(pfm.c_str());
}
