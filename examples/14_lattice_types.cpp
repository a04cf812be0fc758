// Lesson 14: okada1989's three ways to get the same lattice.
// Figure: paper_figures/okada1989/table_types.cpp.
//   Type I   the whole (2^R + 1)^3 array in memory, built level by level: O(2^{3R}).
//   Type II  evaluate one node at a time: compute its parents (and theirs) on demand and
//            keep every node computed in a list, so a node keeps its random number.
//   Type III give each node the random number hashed from its own coordinates: any node can
//            be recomputed at any time with the same value, so only the current ancestry is
//            kept (O(R)). It works where Type I cannot: R = 20 is a 1,048,577^3 lattice.
// With the hash as the noise source all three give the same float at every node. This
// program computes the same 256 x 256 slice with each type, compares them bit for bit,
// prints memory and time, and writes the three slices side by side.
// Run: make examples   (14_lattice_types.png appears in build/examples/out/)
#include <chrono>
#include <cstdio>
#include <cstring>
#include <vector>

#include "shitsukan/image/colormap.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/solid/solid.hpp"

using namespace shitsukan;

int main() {
    FractalParams params;  // R = 6, hash noise
    const int n = 256;
    std::vector<float> d1(n * n), d2(n * n), d3(n * n);
    auto point = [&](int i, int j) {
        return Vec3{64.0f * (i + 0.5f) / n, 64.0f * (j + 0.5f) / n, 20.7f};
    };
    auto now = [] { return std::chrono::steady_clock::now(); };
    auto ms = [](auto t0, auto t1) {
        return std::chrono::duration<double, std::milli>(t1 - t0).count();
    };

    auto t0 = now();
    FractalLattice type1;
    Status s = type1.build(params);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) d1[j * n + i] = turbulence(type1.view(), point(i, j));
    auto t1 = now();
    TypeIILattice type2;
    s = type2.init(params);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) d2[j * n + i] = type2.turbulence(point(i, j));
    auto t2 = now();
    TypeIIILattice type3;
    s = type3.init(params);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) d3[j * n + i] = type3.turbulence(point(i, j));
    auto t3 = now();

    std::printf("Type I  : %8zu bytes (the whole array)      %7.2f ms (build + slice)\n",
                type1.bytes(), ms(t0, t1));
    std::printf("Type II : %8zu bytes (%zu listed nodes)  %7.2f ms\n", type2.list_bytes(),
                type2.list_size(), ms(t1, t2));
    std::printf("Type III: %8zu bytes (ancestry; object %zu) %7.2f ms\n", type3.ancestry_bytes(),
                TypeIIILattice::object_bytes(), ms(t2, t3));
    const bool same12 = std::memcmp(d1.data(), d2.data(), d1.size() * sizeof(float)) == 0;
    const bool same13 = std::memcmp(d1.data(), d3.data(), d1.size() * sizeof(float)) == 0;
    std::printf("slice identical bit for bit: I = II %s, I = III %s\n", same12 ? "yes" : "NO",
                same13 ? "yes" : "NO");

    FractalParams deep = params;
    deep.R = 20;
    TypeIIILattice huge;
    s = huge.init(deep);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("Type III at R = 20 (%lld points a side; Type I would need %llu bytes): "
                "D(524288.5, 3.25, 999999) = %.4f\n",
                static_cast<long long>(lattice_side(20)),
                static_cast<unsigned long long>(lattice_bytes(20)),
                double(huge.turbulence(Vec3{524288.5f, 3.25f, 999999.0f})));

    RgbImage img(3 * n + 16, n, Rgb8{255, 255, 255});
    const std::vector<float>* slices[3] = {&d1, &d2, &d3};
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                img.at(k * (n + 8) + i, n - 1 - j) =
                    colormap(ColorMap::diverging, ((*slices[k])[j * n + i] + 2.0f) / 4.0f);
    s = write_png("14_lattice_types.png", img.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("wrote 14_lattice_types.png (Types I, II, III: the same slice)\n");
    return same12 && same13 ? 0 : 1;
}
