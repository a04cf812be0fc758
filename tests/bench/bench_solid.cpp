// bench_solid — okada's fractal turbulence D(P) against the usual peers, same points, same run:
// stb_perlin fbm (6 octaves) and libnoise Perlin (6 octaves).
#define STB_PERLIN_IMPLEMENTATION
#include <stb/stb_perlin.h>

#include <libnoise/noise.h>

#include <cstdio>
#include <string>
#include <vector>

#include "bench.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/solid/solid.hpp"

using namespace shitsukan;

namespace {

// Scattered points inside the 65^3 lattice (lattice units). The peers see the same points
// divided by 8 (a frequency where their octaves are busy; the cost does not depend on it).
std::vector<Vec3> scattered_points(int n) {
    Pcg32 rng(7u, 3u);
    std::vector<Vec3> pts(static_cast<std::size_t>(n));
    for (Vec3& p : pts)
        p = Vec3{rng.uniform(0.0f, 64.0f), rng.uniform(0.0f, 64.0f), rng.uniform(0.0f, 64.0f)};
    return pts;
}

// A 512 x 512 raster slice through the lattice: pixel (x, y) -> (x/8, y/8, 32.3).
std::vector<Vec3> slice_points() {
    std::vector<Vec3> pts;
    pts.reserve(512 * 512);
    for (int y = 0; y < 512; ++y)
        for (int x = 0; x < 512; ++x)
            pts.push_back(Vec3{(float(x) + 0.5f) / 8.0f, (float(y) + 0.5f) / 8.0f, 32.3f});
    return pts;
}

float stb_fbm(Vec3 p) { return stb_perlin_fbm_noise3(p.x / 8, p.y / 8, p.z / 8, 2.0f, 0.5f, 6); }

// ours(p) and peer(p) summed over every point (the sum keeps the work alive), timed in turns,
// per point.
template <class F, class G>
bench::Pair points_in_turns(const std::vector<Vec3>& pts, F ours, G peer) {
    auto sum = [&pts](auto& sample) {
        double s = 0;
        for (const Vec3& p : pts) s += double(sample(p));
        bench::sink(s);
    };
    return bench::per(bench::in_turns([&] { sum(ours); }, [&] { sum(peer); }), double(pts.size()));
}

using bench::set_up;

const FractalLattice& bench_lattice() {
    static FractalLattice lattice;
    if (lattice.empty()) set_up(lattice.build(FractalParams()), "65^3 Type I lattice");
    return lattice;
}

}  // namespace

SHITSUKAN_BENCH(solid_type1_sample) {
    const LatticeView v = bench_lattice().view();
    const std::vector<Vec3> pts = scattered_points(4096);
    noise::module::Perlin perlin;
    perlin.SetOctaveCount(6);
    auto ours = [&](Vec3 p) { return turbulence(v, p); };
    bench::report("D(P) Type I per sample, scattered points", points_in_turns(pts, ours, stb_fbm),
                  "stb_perlin fbm-6", 15.0);
    bench::report("D(P) Type I per sample, scattered points",
                  points_in_turns(pts, ours,
                                  [&](Vec3 p) { return perlin.GetValue(p.x / 8, p.y / 8, p.z / 8); }),
                  "libnoise Perlin-6");
}

namespace {

// The floor of one D(P) sample: the trilinear lookup alone (no clamping, no NaN handling, no
// check), the same factored eq. (6), on points known to lie inside the lattice.
inline float raw_trilinear(const LatticeView& v, Vec3 p) {
    const int ix = int(p.x), iy = int(p.y), iz = int(p.z);
    const float fx = p.x - float(ix), fy = p.y - float(iy), fz = p.z - float(iz);
    const std::size_t side = std::size_t(v.side), plane = side * side;
    const float* b = v.values + (std::size_t(iz) * side + std::size_t(iy)) * side + std::size_t(ix);
    const float d[8] = {b[0],     b[1],         b[side],         b[side + 1],
                        b[plane], b[plane + 1], b[plane + side], b[plane + side + 1]};
    return trilinear_corners(d, fx, fy, fz);
}

// The two loops timed against each other, each compiled on its own (not inlined into the
// bench, whose register pressure would then weigh on one side), as a renderer's loop is.
// The view is passed by value, as a renderer holds it (a copy of three words): with a
// reference the compiler must reload it after any call it cannot see into.
__attribute__((noinline)) double sum_of_turbulence(const LatticeView v,
                                                   const std::vector<Vec3>& pts) {
    double s = 0;
    for (const Vec3& p : pts) s += double(turbulence(v, p));
    return s;
}
__attribute__((noinline)) double sum_of_raw_trilinear(const LatticeView v,
                                                      const std::vector<Vec3>& pts) {
    double s = 0;
    for (const Vec3& p : pts) s += double(raw_trilinear(v, p));
    return s;
}

// The slice (pixel (x, y) -> ((x + 0.5)/8, (y + 0.5)/8, 32.3)) by turbulence_row and by
// single calls on the same points, each compiled on its own.
__attribute__((noinline)) double slice_by_rows(const LatticeView& v, float* row) {
    double s = 0;
    for (int y = 0; y < 512; ++y) {
        turbulence_row(v, Vec3{0.5f / 8.0f, (float(y) + 0.5f) / 8.0f, 32.3f}, 1.0f / 8.0f, 512,
                       row);
        s += double(row[511]);
    }
    return s;
}
__attribute__((noinline)) double slice_by_single_calls(const LatticeView& v, float* row) {
    double s = 0;
    for (int y = 0; y < 512; ++y) {
        for (int x = 0; x < 512; ++x) {
            const Vec3 p{0.5f / 8.0f + float(x) * (1.0f / 8.0f), (float(y) + 0.5f) / 8.0f, 32.3f};
            row[x] = turbulence(v, p);
        }
        s += double(row[511]);
    }
    return s;
}

}  // namespace

