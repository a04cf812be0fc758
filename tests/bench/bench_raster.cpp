// bench: the rasterizer's overhead on a shader-bound 512 x 512 frame.
//
// shitsukan: draw_mesh of a lit, value-noise-textured sphere and torus (clear included).
// baseline:  the very same shader called on the very same fragments (recorded from one
//            render, overwritten ones included), without the rasterizer.
// The difference is what the rasterizer costs (setup, clipping, edge walking, depth test,
// interpolation); the goal is <= 15 % of the shader time.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "bench.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"

using namespace shitsukan;

namespace {

// 3D value noise: trilinear blend of hashed lattice values with a smooth fade.
float value_noise(Vec3 p) {
    float fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    int ix = int(fx), iy = int(fy), iz = int(fz);
    float tx = p.x - fx, ty = p.y - fy, tz = p.z - fz;
    tx = tx * tx * (3 - 2 * tx);
    ty = ty * ty * (3 - 2 * ty);
    tz = tz * tz * (3 - 2 * tz);
    float c[8];
    for (int k = 0; k < 8; ++k)
        c[k] = hash_uniform(7u, 0u, ix + (k & 1), iy + ((k >> 1) & 1), iz + (k >> 2));
    float x00 = c[0] + (c[1] - c[0]) * tx, x10 = c[2] + (c[3] - c[2]) * tx;
    float x01 = c[4] + (c[5] - c[4]) * tx, x11 = c[6] + (c[7] - c[6]) * tx;
    float y0 = x00 + (x10 - x00) * ty, y1 = x01 + (x11 - x01) * ty;
    return y0 + (y1 - y0) * tz;
}

struct ShaderData {
    Light light = directional_light({-0.4f, 1.0f, 0.6f});
    Material material;
    Vec3 eye;
};

// A solid-texture shader doing real work: 5 octaves of value noise on the object position,
// a marble-like colour ramp, then Blinn-Phong.
Rgb8 noise_shader(const Fragment& f, void* user) {
    const ShaderData& d = *static_cast<const ShaderData*>(user);
    float sum = 0, amp = 0.5f;
    Vec3 p = f.object_position * 4.0f;
    for (int o = 0; o < 5; ++o) {
        sum += amp * value_noise(p);
        p = p * 2.0f;
        amp *= 0.5f;
    }
    float v = 0.5f + 0.5f * std::sin(6.0f * f.object_position.x + 8.0f * sum);
    Vec3 base = Vec3{0.35f, 0.3f, 0.28f} + Vec3{0.6f, 0.6f, 0.55f} * v;
    return to_rgb8(shade_blinn_phong(d.material, base, f.world_position, f.normal, d.eye,
                                     &d.light, 1));
}

}  // namespace

SHITSUKAN_BENCH(raster_frame_overhead) {
    const int W = 512, H = 512;
    TriangleMesh sphere, torus;
    // Tessellation as in the foundation figures (64 x 32 each): ~45 pixels per drawn triangle.
    Status s = make_uv_sphere(0.75f, 64, 32, sphere);
    if (s) s = make_torus(1.25f, 0.3f, 64, 32, torus);
    if (!bench::set_up(s, "rasterizer overhead")) return;
    Camera cam = perspective_camera({0, 1.6f, 3.6f}, {0, 0, 0}, {0, 1, 0}, 45.0f, W, H);
    ShaderData data;
    data.material.specular = 0.3f;
    data.eye = cam.eye;
    std::vector<Rgb8> color_px(std::size_t(W) * H);
    std::vector<float> depth_px(std::size_t(W) * H);
    FrameBand band = full_frame_band(RgbView{color_px.data(), W, H, W},
                                     FloatView{depth_px.data(), W, H, W});
    DrawOptions sphere_opt, torus_opt;
    torus_opt.model = Mat4::rotate_x(0.5f);

    bool ok = true;  // every draw call of every timed frame succeeded
    auto render = [&](FragmentShader shader, void* user, RasterStats* stats) {
        clear_band(band, Rgb8{0, 0, 0});
        ok &= draw_mesh(cam, band, sphere.view(), sphere_opt, shader, user, stats).ok();  // front
        ok &= draw_mesh(cam, band, torus.view(), torus_opt, shader, user, stats).ok();
    };

    // Record the fragments the rasterizer shades.
    struct Recorder {
        std::vector<Fragment> fragments;
    } rec;
    rec.fragments.reserve(std::size_t(W) * H);
    RasterStats stats;
    render([](const Fragment& f, void* u) {
               static_cast<Recorder*>(u)->fragments.push_back(f);
               return Rgb8{};
           },
           &rec, &stats);

    // Timed in turns (the machine is shared); the overhead is that of the medians.
    std::vector<Rgb8> out(rec.fragments.size());
    const bench::Pair t = bench::in_turns([&] { render(noise_shader, &data, nullptr); },
                                          [&] {
                                              for (std::size_t i = 0; i < rec.fragments.size(); ++i)
                                                  out[i] = noise_shader(rec.fragments[i], &data);
                                              bench::sink(out[out.size() / 2].r);
                                          });
    if (!bench::timed_calls_ok(ok, "raster overhead")) return;
    const double ours = t.ours.median, baseline = t.peer.median;
    bench::report("raster 512x512 frame, value-noise shader (sphere + torus)", t,
                  "same shader on the same fragments, no rasterizer");
    char text[200];
    std::snprintf(text, sizeof text,
                  "overhead %.1f %% of the shader time (goal <= 15 %%); %ld fragments shaded, "
                  "%ld of %ld triangles drawn",
                  100.0 * (ours - baseline) / baseline, stats.fragments_shaded,
                  stats.triangles_drawn, stats.triangles_in);
    bench::info("raster overhead", text);
}
