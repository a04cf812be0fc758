// ports/cortex-m/bench_main.cpp — instructions per lattice node, per marble pixel and per
// rasterized pixel on the device, counted by QEMU: run with `-icount shift=0` (one
// instruction = 1 ns of virtual time) and read the MPS2 CMSDK timer 0 (25 MHz, so one tick
// = 40 instructions). `make bench-mcu` runs it on mps2-an386 (Cortex-M4F) and prints
// `bench:` lines; the counts include the loop and call overhead of each measured call.
#include <cstdint>

#include "assert_handler.hpp"
#include "semihosting.hpp"
#include "shitsukan/geom/mesh_arrays.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/render/solid_mesh.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/lattice_type3.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"
#include "shitsukan/solid/solid_material.hpp"

using namespace shitsukan;

namespace {

// CMSDK APB timer 0 of the MPS2 FPGA images (AN386, AN500): a 32-bit down counter.
volatile std::uint32_t* const kTimerCtrl = reinterpret_cast<volatile std::uint32_t*>(0x40000000u);
volatile std::uint32_t* const kTimerValue = reinterpret_cast<volatile std::uint32_t*>(0x40000004u);
volatile std::uint32_t* const kTimerReload = reinterpret_cast<volatile std::uint32_t*>(0x40000008u);
constexpr std::uint64_t kInstructionsPerTick = 40;  // 1 GHz of -icount time / 25 MHz

void timer_start() {
    *kTimerCtrl = 0;
    *kTimerReload = 0xffffffffu;
    *kTimerValue = 0xffffffffu;
    *kTimerCtrl = 1;
}
std::uint64_t instructions_since_start() {
    return std::uint64_t(0xffffffffu - *kTimerValue) * kInstructionsPerTick;
}

void put(const char* s) {
    int n = 0;
    while (s[n]) ++n;
    port::semihosting_write(s, n);
}
void put_uint(std::uint64_t v) {
    char buf[24];
    int n = 0;
    do {
        buf[sizeof buf - 1 - n++] = char('0' + v % 10u);
        v /= 10u;
    } while (v != 0);
    port::semihosting_write(buf + sizeof buf - n, n);
}
void bench_line(const char* what, std::uint64_t instructions, std::uint64_t count,
                const char* unit) {
    put("bench: ");
    put(what);
    put(": ");
    put_uint(instructions / (count ? count : 1));
    put(" instructions per ");
    put(unit);
    put(" (");
    put_uint(count);
    put(" ");
    put(unit);
    put("s, ");
    put_uint(instructions);
    put(" instructions)\n");
}

constexpr int kSide = 65;
float g_lattice[kSide * kSide * kSide];
TypeIIILattice g_type3;
constexpr int kW = 128, kRows = 16;
Rgb8 g_color[kW * kRows];
float g_depth[kW * kRows];
Vec3 g_pos[kBoxVertexCount], g_nrm[kBoxVertexCount];
Vec2 g_uv[kBoxVertexCount];
std::uint32_t g_idx[3 * kBoxTriangleCount];
// A UV sphere of 48 x 24 (2,304 triangles, most a few pixels at 128 x 128): the per-triangle
// set-up (plane normal, barycentric gradients) dominates there.
constexpr int kSlices = 48, kStacks = 24;
constexpr int kSphereVertices = (kStacks + 1) * (kSlices + 1);
constexpr int kSphereIndices = kStacks * kSlices * 6;
Vec3 g_sphere_pos[kSphereVertices], g_sphere_nrm[kSphereVertices];
Vec2 g_sphere_uv[kSphereVertices];
std::uint32_t g_sphere_idx[kSphereIndices];
volatile float g_sink;

// The frame drawn band by band with a flat shader: the rasterizer's own cost per pixel
// (set-up, coverage, interpolation), its statistics summed over the bands.
bool draw_flat_in_bands(const Camera& cam, const MeshView& mesh, const DrawOptions& opt,
                        RasterStats& stats) {
    auto flat = [](const Fragment& f, void*) {
        return Rgb8{std::uint8_t(f.x), std::uint8_t(f.y), 0};
    };
    for (int y0 = 0; y0 < kW; y0 += kRows) {
        const FrameBand band = make_band(RgbView{g_color, kW, kRows, kW},
                                         FloatView{g_depth, kW, kRows, kW}, y0, kW, kW);
        clear_band(band, Rgb8{0, 0, 0});
        if (!draw_mesh(cam, band, mesh, opt, flat, nullptr, &stats)) return false;
    }
    return true;
}

}  // namespace

