// Lesson 15: okada1987 marble (and wood) on a mesh of your own, with one library call.
// Figures: paper_figures/okada1987/fig10_15_objects.cpp,
//   paper_figures/okada1989/fig08_10_objects.cpp.
// The mesh is moved into [-1, 1]^3 (fit_mesh_to_cube), each pixel's object-space point is
// mapped into the 65^3 lattice (object_to_lattice), and render_solid_texture shades it with
// the figures' chosen stripes, colours and light (solid/okada1987_presets.hpp). Replace the
// torus by your own TriangleMesh (positions + indices, geom/mesh.hpp) to texture your model.
// Run: make examples   (15_marble_torus.png, 15_wood_torus.png in build/examples/out/)
#include <cstdio>

#include "shitsukan/shitsukan.hpp"

using namespace shitsukan;

int main() {
    FractalLattice lattice;
    Status s = lattice.build(okada1987_lattice_params());  // R = 6, beta 0.9, seed 1987
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;

    TriangleMesh mesh;
    s = make_torus(0.64f, 0.28f, 96, 48, mesh);
    if (s) s = fit_mesh_to_cube(mesh, 0.92f);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;

    const Camera camera =
        perspective_camera({1.6f, 2.5f, 2.8f}, {0, 0, 0}, {0, 1, 0}, 30.0f, 512, 512);
    RgbImage image;
    s = render_solid_texture(camera, mesh.view(), lattice.view(), okada1987_marble(), image);
    if (s) s = write_png("15_marble_torus.png", image.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;

    s = render_solid_texture(camera, mesh.view(), lattice.view(), okada1987_wood(), image);
    if (s) s = write_png("15_wood_torus.png", image.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("wrote 15_marble_torus.png and 15_wood_torus.png (okada1987 presets)\n");
}