SHITSUKAN_BENCH(solid_type1_floor_and_row) {
    const LatticeView v = bench_lattice().view();
    // Single samples at scattered points against the raw lookup (goal: within 1.15x, i.e.
    // ratio >= 0.87).
    const std::vector<Vec3> pts = scattered_points(4096);
    const bench::Pair single = bench::per(
        bench::in_turns([&] { bench::sink(sum_of_turbulence(v, pts)); },
                        [&] { bench::sink(sum_of_raw_trilinear(v, pts)); }),
        double(pts.size()));
    bench::report("D(P) Type I single sample vs the raw trilinear lookup (goal <= 1.15x)", single,
                  "raw lookup", 1.0 / 1.15);
    // A 512 x 512 slice row by row (pixel (x, y) -> ((x + 0.5)/8, (y + 0.5)/8, 32.3)): the
    // row API against single calls on the same points (goal ratio >= 4).
    std::vector<float> row(512);
    const bench::Pair rows = bench::per(
        bench::in_turns([&] { bench::sink(slice_by_rows(v, row.data())); },
                        [&] { bench::sink(slice_by_single_calls(v, row.data())); }),
        512.0 * 512.0);
    bench::report("D(P) Type I per sample, 512x512 slice: turbulence_row", rows, "single calls",
                  4.0);
}

SHITSUKAN_BENCH(solid_type3_slice) {
    const std::vector<Vec3> pts = slice_points();
    FractalParams params;
    TypeIIILattice t3;
    FractalParams deep;
    deep.R = 20;
    TypeIIILattice t20;
    if (!set_up(t3.init(params), "D(P) Type III") ||
        !set_up(t20.init(deep), "D(P) Type III R = 20"))
        return;
    noise::module::Perlin perlin;
    perlin.SetOctaveCount(6);
    const LatticeView v = bench_lattice().view();
    auto type3 = [&](Vec3 p) { return t3.turbulence(p); };
    bench::report("D(P) Type I per sample, 512x512 slice",
                  points_in_turns(pts, [&](Vec3 p) { return turbulence(v, p); }, stb_fbm),
                  "stb_perlin fbm-6");
    bench::report("D(P) Type III per sample, 512x512 slice", points_in_turns(pts, type3, stb_fbm),
                  "stb_perlin fbm-6", 1.0);
    bench::report(
        "D(P) Type III per sample, 512x512 slice",
        points_in_turns(pts, type3,
                        [&](Vec3 p) { return perlin.GetValue(p.x / 8, p.y / 8, p.z / 8); }),
        "libnoise Perlin-6");
    // The same slice, 1/8 cell per pixel, deep inside the 1,048,577^3 lattice.
    const Vec3 deep_offset{300000.0f, 200000.0f, 400000.0f};
    bench::report("D(P) Type III R = 20 per sample, 512x512 slice",
                  points_in_turns(pts, [&](Vec3 p) { return t20.turbulence(p + deep_offset); },
                                  stb_fbm),
                  "stb_perlin fbm-6");
}

SHITSUKAN_BENCH(solid_lattice_build) {
    FractalParams params;
    std::vector<float> values(65 * 65 * 65);
    LatticeView v;
    if (!set_up(build_fractal_lattice(params, values.data(), values.size() * sizeof(float), v),
                "65^3 lattice build"))
        return;
    const bench::Pair t = bench::in_turns(
        [&] {
            (void)build_fractal_lattice(params, values.data(), values.size() * sizeof(float), v);
            bench::sink(values[1000]);
        },
        [&] {
            Pcg32 rng(params.seed, 0u);
            float s = 0;
            for (int i = 0; i < 65 * 65 * 65 - 8; ++i) s += rng.gaussian();
            bench::sink(s);
        });
    bench::report("65^3 lattice build, whole", t, "274617 Pcg32 Gaussians", 0.6);
}

SHITSUKAN_BENCH(solid_type3_memory) {
    for (int R : {6, 20}) {
        FractalParams p;
        p.R = R;
        TypeIIILattice t3;
        if (!set_up(t3.init(p), "Type III memory")) return;
        bench::info("Type III memory R = " + std::to_string(R),
                    "ancestry " + std::to_string(t3.ancestry_bytes()) + " bytes, whole object " +
                        std::to_string(TypeIIILattice::object_bytes()) +
                        " bytes (fixed, no allocation); Type I would need " +
                        std::to_string(lattice_bytes(R)) + " bytes");
    }
}
