// ports/cortex-m/transcript.cpp — see transcript.hpp. Sections (each line "name: values"):
//   lattice   okada1987's 65^3 fractal lattice (hash noise, seed 1987): Type I built into a
//             static array, its hash; Type III (no table) at sample nodes and D(P) (eq. (6))
//   marble    okada1987 marble G' on a 64 x 64 slice (eqs. (6)-(9), (12)); wood the same
//   ist       fujimoto2000 fully-connected and unit IST axes, forward and inverse
//   relief    tokai1994 fig. 12 relief (height, normal) of one hexagonal scale
//   lit       a box under two lights, Blinn-Phong, rotated, perspective camera, 16-row bands
//             (the frames are binned once, raster/rasterizer.hpp's bin_mesh, then drawn band
//             by band with draw_binned_mesh: the same bytes as draw_mesh per band)
//   fig10a    okada1987 fig. 10a: the marble cube, 512 x 512 in 16-row bands, the figure's
//             scene, shader and background (paper_figures/okada1987/okada_common.cpp)
// Two build options keep the same transcript on a device with little RAM (the Cortex-M0 of
// `make test-mcu`, 16 KB):
//   TRANSCRIPT_NO_TABLE     no 1.1 MB Type I table: every D(P) comes from the Type III lattice
//                           (okada1989 §3-3, 3.3 KB without its row cache). The "type1" lines
//                           then come from a walk over all 65^3 nodes in the table's order,
//                           and D(P)'s second column from Type III without reuse (okada1989's
//                           own descent from the initial cube): the transcript equals the
//                           host's only if Types I and III agree bit for bit.
//   TRANSCRIPT_BAND_PIXELS  the band buffer in pixels (default 512 x 16): frames are drawn in
//                           bands of TRANSCRIPT_BAND_PIXELS / width rows (the pixels do not
//                           depend on the band height; raster/rasterizer.hpp).
#include "transcript.hpp"

#include <cstdint>

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh_arrays.hpp"
#include "shitsukan/leather/relief.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"
#include "shitsukan/render/solid_mesh.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/lattice_type3.hpp"
#include "shitsukan/solid/object_mapping.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"
#include "shitsukan/solid/solid_material.hpp"
#include "shitsukan/solid/turbulence.hpp"
#include "shitsukan/wrinkly/ist_axis.hpp"
#include "shitsukan/wrinkly/ist_formula.hpp"
#include "type3_solid_shader.hpp"

