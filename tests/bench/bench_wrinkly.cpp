// bench_wrinkly: the cost of the wrinkles (fujimoto2000 §4.2, §5, Table 2). Tessellating and
// rendering fig. 21's superposed IST-B-spline terrain (eq. 20, 800 x 800) against the plain
// B-spline surface at the same tessellation, measured in the same run; then the stages of the
// superposed panel beside the paper's Origin2000 minutes (Table 2 (f)).
#include <chrono>
#include <cmath>

#include "bench.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"

using namespace shitsukan;

namespace {

// The terrain of paper_figures/fujimoto2000/fig21_terrain.cpp, panel (f) (delta 0.55), in
// short: 10 x 10 points on [-3, 3]^2, two ranges at the back, a flat field at the front right.
WrControlMesh terrain() {
    const int n = 10;
    WrControlMesh m = make_control_mesh(n, n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            WrControlPoint& p = m.at(c, r);
            const float x = -3.0f + 6.0f * float(c) / float(n - 1);
            const float z = 3.0f - 6.0f * float(r) / float(n - 1);
            const float g =
                clamp((x - 0.3f) * 1.2f, 0.0f, 1.0f) * clamp((z - 0.2f) * 1.2f, 0.0f, 1.0f);
            const float h =
                1.9f *
                    std::exp(-((x + 1.0f) * (x + 1.0f) / 2.2f + (z + 1.1f) * (z + 1.1f) / 1.3f)) +
                1.1f *
                    std::exp(-((x - 1.7f) * (x - 1.7f) / 1.0f + (z + 1.9f) * (z + 1.9f) / 0.7f)) +
                0.25f * hash_uniform(21, 0, c, r);
            p.position = {x, 0.0f, z};
            p.height = (1.0f - g) * h + g * 0.1f;
            p.color = {0.5f, 0.5f, 0.45f};
            p.delta = (1.0f - g) * 0.55f + g * 0.02f;
        }
    return m;
}

}  // namespace

SHITSUKAN_BENCH(wrinkly_terrain) {
    const int size = 800;
    WrControlMesh mesh = terrain();
    WrSurface surface;
    if (!make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface)) return;
    IstAxis iu;
    Status s = ist_fully_connected_axis(3, 1, surface.spans_u(), IstEnds::translation, iu);
    WrIstAxis au, av;
    if (s) s = make_wr_ist_axis(iu, 4, au);
    if (s) s = make_wr_ist_axis(iu, 4, av);
    if (s) s = surface.set_axes(au.axis(), av.axis());
    if (!bench::set_up(s, "WR terrain")) return;
    const Vec3 eye{2.4f, 3.4f, 7.0f}, target{-0.3f, 0.2f, -0.3f};
    const Camera camera = perspective_camera(eye, target, {0, 1, 0}, 43.0f, size, size);
    const float ppu = 0.5f * float(size) / (std::tan(21.5f * kPi / 180.0f) * length(eye - target));
    const AdaptiveLevels a = choose_adaptive_levels(surface, mesh, ppu, 1.5f, 0.5f, 4);
    RgbImage color(size, size);
    FloatImage depth(size, size);
    const FrameBand band = full_frame_band(color.view(), depth.view());
    auto shader = [](const Fragment& f) {
        const float l = 0.3f + 0.7f * std::fabs(f.normal.y);
        return Rgb8{std::uint8_t(200 * l), std::uint8_t(190 * l), std::uint8_t(170 * l)};
    };
    DrawOptions opt;
    opt.cull = CullMode::none;
    WrTessellationOptions o;
    o.grid_level = a.grid_level;
    o.tail_tolerance = a.world_tolerance;
    HierarchicalOptions ho;
    ho.levels = a.sum_levels;
    long triangles = 0;
    bool ok = true;  // every call of every timed run succeeded
    auto run = [&](WrSurfaceForm form, double* stages) {
        auto t0 = std::chrono::steady_clock::now();
        HierarchicalSampling hs;
        WrMesh wm;
        o.form = form;
        if (form == WrSurfaceForm::superposed) ok &= sample_hierarchy(surface, ho, hs).ok();
        ok &= evaluate_wr_grid(surface, &hs, o, wm).ok();
        auto t1 = std::chrono::steady_clock::now();
        polygonise_wr_grid(surface, &wm);
        auto t2 = std::chrono::steady_clock::now();
        clear_band(band, Rgb8{0, 0, 0});
        ok &= draw_mesh(camera, band, wm.mesh.view(), opt, shader).ok();
        auto t3 = std::chrono::steady_clock::now();
        triangles = wm.mesh.triangle_count();
        if (stages) {
            stages[0] = std::chrono::duration<double>(t1 - t0).count();
            stages[1] = std::chrono::duration<double>(t2 - t1).count();
            stages[2] = std::chrono::duration<double>(t3 - t2).count();
        }
        bench::sink(color.view().at(size / 2, size / 2).g);
    };
    const bench::Pair t = bench::in_turns([&] { run(WrSurfaceForm::superposed, nullptr); },
                                          [&] { run(WrSurfaceForm::plain, nullptr); });
    if (!bench::timed_calls_ok(ok, "WR terrain")) return;
    bench::report("fig21 superposed terrain, tessellate + render 800x800 (" +
                      std::to_string(triangles) + " triangles, K = " + std::to_string(ho.levels) +
                      ")",
                  t, "plain B-spline, same tessellation");
    double st[3];
    run(WrSurfaceForm::superposed, st);
    char text[200];
    std::snprintf(
        text, sizeof text,
        "sam. %.2f s, pol. %.2f s, ren. %.2f s (paper Origin2000: 1:49, 0:12, 2:11 = 4:12)", st[0],
        st[1], st[2]);
    bench::info("fig21 (f) stages vs. Table 2", text);
}
