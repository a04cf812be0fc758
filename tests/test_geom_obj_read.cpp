// Tests for lib/shitsukan/geom/obj_read: write_obj output reads back (positions, normals, uv,
// colours, indices), polygons, negative indices, and every file of tests/data/obj_malformed
// is refused with its line number, without a crash (also under the sanitizer).
#include <doctest/doctest.h>

#include <dirent.h>  // POSIX: listing the corpus (tests only)
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/geom/obj.hpp"
#include "shitsukan/geom/obj_read.hpp"

using namespace shitsukan;

namespace {
std::string here() {
    std::string f = __FILE__;
    const std::size_t slash = f.find_last_of('/');
    return slash == std::string::npos ? "." : f.substr(0, slash);
}
std::string temp_path(const char* name) {
    return std::string("/tmp/shitsukan_objread_") + std::to_string(getpid()) + "_" + name;
}
TriangleMesh read_text(const char* text) {
    TriangleMesh m;
    Status s = read_obj_text(text, std::strlen(text), "inline", m);
    REQUIRE_MESSAGE(s.ok(), s.message());
    return m;
}
}  // namespace

TEST_CASE("read_obj: write_obj output reads back bit for bit (positions, normals, uv, colours)") {
    TriangleMesh m;
    REQUIRE(make_torus(1.0f, 0.3f, 24, 12, m).ok());
    Pcg32 rng(5, 0);
    for (Vec2& t : m.uvs) t = {rng.uniform(), rng.uniform()};
    for (int with_colours = 0; with_colours < 2; ++with_colours) {
        if (with_colours) {
            m.colors.resize(m.positions.size());
            for (Vec3& c : m.colors) c = {0.25f, 0.5f, 0.75f};
        }
        const std::string path = temp_path("torus.obj");
        REQUIRE(write_obj(path.c_str(), m).ok());
        TriangleMesh back;
        Status s = read_obj(path.c_str(), back);
        REQUIRE_MESSAGE(s.ok(), s.message());
        std::remove(path.c_str());
        REQUIRE(back.vertex_count() == m.vertex_count());
        REQUIRE(back.indices == m.indices);
        int pos = 0, uv = 0, nrm = 0;
        for (int i = 0; i < m.vertex_count(); ++i) {
            pos += std::memcmp(&back.positions[i], &m.positions[i], sizeof(Vec3)) != 0;
            uv += std::memcmp(&back.uvs[i], &m.uvs[i], sizeof(Vec2)) != 0;
            nrm += length(back.normals[i] - m.normals[i]) > 1e-5f;
        }
        CHECK(pos == 0);
        CHECK(uv == 0);
        CHECK(nrm == 0);
        CHECK(back.colors.size() == (with_colours ? m.positions.size() : 0u));
    }
}

TEST_CASE("read_obj: quads and polygons as fans, negative indices, comments, groups, no vn") {
    TriangleMesh m = read_text(
        "# a unit square and a pentagon\no square\ng g1\ns off\nusemtl stone\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0   # trailing comment\r\n"
        "f -4 -3 -2 -1\n"
        "v 3 0 0\nv 4 0 0\nv 4.5 1 0\nv 3.5 2 0\nv 2.5 1 0\nl 1 2\n"
        "f 5 6 7 8 9\n");
    CHECK(m.triangle_count() == 2 + 3);
    CHECK(m.vertex_count() == 9);
    CHECK(m.uvs.empty());
    REQUIRE(m.normals.size() == 9u);
    for (const Vec3& n : m.normals) CHECK(n.z == doctest::Approx(1.0f));  // computed, +z (CCW)
    CHECK(m.indices[0] == 0u);
    CHECK(m.indices[4] == 2u);
    CHECK(m.indices[5] == 3u);
}

TEST_CASE("read_obj: corners v/t and v//n; shared positions with different uv are split") {
    TriangleMesh m = read_text(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\nvn 0 0 1\n"
        "f 1/1 2/2 3/3\nf 1/4 3/3 2/2\nf 1//1 2//1 3//1\n");
    CHECK(m.triangle_count() == 3);
    // (1,1) (2,2) (3,3) (1,4) and then three corners without uv: a mesh has one uv per
    // vertex, so the uv-less corners get (0, 0) and their own vertices.
    CHECK(m.vertex_count() == 4 + 3);
    CHECK(m.uvs[3].x == 0.5f);
}

