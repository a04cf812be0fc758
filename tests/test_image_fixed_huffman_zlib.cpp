// Tests for lib/shitsukan/image/fixed_huffman_zlib: the same bytes as stb_image_write's own
// stbi_zlib_compress (compiled here, without the library's hook) on inputs that reach each of
// its paths, and a round trip through stb_image's inflater.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "shitsukan/image/fixed_huffman_zlib.hpp"

// stb_image_write's reference compressor, private to this file; stb_image's implementation
// (the inflater) is compiled in test_image_png16.cpp. Their own code is not ours to make
// warning-free.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

using namespace shitsukan;

namespace {

std::vector<unsigned char> compressed(unsigned char* z, int size) {
    std::vector<unsigned char> v(z, z + size);
    std::free(z);
    return v;
}

// Both compressors on data; the streams compared byte for byte, and ours inflated back.
void check_same_stream(std::vector<unsigned char> data, int quality) {
    int ours_size = -1, stb_size = -1;
    unsigned char* ours = fixed_huffman_zlib(data.data(), int(data.size()), &ours_size, quality);
    unsigned char* ref = stbi_zlib_compress(data.data(), int(data.size()), &stb_size, quality);
    REQUIRE(ours != nullptr);
    REQUIRE(ref != nullptr);
    const std::vector<unsigned char> a = compressed(ours, ours_size);
    const std::vector<unsigned char> b = compressed(ref, stb_size);
    CHECK(a.size() == b.size());
    CHECK(a == b);
    if (data.empty()) return;  // stb writes no block at all then (header and Adler-32 only)
    int back_size = -1;
    char* back =
        stbi_zlib_decode_malloc(reinterpret_cast<const char*>(a.data()), int(a.size()), &back_size);
    REQUIRE(back != nullptr);
    CHECK(std::vector<unsigned char>(back, back + back_size) == data);
    std::free(back);
}

std::uint32_t next(std::uint32_t& state) {  // xorshift32
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state;
}

}  // namespace

TEST_CASE("fixed_huffman_zlib: stb's stream on short inputs, noise (stored blocks) and text") {
    for (int n = 0; n <= 8; ++n)
        check_same_stream(std::vector<unsigned char>(std::size_t(n), 7), 8);
    std::uint32_t s = 12345;
    std::vector<unsigned char> noise(100000);
    for (unsigned char& c : noise) c = static_cast<unsigned char>(next(s) >> 24);
    check_same_stream(noise, 8);  // incompressible: stb's stored blocks, 32767 bytes each
    std::vector<unsigned char> text;
    const char* words[] = {"bark ", "crack ", "marble ", "wood ", "leather ", "wave "};
    while (text.size() < 50000)
        for (const char* c = words[next(s) % 6]; *c; ++c)
            text.push_back(static_cast<unsigned char>(*c));
    for (int quality : {1, 5, 8, 16}) check_same_stream(text, quality);
}

TEST_CASE("fixed_huffman_zlib: stb's stream on image rows (long runs, full buckets, far matches)") {
    // Rows of an RGB image as PNG filtering leaves them: flat runs (258-byte matches, buckets
    // overflowing and halving), a repeating texture (matches tied in length: the newest wins),
    // and rows that repeat 30000 bytes apart (distances near the window's end).
    std::uint32_t s = 99;
    std::vector<unsigned char> img;
    const int w = 1200, rows = 60;
    for (int y = 0; y < rows; ++y) {
        img.push_back(static_cast<unsigned char>(y % 5));  // the filter byte
        for (int x = 0; x < w; ++x) {
            const bool flat = (x / 200 + y / 7) % 3 == 0;
            const int tex = ((x * 7) ^ (y * 3)) & 15;
            for (int c = 0; c < 3; ++c)
                img.push_back(static_cast<unsigned char>(
                    flat ? 236 + c : (tex * 16 + c * 5 + ((next(s) & 63) == 0 ? int(s & 7) : 0))));
        }
    }
    for (int quality : {5, 8, 12}) check_same_stream(img, quality);
    std::vector<unsigned char> far(32760 * 3 + 100);
    for (std::size_t i = 0; i < far.size(); ++i)
        far[i] = static_cast<unsigned char>(i < 32760 ? next(s) : far[i % 32760 + (i / 32760 > 1)]);
    check_same_stream(far, 8);
}

TEST_CASE(
    "fixed_huffman_zlib: stb's window edges (32767 back for a match, one less for the "
    "lazy look at the next byte)") {
    // Zeros (compressible, so no stored blocks) with random bytes planted: they match nothing
    // but their planted copies.
    std::uint32_t s = 7;
    auto plant = [&](std::vector<unsigned char>& v, std::size_t at, int n) {
        for (int k = 0; k < n; ++k)
            v[at + std::size_t(k)] = static_cast<unsigned char>(1 + next(s) % 255);
    };
    for (int distance : {32766, 32767, 32768}) {  // a 12-byte repeat exactly that far back
        std::vector<unsigned char> v(40000, 0);
        plant(v, 100, 12);
        for (int k = 0; k < 12; ++k) v[std::size_t(100 + distance + k)] = v[std::size_t(100 + k)];
        check_same_stream(v, 8);
    }
    for (int distance : {32766, 32767, 32768}) {
        // At i a 3-byte match 1000 back; at i + 1 a 10-byte one `distance` back, which makes
        // i a literal only where stb's lazy test looks that far.
        std::vector<unsigned char> v(40000, 0);
        const std::size_t p = 100, i = p + std::size_t(distance) - 1, q = i - 1000;
        plant(v, p, 10);
        plant(v, i, 1);
        for (int k = 0; k < 10; ++k) v[i + 1 + std::size_t(k)] = v[p + std::size_t(k)];
        for (int k = 0; k < 3; ++k) v[q + std::size_t(k)] = v[i + std::size_t(k)];
        check_same_stream(v, 8);
    }
}
