#include "shitsukan/geom/block_letters.hpp"

namespace shitsukan {

// Stroke width 0.18; diagonal strokes keep the same horizontal width. Coordinates chosen
// here (the paper does not print its letters).
Status block_letter_outline(char letter, std::vector<std::vector<Vec2>>* rings) {
    if (!rings)
        return Status::error(StatusCode::invalid_argument, "block_letter_outline: null output");
    using R = std::vector<Vec2>;
    switch (letter) {
        case 'A':  // legs x = 0.18 + 0.3y (left inner) and 0.62 - 0.3y (right inner) meet at y =
                   // 0.733
            *rings = {R{{0, 0},
                        {0.18f, 0},
                        {0.255f, 0.25f},
                        {0.545f, 0.25f},
                        {0.62f, 0},
                        {0.8f, 0},
                        {0.5f, 1},
                        {0.3f, 1}},
                      R{{0.3f, 0.4f}, {0.5f, 0.4f}, {0.4f, 0.7333f}}};
            return Status::success();
        case 'E':
            *rings = {R{{0, 0},
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
            return Status::success();
        case 'F':
            *rings = {R{{0, 0},
                        {0.18f, 0},
                        {0.18f, 0.41f},
                        {0.6f, 0.41f},
                        {0.6f, 0.59f},
                        {0.18f, 0.59f},
                        {0.18f, 0.82f},
                        {0.8f, 0.82f},
                        {0.8f, 1},
                        {0, 1}}};
            return Status::success();
        case 'G':  // an O opened on the right, with an inward bar
            *rings = {R{{0.2f, 0},      {0.6f, 0},      {0.8f, 0.2f},   {0.8f, 0.5f},
                        {0.42f, 0.5f},  {0.42f, 0.36f}, {0.62f, 0.36f}, {0.62f, 0.25f},
                        {0.55f, 0.18f}, {0.25f, 0.18f}, {0.18f, 0.25f}, {0.18f, 0.75f},
                        {0.25f, 0.82f}, {0.55f, 0.82f}, {0.62f, 0.72f}, {0.8f, 0.72f},
                        {0.8f, 0.8f},   {0.6f, 1},      {0.2f, 1},      {0, 0.8f},
                        {0, 0.2f}}};
            return Status::success();
        case 'H':
            *rings = {R{{0, 0},
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
            return Status::success();
        case 'I':
            *rings = {R{{0.31f, 0}, {0.49f, 0}, {0.49f, 1}, {0.31f, 1}}};
            return Status::success();
        case 'L':
            *rings = {R{{0, 0}, {0.8f, 0}, {0.8f, 0.18f}, {0.18f, 0.18f}, {0.18f, 1}, {0, 1}}};
            return Status::success();
        case 'N':
            *rings = {R{{0, 0},
                        {0.18f, 0},
                        {0.18f, 0.68f},
                        {0.62f, 0},
                        {0.8f, 0},
                        {0.8f, 1},
                        {0.62f, 1},
                        {0.62f, 0.32f},
                        {0.18f, 1},
                        {0, 1}}};
            return Status::success();
        case 'O':  // chamfered rectangle with a chamfered hole
            *rings = {R{{0.2f, 0},
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
            return Status::success();
        case 'T':
            *rings = {R{{0.31f, 0},
                        {0.49f, 0},
                        {0.49f, 0.82f},
                        {0.8f, 0.82f},
                        {0.8f, 1},
                        {0, 1},
                        {0, 0.82f},
                        {0.31f, 0.82f}}};
            return Status::success();
        case 'Y':
            *rings = {R{{0.31f, 0},
                        {0.49f, 0},
                        {0.49f, 0.45f},
                        {0.8f, 1},
                        {0.6f, 1},
                        {0.4f, 0.64f},
                        {0.2f, 1},
                        {0, 1},
                        {0.31f, 0.45f}}};
            return Status::success();
        default:
            rings->clear();
            return Status::error(
                StatusCode::not_supported,
                "block letter '%c' is not drawn (supported: A E F G H I L N O T Y)",
                letter > 32 && letter < 127 ? letter : '?');
    }
}

}  // namespace shitsukan
