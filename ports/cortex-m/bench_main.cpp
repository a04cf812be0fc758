// ports/cortex-m/bench_main.cpp — instructions per lattice node, per marble pixel, per
// rasterized pixel and per triangle on the device, counted by QEMU `-icount shift=0`
// (icount.hpp). `make bench-mcu` runs it on every core (bench_mcu.sh) and prints `bench:`
// lines; the counts include the loop and call overhead of each measured call. Outside the counted
// runs the UV sphere's frame binned with its vertices kept is compared with the unbinned one
// (every fragment's fields and every pixel, hashed): a difference fails the firmware.
// BENCH_CORE names the core in the lines. BENCH_SMALL_RAM (the Cortex-M0's 16 KB): the Type I
// build is measured on a 9^3 lattice (R = 3, 2.9 KB) instead of 65^3 (1.1 MB), the marble
// and the fig. 10a cube take D(P) from the Type III lattice, the bands are 4 rows instead of
// 16, and the 48 x 24 UV sphere (66 KB of arrays) is left out.
#include <cstdint>
#include <limits>

#include "assert_handler.hpp"
#include "icount.hpp"
#include "semihosting.hpp"
#include "shitsukan/geom/mesh_arrays.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/lattice_type3.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"
#include "shitsukan/solid/solid_material.hpp"
#include "shitsukan/solid/turbulence.hpp"
#include "type3_solid_shader.hpp"
#if !defined(BENCH_SMALL_RAM)
#include "shitsukan/render/solid_mesh.hpp"
#endif

#if !defined(BENCH_CORE)
#define BENCH_CORE "M4F"
#endif

using namespace shitsukan;

