// ports/cortex-m/footprint_main.cpp — the two firmwares of the footprint goals, built by
// `make footprint-mcu` for the Cortex-M4F and run under QEMU (so the numbers are of programs
// that work):
//   FOOTPRINT_LATTICE   a Type III lattice (okada1987's R = 6, no table, eq. (2)'s
//                       amplitudes computed at compile time) and D(P) at 4096 points: the
//                       digest of the values
//   FOOTPRINT_MARBLE    okada1987's marble cube (fig. 10a's scene and shader maths) at
//                       128 x 128 in 8-row bands, D(P) from the Type III lattice (no 1.1 MB
//                       table): the digest of the frame
// Both print the main stack's high-water mark (the stack is painted before the work). Two
// variants of the lattice firmware measure what ports/PORTING.md section 7's two choices save:
//   FOOTPRINT_LATTICE_RUNTIME_BETA  the amplitudes computed on the device (init(params))
//   FOOTPRINT_LATTICE_MESSAGES      built without SHITSUKAN_STATUS_NO_ARGUMENTS (mcu.mk)
// Both print the lattice firmware's digest.
#include <cstdint>

#if defined(FOOTPRINT_LATTICE_RUNTIME_BETA) || defined(FOOTPRINT_LATTICE_MESSAGES)
#define FOOTPRINT_LATTICE 1
#endif

#include "semihosting.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/solid/lattice_type3.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"
#if defined(FOOTPRINT_MARBLE)
#include "shitsukan/geom/mesh_arrays.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/solid/marble.hpp"
#include "shitsukan/solid/object_mapping.hpp"
#include "shitsukan/solid/solid_material.hpp"
#endif

extern "C" std::uint32_t _sstack, _estack;

using namespace shitsukan;

namespace {

void put(const char* s) {
    int n = 0;
    while (s[n]) ++n;
    port::semihosting_write(s, n);
}
// 32-bit digits only: a 64-bit division would link libgcc's __udivmoddi4 (700 bytes)
void put_uint(std::uint32_t v, unsigned base = 10) {
    char buf[12];
    int n = 0;
    do {
        buf[sizeof buf - 1 - n++] = "0123456789abcdef"[v % base];
        v /= base;
    } while (v != 0);
    port::semihosting_write(buf + sizeof buf - n, n);
}
void put_hex64(std::uint64_t v) {
    for (int shift = 60; shift >= 0; shift -= 4) {
        const char c = "0123456789abcdef"[(v >> shift) & 15u];
        port::semihosting_write(&c, 1);
    }
}
struct Fnv {
    std::uint64_t h = 0xcbf29ce484222325ull;
    void byte(std::uint8_t b) { h = (h ^ b) * 0x100000001b3ull; }
};

constexpr std::uint32_t kPaint = 0x5a5aa5a5u;
__attribute__((noinline)) void paint_stack() {
    // up to 64 bytes below this frame (the frame itself and its callers stay untouched)
    const auto sp = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0)) - 64;
    for (std::uint32_t* p = &_sstack; reinterpret_cast<std::uintptr_t>(p) < sp; ++p) *p = kPaint;
}
std::uint32_t stack_high_water() {
    std::uint32_t* p = &_sstack;
    while (p < &_estack && *p == kPaint) ++p;
    return std::uint32_t(reinterpret_cast<std::uintptr_t>(&_estack) -
                         reinterpret_cast<std::uintptr_t>(p));
}

TypeIIILattice g_lattice;

#if defined(FOOTPRINT_MARBLE)
constexpr int kSize = 128, kRows = 8;
Rgb8 g_color[kSize * kRows];
float g_depth[kSize * kRows];
Vec3 g_pos[kBoxVertexCount], g_nrm[kBoxVertexCount];
Vec2 g_uv[kBoxVertexCount];
std::uint32_t g_idx[3 * kBoxTriangleCount];

// render/solid_mesh.cpp's shader with D(P) from the Type III lattice.
struct TypeIIIMarbleShader {
    SolidMaterial material;
    ObjectToLattice mapping;
    Vec3 light;
    Rgb8 operator()(const Fragment& f) {
        const Vec3 p = object_to_lattice(f.object_position, mapping);
        // marble_density: solid_density_at's marble case (the material has no layer period),
        // without the wood code a dispatch on the pattern would link
        const float density = marble_density(p, g_lattice.turbulence(p), material.marble);
        const Vec3 c = solid_density_color(material, density);
        Vec3 n = f.normal;
        if (!f.front_facing) n = -n;
        const float lambert = dot(n, light) > 0.0f ? dot(n, light) : 0.0f;
        const float l = 0.3f + 0.7f * lambert;
        auto byte = [](float v) {
            return std::uint8_t(v <= 0.0f ? 0 : (v >= 255.0f ? 255 : int(v + 0.5f)));
        };
        return Rgb8{byte(c.x * l), byte(c.y * l), byte(c.z * l)};
    }
};
#endif

}  // namespace

int main() {
    paint_stack();
#if defined(FOOTPRINT_LATTICE_RUNTIME_BETA)
    if (!g_lattice.init(okada1987_lattice_params())) return 1;  // det_exp on the device
#else
    // eq. (2)'s amplitudes computed by the compiler for the preset's beta: no double
    // arithmetic on the device (the same floats as level_amplitude's at run time)
    if (!g_lattice.init(okada1987_lattice_params(), kOkada1987Amplitudes)) return 1;
#endif
    Fnv h;
#if defined(FOOTPRINT_LATTICE)
    for (int i = 0; i < 4096; ++i) {
        const Vec3 q{float(i % 64) + 0.25f, float((i / 64) % 64) + 0.5f, 31.75f};
        float d = g_lattice.turbulence(q);
        std::uint32_t u;
        __builtin_memcpy(&u, &d, sizeof u);
        for (int k = 0; k < 4; ++k) h.byte(std::uint8_t(u >> (8 * k)));
    }
    put("footprint lattice: D(P) at 4096 points fnv ");
#else
    MeshView cube;
    if (!make_box_arrays({-0.9f, -0.9f, -0.9f}, {0.9f, 0.9f, 0.9f}, g_pos, g_nrm, g_uv,
                         kBoxVertexCount, g_idx, 3 * kBoxTriangleCount, cube))
        return 1;
    const Camera cam =
        perspective_camera({3.6f, 3.0f, 4.6f}, {0, 0, 0}, {0, 1, 0}, 30.0f, kSize, kSize);
    TypeIIIMarbleShader shader{okada1987_marble(kOkada1987MarbleK), ObjectToLattice{},
                               normalize(Vec3{0.3f, 0.8f, 0.55f})};
    DrawOptions opt;
    for (int y0 = 0; y0 < kSize; y0 += kRows) {
        const FrameBand band = make_band(RgbView{g_color, kSize, kRows, kSize},
                                         FloatView{g_depth, kSize, kRows, kSize}, y0, kSize, kSize);
        clear_band(band, Rgb8{24, 26, 32});
        if (!draw_mesh(cam, band, cube, opt, shader)) return 1;
        for (const Rgb8& c : g_color) {
            h.byte(c.r);
            h.byte(c.g);
            h.byte(c.b);
        }
    }
    put("footprint marble: cube 128x128 in 8-row bands (Type III) fnv ");
#endif
    put_hex64(h.h);
    put(", main stack used ");
    put_uint(stack_high_water());
    put(" bytes\n");
    return 0;
}
