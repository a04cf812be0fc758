// A small program that uses shitsukan as an outside project would: okada1987 marble on a
// mesh of its own (a torus) through the umbrella header and one library call. Built by
// tests/consumer/run.sh (make test-consumers) four ways: CMake add_subdirectory, FetchContent,
// find_package after install, and pkg-config after `make install`. It checks that the
// version macro is the version the build system reported (SHITSUKAN_EXPECTED_VERSION), and
// prints a hash of the image: every way of building must give the same bits.
#include <cstdint>
#include <cstdio>
#include <cstring>

#include <shitsukan/shitsukan.hpp>

#ifndef SHITSUKAN_EXPECTED_VERSION
#error "build with -DSHITSUKAN_EXPECTED_VERSION=\"x.y.z\" (the version the build system found)"
#endif

using namespace shitsukan;

int main(int argc, char** argv) {
    if (std::strcmp(SHITSUKAN_VERSION_STRING, SHITSUKAN_EXPECTED_VERSION) != 0) {
        std::fprintf(stderr, "consumer: header version %s, package version %s\n",
                     SHITSUKAN_VERSION_STRING, SHITSUKAN_EXPECTED_VERSION);
        return 1;
    }
    FractalLattice lattice;
    Status s = lattice.build(okada1987_lattice_params());
    TriangleMesh mesh;
    if (s) s = make_torus(0.64f, 0.28f, 48, 24, mesh);
    if (s) s = fit_mesh_to_cube(mesh, 0.92f);
    const Camera camera =
        perspective_camera({1.6f, 2.5f, 2.8f}, {0, 0, 0}, {0, 1, 0}, 30.0f, 128, 128);
    RgbImage image;
    if (s) s = render_solid_texture(camera, mesh.view(), lattice.view(), okada1987_marble(), image);
    if (s && argc > 1) s = write_png(argv[1], image.view());
    if (!s) {
        std::fprintf(stderr, "consumer: %s\n", s.message());
        return 1;
    }
    std::uint32_t hash = 2166136261u;  // FNV-1a over the pixels
    int covered = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const Rgb8 p = image.at(x, y);
            for (std::uint8_t b : {p.r, p.g, p.b}) hash = (hash ^ b) * 16777619u;
            covered += p.r != 24 || p.g != 26 || p.b != 32;
        }
    if (covered < 128 * 128 / 5) {
        std::fprintf(stderr, "consumer: only %d pixels show the torus\n", covered);
        return 1;
    }
    std::printf("consumer: shitsukan %s, marble torus 128x128, %d pixels, hash 0x%08x\n",
                SHITSUKAN_VERSION_STRING, covered, unsigned(hash));
    return 0;
}