namespace {

void put(const char* s) {
    int n = 0;
    while (s[n]) ++n;
    port::semihosting_write(s, n);
}
void put_uint(std::uint32_t v) {  // 32-bit digits: no 64-bit division helpers on the M0
    char buf[12];
    int n = 0;
    do {
        buf[sizeof buf - 1 - n++] = char('0' + v % 10u);
        v /= 10u;
    } while (v != 0);
    port::semihosting_write(buf + sizeof buf - n, n);
}
void bench_line(const char* what, std::uint64_t instructions, std::uint32_t count,
                const char* unit) {
    put("bench: ");
    put(what);
    put(" (" BENCH_CORE "): ");
    put_uint(std::uint32_t(instructions / (count ? count : 1)));
    put(" instructions per ");
    put(unit);
    put(" (");
    put_uint(count);
    put(" ");
    put(unit);
    put("s, ");
    put_uint(std::uint32_t(instructions / 1000u));
    put(" thousand instructions)\n");
}

#if defined(BENCH_SMALL_RAM)
constexpr int kBenchR = 3, kRows = 4;
#else
constexpr int kBenchR = kOkada1987R, kRows = 16;
#endif
constexpr int kSide = (1 << kBenchR) + 1;
float g_lattice[kSide * kSide * kSide];
TypeIIILattice g_type3;
constexpr int kW = 128;
Rgb8 g_color[kW * kRows];
float g_depth[kW * kRows];
Vec3 g_pos[kBoxVertexCount], g_nrm[kBoxVertexCount];
Vec2 g_uv[kBoxVertexCount];
std::uint32_t g_idx[3 * kBoxTriangleCount];
volatile float g_sink;

// The frame drawn band by band: draw(band) per band, statistics summed over the bands.
template <class Draw>
bool draw_in_bands(Draw draw) {
    for (int y0 = 0; y0 < kW; y0 += kRows) {
        const FrameBand band = make_band(RgbView{g_color, kW, kRows, kW},
                                         FloatView{g_depth, kW, kRows, kW}, y0, kW, kW);
        clear_band(band, Rgb8{24, 26, 32});
        if (!draw(band)) return false;
    }
    return true;
}
Rgb8 flat_shader(const Fragment& f, void*) { return Rgb8{std::uint8_t(f.x), std::uint8_t(f.y), 0}; }

#if !defined(BENCH_SMALL_RAM)  // the frame comparisons go with bench_sphere (below)
// FNV-1a (32 bits) of n bytes, folded into h.
void fnv1a(std::uint32_t* h, const void* bytes, std::uint32_t n) {
    const unsigned char* p = static_cast<const unsigned char*>(bytes);
    for (std::uint32_t i = 0; i < n; ++i) *h = (*h ^ p[i]) * 16777619u;
}
// A shader for the frame comparisons (not measured): the FNV-1a of every field of the fragment,
// folded into *user in the order the fragments come, and its low bytes as the colour.
Rgb8 fragment_hash_shader(const Fragment& f, void* user) {
    std::uint32_t h = 2166136261u;
    const Vec3* vectors[5] = {&f.object_position, &f.world_position, &f.normal,
                              &f.object_normal, &f.color};
    for (const Vec3* v : vectors) fnv1a(&h, v, sizeof *v);
    fnv1a(&h, &f.uv, sizeof f.uv);
    const std::int32_t ints[4] = {f.x, f.y, f.triangle, f.front_facing ? 1 : 0};
    fnv1a(&h, ints, sizeof ints);
    fnv1a(&h, &f.depth, sizeof f.depth);
    fnv1a(static_cast<std::uint32_t*>(user), &h, sizeof h);
    return Rgb8{std::uint8_t(h), std::uint8_t(h >> 8), std::uint8_t(h >> 16)};
}
// The frame drawn band by band with fragment_hash_shader, outside any counted region: the
// fragments' hash (fragments) and the FNV-1a of every band's colour and depth (pixels).
template <class Draw>
bool hash_frame(Draw draw, std::uint32_t* fragments, std::uint32_t* pixels) {
    *fragments = *pixels = 2166136261u;
    return draw_in_bands([&](const FrameBand& b) {
        if (!draw(b, fragments)) return false;
        fnv1a(pixels, g_color, sizeof g_color);
        fnv1a(pixels, g_depth, sizeof g_depth);
        return true;
    });
}
#endif

bool bench_lattice() {
    FractalParams p = okada1987_lattice_params();
    p.R = kBenchR;
    LatticeView view;
    port::icount_start();
    if (!build_fractal_lattice(p, g_lattice, sizeof g_lattice, view)) return false;
    bench_line(kBenchR == 6 ? "Type I lattice 65^3 build" : "Type I lattice 9^3 build",
               port::icount_since_start(), std::uint32_t(kSide) * kSide * kSide, "lattice node");
    if (!g_type3.init(okada1987_lattice_params())) return false;
    port::icount_start();
    float acc = 0;
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) acc += g_type3.node_value(x * 4 + 1, y * 4 + 3, z * 4 + 2);
    g_sink = acc;
    bench_line("Type III node_value, scattered nodes", port::icount_since_start(), 4096,
               "lattice node");
    return true;
}

// G' on a 64 x 64 slice with D(P) from `density(p)`.
template <class Density>
void bench_slice(const char* what, const SolidMaterial& m, const char* unit, Density density) {
    float acc = 0;
    port::icount_start();
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Vec3 p{0.5f + float(x), 0.5f + float(y), 32.25f};
            acc += solid_density_at(m, p, density(p));
        }
    g_sink = acc;
    bench_line(what, port::icount_since_start(), 4096, unit);
}

bool bench_raster(const Camera& cam, const MeshView& cube) {
    const DrawOptions opt;
    RasterStats stats;
    port::icount_start();
    if (!draw_in_bands([&](const FrameBand& b) {
            return bool(draw_mesh(cam, b, cube, opt, flat_shader, nullptr, &stats));
        }))
        return false;
    bench_line(kRows == 16 ? "rasterized cube 128x128 in 16-row bands, flat shader"
                           : "rasterized cube 128x128 in 4-row bands, flat shader",
               port::icount_since_start(), std::uint32_t(stats.fragments_shaded),
               "rasterized pixel");
    return true;
}

