// Lesson 12: a marble slab (okada1987 §4.1): layers of impurity as trapezoids with
// exponential skirts (eq. (8)), displaced along z by k·D(P) (eq. (9), as pixel shift), and
// coloured by eq. (12). The slab is the vertical plane y = 32 of the lattice: every pixel
// is one point P = (x, 32, z), no rasterizer needed.
// Figures: paper_figures/okada1987/fig09_trapezoid.cpp,
//   paper_figures/okada1987/fig12_k_variation.cpp,
//   paper_figures/okada1989/fig06_07_fundamental.cpp.
// Run: make examples   (12_marble_slab.png appears in build/examples/out/)
#include <cstdio>

#include "shitsukan/image/image_io.hpp"
#include "shitsukan/solid/solid.hpp"

using namespace shitsukan;

int main() {
    FractalParams params;
    FractalLattice lattice;
    Status s = lattice.build(params);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    // c (z of the layer's middle), w (width), alpha (skirt decay), in lattice units.
    const MarbleStripe stripes[4] = {{12.0f, 1.5f, 0.8f}, {26.0f, 3.0f, 0.5f},
                                     {40.0f, 1.0f, 1.2f}, {52.0f, 2.5f, 0.6f}};
    MarbleParams marble{stripes, 4, 16.0f};  // k = 16 (okada1987 §4.4)
    s = validate_marble(marble);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    const Vec3 limestone{238, 234, 226}, impurity{62, 74, 80};  // I_max, I_min of eq. (12)

    const int size = 512;
    RgbImage img(size, size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const Vec3 p{64.0f * (i + 0.5f) / size, 32.0f, 64.0f * (1.0f - (j + 0.5f) / size)};
            const float d = turbulence(lattice.view(), p);     // D(P), eq. (6)
            const float g = marble_texture(p, d, marble);     // G(P + k·D(P)·(0, 0, 1))
            // G = 1 inside a layer (impurity): the density of limestone is 1 - G.
            const Vec3 c = lookup_color(1.0f - g, impurity, limestone);
            img.at(i, j) = Rgb8{std::uint8_t(c.x), std::uint8_t(c.y), std::uint8_t(c.z)};
        }
    s = write_png("12_marble_slab.png", img.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("wrote 12_marble_slab.png (the plane y = 32, x right, z up, k = 16)\n");
    return 0;
}
