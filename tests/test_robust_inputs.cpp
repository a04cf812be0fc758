// Tests for hostile inputs outside geom: one named regression case per defect the
// probing found in lib/shitsukan/{wrinkly/ist_digits, image/image_view,
// wrinkly/hierarchical_sampling, solid/lattice_store}.
#include <doctest/doctest.h>

#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "shitsukan/geom/bezier_patch.hpp"
#include "shitsukan/image/image_view.hpp"
#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/ist_digits.hpp"
#include "shitsukan/wrinkly/ist_original.hpp"

using namespace shitsukan;

TEST_CASE("ist_digits_format: a buffer of size 0 (or none) gives an empty string, no abort") {
    IstDigits alpha;
    char buf[4] = {'x', 'x', 'x', 'x'};
    CHECK(std::string(ist_digits_format(alpha, 1, buf, 0)) == "");
    CHECK(buf[0] == 'x');  // nothing written
    CHECK(std::string(ist_digits_format(alpha, 1, nullptr, 8)) == "");
    CHECK(std::string(ist_digits_format(alpha, 1, buf, 1)) == "");
}

TEST_CASE("ImageView::subview: extreme arguments clip, without signed overflow") {
    std::vector<Rgb8> px(16 * 8);
    ImageView<Rgb8> v{px.data(), 16, 8, 16};
    CHECK(v.subview(INT_MAX, 0, INT_MAX, 4).empty());
    CHECK(v.subview(INT_MIN, INT_MIN, INT_MAX, INT_MAX).empty());  // w + x0 = -1
    ImageView<Rgb8> all = v.subview(-5, -5, INT_MAX, INT_MAX);
    CHECK(all.width == 16);
    CHECK(all.height == 8);
    ImageView<Rgb8> tail = v.subview(10, 6, INT_MAX, INT_MAX);  // 10 + INT_MAX overflowed
    CHECK(tail.width == 6);
    CHECK(tail.height == 2);
    CHECK(tail.pixels == px.data() + 6 * 16 + 10);
}

TEST_CASE("hierarchical_sample_positions: huge or invalid counts give no positions, no overflow") {
    CHECK(hierarchical_sample_positions(4, 2, 3).size() == 4 * 8 + 2);
    CHECK(hierarchical_sample_positions(1000, 1000, 40).empty());  // B N^k overflowed a long
    CHECK(hierarchical_sample_positions(INT_MAX, INT_MAX, 2).empty());
    CHECK(hierarchical_sample_positions(0, 2, 1).empty());
    CHECK(hierarchical_sample_positions(2, 2, -1).empty());
}

namespace {
// A copy of a saved lattice file with `edit` applied.
std::string edited_lattice(const char* name, void (*edit)(std::vector<unsigned char>&)) {
    FractalParams p;
    p.R = 2;
    FractalLattice lat;
    REQUIRE(lat.build(p).ok());
    const std::string path = std::string("build/") + name;
    REQUIRE(save_lattice(path, lat).ok());
    std::vector<unsigned char> bytes;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    REQUIRE(f != nullptr);
    for (int c; (c = std::fgetc(f)) != EOF;) bytes.push_back((unsigned char)c);
    std::fclose(f);
    edit(bytes);
    f = std::fopen(path.c_str(), "wb");
    REQUIRE(f != nullptr);
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
    return path;
}
}  // namespace

TEST_CASE("load_lattice: refuses NaN values and trailing bytes") {
    std::string ok = edited_lattice("robust_ok.shl", [](std::vector<unsigned char>&) {});
    FractalLattice back;
    CHECK(load_lattice(ok, back).ok());
    std::string nan = edited_lattice("robust_nan.shl", [](std::vector<unsigned char>& b) {
        const unsigned char q[4] = {0x00, 0x00, 0xc0, 0x7f};  // quiet NaN, little-endian
        std::memcpy(b.data() + b.size() - 8, q, 4);
    });
    Status s = load_lattice(nan, back);
    CHECK(s.code() == StatusCode::io_error);
    CHECK(std::string(s.message()).find("not finite") != std::string::npos);
    std::string extra = edited_lattice("robust_extra.shl",
                                       [](std::vector<unsigned char>& b) { b.push_back(0); });
    s = load_lattice(extra, back);
    CHECK(s.code() == StatusCode::io_error);
    CHECK(std::string(s.message()).find("bytes after") != std::string::npos);
    for (const std::string& p : {ok, nan, extra}) std::remove(p.c_str());
}

TEST_CASE("original IST: K beyond double resolution is refused; accepted ones stay in [0, 1]") {
    IstOriginal ist;
    ist.crossing_all = 9;  // 19 parts a step
    ist.iterations = 33;   // 19^33: sub-intervals 1e-42 wide; forward(1) gave 1 + 2^-52
    Status s = ist_original_check(ist);
    CHECK(s.code() == StatusCode::out_of_range);
    CHECK(std::string(s.message()).find("2^-45") != std::string::npos);
    int checked = 0;
    for (int b = 1; b <= 3; ++b)
        for (int m = 0; m <= 15; ++m)
            for (int k = 0; k <= 40; ++k) {
                ist.base_intervals = b;
                ist.crossing_all = m;
                ist.iterations = k;
                if (!ist_original_check(ist)) continue;
                for (int i = 0; i <= 32; ++i) {
                    const double v = ist_original_forward(ist, i / 32.0);
                    REQUIRE((v >= 0.0 && v <= 1.0));
                    const double w = ist_original_inverse(ist, v);
                    REQUIRE((w >= 0.0 && w <= 1.0));
                }
                ++checked;
            }
    CHECK(checked > 300);
}

TEST_CASE("Bezier patch normal: unit length on a tiny patch and next to a cusp") {
    // n = du x dv has components ~1e-26 here: their squares underflow float and a plain
    // normalize() returned normals of the wrong length (1.076 was measured near a cusp).
    // sizes 1e-13 .. 1e-9: n's squares pass through the subnormal range (at 1.7e-12 the old
    // normals were 27 % short)
    float worst = 0.0f;
    for (float size = 1e-13f; size < 1e-9f; size *= 1.1f) {
        BezierPatch patch;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                patch.p[i][j] = Vec3{float(i), float(j), 0.1f * float(i * j)} * size;
        for (float u : {0.0f, 0.3f, 1.0f})
            for (float v : {0.0f, 0.7f, 1.0f}) {
                const PatchPoint q = patch_point(patch, u, v);
                worst = std::fmax(worst, std::fabs(length(q.normal) - 1.0f));
            }
    }
    CHECK(worst < 1e-5f);
    BezierPatch cusp;  // the whole u = 0 edge collapsed to one point
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            cusp.p[i][j] = i == 0 ? Vec3{0, 0, 0} : Vec3{float(i), float(j) * 1e-12f * float(i), 0};
    for (float v : {0.0f, 0.5f, 1.0f}) {
        const PatchPoint q = patch_point(cusp, 0.0f, v);
        CHECK(length(q.normal) == doctest::Approx(1.0f).epsilon(1e-5));
    }
}
