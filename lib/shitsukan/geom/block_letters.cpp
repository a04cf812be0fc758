#include "shitsukan/geom/block_letters.hpp"

namespace shitsukan {
namespace {

using R = std::vector<Vec2>;
using Rings = std::vector<R>;

// One function per letter: the outer ring, then the holes. Stroke width 0.18; diagonal
// strokes keep the same horizontal width. Coordinates chosen here (the paper does not print
// its letters).

// legs x = 0.18 + 0.3y (left inner) and 0.62 - 0.3y (right inner) meet at y = 0.733
Rings letter_A() {
    return {R{{0, 0},
              {0.18f, 0},
              {0.255f, 0.25f},
              {0.545f, 0.25f},
              {0.62f, 0},
              {0.8f, 0},
              {0.5f, 1},
              {0.3f, 1}},
            R{{0.3f, 0.4f}, {0.5f, 0.4f}, {0.4f, 0.7333f}}};
}

Rings letter_E() {
    return {R{{0, 0},
              {0.8f, 0},
              {0.8f, 0.18f},
              {0.18f, 0.18f},
              {0.18f, 0.41f},
              {0.6f, 0.41f},
              {0.6f, 0.59f},
              {0.18f, 0.59f},
              {0.18f, 0.82f},
              {0.8f, 0.82f},
              {0.8f, 1},
              {0, 1}}};
}

Rings letter_F() {
    return {R{{0, 0},
              {0.18f, 0},
              {0.18f, 0.41f},
              {0.6f, 0.41f},
              {0.6f, 0.59f},
              {0.18f, 0.59f},
              {0.18f, 0.82f},
              {0.8f, 0.82f},
              {0.8f, 1},
              {0, 1}}};
}

// an O opened on the right, with an inward bar
Rings letter_G() {
    return {R{{0.2f, 0},      {0.6f, 0},      {0.8f, 0.2f},   {0.8f, 0.5f},   {0.42f, 0.5f},
              {0.42f, 0.36f}, {0.62f, 0.36f}, {0.62f, 0.25f}, {0.55f, 0.18f}, {0.25f, 0.18f},
              {0.18f, 0.25f}, {0.18f, 0.75f}, {0.25f, 0.82f}, {0.55f, 0.82f}, {0.62f, 0.72f},
              {0.8f, 0.72f},  {0.8f, 0.8f},   {0.6f, 1},      {0.2f, 1},      {0, 0.8f},
              {0, 0.2f}}};
}

Rings letter_H() {
    return {R{{0, 0},
              {0.18f, 0},
              {0.18f, 0.41f},
              {0.62f, 0.41f},
              {0.62f, 0},
              {0.8f, 0},
              {0.8f, 1},
              {0.62f, 1},
              {0.62f, 0.59f},
              {0.18f, 0.59f},
              {0.18f, 1},
              {0, 1}}};
}

Rings letter_I() { return {R{{0.31f, 0}, {0.49f, 0}, {0.49f, 1}, {0.31f, 1}}}; }

Rings letter_L() {
    return {R{{0, 0}, {0.8f, 0}, {0.8f, 0.18f}, {0.18f, 0.18f}, {0.18f, 1}, {0, 1}}};
}

Rings letter_N() {
    return {R{{0, 0},
              {0.18f, 0},
              {0.18f, 0.68f},
              {0.62f, 0},
              {0.8f, 0},
              {0.8f, 1},
              {0.62f, 1},
              {0.62f, 0.32f},
              {0.18f, 1},
              {0, 1}}};
}

// chamfered rectangle with a chamfered hole
Rings letter_O() {
    return {R{{0.2f, 0},
              {0.6f, 0},
              {0.8f, 0.2f},
              {0.8f, 0.8f},
              {0.6f, 1},
              {0.2f, 1},
              {0, 0.8f},
              {0, 0.2f}},
            R{{0.25f, 0.18f},
              {0.55f, 0.18f},
              {0.62f, 0.25f},
              {0.62f, 0.75f},
              {0.55f, 0.82f},
              {0.25f, 0.82f},
              {0.18f, 0.75f},
              {0.18f, 0.25f}}};
}

Rings letter_T() {
    return {R{{0.31f, 0},
              {0.49f, 0},
              {0.49f, 0.82f},
              {0.8f, 0.82f},
              {0.8f, 1},
              {0, 1},
              {0, 0.82f},
              {0.31f, 0.82f}}};
}

Rings letter_Y() {
    return {R{{0.31f, 0},
              {0.49f, 0},
              {0.49f, 0.45f},
              {0.8f, 1},
              {0.6f, 1},
              {0.4f, 0.64f},
              {0.2f, 1},
              {0, 1},
              {0.31f, 0.45f}}};
}

}  // namespace

Status block_letter_outline(char letter, std::vector<std::vector<Vec2>>& rings) {
    switch (letter) {
        case 'A':
            rings = letter_A();
            return Status::success();
        case 'E':
            rings = letter_E();
            return Status::success();
        case 'F':
            rings = letter_F();
            return Status::success();
        case 'G':
            rings = letter_G();
            return Status::success();
        case 'H':
            rings = letter_H();
            return Status::success();
        case 'I':
            rings = letter_I();
            return Status::success();
        case 'L':
            rings = letter_L();
            return Status::success();
        case 'N':
            rings = letter_N();
            return Status::success();
        case 'O':
            rings = letter_O();
            return Status::success();
        case 'T':
            rings = letter_T();
            return Status::success();
        case 'Y':
            rings = letter_Y();
            return Status::success();
        default:
            rings.clear();
            return Status::error(
                StatusCode::not_supported,
                "block letter '%c' is not drawn (supported: A E F G H I L N O T Y)",
                letter > 32 && letter < 127 ? letter : '?');
    }
}

}  // namespace shitsukan