int main() {
    port::install_check_handler();
    const FractalParams p = okada1987_lattice_params();
    LatticeView view;
    timer_start();
    if (!build_fractal_lattice(p, g_lattice, sizeof g_lattice, view)) return 1;
    bench_line("Type I lattice 65^3 build (M4F)", instructions_since_start(),
               std::uint64_t(kSide) * kSide * kSide, "lattice node");

    if (!g_type3.init(p)) return 1;
    timer_start();
    float acc = 0;
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) acc += g_type3.node_value(x * 4 + 1, y * 4 + 3, z * 4 + 2);
    g_sink = acc;
    bench_line("Type III node_value, scattered nodes (M4F)", instructions_since_start(), 4096,
               "lattice node");

    const SolidMaterial marble = okada1987_marble(kOkada1987MarbleK);
    timer_start();
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            acc += solid_density(marble, view, Vec3{0.5f + float(x), 0.5f + float(y), 32.25f});
    g_sink = acc;
    bench_line("marble density G' (eqs. (6)-(12)) (M4F)", instructions_since_start(), 4096,
               "marble pixel");

    const SolidMaterial wood = okada1987_wood(kOkada1987WoodK);
    timer_start();
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            acc += solid_density(wood, view, Vec3{0.5f + float(x), 0.5f + float(y), 32.25f});
    g_sink = acc;
    bench_line("wood density G' (M4F)", instructions_since_start(), 4096, "wood pixel");

    MeshView cube;
    if (!make_box_arrays({-0.9f, -0.9f, -0.9f}, {0.9f, 0.9f, 0.9f}, g_pos, g_nrm, g_uv,
                         kBoxVertexCount, g_idx, 3 * kBoxTriangleCount, cube))
        return 1;
    const Camera cam = perspective_camera({3.6f, 3.0f, 4.6f}, {0, 0, 0}, {0, 1, 0}, 30.0f, kW, kW);
    DrawOptions opt;
    RasterStats flat_stats;
    timer_start();
    if (!draw_flat_in_bands(cam, cube, opt, flat_stats)) return 1;
    bench_line("rasterized cube 128x128 in 16-row bands, flat shader (M4F)",
               instructions_since_start(), std::uint64_t(flat_stats.fragments_shaded),
               "rasterized pixel");
    MeshView sphere;
    if (!make_uv_sphere_arrays(1.2f, kSlices, kStacks, g_sphere_pos, g_sphere_nrm, g_sphere_uv,
                               kSphereVertices, g_sphere_idx, kSphereIndices, sphere))
        return 1;
    RasterStats sphere_stats;
    timer_start();
    if (!draw_flat_in_bands(cam, sphere, opt, sphere_stats)) return 1;
    const std::uint64_t sphere_instructions = instructions_since_start();
    bench_line("rasterized UV sphere 48x24 128x128 in 16-row bands, flat shader (M4F)",
               sphere_instructions, std::uint64_t(sphere_stats.triangles_in) / (kW / kRows),
               "triangle");  // every band walks every triangle: per triangle of the frame
    bench_line("rasterized UV sphere 48x24 128x128 in 16-row bands, flat shader (M4F)",
               sphere_instructions, std::uint64_t(sphere_stats.fragments_shaded),
               "rasterized pixel");
    RasterStats stats;
    timer_start();
    for (int y0 = 0; y0 < kW; y0 += kRows) {
        const FrameBand band = make_band(RgbView{g_color, kW, kRows, kW},
                                         FloatView{g_depth, kW, kRows, kW}, y0, kW, kW);
        clear_band(band, Rgb8{24, 26, 32});
        if (!draw_solid_textured_mesh(cam, band, cube, opt, view, marble, SolidShading{}, &stats))
            return 1;
    }
    bench_line("fig. 10a marble cube 128x128 in 16-row bands (M4F)", instructions_since_start(),
               std::uint64_t(stats.fragments_shaded), "marble pixel");
    return 0;
}
