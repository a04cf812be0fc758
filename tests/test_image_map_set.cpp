// Tests for lib/shitsukan/image/map_set: DirectX and OpenGL normal maps differ exactly in the
// green channel; AO is 1 on a flat map and lower in a pit than on the rim; roughness is higher
// in the pit; a tileable (wrapped) map's derived maps tile; the set's files are written.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "shitsukan/image/map_set.hpp"

using namespace shitsukan;

namespace {
// A pit: a bowl of depth 1 and radius 10 in a 64 x 48 map, plus a wave along x with period 64.
std::vector<float> pit_heights(int w, int h) {
    std::vector<float> v(std::size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float r = std::hypot(float(x - 32), float(y - 24));
            v[std::size_t(y) * w + x] = (r < 10.0f ? -std::cos(r * 0.157f) : 0.0f) +
                                        0.2f * std::sin(float(x) * 6.2831853f / 64.0f);
        }
    return v;
}
}  // namespace

TEST_CASE("map_set: DirectX normals differ from OpenGL ones exactly in the green channel") {
    const int w = 64, h = 48;
    std::vector<float> h01;
    const std::vector<float> heights = pit_heights(w, h);
    REQUIRE(normalise_heights(heights.data(), w, h, h01));
    MapSetOptions gl, dx;
    dx.normal = NormalConvention::directx;
    std::vector<Rgb8> a, b;
    REQUIRE(derive_normal_map(h01, w, h, gl, a));
    REQUIRE(derive_normal_map(h01, w, h, dx, b));
    int green_differs = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i].r == b[i].r);
        CHECK(a[i].b == b[i].b);
        CHECK(int(a[i].g) + int(b[i].g) == 255);
        green_differs += a[i].g != b[i].g;
    }
    CHECK(green_differs == int(a.size()));  // 255 - g != g for every byte
}

TEST_CASE("map_set: ambient occlusion and roughness follow the relief") {
    const int w = 64, h = 48;
    std::vector<float> flat(std::size_t(w * h), 0.3f), h01, ao, rough;
    MapSetOptions o;
    o.strength = 8.0f;
    REQUIRE(normalise_heights(flat.data(), w, h, h01));
    REQUIRE(derive_ambient_occlusion(h01, w, h, o, ao));
    for (float v : ao) CHECK(v == 1.0f);
    const std::vector<float> heights = pit_heights(w, h);
    REQUIRE(normalise_heights(heights.data(), w, h, h01));
    REQUIRE(derive_ambient_occlusion(h01, w, h, o, ao));
    derive_roughness(h01, ao, o, rough);
    const std::size_t bottom = std::size_t(24) * w + 32, outside = std::size_t(4) * w + 2;
    CHECK(ao[bottom] < ao[outside] - 0.2f);
    CHECK(rough[bottom] > rough[outside]);
    for (float r : rough) CHECK((r >= o.roughness_low && r <= o.roughness_high));
}

TEST_CASE("map_set: wrapped maps tile (the AO and normals of column 0 see column w-1)") {
    const int w = 64, h = 8;
    std::vector<float> v(std::size_t(w * h)), h01, ao;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) v[std::size_t(y) * w + x] = x == 0 || x == w - 1 ? 0.0f : 1.0f;
    REQUIRE(normalise_heights(v.data(), w, h, h01));
    MapSetOptions o;
    o.wrap = true;
    REQUIRE(derive_ambient_occlusion(h01, w, h, o, ao));
    CHECK(ao[0] == doctest::Approx(ao[std::size_t(w - 1)]).epsilon(1e-6));  // a groove, mirrored
    CHECK(ao[0] < 0.9f);
    o.wrap = false;
    REQUIRE(derive_ambient_occlusion(h01, w, h, o, ao));
    CHECK(ao[0] > ao[1] - 1.0f);
}

TEST_CASE("map_set: write_map_set writes the named files; refuses a non-finite height") {
    const int w = 16, h = 16;
    std::vector<float> heights = pit_heights(w, h);
    std::vector<Rgb8> albedo(std::size_t(w * h), Rgb8{10, 20, 30});
    const std::string prefix = "/tmp/shitsukan_mapset_" + std::to_string(getpid());
    MapSetOptions o;
    o.pfm = true;
    std::vector<std::string> written;
    REQUIRE(write_map_set(prefix.c_str(), MapSetInput{albedo.data(), heights.data(), w, h}, o,
                          written));
    CHECK(written.size() == 7);
    for (const char* suffix : {"_albedo.png", "_height16.png", "_height.exr", "_height.pfm",
                               "_normal.png", "_roughness.png", "_ao.png"}) {
        const std::string path = prefix + suffix;
        std::FILE* f = std::fopen(path.c_str(), "rb");
        CHECK_MESSAGE(f != nullptr, path);
        if (f) std::fclose(f);
        std::remove(path.c_str());
    }
    heights[3] = std::nanf("");
    written.clear();
    const Status s = write_map_set(prefix.c_str(), MapSetInput{nullptr, heights.data(), w, h}, o,
                                   written);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("(3, 0)") != std::string::npos);
}