namespace shitsukan::port {

namespace {

// ---- output without printf: text, decimal integers, hex bits ----
WriteFn g_write = nullptr;
int g_failures = 0;

int text_length(const char* s) {
    int n = 0;
    while (s[n]) ++n;
    return n;
}
void put(const char* s) { g_write(s, text_length(s)); }
void put_hex(std::uint64_t v, int digits) {
    char buf[17];
    for (int i = digits - 1; i >= 0; --i) {
        buf[i] = "0123456789abcdef"[v & 15u];
        v >>= 4;
    }
    g_write(buf, digits);
}
void put_int(long v) {
    char buf[24];
    int n = 0;
    const bool negative = v < 0;
    unsigned long u = negative ? 0ul - static_cast<unsigned long>(v) : static_cast<unsigned long>(v);
    do {
        buf[sizeof buf - 1 - n++] = char('0' + u % 10u);
        u /= 10u;
    } while (u != 0);
    if (negative) buf[sizeof buf - 1 - n++] = '-';
    g_write(buf + sizeof buf - n, n);
}
std::uint32_t bits(float f) {
    std::uint32_t u;
    __builtin_memcpy(&u, &f, sizeof u);
    return u;
}
void put_float(float f) { put_hex(bits(f), 8); }

// FNV-1a 64 over bytes (the transcript's image and array digest).
struct Fnv {
    std::uint64_t h = 0xcbf29ce484222325ull;
    void byte(std::uint8_t b) { h = (h ^ b) * 0x100000001b3ull; }
    void word(std::uint32_t w) {
        for (int i = 0; i < 4; ++i) byte(std::uint8_t(w >> (8 * i)));
    }
    void f(float v) { word(bits(v)); }
};
void put_hash(const Fnv& f) { put_hex(f.h, 16); }

bool check(const Status& s, const char* what) {
    if (s.ok()) return true;
    put("error: ");
    put(what);
    put(": ");
    put(s.message());
    put("\n");
    ++g_failures;
    return false;
}

// ---- deterministic maths ----
void section_detmath() {
    Fnv h;
    for (int i = 0; i < 4096; ++i) {
        const float x = float(i - 2048) * 0.0123f, u = float(i) / 4096.0f;
        h.f(det_sinf(x * 37.0f));
        h.f(det_cosf(x));
        h.f(det_tanf(x));
        h.f(det_expf(x * 0.5f));
        h.f(det_logf(u + 0.001f));
        h.f(det_powf(u * 1.7f, 1.0f + float(i % 97)));
        h.f(det_acosf(u * 2.0f - 1.0f));
        h.f(det_atan2f(x, u - 0.5f));
    }
    put("detmath fnv ");
    put_hash(h);
    const float samples[] = {det_sinf(1.0e22f), det_cosf(3.14159274f), det_tanf(1.5f),
                             det_powf(0.87f, 37.5f), det_expf(-7.25f), det_acosf(-0.3f),
                             det_atan2f(-2.0f, -3.0f)};
    for (float v : samples) {
        put(" ");
        put_float(v);
    }
    put("\n");
    Fnv fast;  // the float-arithmetic-only functions of the hot paths
    for (int i = 0; i < 4096; ++i) {
        const float x = float(i - 2048) * 0.0123f, u = float(i) / 4096.0f;
        fast.f(det_expf_fast(x * 0.5f));
        fast.f(det_logf_fast(u + 0.001f));
        fast.f(det_logf_fast(float(i + 1) * 1.0e-9f));
        fast.f(det_sinf_fast(x * 37.0f));
    }
    put("detmath fast fnv ");
    put_hash(fast);
    put("\n");
}

// ---- lattice ----
constexpr int kR = kOkada1987R;
constexpr int kSide = (1 << kR) + 1;
TypeIIILattice g_type3;  // static: 10.9 KB (3.3 KB without the row cache) is no stack object
constexpr int kSampleNodes[8][3] = {{0, 0, 0},   {32, 32, 32}, {1, 2, 3},    {64, 63, 17},
                                    {33, 7, 50}, {5, 61, 29},  {48, 16, 40}, {13, 13, 13}};
float g_type1_samples[8];  // the Type I values at kSampleNodes

#if defined(TRANSCRIPT_NO_TABLE)
// D(P) on this device: Type III; "Type I" is the full walk over the nodes (see the top).
float lattice_density(Vec3 p) { return g_type3.turbulence(p); }
float type1_density(Vec3 p) {
    g_type3.set_reuse(false);
    const float d = g_type3.turbulence(p);
    g_type3.set_reuse(true);
    return d;
}
bool build_type1(const FractalParams& p, Fnv* all) {
    if (!check(g_type3.init(p), "Type III")) return false;
    for (int z = 0; z < kSide; ++z)
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x) {
                const float v = g_type3.node_value(x, y, z);
                all->f(v);
                for (int k = 0; k < 8; ++k)
                    if (kSampleNodes[k][0] == x && kSampleNodes[k][1] == y && kSampleNodes[k][2] == z)
                        g_type1_samples[k] = v;
            }
    return true;
}
#else
float g_lattice[kSide * kSide * kSide];  // Type I: 1,098,500 bytes (fig. 10a needs it whole)
LatticeView g_view;
float lattice_density(Vec3 p) { return turbulence(g_view, p); }
float type1_density(Vec3 p) { return turbulence(g_view, p); }
bool build_type1(const FractalParams& p, Fnv* all) {
    if (!check(build_fractal_lattice(p, g_lattice, sizeof g_lattice, g_view), "Type I"))
        return false;
    for (float v : g_lattice) all->f(v);
    for (int k = 0; k < 8; ++k)
        g_type1_samples[k] = g_view.at(kSampleNodes[k][0], kSampleNodes[k][1], kSampleNodes[k][2]);
    return check(g_type3.init(p), "Type III");
}
#endif

void section_lattice() {
    const FractalParams p = okada1987_lattice_params();
    Fnv all;
    if (!build_type1(p, &all)) return;
    put("lattice type1 65^3 fnv ");
    put_hash(all);
    put("\n");
    int agree = 0;
    put("lattice type3 nodes");
    for (int k = 0; k < 8; ++k) {
        const float v = g_type3.node_value(kSampleNodes[k][0], kSampleNodes[k][1], kSampleNodes[k][2]);
        agree += bits(v) == bits(g_type1_samples[k]);
        put(" ");
        put_float(v);
    }
    put(" (type1 agrees at ");
    put_int(agree);
    put(" of 8)\nlattice D(P)");
    Fnv d;
    for (int i = 0; i < 64; ++i) {
        const Vec3 q{0.37f + 0.93f * float(i), 31.5f + 0.25f * float(i % 7), 63.9f - 0.81f * float(i)};
        const float t3 = g_type3.turbulence(q);
        d.f(t3);
        d.f(type1_density(q));
        if (i % 16 == 0) {
            put(" ");
            put_float(t3);
        }
    }
    put(" fnv ");
    put_hash(d);
    put("\n");
}

// ---- marble and wood slices ----
void section_slice(const char* name, const SolidMaterial& m) {
    if (!check(validate_solid_material(m), name)) return;
    Fnv h;
    put(name);
    put(" slice 64x64 z=32");
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Vec3 p{0.5f + float(x), 0.5f + float(y), 32.25f};
            const float g = solid_density_at(m, p, lattice_density(p));  // = solid_density
            h.f(g);
            if ((x == 7 || x == 40) && (y == 9 || y == 50)) {
                put(" ");
                put_float(g);
            }
        }
    put(" fnv ");
    put_hash(h);
    put("\n");
}

