// Lesson 0: a triangle in thirty lines, before the exact rasterizer.
// Figure: paper_figures/foundation/coverage.cpp.
//
// For every pixel in the triangle's bounding box, ask the three edge functions on which side
// of each edge the pixel centre lies; inside all three, blend the corners' colours by the
// barycentric weights (the edge functions divided by the whole area) and keep the pixel if it
// is nearer than what the depth buffer holds. Lesson 1 (01_first_triangle) is the same thing
// made exact: sub-pixel snapping, integer edge tests, the top-left rule for shared edges,
// perspective-correct colours, clipping and bands.
//
// Build and run:  make examples   (writes build/examples/out/naive_triangle.png)
#include <cmath>
#include <cstdio>
#include <vector>

#include "shitsukan/core/vec.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/image_io.hpp"

using namespace shitsukan;

// Twice the signed area of (a, b, p): > 0 when p is left of the edge a -> b.
static float edge(Vec2 a, Vec2 b, Vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

int main() {
    const int W = 256, H = 256;
    const Vec2 v[3] = {{30, 220}, {230, 200}, {120, 20}};  // screen corners (y down)
    const float depth[3] = {0.5f, 0.5f, 0.5f};
    const Vec3 colour[3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
    RgbImage img(W, H, Rgb8{20, 20, 24});
    std::vector<float> zbuffer(std::size_t(W * H), 1e30f);
    const float area = edge(v[0], v[1], v[2]);  // the whole triangle (negative: clockwise)
    const int x0 = int(std::fmin(v[0].x, std::fmin(v[1].x, v[2].x)));  // bounding box
    const int x1 = int(std::fmax(v[0].x, std::fmax(v[1].x, v[2].x)));
    const int y0 = int(std::fmin(v[0].y, std::fmin(v[1].y, v[2].y)));
    const int y1 = int(std::fmax(v[0].y, std::fmax(v[1].y, v[2].y)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const Vec2 p{x + 0.5f, y + 0.5f};                // the pixel centre
            const float w0 = edge(v[1], v[2], p) / area;     // barycentric weights
            const float w1 = edge(v[2], v[0], p) / area;
            const float w2 = edge(v[0], v[1], p) / area;
            if (w0 < 0 || w1 < 0 || w2 < 0) continue;        // outside an edge
            const float z = w0 * depth[0] + w1 * depth[1] + w2 * depth[2];
            float& stored = zbuffer[std::size_t(y * W + x)];
            if (z >= stored) continue;                       // the depth test
            stored = z;
            const Vec3 c = colour[0] * w0 + colour[1] * w1 + colour[2] * w2;
            img.at(x, y) = Rgb8{std::uint8_t(c.x), std::uint8_t(c.y), std::uint8_t(c.z)};
        }
    const Status s = write_png("naive_triangle.png", img.view());
    if (!s) {
        std::fprintf(stderr, "%s\n", s.message());
        return 1;
    }
    std::printf("wrote naive_triangle.png (%d x %d)\n", W, H);
    return 0;
}
