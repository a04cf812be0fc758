// small-device: yes (2D quadtree lattice into a caller buffer; no allocation)
#include "shitsukan/solid/quadtree_lattice.hpp"

#include <limits>

#include "shitsukan/core/hash.hpp"
#include "shitsukan/solid/fractal_node.hpp"
#include "shitsukan/solid/fractal_params.hpp"

namespace shitsukan {

Status build_quadtree_lattice(const QuadtreeParams& params, float* buffer,
                              std::size_t buffer_bytes, int& side_out, int levels) {
    SHITSUKAN_TRY(validate_fractal_levels("quadtree lattice", params.R, kQuadtreeMaxDepth,
                                          params.beta, params.corners, 4));
    if (buffer == nullptr)
        return Status::error(StatusCode::invalid_argument, "quadtree lattice: null buffer");
    const int side = (1 << params.R) + 1;
    const std::size_t need = std::size_t(side) * std::size_t(side) * sizeof(float);
    if (buffer_bytes < need)
        return Status::error(StatusCode::buffer_too_small,
                             "quadtree lattice: R = %d needs %zu bytes, the buffer has %zu",
                             params.R, need, buffer_bytes);
    if (levels < 0 || levels > params.R) levels = params.R;

    for (int i = 0; i < side * side; ++i) buffer[i] = std::numeric_limits<float>::quiet_NaN();
    const int last = side - 1;
    auto at = [&](int x, int y) -> float& { return buffer[y * side + x]; };
    at(0, 0) = params.corners[0], at(last, 0) = params.corners[1];
    at(0, last) = params.corners[2], at(last, last) = params.corners[3];

    for (int n = 1; n <= levels; ++n) {
        const int h = 1 << (params.R - n), s = 2 * h;
        const float amplitude = level_amplitude(n, params.beta);  // eq. (2)
        auto g = [&](int x, int y) {
            return hash_gaussian(params.seed, kQuadtreeStream, x, y, 0) * amplitude;
        };
        // Edge midpoints: the mean of the edge's two ends (shared edges are done once).
        for (int y = 0; y < side; y += h)
            for (int x = 0; x < side; x += h) {
                bool odd_x = (x / h) & 1, odd_y = (y / h) & 1;
                if (odd_x && !odd_y) at(x, y) = edge_midpoint(at(x - h, y), at(x + h, y), g(x, y));
                if (!odd_x && odd_y) at(x, y) = edge_midpoint(at(x, y - h), at(x, y + h), g(x, y));
            }
        // Square centres: the mean of the square's four vertices (bilinear at the centre).
        for (int y = h; y < side; y += s)
            for (int x = h; x < side; x += s)
                at(x, y) = (at(x - h, y - h) + at(x + h, y - h) + at(x - h, y + h) +
                            at(x + h, y + h)) * 0.25f + g(x, y);
    }
    side_out = side;
    return Status::success();
}

}  // namespace shitsukan