// ---- IST axes ----
void section_ist() {
    IstAxis full, unit;
    if (!check(ist_fully_connected_axis(5, 3, 5, IstEnds::cyclic, full), "IST axis")) return;
    if (!check(ist_unit_axis(3, 4, unit), "IST unit axis")) return;
    const IstAxis* axes[2] = {&full, &unit};
    const char* names[2] = {"ist fully-connected N5 K3 B5", "ist unit N3 K4"};
    for (int a = 0; a < 2; ++a) {
        Fnv h;
        put(names[a]);
        for (int i = 0; i < 256; ++i) {
            const float u = (float(i) + 0.37f) / 256.0f;
            const float f = ist_forward(*axes[a], u);
            const float b = ist_inverse(*axes[a], f);
            h.f(f);
            h.f(b);
            if (i % 64 == 0) {
                put(" ");
                put_float(f);
            }
        }
        put(" fnv ");
        put_hash(h);
        put("\n");
    }
}

// ---- leather relief of one scale ----
void section_relief() {
    const Vec2 hexagon[6] = {{1.0f, 0.0f},   {0.5f, 0.87f},   {-0.5f, 0.87f},
                             {-1.0f, 0.05f}, {-0.45f, -0.9f}, {0.55f, -0.85f}};
    Vec2 m{0, 0};
    for (const Vec2& v : hexagon) m = m + v * (1.0f / 6.0f);
    const BezierChain section = table1_section(Table1Section::convex);
    const ReliefOptions opt;
    if (!check(validate_section(section), "relief section")) return;
    Fnv h;
    put("relief convex hexagon 32x32");
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const Vec2 q{-0.95f + 1.9f * float(x) / 31.0f, -0.88f + 1.76f * float(y) / 31.0f};
            ReliefSample s;
            scale_relief(hexagon, 6, m, q, section, opt, &s);
            h.f(s.height);
            h.f(s.normal.x);
            h.f(s.normal.y);
            h.f(s.normal.z);
            if (x == 16 && y % 8 == 4) {
                put(" ");
                put_float(s.height);
            }
        }
    put(" fnv ");
    put_hash(h);
    put("\n");
}

