// shitsukan/image/font.hpp — the built-in bitmap font for labels (drawn here, not copied).
//
// Manual
//   int w = text_width("k = 16", 2);        // (6·6 - 1)·2 = 70 pixels at magnification 2
//   int h = text_height(2);                 // 18: one line, descenders included
//   const Glyph& g = font_glyph(U'κ');      // unknown code points give the fallback box
//   bool on = glyph_pixel(g, 2, 4);         // col in [0, 5), row in [0, 9)
//   // Canvas::text draws with it (RasterCanvas) or sizes an SVG monospace font to match.
//
// Metrics (one cell, before the integer magnification `scale`):
//   advance 6 px per character (5 glyph columns + 1 px gap), cell height 9 rows:
//   rows 0..6 hold capitals and digits (the baseline is under row 6), rows 7..8 hold the
//   descenders of g j p q y , ; _ and some Greek letters. Lines advance 10 px ('\n').
// Characters: printable ASCII 32..126, and, written as UTF-8 in the string, the Greek
//   letters the papers' labels use: α β γ δ ε θ κ λ μ π ρ σ τ φ ω Δ Σ Ω, and ° ± · ×.
//   In C++ source write them directly ("κ = 1.04") or as "\u03ba". Anything else, and
//   malformed UTF-8, draws the fallback glyph (a hollow box) so a missing letter is visible.
// Each glyph is 9 rows of 5 bits (bit 4 = left column): 9 bytes. The table is built at
// compile time from the readable '#'/'.' drawings in font.cpp; nothing is allocated.
#pragma once

#include <cstdint>

#include "shitsukan/core/assert.hpp"

namespace shitsukan {

constexpr int kFontGlyphWidth = 5;    // columns drawn per glyph
constexpr int kFontGlyphRows = 9;     // rows drawn per glyph (7 above the baseline + 2 below)
constexpr int kFontAdvance = 6;       // horizontal advance per character
constexpr int kFontCellHeight = 9;    // height of one line of text
constexpr int kFontLineAdvance = 10;  // vertical advance for '\n'
constexpr int kFontBaseline = 7;      // rows above the baseline

struct Glyph {
    std::uint32_t codepoint = 0;
    std::uint8_t rows[kFontGlyphRows] = {0};  // bit (4 - col) of rows[row]
};

// The glyph for a Unicode code point, or the fallback box when the font lacks it.
const Glyph& font_glyph(std::uint32_t codepoint);
// True when the font has a glyph of its own for the code point.
bool font_has_glyph(std::uint32_t codepoint);
// All glyphs of the font (for tests and specimen sheets), fallback excluded.
int font_glyph_count();
const Glyph& font_glyph_at(int index);

inline bool glyph_pixel(const Glyph& g, int col, int row) {
    return col >= 0 && col < kFontGlyphWidth && row >= 0 && row < kFontGlyphRows &&
           ((g.rows[row] >> (kFontGlyphWidth - 1 - col)) & 1u) != 0;
}

// Decode one UTF-8 code point from [*cursor, end) and advance *cursor past it.
// Malformed or truncated sequences give U+FFFD and advance by one byte.
std::uint32_t next_codepoint(const char** cursor, const char* end);

// Size of a (possibly multi-line) text in pixels at integer magnification scale (>= 1;
// smaller values count as 1). Width is the longest line; height is
// kFontCellHeight·scale for one line plus kFontLineAdvance·scale per extra line.
int text_width(const char* text, int scale = 1);
int text_height(int scale = 1);
int text_block_height(const char* text, int scale = 1);
// (std::string overloads of text_width / text_block_height are in canvas.hpp: this header
// stays free of the host library for small-device builds.)

}  // namespace shitsukan
