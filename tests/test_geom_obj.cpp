// geom/obj: write_obj's numbers (core/format_number, no printf) read back to the same floats.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "shitsukan/core/prng.hpp"
#include "shitsukan/geom/obj.hpp"

using namespace shitsukan;

namespace {
float random_float(Pcg32& rng, int i) {
    std::uint32_t u = rng.next_u32();
    if (i % 3 == 0) u = (u & 0x807fffffu) | ((110u + u % 40u) << 23);  // 1e-5 .. 1e7
    float v;
    std::memcpy(&v, &u, 4);
    if (v != v || v - v != 0.0f) v = 0.5f;  // NaN and inf: not coordinates
    return v;
}
}  // namespace

TEST_CASE("write_obj: every position, uv, normal and colour reads back to the same float") {
    Pcg32 rng(21);
    TriangleMesh m;
    const int n = 3000;
    for (int i = 0; i < n; ++i) {
        m.positions.push_back({random_float(rng, i), random_float(rng, i + 1), -0.0f});
        m.uvs.push_back({random_float(rng, i), float(i) * 1e-3f});
        m.normals.push_back({random_float(rng, i + 2), 1e-45f, 3.4028235e38f});
        m.colors.push_back({random_float(rng, i), 0.1f, 1.0f / 3.0f});
    }
    for (int i = 0; i + 2 < n; i += 3)
        for (int k = 0; k < 3; ++k) m.indices.push_back(std::uint32_t(i + k));
    const char* path = "build/test_geom_obj_roundtrip.obj";
    REQUIRE(write_obj(path, m).ok());
    std::FILE* f = std::fopen(path, "rb");
    REQUIRE(f != nullptr);
    char line[512];
    int v = 0, vt = 0, vn = 0, faces = 0, wrong = 0;
    auto same = [&](const char*& p, float want) {
        char* end = nullptr;
        float got = std::strtof(p, &end);
        if (end == p || std::memcmp(&got, &want, 4) != 0) ++wrong;
        p = end;
    };
    while (std::fgets(line, sizeof line, f)) {
        const char* p = line + 2;
        if (!std::strncmp(line, "v ", 2)) {
            const Vec3& q = m.positions[std::size_t(v)];
            const Vec3& c = m.colors[std::size_t(v++)];
            for (float want : {q.x, q.y, q.z, c.x, c.y, c.z}) same(p, want);
        } else if (!std::strncmp(line, "vt ", 3)) {
            ++p;
            const Vec2& t = m.uvs[std::size_t(vt++)];
            for (float want : {t.x, t.y}) same(p, want);
        } else if (!std::strncmp(line, "vn ", 3)) {
            ++p;
            const Vec3& q = m.normals[std::size_t(vn++)];
            for (float want : {q.x, q.y, q.z}) same(p, want);
        } else if (!std::strncmp(line, "f ", 2)) {
            char want[96];
            const unsigned a = unsigned(3 * faces + 1);
            std::snprintf(want, sizeof want, "f %u/%u/%u %u/%u/%u %u/%u/%u\n", a, a, a, a + 1,
                          a + 1, a + 1, a + 2, a + 2, a + 2);
            wrong += std::strcmp(line, want) != 0;
            ++faces;
        }
    }
    std::fclose(f);
    std::remove(path);
    CHECK(v == n);
    CHECK(vt == n);
    CHECK(vn == n);
    CHECK(faces == n / 3);
    CHECK(wrong == 0);
}
