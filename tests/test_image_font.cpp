// Tests for lib/shitsukan/image/font: the glyph set, distinctness, UTF-8 decoding, metrics.
#include <doctest/doctest.h>

#include <cstring>
#include <string>

#include "shitsukan/image/canvas.hpp"  // the std::string overloads
#include "shitsukan/image/font.hpp"

using namespace shitsukan;

namespace {

int lit(const Glyph& g) {
    int n = 0;
    for (int r = 0; r < kFontGlyphRows; ++r)
        for (int c = 0; c < kFontGlyphWidth; ++c) n += glyph_pixel(g, c, r);
    return n;
}

}  // namespace

TEST_CASE("every printable ASCII character has its own glyph, non-empty except space") {
    for (std::uint32_t c = 32; c <= 126; ++c) {
        CAPTURE(c);
        REQUIRE(font_has_glyph(c));
        CHECK(font_glyph(c).codepoint == c);
        if (c == ' ') CHECK(lit(font_glyph(c)) == 0);
        else CHECK(lit(font_glyph(c)) > 0);
        // No bits outside the 5 drawn columns.
        for (int r = 0; r < kFontGlyphRows; ++r) CHECK((font_glyph(c).rows[r] & ~0x1Fu) == 0);
    }
}

TEST_CASE("all glyphs differ pairwise (ASCII, Greek, signs and the fallback box)") {
    int n = font_glyph_count();
    CHECK(n >= 95 + 18);
    const Glyph& fallback = font_glyph(0x4E00);  // a CJK ideograph: not in the font
    CHECK_FALSE(font_has_glyph(0x4E00));
    for (int i = 0; i < n; ++i) {
        const Glyph& a = font_glyph_at(i);
        CHECK(std::memcmp(a.rows, fallback.rows, sizeof a.rows) != 0);
        for (int j = i + 1; j < n; ++j) {
            const Glyph& b = font_glyph_at(j);
            CAPTURE(a.codepoint);
            CAPTURE(b.codepoint);
            CHECK(std::memcmp(a.rows, b.rows, sizeof a.rows) != 0);
            CHECK(a.codepoint < b.codepoint);  // sorted, no duplicates
        }
    }
}

TEST_CASE("descenders only where they belong") {
    const std::string with_descender = "gjpqy,;_|";
    for (std::uint32_t c = 33; c <= 126; ++c) {
        const Glyph& g = font_glyph(c);
        bool below = g.rows[7] != 0 || g.rows[8] != 0;
        CAPTURE(char(c));
        CHECK(below == (with_descender.find(char(c)) != std::string::npos));
    }
}

TEST_CASE("the Greek letters of the papers' labels are present") {
    // alpha beta gamma delta epsilon theta kappa lambda mu pi rho sigma tau phi omega
    const std::uint32_t greek[] = {0x3B1, 0x3B2, 0x3B3, 0x3B4, 0x3B5, 0x3B8, 0x3BA, 0x3BB,
                                   0x3BC, 0x3C0, 0x3C1, 0x3C3, 0x3C4, 0x3C6, 0x3C9,
                                   0x394, 0x3A3, 0x3A9, 0xB0, 0xB1, 0xB7, 0xD7};
    for (std::uint32_t c : greek) {
        CAPTURE(c);
        CHECK(font_has_glyph(c));
        CHECK(lit(font_glyph(c)) > 0);
    }
}

TEST_CASE("UTF-8 decoding: Greek, ASCII, malformed input") {
    std::string s = "a\u03ba=\xce";  // 'a', kappa (2 bytes), '=', a truncated lead byte
    const char* p = s.data();
    const char* end = p + s.size();
    CHECK(next_codepoint(&p, end) == 'a');
    CHECK(next_codepoint(&p, end) == 0x3BA);
    CHECK(next_codepoint(&p, end) == '=');
    CHECK(next_codepoint(&p, end) == 0xFFFD);
    CHECK(p == end);
    const char bad[] = {char(0xC0), char(0x80), char(0xED), char(0xA0), char(0x80), char(0xFF)};
    p = bad;
    int count = 0;
    while (p < bad + sizeof bad) {
        CHECK(next_codepoint(&p, bad + sizeof bad) == 0xFFFD);  // overlong, surrogate, 0xFF
        ++count;
    }
    CHECK(count == 6);  // each bad byte is skipped alone
    std::string four = "\xF0\x9F\x98\x80";  // U+1F600
    p = four.data();
    CHECK(next_codepoint(&p, p + 4) == 0x1F600);
}

TEST_CASE("metrics: width counts characters (not bytes), lines, scale") {
    CHECK(text_width("", 1) == 0);
    CHECK(text_width("k", 1) == 5);
    CHECK(text_width("k = 16", 1) == 35);
    CHECK(text_width("k = 16", 2) == 70);
    CHECK(text_width("\u03ba = 1.04", 1) == text_width("k = 1.04", 1));
    CHECK(text_width("ab\nabcd\nc", 1) == 23);
    CHECK(text_width("abc", 0) == text_width("abc", 1));  // scale < 1 counts as 1
    CHECK(text_height(1) == 9);
    CHECK(text_height(3) == 27);
    CHECK(text_block_height("a", 2) == 18);
    CHECK(text_block_height("a\nb\nc", 1) == 9 + 2 * kFontLineAdvance);
    CHECK(text_width(std::string("xyz"), 2) == text_width("xyz", 2));
}