// ---- band rendering ----
#if !defined(TRANSCRIPT_BAND_PIXELS)
#define TRANSCRIPT_BAND_PIXELS (512 * 16)
#endif
constexpr int kBandPixels = TRANSCRIPT_BAND_PIXELS;
Rgb8 g_band_color[kBandPixels];
float g_band_depth[kBandPixels];

// Renders a frame band by band with draw(band) and hashes its rows top to bottom.
template <class Draw>
bool render_in_bands(const Camera& cam, Rgb8 background, Draw draw, Fnv* h) {
    const int band_rows = kBandPixels / cam.width;
    if (band_rows < 1)
        return check(Status::error(StatusCode::too_large,
                                   "band buffer of %d pixels is narrower than the frame (%d)",
                                   kBandPixels, cam.width),
                      "bands");
    for (int y0 = 0; y0 < cam.height; y0 += band_rows) {
        const int rows = cam.height - y0 < band_rows ? cam.height - y0 : band_rows;
        const RgbView color{g_band_color, cam.width, rows, cam.width};
        const FloatView depth{g_band_depth, cam.width, rows, cam.width};
        const FrameBand band = make_band(color, depth, y0, cam.width, cam.height);
        clear_band(band, background);
        if (!draw(band)) return false;
        for (int y = 0; y < rows; ++y)
            for (int x = 0; x < cam.width; ++x) {
                const Rgb8 c = color.at(x, y);
                h->byte(c.r);
                h->byte(c.g);
                h->byte(c.b);
            }
    }
    return true;
}

TriangleRows g_box_rows[kBoxTriangleCount];  // the rows of each triangle (bin_mesh)
Vec3 g_box_positions[kBoxVertexCount], g_box_normals[kBoxVertexCount];
Vec2 g_box_uvs[kBoxVertexCount];
std::uint32_t g_box_indices[3 * kBoxTriangleCount];

struct LitShader {
    const Camera* camera;
    Material material;
    Light lights[2];
    Rgb8 operator()(const Fragment& f) const {
        const Vec3 base{0.2f + 0.6f * f.uv.x, 0.35f + 0.5f * f.uv.y, 0.55f};
        return to_rgb8(shade_blinn_phong(material, base, f.world_position, f.normal, camera->eye,
                                         lights, 2));
    }
};

void section_lit() {
    MeshView box;
    if (!check(make_box_arrays({-0.8f, -0.6f, -0.7f}, {0.8f, 0.6f, 0.7f}, g_box_positions,
                               g_box_normals, g_box_uvs, kBoxVertexCount, g_box_indices,
                               3 * kBoxTriangleCount, box),
               "box"))
        return;
    const Camera cam = perspective_camera({2.2f, 1.7f, 3.1f}, {0, 0, 0}, {0, 1, 0}, 38.0f, 160, 120);
    LitShader shader{&cam, Material{}, {directional_light({-0.4f, 1.0f, 0.7f}),
                                        point_light({2.5f, 2.0f, 1.5f}, {1.0f, 0.9f, 0.75f}, 0.8f)}};
    shader.material.specular = 0.6f;
    shader.material.shininess = 40.0f;
    put("lit box 160x120 blinn-phong");
    for (int frame = 0; frame < 4; ++frame) {
        DrawOptions opt;
        opt.model = Mat4::rotate_y(0.41f * float(frame) + 0.2f) * Mat4::rotate_x(0.23f * float(frame) - 0.3f);
        Fnv h;
        if (!check(bin_mesh(cam, box, opt, g_box_rows, kBoxTriangleCount), "lit bins")) return;
        const bool ok = render_in_bands(cam, Rgb8{10, 12, 16},
            [&](const FrameBand& band) {
                return check(draw_binned_mesh(cam, band, box, opt, g_box_rows, kBoxTriangleCount,
                                              shader),
                             "lit draw");
            },
            &h);
        if (!ok) return;
        put(" ");
        put_hash(h);
    }
    put("\n");
}

