// Lesson 40: a Voronoi division that stays exact on a lattice.
// Figures: paper_figures/tokai1994/fig02_voronoi.cpp, paper_figures/tokai1994/fig03_lattices.cpp.
//
// The Voronoi cell of a seed is the part of the plane nearer to it than to any other seed.
// On a square lattice four seeds lie on every little circle, and a floating-point Voronoi
// code turns each such corner into two corners a hair apart (a zero-length edge), or worse.
// shitsukan decides "which side of a line" and "inside which circle" with exact predicates,
// merges triangles whose circles coincide exactly, and so gives each lattice cell exactly
// four corners. Then we move the seeds a little (tokai1994 eq. (1): M = D·a·Rnd) and see the
// cells turn into irregular polygons.
//
// Build and run:  make examples   (writes build/examples/out/exact_voronoi.png and .svg)
#include <cstdio>
#include <vector>

#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/geom/voronoi.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/leather/seed_layout.hpp"

using namespace shitsukan;

namespace {

// Draw every cell of the unit square into a w x w panel whose corner is at (ox, 0).
void draw_cells(Canvas& c, const VoronoiCells& cells, const std::vector<Vec2d>& seeds, float ox,
                float w) {
    std::vector<Vec2> px;
    for (int i = 0; i < cells.cell_count(); ++i) {
        int k;
        const Vec2d* v = cells.cell(i, &k);
        px.clear();
        for (int j = 0; j < k; ++j) px.push_back({ox + float(v[j].x) * w, float(v[j].y) * w});
        if (k) c.polygon_outline(px.data(), k, Rgb8{20, 20, 20}, 1.2f);
        const Vec2d s = seeds[std::size_t(i)];
        if (s.x >= 0 && s.x <= 1 && s.y >= 0 && s.y <= 1)
            c.marker({ox + float(s.x) * w, float(s.y) * w}, MarkerShape::dot, 4, Rgb8{200, 40, 30});
    }
}

}  // namespace

int main() {
    const Vec2d square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // the region, counter-clockwise

    // 1. Seeds on a square lattice, D = 1/8, not moved (a = 0) and moved (a = 0.3).
    SeedLayout lattice, moved;
    if (!square_lattice_seeds(1, 1, 0.125f, 0.0f, 1, lattice) ||
        !square_lattice_seeds(1, 1, 0.125f, 0.3f, 1, moved)) {
        std::fprintf(stderr, "seed layout failed\n");
        return 1;
    }

    // 2. The Voronoi cells, clipped to the square. Count the corners of the inner cells.
    VoronoiCells exact, irregular;
    Status s = voronoi_cells(lattice.moved.data(), int(lattice.moved.size()), square, 4, exact);
    if (s) s = voronoi_cells(moved.moved.data(), int(moved.moved.size()), square, 4, irregular);
    if (!s) {
        std::fprintf(stderr, "%s\n", s.message());
        return 1;
    }
    int inner = 0, four = 0;
    for (int i = 0; i < exact.cell_count(); ++i) {
        int k;
        const Vec2d* v = exact.cell(i, &k);
        bool inside = k > 0;
        for (int j = 0; j < k; ++j)
            inside = inside && v[j].x > 0 && v[j].x < 1 && v[j].y > 0 && v[j].y < 1;
        inner += inside;
        four += inside && k == 4;
    }
    std::printf("a = 0: %d of %d inner cells have exactly 4 corners\n", four, inner);

    // 3. Draw both divisions side by side, as pixels and as SVG.
    const float w = 256;
    RgbImage img(2 * int(w) + 16, int(w), Rgb8{255, 255, 255});
    RasterCanvas canvas(img.view());
    SvgCanvas svg(img.width(), img.height(), Rgb8{255, 255, 255});
    for (Canvas* c : {static_cast<Canvas*>(&canvas), static_cast<Canvas*>(&svg)}) {
        draw_cells(*c, exact, lattice.moved, 0, w);
        draw_cells(*c, irregular, moved.moved, w + 16, w);
    }
    s = write_png("exact_voronoi.png", img.view());
    if (s) s = svg.save("exact_voronoi.svg");
    std::printf("%s\n", s ? "wrote exact_voronoi.png and exact_voronoi.svg" : s.message());
    return s ? 0 : 1;
}
