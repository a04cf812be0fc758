// Lesson 13: wood (okada1987 §4.2): rings G = sin(k2·r) about an axis parallel to z
// (eq. (10)), displaced along the radius by k·D(P) (eq. (11), as pixel shift). Two slabs cut
// from the same solid: the end grain (the plane z = 32, across the axis: rings) and a
// board sawn along the axis (the plane y = 20: stripes). sin lies in [-1, 1]; eq. (12)
// wants [0, 1]: (G + 1)/2. On the axis (r = 0) the radial direction is undefined and the
// point is not moved (wood_radial_direction() reports it).
// Figures: paper_figures/okada1987/fig10_15_objects.cpp,
//   paper_figures/okada1989/fig06_07_fundamental.cpp.
// Run: make examples   (13_wood_slab.png appears in build/examples/out/)
#include <cstdio>

#include "shitsukan/image/image_io.hpp"
#include "shitsukan/solid/solid.hpp"

using namespace shitsukan;

int main() {
    FractalParams params;
    FractalLattice lattice;
    Status s = lattice.build(params);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    WoodParams wood;
    wood.x0 = 26.0f, wood.y0 = 30.0f;  // the axis
    wood.k2 = 1.2f;                    // a ring every 2·pi/1.2 = 5.2 lattice units
    wood.k = 1.6f;                     // okada1987 §4.4
    s = validate_wood(wood);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    Vec3 u;
    Status on_axis = wood_radial_direction(Vec3{26.0f, 30.0f, 5.0f}, wood, u);
    std::printf("on the axis: %s\n", on_axis.message());
    const Vec3 winter{128, 72, 34}, summer{226, 184, 128};  // I_max, I_min of eq. (12)

    const int size = 384;
    RgbImage img(2 * size + 8, size, Rgb8{255, 255, 255});
    for (int panel = 0; panel < 2; ++panel)
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i) {
                const float a = 64.0f * (i + 0.5f) / size, b = 64.0f * (1.0f - (j + 0.5f) / size);
                const Vec3 p = panel == 0 ? Vec3{a, b, 32.0f} : Vec3{a, 20.0f, b};
                const float g = wood_texture(p, turbulence(lattice.view(), p), wood);
                const Vec3 c = lookup_color(wood_unit_range(g), summer, winter);
                img.at(panel * (size + 8) + i, j) =
                    Rgb8{std::uint8_t(c.x), std::uint8_t(c.y), std::uint8_t(c.z)};
            }
    s = write_png("13_wood_slab.png", img.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("wrote 13_wood_slab.png (left: end grain z = 32; right: board y = 20)\n");
    return 0;
}
