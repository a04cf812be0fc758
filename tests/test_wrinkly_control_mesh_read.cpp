// Tests for lib/shitsukan/wrinkly/control_mesh_read: the control-mesh text format
// (fujimoto2000 §3.1's x_i, h_i, c_i, delta_i), its line numbers in errors, colours and delta
// in range, long lines refused rather than split, and the file reader's bounds.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "shitsukan/wrinkly/control_mesh_read.hpp"

using namespace shitsukan;

namespace {
Status read(const std::string& text, WrControlMesh& mesh) {
    return read_control_mesh_text(text.data(), text.size(), "m", mesh);
}
std::string message(const Status& s) { return s.message(); }
}  // namespace

TEST_CASE("control mesh text: sizes, points, comments, optional colour and delta") {
    WrControlMesh mesh;
    REQUIRE(read("# two by one\n\n2 1   # cols rows\n0 1 2 0.5\n3 4 5 -0.25 1 0.5 0 0.75\n", mesh)
                .ok());
    CHECK(mesh.cols == 2);
    CHECK(mesh.rows == 1);
    CHECK(mesh.at(0, 0).position.y == 1.0f);
    CHECK(mesh.at(0, 0).height == 0.5f);
    CHECK(mesh.at(0, 0).color.x == 1.0f);  // default white
    CHECK(mesh.at(1, 0).color.y == 0.5f);
    CHECK(mesh.at(1, 0).delta == 0.75f);
    CHECK(message(read("2 1\n0 0 0 0\n", mesh)) == "m: 1 of 2 x 1 points given");
    CHECK(message(read("2 1\n0 0 0 0\n1 0 0 x\n", mesh)).rfind("m:3: a point is", 0) == 0);
    CHECK(message(read("1 1\n0 0 0 0\n0 0 0 0\n", mesh)) == "m:3: more than 1 x 1 points");
    CHECK(message(read("300 300\n", mesh)).rfind("m:1: the first line", 0) == 0);
    CHECK(message(read("1 1\n0 0 0 0 1 1 1 1\n", mesh)).rfind("m:2: delta must be", 0) == 0);
    // fuzz_readers: a number finite as a double but not as a float became an infinite position.
    CHECK(message(read("1 1\n1e115 0 0 0\n", mesh)).rfind("m:2: a point is", 0) == 0);
    CHECK(read("1 1\n3e38 0 0 0\n", mesh).ok());
}

// The CLI's reader accepted colours outside [0, 1] and split a line over 1023 bytes in two
// (its fgets buffer), reading the tail as the next point.
TEST_CASE("control mesh text: colours outside [0, 1] and over-long lines are refused") {
    WrControlMesh mesh;
    for (const char* colour : {"2 0 0", "0 -0.5 0", "0 0 1.0001"}) {
        CAPTURE(colour);
        const Status s = read(std::string("1 1\n0 0 0 0 ") + colour + "\n", mesh);
        CHECK(s.code() == StatusCode::invalid_argument);
        CHECK(message(s).rfind("m:2: the colour", 0) == 0);
    }
    // "0 0 0 0" padded with blanks past the limit, then "0 0 0 0": split, it was two points.
    const std::string padded = "0 0 0 0" + std::string(kControlMeshMaxLine, ' ') + "0 0 0 0";
    const Status s = read("2 1\n" + padded + "\n", mesh);
    CHECK(s.code() == StatusCode::too_large);
    CHECK(message(s).rfind("m:2: line longer than 1024 bytes", 0) == 0);
    // A line of exactly the limit is read.
    const std::string full = "0 0 0 0" + std::string(kControlMeshMaxLine - 7, ' ');
    CHECK(read("1 1\n" + full + "\n", mesh).ok());
    CHECK(read(std::string("1 1\n0 0\0 0 0\n", 13), mesh).code() == StatusCode::invalid_argument);
}

TEST_CASE("control mesh file: line numbers name the file; /dev/zero stops at once") {
    WrControlMesh mesh;
    CHECK(read_control_mesh("/nonexistent/x.mesh", mesh).code() == StatusCode::io_error);
    const Status zero = read_control_mesh("/dev/zero", mesh);
    CHECK(zero.code() == StatusCode::invalid_argument);
    CHECK(message(zero).find("NUL byte") != std::string::npos);
    const std::string path =
        std::string("/tmp/shitsukan_cmesh_") + std::to_string(getpid()) + ".mesh";
    std::FILE* f = std::fopen(path.c_str(), "wb");
    REQUIRE(f != nullptr);
    std::fputs("1 1\n0 0 0 0 0.5 0.5 2\n", f);
    REQUIRE(std::fclose(f) == 0);
    CHECK(message(read_control_mesh(path.c_str(), mesh)).rfind(path + ":2: the colour", 0) == 0);
    std::remove(path.c_str());
}
