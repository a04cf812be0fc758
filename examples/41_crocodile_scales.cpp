// Lesson 41: a crocodile-belly scale pattern in four steps (tokai1994 §3.1).
// Figures: paper_figures/tokai1994/fig04_06_layouts.cpp,
//   paper_figures/tokai1994/fig07_10_patterns.cpp.
//
// Stage 1 puts two columns of seeds beside the centre line and divides the square by
// Voronoi: long horizontal bands that meet along the centre in a zig-zag (the "joint").
// Stage 2 divides every band again with a row of seeds whose spacing narrows toward the
// left and right edges: near-square scales in rows, smaller at the sides. Processing 4 bends
// every edge once, with random numbers hashed from the edge's end points, so the two scales
// on its sides still fit. The result is a list of polygons (ScalePattern) and, here, a label
// image: every pixel knows which scale it belongs to.
//
// Build and run:  make examples   (writes build/examples/out/crocodile_scales.png)
#include <cstdio>
#include <vector>

#include "shitsukan/image/image_io.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/scale_labels.hpp"

using namespace shitsukan;

int main() {
    // 1. The fig. 7 parameters: d = 1.0 D, a = 0.25, p = 0.015 (ScaleParams' defaults).
    ScaleParams prm;
    ScalePattern pattern;
    ScaleDivision steps;
    Status s = generate_scale_pattern(prm, pattern, &steps);
    if (!s) {
        std::fprintf(stderr, "%s\n", s.message());
        return 1;
    }
    std::printf("stage 1: %d polygons; stage 2: %d scales; %d edges perturbed once each\n",
                steps.stage1.face_count(), pattern.polygon_count(), steps.perturbation.edges);

    // 2. The label image: pixel centre -> scale id, each pixel exactly once.
    const int n = 384;
    std::vector<std::int32_t> labels(std::size_t(n) * n);
    s = rasterize_scale_labels(pattern, n, n, labels.data());
    if (!s) {
        std::fprintf(stderr, "%s\n", s.message());
        return 1;
    }

    // 3. Colour each scale by a hash of its id; darken pixels whose neighbour is another scale.
    RgbImage img(n, n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            std::int32_t l = labels[std::size_t(j) * n + std::size_t(i)];
            std::uint32_t h = std::uint32_t(l) * 2654435761u;
            bool edge = (i + 1 < n && labels[std::size_t(j) * n + std::size_t(i) + 1] != l) ||
                        (j + 1 < n && labels[std::size_t(j + 1) * n + std::size_t(i)] != l);
            img.at(i, j) =
                edge ? Rgb8{60, 50, 30}
                     : Rgb8{std::uint8_t(150 + (h >> 8) % 60), std::uint8_t(130 + (h >> 16) % 50),
                            std::uint8_t(90 + (h >> 24) % 40)};
        }
    s = write_png("crocodile_scales.png", img.view());
    std::printf("%s\n", s ? "wrote crocodile_scales.png" : s.message());
    return s ? 0 : 1;
}