#if !defined(BENCH_SMALL_RAM)
// A UV sphere of 48 x 24 (2,304 triangles, most a few pixels at 128 x 128): the per-triangle
// set-up (plane normal, barycentric gradients) dominates there.
constexpr int kSlices = 48, kStacks = 24;
constexpr int kSphereVertices = (kStacks + 1) * (kSlices + 1);
constexpr int kSphereIndices = kStacks * kSlices * 6;
Vec3 g_sphere_pos[kSphereVertices], g_sphere_nrm[kSphereVertices];
Vec2 g_sphere_uv[kSphereVertices];
std::uint32_t g_sphere_idx[kSphereIndices];
TriangleRows g_sphere_rows[kSphereIndices / 3];
BinnedVertex g_sphere_kept[kSphereVertices];  // the vertices bin_mesh keeps (56 bytes each)

// The binned frame with the kept vertices against the unbinned one on the device, after the
// counted runs: every fragment (all its fields, in order) and every pixel and depth the same.
bool same_binned_frame(const Camera& cam, const MeshView& sphere, const DrawOptions& opt) {
    std::uint32_t unbinned_fragments, unbinned_pixels, kept_fragments, kept_pixels;
    if (!hash_frame(
            [&](const FrameBand& b, std::uint32_t* h) {
                return bool(draw_mesh(cam, b, sphere, opt, fragment_hash_shader, h));
            },
            &unbinned_fragments, &unbinned_pixels))
        return false;
    if (!bin_mesh(cam, sphere, opt, g_sphere_rows, kSphereIndices / 3, g_sphere_kept,
                  kSphereVertices))
        return false;
    if (!hash_frame(
            [&](const FrameBand& b, std::uint32_t* h) {
                return bool(draw_binned_mesh(cam, b, sphere, opt, g_sphere_rows,
                                             kSphereIndices / 3, g_sphere_kept, kSphereVertices,
                                             fragment_hash_shader, h));
            },
            &kept_fragments, &kept_pixels))
        return false;
    if (kept_fragments == unbinned_fragments && kept_pixels == unbinned_pixels) return true;
    put("bench: FAILED (" BENCH_CORE "): the UV sphere binned with its vertices kept is not the "
        "unbinned frame\n");
    return false;
}

bool bench_sphere(const Camera& cam) {
    MeshView sphere;
    if (!make_uv_sphere_arrays(1.2f, kSlices, kStacks, g_sphere_pos, g_sphere_nrm, g_sphere_uv,
                               kSphereVertices, g_sphere_idx, kSphereIndices, sphere))
        return false;
    const DrawOptions opt;
    RasterStats stats;
    port::icount_start();
    if (!draw_in_bands([&](const FrameBand& b) {
            return bool(draw_mesh(cam, b, sphere, opt, flat_shader, nullptr, &stats));
        }))
        return false;
    const std::uint64_t n = port::icount_since_start();
    // per triangle of the frame (every band is handed every triangle: triangles_in / bands)
    bench_line("rasterized UV sphere 48x24 128x128 in 16-row bands, flat shader, unbinned", n,
               std::uint32_t(stats.triangles_in / (kW / kRows)), "triangle");
    RasterStats binned;
    port::icount_start();
    if (!bin_mesh(cam, sphere, opt, g_sphere_rows, kSphereIndices / 3, g_sphere_kept,
                  kSphereVertices))
        return false;
    if (!draw_in_bands([&](const FrameBand& b) {
            return bool(draw_binned_mesh(cam, b, sphere, opt, g_sphere_rows, kSphereIndices / 3,
                                         g_sphere_kept, kSphereVertices, flat_shader, nullptr,
                                         &binned));
        }))
        return false;
    const std::uint64_t nb = port::icount_since_start();
    bench_line("rasterized UV sphere 48x24 128x128 in 16-row bands, flat shader, binned", nb,
               std::uint32_t(sphere.triangle_count), "triangle");
    bench_line("rasterized UV sphere 48x24 128x128 in 16-row bands, flat shader, binned", nb,
               std::uint32_t(binned.fragments_shaded), "rasterized pixel");
    // The same frame with every fragment behind the depth buffer (depth -inf): binning, set-up,
    // edge walks and depth tests, no interpolation and no shader call. That is the per-triangle
    // cost; the rest of the frame above is the shading of its fragments.
    RasterStats hidden;
    port::icount_start();
    if (!bin_mesh(cam, sphere, opt, g_sphere_rows, kSphereIndices / 3, g_sphere_kept,
                  kSphereVertices))
        return false;
    if (!draw_in_bands([&](const FrameBand& b) {
            for (float& d : g_depth) d = -std::numeric_limits<float>::infinity();
            return bool(draw_binned_mesh(cam, b, sphere, opt, g_sphere_rows, kSphereIndices / 3,
                                         g_sphere_kept, kSphereVertices, flat_shader, nullptr,
                                         &hidden));
        }))
        return false;
    const std::uint64_t ns = port::icount_since_start();
    if (hidden.fragments_shaded != 0) return false;
    bench_line("rasterized UV sphere 48x24 128x128 in 16-row bands, binned, set-up only (every "
               "fragment behind the depth buffer)", ns, std::uint32_t(sphere.triangle_count),
               "triangle");
    bench_line("rasterized UV sphere 48x24 128x128 in 16-row bands, flat shader, binned, "
               "shading alone (frame minus set-up only)", nb > ns ? nb - ns : 0,
               std::uint32_t(binned.fragments_shaded), "rasterized pixel");
    return same_binned_frame(cam, sphere, opt);
}
#endif

}  // namespace

