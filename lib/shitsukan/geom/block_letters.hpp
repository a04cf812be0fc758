// shitsukan/geom/block_letters.hpp — outlines of block capitals, for okada1987 fig. 15
// ("NAGOYA" constructed by planes).
//
// Manual
//   std::vector<std::vector<Vec2>> rings;
//   Status s = block_letter_outline('A', rings);   // rings[0] outer, rings[1..] holes
//   return s;
// Letters sit in the box [0, 0.8] x [0, 1] (baseline y = 0, cap height 1); advance
// kBlockLetterAdvance per letter. Supported: A E F G H I L N O T Y (the NAGOYA letters and a
// few straight ones, drawn here as polygons with 0.18-wide strokes). Others: not_supported.
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

constexpr float kBlockLetterAdvance = 1.0f;

Status block_letter_outline(char letter, std::vector<std::vector<Vec2>>& rings);

}  // namespace shitsukan
