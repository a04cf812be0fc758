// Tests for lib/shitsukan/image/normal_map: the height-field normal (-s h_x, -s h_y, 1)/|.| of
// a height map, its axes (y up the image), borders, wrap and the RGB encoding.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <doctest/doctest.h>
#include "shitsukan/image/normal_map.hpp"

using namespace shitsukan;

TEST_CASE("height_map_normals: a plane gives its exact normal everywhere, y up the image") {
    const int w = 7, h = 5;
    std::vector<float> height(w * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) height[y * w + x] = 0.01f * x + 0.02f * y;  // rises down
    HeightNormalOptions o;
    o.strength = 10.0f;
    std::vector<Vec3> n(height.size());
    REQUIRE(height_map_normals(height.data(), w, h, o, n.data()).ok());
    // h_x = 0.01, h_y(up) = -0.02 per pixel: n = (-0.1, +0.2, 1) / |.|, at borders too
    const float len = std::sqrt(0.01f + 0.04f + 1.0f);
    for (const Vec3& v : n) {
        CHECK(v.x == doctest::Approx(-0.1f / len).epsilon(1e-4));
        CHECK(v.y == doctest::Approx(0.2f / len).epsilon(1e-4));
        CHECK(v.z == doctest::Approx(1.0f / len).epsilon(1e-4));
    }
}

TEST_CASE("height_map_normals: wrap differences across the borders (tileable maps)") {
    const int w = 32, h = 16;
    const float pi = 3.14159265f;
    std::vector<float> height(w * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            height[y * w + x] = 0.5f + 0.25f * std::cos(2 * pi * x / w) * std::cos(2 * pi * y / h);
    HeightNormalOptions o;
    o.strength = 20.0f;
    o.wrap = true;
    std::vector<Vec3> n(height.size());
    REQUIRE(height_map_normals(height.data(), w, h, o, n.data()).ok());
    // the border column takes its differences across the border, like any other column
    for (int y = 0; y < h; ++y) {
        const float hx = (height[y * w + 1] - height[y * w + w - 1]) / 2;
        const float hy_up = -(height[((y + 1) % h) * w] - height[((y + h - 1) % h) * w]) / 2;
        const Vec3 want = normalize(Vec3{-o.strength * hx, -o.strength * hy_up, 1.0f});
        CHECK(n[y * w].x == doctest::Approx(want.x).epsilon(1e-5));
        CHECK(n[y * w].y == doctest::Approx(want.y).epsilon(1e-5));
        CHECK(std::fabs(length(n[y * w]) - 1.0f) < 1e-5f);
    }
    o.wrap = false;  // without wrap the border uses one-sided differences: different there
    std::vector<Vec3> m(height.size());
    REQUIRE(height_map_normals(height.data(), w, h, o, m.data()).ok());
    CHECK(std::fabs(m[3 * w].x - n[3 * w].x) > 1e-3f);
    CHECK(m[3 * w + 5].x == n[3 * w + 5].x);  // inside: the same
}

TEST_CASE("height_map_normals: bad input and the RGB encoding") {
    float one = 0.5f;
    Vec3 n;
    HeightNormalOptions o;
    CHECK(height_map_normals(nullptr, 1, 1, o, &n).code() == StatusCode::invalid_argument);
    CHECK(height_map_normals(&one, 0, 1, o, &n).code() == StatusCode::invalid_argument);
    o.strength = NAN;
    CHECK(height_map_normals(&one, 1, 1, o, &n).code() == StatusCode::invalid_argument);
    o.strength = 3.0f;
    REQUIRE(height_map_normals(&one, 1, 1, o, &n).ok());  // a single pixel: flat
    CHECK(n.z == 1.0f);
    const Vec3 v[2] = {{0, 0, 1}, {-1, 1, 0}};
    std::uint8_t rgb[6];
    encode_normal_rgb8(v, 2, rgb);
    CHECK(rgb[0] == 128);
    CHECK(rgb[2] == 255);
    CHECK(rgb[3] == 0);
    CHECK(rgb[4] == 255);
}

TEST_CASE("height_map_normals: non-finite heights and overflowing slopes are refused, steep "
          "finite slopes give unit normals") {
    const int w = 4, h = 3;
    HeightNormalOptions o;
    o.strength = 8.0f;
    std::vector<Vec3> n(w * h);
    const float bad_heights[] = {std::nanf(""), INFINITY, -INFINITY};
    for (float bad : bad_heights) {
        std::vector<float> height(w * h, 0.5f);
        height[1 * w + 2] = bad;
        const Status s = height_map_normals(height.data(), w, h, o, n.data());
        CHECK(s.code() == StatusCode::invalid_argument);
        CHECK(std::string(s.message()).find("(2, 1)") != std::string::npos);
    }
    // +-3e38 next to each other: the difference overflows a float.
    std::vector<float> height(w * h, 0.0f);
    height[1] = 3e38f, height[3] = -3e38f;
    const Status s = height_map_normals(height.data(), w, h, o, n.data());
    CHECK(s.code() == StatusCode::out_of_range);
    CHECK(std::string(s.message()).find("overflows") != std::string::npos);
    // A steep but finite slope (1e30 per pixel, squares past FLT_MAX): a unit normal along -x.
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) height[y * w + x] = 1e30f * float(x);
    REQUIRE(height_map_normals(height.data(), w, h, o, n.data()).ok());
    for (const Vec3& v : n) {
        CHECK(v.x == doctest::Approx(-1.0f).epsilon(1e-6));
        CHECK(std::fabs(v.y) < 1e-6f);
        CHECK(v.z >= 0.0f);
        CHECK(std::isfinite(v.z));
    }
}