int main() {
    port::install_check_handler();
    if (!bench_lattice()) return 1;
    const SolidMaterial marble = okada1987_marble(kOkada1987MarbleK);
    auto type3 = [](Vec3 p) { return g_type3.turbulence(p); };
#if !defined(BENCH_SMALL_RAM)
    LatticeView view;
    if (!build_fractal_lattice(okada1987_lattice_params(), g_lattice, sizeof g_lattice, view))
        return 1;
    auto type1 = [&](Vec3 p) { return turbulence(view, p); };
    bench_slice("marble density G' (eqs. (6)-(12))", marble, "marble pixel", type1);
    bench_slice("wood density G'", okada1987_wood(kOkada1987WoodK), "wood pixel", type1);
#endif
    bench_slice("marble density G', D(P) from Type III", marble, "marble pixel", type3);

    MeshView cube;
    if (!make_box_arrays({-0.9f, -0.9f, -0.9f}, {0.9f, 0.9f, 0.9f}, g_pos, g_nrm, g_uv,
                         kBoxVertexCount, g_idx, 3 * kBoxTriangleCount, cube))
        return 1;
    const Camera cam = perspective_camera({3.6f, 3.0f, 4.6f}, {0, 0, 0}, {0, 1, 0}, 30.0f, kW, kW);
    if (!bench_raster(cam, cube)) return 1;
#if !defined(BENCH_SMALL_RAM)
    if (!bench_sphere(cam)) return 1;
#endif
    RasterStats stats;
    const DrawOptions opt;
#if defined(BENCH_SMALL_RAM)
    port::TypeIIISolidShader shader{&g_type3, marble, SolidShading{}};
    const char* what = "fig. 10a marble cube 128x128 in 4-row bands, D(P) from Type III";
    port::icount_start();
    if (!draw_in_bands([&](const FrameBand& b) {
            return bool(draw_mesh(cam, b, cube, opt, shader, &stats));
        }))
        return 1;
#else
    const char* what = "fig. 10a marble cube 128x128 in 16-row bands";
    port::icount_start();
    if (!draw_in_bands([&](const FrameBand& b) {
            return bool(draw_solid_textured_mesh(cam, b, cube, opt, view, marble, SolidShading{},
                                                 &stats));
        }))
        return 1;
#endif
    bench_line(what, port::icount_since_start(), std::uint32_t(stats.fragments_shaded),
               "marble pixel");
    return 0;
}