TEST_CASE("read_obj: every malformed file of the corpus is refused with its line number") {
    const std::string dir = here() + "/data/obj_malformed";
    DIR* d = opendir(dir.c_str());
    REQUIRE_MESSAGE(d != nullptr, dir);
    int files = 0;
    while (dirent* e = readdir(d)) {
        const std::string name = e->d_name;
        if (name.size() < 5 || name.substr(name.size() - 4) != ".obj") continue;
        const std::string path = dir + "/" + name;
        ++files;
        TriangleMesh m;
        Status s = read_obj(path.c_str(), m);
        CAPTURE(path);
        CAPTURE(s.message());
        CHECK(!s.ok());
        CHECK(std::strstr(s.message(), path.c_str()) != nullptr);
        // "# expect N: text" on the first line: the line number and part of the message.
        std::FILE* f = std::fopen(path.c_str(), "rb");
        char first[200] = {0};
        if (f && std::fgets(first, sizeof first, f) && std::strncmp(first, "# expect ", 9) == 0) {
            const int line = std::atoi(first + 9);
            std::string want = std::strchr(first, ':') + 2;
            while (!want.empty() && (want.back() == '\n' || want.back() == '\r')) want.pop_back();
            if (line > 0)
                CHECK(std::strstr(s.message(), (path + ":" + std::to_string(line) + ":").c_str()) !=
                      nullptr);
            CHECK(std::strstr(s.message(), want.c_str()) != nullptr);
        }
        if (f) std::fclose(f);
    }
    closedir(d);
    CHECK(files >= 20);
}

TEST_CASE("read_obj: random bytes and mutated OBJ text never crash") {
    Pcg32 rng(2026, 15);
    const char* good = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n";
    const char alphabet[] = "vtnf /-0123456789.e#\n\\\t";
    int ok = 0, refused = 0;
    for (int round = 0; round < 3000; ++round) {
        std::string text = good;
        const int edits = 1 + int(rng.next_u32() % 6);
        for (int k = 0; k < edits; ++k) {
            const std::size_t at = rng.next_u32() % (text.size() + 1);
            const char c = round % 3 == 0 ? char(rng.next_u32() & 0xFF)
                                          : alphabet[rng.next_u32() % (sizeof alphabet - 1)];
            if (rng.next_u32() % 2 && at < text.size()) text[at] = c;
            else text.insert(at, 1, c);
        }
        TriangleMesh m;
        Status s = read_obj_text(text.data(), text.size(), "fuzz", m);
        if (s.ok()) {
            ++ok;
            for (std::uint32_t i : m.indices) REQUIRE(i < std::uint32_t(m.vertex_count()));
        } else {
            ++refused;
        }
    }
    CHECK(ok > 0);
    CHECK(refused > 0);
    TriangleMesh m;
    CHECK(read_obj("/nonexistent/dir/x.obj", m).code() == StatusCode::io_error);
    CHECK(read_obj_text(nullptr, 0, "empty", m).code() == StatusCode::degenerate);
}

// read_obj read a whole file into memory with no cap: `--obj /dev/zero` grew until killed.
// Now a NUL byte stops the read at its 64 KiB chunk, and the text is capped (kObjMaxBytes)
// and held to the memory budget as it grows.
TEST_CASE("read_obj: /dev/zero stops at once, the text is held to the memory budget") {
    TriangleMesh m;
    Status s = read_obj("/dev/zero", m);
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("NUL byte") != std::string::npos);
    const std::string path = temp_path("long.obj");
    std::FILE* f = std::fopen(path.c_str(), "wb");
    REQUIRE(f != nullptr);
    for (int i = 0; i < 20000; ++i) std::fputs("v 0.125 0.25 0.5\n", f);
    std::fputs("f 1 2 3\n", f);
    REQUIRE(std::fclose(f) == 0);
    REQUIRE(read_obj(path.c_str(), m).ok());
    set_memory_budget(100000);  // the file is 360,008 bytes
    s = read_obj(path.c_str(), m);
    set_memory_budget(0);
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::string(s.message()).find("read_obj: the text") != std::string::npos);
    std::remove(path.c_str());
    CHECK(kObjMaxBytes >= std::size_t(kObjMaxLine) * 1024);
}
