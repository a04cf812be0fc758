// Lesson 11: the turbulence D(P) along a line, and why a renderer shifts backwards.
// Figures: paper_figures/okada1987/fig06_interpolation.cpp,
//   paper_figures/okada1987/fig07_turbulence.cpp.
//
// D(P) is the lattice interpolated trilinearly (okada1987 eq. (6)): exact at the nodes,
// straight between them along a cell edge. The texture is a regular function G disturbed
// by D. okada1987 §3.2 words it as a FORWARD map: the value G(P) "is observed at"
// P' = P + k·D(P)·u. okada1989 §4-1 states the BACKWARD (pixel shift) form: the point P
// shows G(P + k·D(P)·u). A renderer asks for the colour AT a given point, so it needs the
// backward form. This program walks a line along z through the marble stripes and does both:
//   backward: value(z) = G(z + k·D(z))               (one lookup per sample, no gaps)
//   forward:  scatter G(z) to z' = z + k·D(z)          (samples pile up or leave holes)
// It prints D at the nodes, counts the holes of the forward map, and plots the three curves.
// Run: make examples   (11_turbulence_line.png appears in build/examples/out/)
#include <cmath>
#include <cstdio>
#include <vector>

#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/plot.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/solid/solid.hpp"

using namespace shitsukan;

int main() {
    FractalParams params;
    FractalLattice lattice;
    Status s = lattice.build(params);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    const LatticeView v = lattice.view();
    const float x = 20.0f, y = 33.0f, k = 16.0f;
    const MarbleStripe stripes[3] = {{16.0f, 3.0f, 0.6f}, {32.0f, 6.0f, 0.4f}, {48.0f, 2.0f, 0.8f}};

    std::printf("D at the nodes of the line (x, y) = (20, 33):\n  z:");
    for (int z = 0; z <= 64; z += 8) std::printf(" %6d", z);
    std::printf("\n  D:");
    for (int z = 0; z <= 64; z += 8) std::printf(" %6.3f", double(v.at(20, 33, z)));
    std::printf("\n  halfway (z + 0.5) equals the mean of the two nodes: D(8.5) = %.4f, "
                "(D(8) + D(9))/2 = %.4f\n",
                double(turbulence(v, Vec3{x, y, 8.5f})),
                double(0.5f * (v.at(20, 33, 8) + v.at(20, 33, 9))));

    // Samples every 1/8 lattice unit along z.
    const int n = 64 * 8 + 1;
    std::vector<float> zs(n), original(n), backward(n), forward(n, NAN);
    std::vector<int> hits(n, 0);
    for (int i = 0; i < n; ++i) {
        const float z = float(i) / 8.0f;
        const float d = turbulence(v, Vec3{x, y, z});
        zs[i] = z;
        original[i] = marble_original(z, stripes, 3);
        backward[i] = marble_original(z + k * d, stripes, 3);  // G(P + k·D(P)·u)
        const int j = int(std::lround((z + k * d) * 8.0f));     // forward: where G(z) lands
        if (j >= 0 && j < n) forward[j] = original[i], ++hits[j];
    }
    int holes = 0, piled = 0;
    for (int j = 0; j < n; ++j) holes += hits[j] == 0, piled += hits[j] > 1;
    std::printf("forward map: %d of %d samples received no value, %d received several\n", holes,
                n, piled);
    std::printf("backward map: every sample has exactly one value\n");

    RgbImage img(720, 420, Rgb8{255, 255, 255});
    RasterCanvas canvas(img.view());
    const Axes axes = axes_in(canvas, 0.0, 64.0, -0.05, 1.25);
    s = draw_axes(canvas, axes, {"G along z at (20, 33), k = 16", "z (lattice units)", "G"});
    if (s) s = plot_series(canvas, axes, zs.data(), original.data(), n, Rgb8{170, 170, 170}, 1.0f);
    if (s) s = plot_series(canvas, axes, zs.data(), backward.data(), n, Rgb8{30, 80, 200}, 1.5f);
    if (s) s = plot_scatter(canvas, axes, zs.data(), forward.data(), n, MarkerShape::dot, 3.0f,
                            Rgb8{220, 90, 20});
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    canvas.text({axes.corner.x + 8, axes.corner.y + 6}, "grey: G(z) (k = 0)", Rgb8{120, 120, 120});
    canvas.text({axes.corner.x + 8, axes.corner.y + 18}, "blue: backward G(z + k D(z))",
                Rgb8{30, 80, 200});
    canvas.text({axes.corner.x + 8, axes.corner.y + 30},
                "orange dots: forward, G(z) moved to z + k D(z)", Rgb8{220, 90, 20});
    s = write_png("11_turbulence_line.png", img.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("wrote 11_turbulence_line.png\n");
    return 0;
}
