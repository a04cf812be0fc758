// fuzz/fuzz_readers.cpp — every file reader on any bytes, chosen by the first byte:
// 0 read_obj (through a file: the chunked read, the NUL stop, the cap), 1 read_obj_text,
// 2 read_pfm, 3 read_image (stb_image's formats), 4 read_control_mesh (through a file),
// 5 read_control_mesh_text. The memory budget is 64 MiB, so a header that claims more is
// refused, not allocated.
// Contracts (a non-ok Status is always fine; never a crash, a leak or a run-away allocation):
//   OBJ: indices in range, a multiple of 3; one normal per position, uvs and colours none or
//     one per position; every position and normal finite.
//   PFM: 1..65536 a side, 1 or 3 channels, width·height·channels samples, and no more sample
//     bytes than the file holds (the header was checked against the file).
//   image: 1..4 channels, 8 or 16 bits, width·height·channels samples, each below 2^bits, no
//     more than kImageMaxExpansion decoded bytes per byte of file.
//   control mesh: cols·rows points (at most kControlMeshMaxPoints), every value finite, every
//     colour component in [0, 1], delta in (0, 1).
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "fuzz_input.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/geom/obj_read.hpp"
#include "shitsukan/image/image_read.hpp"
#include "shitsukan/image/pfm.hpp"
#include "shitsukan/wrinkly/control_mesh_read.hpp"

using namespace shitsukan;

namespace {

bool finite3(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

const std::string& temp_file(const std::uint8_t* data, std::size_t size) {
    static const std::string path = "/tmp/shitsukan-fuzz-readers-" + std::to_string(getpid());
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f) {
        const bool ok = std::fwrite(data, 1, size, f) == size;
        if (std::fclose(f) != 0 || !ok) fuzz::fail("cannot write the temporary file");
    }
    return path;
}

void check_obj(const TriangleMesh& m) {
    const std::size_t n = m.positions.size();
    FUZZ_REQUIRE(m.indices.size() % 3 == 0 && !m.indices.empty());
    for (std::uint32_t i : m.indices) FUZZ_REQUIRE(i < n);
    FUZZ_REQUIRE(m.normals.size() == n);
    FUZZ_REQUIRE(m.uvs.empty() || m.uvs.size() == n);
    FUZZ_REQUIRE(m.colors.empty() || m.colors.size() == n);
    for (std::size_t i = 0; i < n; ++i) FUZZ_REQUIRE(finite3(m.positions[i]) && finite3(m.normals[i]));
}

void check_control_mesh(const WrControlMesh& mesh) {
    FUZZ_REQUIRE(mesh.cols >= 1 && mesh.rows >= 1);
    FUZZ_REQUIRE(long(mesh.cols) * long(mesh.rows) <= kControlMeshMaxPoints);
    FUZZ_REQUIRE(mesh.points.size() == std::size_t(mesh.cols) * std::size_t(mesh.rows));
    for (const WrControlPoint& p : mesh.points) {
        FUZZ_REQUIRE(finite3(p.position) && std::isfinite(p.height) && std::isfinite(p.delta));
        for (int c = 0; c < 3; ++c) FUZZ_REQUIRE(p.color[c] >= 0.0f && p.color[c] <= 1.0f);
        FUZZ_REQUIRE(p.delta > 0.0f && p.delta < 1.0f);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    set_memory_budget(std::uint64_t(64) << 20);
    if (size == 0) return 0;
    const int which = data[0] % 6;
    ++data, --size;
    const char* text = reinterpret_cast<const char*>(data);
    if (which == 0 || which == 1) {
        TriangleMesh m;
        const Status s = which == 0 ? read_obj(temp_file(data, size).c_str(), m)
                                    : read_obj_text(text, size, "fuzz", m);
        if (s) check_obj(m);
    } else if (which == 2) {
        PfmImage img;
        if (!read_pfm(temp_file(data, size).c_str(), img)) return 0;
        FUZZ_REQUIRE(img.width >= 1 && img.width <= 65536 && img.height >= 1 &&
                     img.height <= 65536);
        FUZZ_REQUIRE(img.channels == 1 || img.channels == 3);
        const std::size_t n =
            std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels);
        FUZZ_REQUIRE(img.data.size() == n);
        FUZZ_REQUIRE(n * 4 <= size);
    } else if (which == 3) {
        LoadedImage img;
        if (!read_image(temp_file(data, size).c_str(), img)) return 0;
        FUZZ_REQUIRE(img.channels >= 1 && img.channels <= 4);
        FUZZ_REQUIRE(img.bits == 8 || img.bits == 16);
        const std::size_t n =
            std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels);
        FUZZ_REQUIRE(img.width >= 1 && img.height >= 1 && img.samples.size() == n);
        FUZZ_REQUIRE(n * std::size_t(img.bits / 8) <= (size + 64) * kImageMaxExpansion);
        if (img.bits == 8)
            for (std::uint16_t v : img.samples) FUZZ_REQUIRE(v <= 255);
    } else {
        WrControlMesh mesh;
        const Status s = which == 4 ? read_control_mesh(temp_file(data, size).c_str(), mesh)
                                    : read_control_mesh_text(text, size, "fuzz", mesh);
        if (s) check_control_mesh(mesh);
    }
    return 0;
}