// ---- okada1987 fig. 10a ----
void section_fig10a() {
    MeshView cube;  // okada_common.cpp's "cube" scene: make_box(-0.9, 0.9), same vertices
    if (!check(make_box_arrays({-0.9f, -0.9f, -0.9f}, {0.9f, 0.9f, 0.9f}, g_box_positions,
                               g_box_normals, g_box_uvs, kBoxVertexCount, g_box_indices,
                               3 * kBoxTriangleCount, cube),
               "cube"))
        return;
    const Camera cam = perspective_camera({3.6f, 3.0f, 4.6f}, {0, 0, 0}, {0, 1, 0}, 30.0f, 512, 512);
    const SolidMaterial marble = okada1987_marble(kOkada1987MarbleK);
    DrawOptions opt;
    opt.cull = CullMode::back;
    Fnv h;
    if (!check(validate_solid_material(marble), "fig10a marble")) return;
    if (!check(bin_mesh(cam, cube, opt, g_box_rows, kBoxTriangleCount), "fig10a bins")) return;
#if defined(TRANSCRIPT_NO_TABLE)
    TypeIIISolidShader shader{&g_type3, marble, SolidShading{}};
#else  // draw_solid_textured_mesh's shader (render/solid_mesh.hpp), the mesh binned
    SolidTextureShader shader{g_view, marble, SolidShading{}};
#endif
    auto draw = [&](const FrameBand& band) {
        return check(draw_binned_mesh(cam, band, cube, opt, g_box_rows, kBoxTriangleCount, shader),
                     "fig10a draw");
    };
    const bool ok = render_in_bands(cam, Rgb8{24, 26, 32}, draw, &h);
    if (!ok) return;
    put("fig10a 512x512 rgb fnv ");
    put_hash(h);
    put("\n");
}

// ---- status: messages keep their numbers on newlib-nano (core/format_number.hpp) ----
void section_status() {
    FractalParams p = okada1987_lattice_params();
    p.beta = -0.25f;
    float tiny[8];
    LatticeView v;
    const Status refused = build_fractal_lattice(p, tiny, sizeof tiny, v);
    put("status ");
    put(refused.ok() ? "ok (expected a refusal)" : refused.message());
    put("\n");
    const Status made = Status::error(StatusCode::out_of_range, "%s %d %u %.3g %g %e %.17g %zu",
                                      "numbers", -7, 4000000000u, 2.0 / 3.0, 1.5e-7f, 6.02e23,
                                      0.1, sizeof(float));
    put("status ");
    put(made.message());
    put("\n");
}

}  // namespace

int run_transcript(WriteFn write) {
    g_write = write;
    g_failures = 0;
    put("shitsukan transcript 1\n");
    section_detmath();
    section_status();
    section_lattice();
    section_slice("marble", okada1987_marble(kOkada1987MarbleK));
    section_slice("wood", okada1987_wood(kOkada1987WoodK));
    section_ist();
    section_relief();
    section_lit();
    section_fig10a();
    put(g_failures == 0 ? "end ok\n" : "end with errors\n");
    return g_failures == 0 ? 0 : 1;
}

}  // namespace shitsukan::port
