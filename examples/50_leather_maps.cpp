// Lesson 50: from a scale pattern to the files an artist loads — a 16-bit height map, an RGB
// normal map and an OBJ relief mesh (tokai1994 §3.2).
// Figures: paper_figures/tokai1994/fig12_one_scale.cpp,
//   paper_figures/tokai1994/fig13_15_sections.cpp.
//
// Each scale gets a relief from a Bezier cross-section z(r) swept around its centroid m:
// for a pixel x, the ray from m through x leaves the scale at p, r = |x - m| / |p - m|, and
// the height is z(r). The normal comes from eq. (4), the section's slope turned toward p - m.
//
// Build and run:  make examples   (writes build/examples/out/leather_height16.png,
//                 leather_normal.png, leather_relief.obj)
#include <cstdio>
#include <cstdint>
#include <vector>

#include "shitsukan/geom/obj.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/png16.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/scale_labels.hpp"

using namespace shitsukan;

static int fail(const Status& s) { return std::fprintf(stderr, "%s\n", s.message()), 1; }

int main() {
    // 1. The crocodile-belly pattern of tokai1994 fig. 7 (two-stage Voronoi division).
    ScalePattern pattern;
    Status s = generate_scale_pattern(ScaleParams{}, pattern);
    if (!s) return fail(s);

    // 2. Which polygon holds each pixel: the pattern module's label image.
    const int w = 512, h = 512;
    std::vector<std::int32_t> labels(std::size_t(w) * h);
    if (!(s = rasterize_scale_labels(pattern, w, h, labels.data()))) return fail(s);

    // 3. The relief with the convex section of Table 1 (fig. 13a).
    LeatherMaps maps;
    s = make_leather_maps(pattern, labels.data(), w, h, table1_section(Table1Section::convex),
                          ReliefOptions{}, maps);
    if (!s) return fail(s);

    // 4. Height map: 16 bits, 0 = groove floor, 65535 = the highest point.
    Gray16Image height(w, h);
    encode_height16(maps, height.data());
    if (!(s = write_png16("leather_height16.png", height.view()))) return fail(s);

    // 5. Normal map: rgb = (n + 1) / 2, green = +y (the OpenGL convention).
    std::vector<std::uint8_t> rgb(3 * std::size_t(w) * h);
    encode_normal_rgb(maps, rgb.data());
    RgbImage normal(w, h);
    for (std::size_t i = 0; i < std::size_t(w) * h; ++i)
        normal.data()[i] = Rgb8{rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]};
    if (!(s = write_png("leather_normal.png", normal.view()))) return fail(s);

    // 6. The relief as a mesh: every 4th pixel a vertex, heights x 1 (the true relief).
    TriangleMesh mesh;
    if (!(s = make_relief_mesh(maps, 4, 1.0f, mesh))) return fail(s);
    if (!(s = write_obj("leather_relief.obj", mesh))) return fail(s);

    std::printf("%d scales; height map unit = %.3g pattern units; relief mesh %d triangles\n",
                pattern.polygon_count(), double(maps.max_height) / 65535.0, mesh.triangle_count());
    return 0;
}
