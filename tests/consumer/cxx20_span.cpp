// A C++20 project using shitsukan through pkg-config (tests/consumer/run.sh, make
// test-consumers): it must stay C++20 after `pkg-config --cflags shitsukan` is appended to
// its command line (the .pc carries no -std), so std::span compiles beside the library.
#include <cstdio>
#include <span>

#include <shitsukan/shitsukan.hpp>

static_assert(__cplusplus >= 202002L, "pkg-config's Cflags turned this C++20 build back");

using namespace shitsukan;

// The mean of okada1987's turbulence D(P) over some lattice points, taken as a std::span.
static float mean_turbulence(LatticeView lattice, std::span<const Vec3> points) {
    float sum = 0.0f;
    for (const Vec3& p : points) sum += turbulence(lattice, p);
    return points.empty() ? 0.0f : sum / float(points.size());
}

int main() {
    FractalLattice lattice;
    const Status s = lattice.build(okada1987_lattice_params());
    if (!s) {
        std::fprintf(stderr, "cxx20 consumer: %s\n", s.message());
        return 1;
    }
    const Vec3 points[] = {{10.5f, 20.25f, 30.0f}, {32.0f, 32.0f, 32.0f}, {1.0f, 60.0f, 7.5f}};
    const float mean = mean_turbulence(lattice.view(), points);
    if (!(mean == mean)) {
        std::fprintf(stderr, "cxx20 consumer: turbulence is not a number\n");
        return 1;
    }
    std::printf("C++%ld consumer through pkg-config: std::span of %zu points, mean D = %.6f\n",
                long(__cplusplus / 100 % 100), std::size(points), double(mean));
    return 0;
}
