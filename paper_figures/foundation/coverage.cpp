// Foundation demo figure: the coverage test as a picture. A screen-filling tiling of
// triangles (shared edges, shared vertices, fans; a third of the vertices exactly on pixel
// centres, a third exactly on pixel corners) is rasterized triangle by triangle while every
// pixel counts its writes. Each pixel is then shown enlarged, coloured by its count: written
// once = a pastel colour of its triangle, never = red, more than once = magenta. The
// triangle edges are drawn over it, so one sees which side of an edge each pixel centre
// went to (the top-left rule).
// Examples: examples/00_naive_triangle.cpp, examples/01_first_triangle.cpp.
#include <cmath>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/wireframe.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

// Cells over [-1, 1]^2 (the screen of an orthographic camera with half height 1); interior
// vertices jittered, snapped to pixel centres or corners a third of the time each. Every
// third cell is a fan of four triangles around a centre vertex.
TriangleMesh tiling(int cells, int pixels, std::uint64_t seed) {
    TriangleMesh m;
    Pcg32 rng(seed, 11u);
    const float pixel = 2.0f / float(pixels);
    auto snap = [&](float v) {
        switch (rng.next_u32() % 3u) {
            case 0: return (std::floor(v / pixel) + 0.5f) * pixel;  // a pixel centre
            case 1: return std::floor(v / pixel) * pixel;           // a pixel corner
            default: return v;
        }
    };
    const float step = 2.0f / float(cells);
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            float x = -1 + step * float(i), y = -1 + step * float(j);
            if (i > 0 && i < cells && j > 0 && j < cells) {
                x = snap(x + (rng.uniform() - 0.5f) * 0.5f * step);
                y = snap(y + (rng.uniform() - 0.5f) * 0.5f * step);
            }
            m.add_vertex({x, y, 0}, {0, 0, 1});
        }
    auto id = [&](int i, int j) { return std::uint32_t(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            std::uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if ((i + 2 * j) % 3 == 0) {
                Vec3 centre =
                    (m.positions[a] + m.positions[b] + m.positions[c] + m.positions[d]) * 0.25f;
                std::uint32_t e = m.add_vertex({snap(centre.x), snap(centre.y), 0}, {0, 0, 1});
                m.add_triangle(a, b, e);
                m.add_triangle(b, c, e);
                m.add_triangle(c, d, e);
                m.add_triangle(d, a, e);
            } else if ((i + j) % 2 == 0) {
                m.add_triangle(a, b, c);
                m.add_triangle(a, c, d);
            } else {
                m.add_triangle(a, b, d);
                m.add_triangle(b, c, d);
            }
        }
    return m;
}

}  // namespace

SHITSUKAN_FIGURE(foundation_coverage, "foundation", "coverage",
                 "Coverage test: a tiling of triangles writes every pixel exactly once") {
    const int pixels = ctx.quick() ? 24 : 48;  // the rasterized frame, pixels per side
    const int zoom = ctx.quick() ? 5 : 11;     // enlargement for display
    const int cells = ctx.quick() ? 4 : 6;
    ctx.chosen("frame", fmt("%d x %d pixels, shown %dx enlarged", pixels, pixels, zoom),
               "small enough to see single pixels");
    ctx.chosen("tiling",
               fmt("%d x %d cells, a third fans of 4 triangles, jitter 1/4 cell", cells, cells),
               "shared edges, shared vertices and fans, as the coverage test");
    ctx.chosen("vertex snapping", "1/3 on pixel centres, 1/3 on pixel corners, 1/3 free",
               "edges through pixel centres are where a fill rule must decide");
    ctx.chosen("seed", "3", "any; the test suite checks several");

    TriangleMesh grid = tiling(cells, pixels, 3u);
    MeshView mesh = grid.view();
    Camera cam = orthographic_camera({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 1.0f, pixels, pixels);

    // Count writes per pixel: each triangle drawn alone, on a fresh depth buffer.
    std::vector<int> count(std::size_t(pixels) * pixels, 0), owner(count.size(), -1);
    RgbImage color(pixels, pixels);
    FloatImage depth(pixels, pixels, INFINITY);
    FrameBand band = full_frame_band(color.view(), depth.view());
    int current = 0;
    auto counter = [&](const Fragment& f) {
        std::size_t i = std::size_t(f.y) * pixels + f.x;
        ++count[i];
        owner[i] = current;
        return Rgb8{};
    };
    for (current = 0; current < mesh.triangle_count; ++current) {
        MeshView one = mesh;
        one.indices = mesh.indices + 3 * current;
        one.triangle_count = 1;
        SHITSUKAN_TRY(draw_mesh(cam, band, one, DrawOptions{}, counter));
        fill(depth.view(), INFINITY);
    }

    // Enlarge, colour by count, then draw the triangle edges over it at the enlarged scale.
    const int big = pixels * zoom;
    RgbImage out(big, big);
    FloatImage out_depth(big, big, INFINITY);
    int once = 0, never = 0, more = 0;
    for (int y = 0; y < pixels; ++y)
        for (int x = 0; x < pixels; ++x) {
            std::size_t i = std::size_t(y) * pixels + x;
            Rgb8 c;
            if (count[i] == 1) {
                ++once;
                // A pastel per triangle, kept away from the reds and magentas of the errors.
                float h = hash_uniform(5u, 0u, owner[i], 0, 0);
                float g = hash_uniform(5u, 1u, owner[i], 0, 0);
                c = Rgb8{std::uint8_t(140 + 70 * h), std::uint8_t(190 + 55 * g),
                         std::uint8_t(235 - 80 * h)};
            } else if (count[i] == 0) {
                ++never;
                c = Rgb8{230, 20, 20};
            } else {
                ++more;
                c = Rgb8{230, 0, 230};
            }
            for (int v = 0; v < zoom; ++v)
                for (int u = 0; u < zoom; ++u) {
                    bool centre = u == zoom / 2 && v == zoom / 2;  // mark the sample point
                    out.at(x * zoom + u, y * zoom + v) = centre ? Rgb8{40, 40, 40} : c;
                }
        }
    Camera big_cam = orthographic_camera({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 1.0f, big, big);
    std::vector<WireEdge> edges(std::size_t(3 * mesh.triangle_count));
    int n = 0;
    SHITSUKAN_TRY(collect_edges(mesh, edges.data(), int(edges.size()), n));
    WireOptions w;
    w.color = Rgb8{20, 20, 20};
    SHITSUKAN_TRY(draw_edges(big_cam, full_frame_band(out.view(), out_depth.view()), mesh,
                             edges.data(), n, w));
    ctx.note("Legend: pastel = written once (one colour per triangle), red = never written, "
             "magenta = written more than once; dark dots = pixel centres (the sample points), "
             "black lines = the triangle edges.");
    ctx.note(fmt("%d triangles, %d pixels: %d written once, %d never, %d more than once.",
                 mesh.triangle_count, pixels * pixels, once, never, more));
    if (once != pixels * pixels)
        return Status::error(StatusCode::invalid_argument,
                             "coverage: %d pixels never written, %d written more than once",
                             never, more);
    return ctx.save_png(out.view());
}
