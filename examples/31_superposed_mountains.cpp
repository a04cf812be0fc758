// Lesson 31: superposed wrinkly surfaces (fujimoto2000 §4, eqs. 16-20).
// Figures: paper_figures/fujimoto2000/fig17_18_superposed.cpp,
//   paper_figures/fujimoto2000/fig19_20_sampling.cpp, paper_figures/fujimoto2000/fig21_terrain.cpp.
//
// A plain wrinkly surface turns spiky as its heights grow. The superposed surface adds the
// shuffled heights of every IST step k = 0, 1, 2, ... with weights W^k = (1 - delta)·delta^k
// (eq. 19). The weights sum to 1, so the overall height stays that of H; delta only decides
// how much of it goes to the fine steps: small delta = smooth hills, large delta = rough
// mountains. To avoid the staircase that F^k leaves (fig. 19b), each step is sampled once per
// small region and the samples are interpolated ("hierarchical sampling", eq. 20).
//
// Build and run:  make examples   (writes build/examples/out/superposed_delta_0.30.png, _0.70)
#include <cmath>
#include <cstdio>

#include "shitsukan/image/image_io.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/wrinkly/superposition.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"
#include "shitsukan/core/detmath.hpp"

using namespace shitsukan;

int main() {
    for (float delta : {0.30f, 0.70f}) {
        // 1. A ridge of heights on a flat 8 x 8 mesh, the same delta everywhere.
        WrControlMesh mesh = make_control_mesh(8, 8);
        for (int r = 0; r < 8; ++r)
            for (int c = 0; c < 8; ++c) {
                WrControlPoint& p = mesh.at(c, r);
                p.position = {float(c) - 3.5f, 0.0f, 3.5f - float(r)};
                const float d = float(r) - 4.0f - 0.8f * det_sin(float(c));
                p.height = 0.1f + 1.6f * det_expf(-0.5f * d * d);
                p.color = {0.75f, 0.7f, 0.6f};
                p.delta = delta;
            }
        WrSurface surface;
        Status s = make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface);
        IstAxis ist;
        if (s) s = ist_fully_connected_axis(3, 1, surface.spans_u(), IstEnds::translation, ist);
        WrIstAxis axis;
        if (s) s = make_wr_ist_axis(ist, 4, axis);
        if (s) s = surface.set_axes(axis.axis(), axis.axis());
        if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;

        // 2. Hierarchical sampling of the steps k = 1..4 (k = 0 is H itself).
        HierarchicalOptions ho;
        ho.levels = 4;
        ho.interpolation = SampleInterpolation::hermite;
        HierarchicalSampling hs;
        s = sample_hierarchy(surface, ho, hs);
        if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
        std::printf("delta %.2f: weights", double(delta));
        for (int k = 0; k <= 4; ++k)
            std::printf(" W^%d = %.3f", k, double(superposition_weight(delta, k)));
        std::printf(
            " (sum %.3f = 1 - delta^5; the sum stops at K = 4, so each weight is divided "
            "by it and they add up to 1 again, eq. 18: W^0 -> %.3f)\n",
            double(superposition_weight_sum(delta, 4)),
            double(superposition_weight_truncated(delta, 0, 4)));

        // 3. Polygonise eq. (20) and render.
        WrTessellationOptions o;
        o.form = WrSurfaceForm::superposed;
        o.grid_level = 3;
        o.subdivisions = 2;
        WrMesh wm;
        s = tessellate_wr_surface(surface, &hs, o, wm);
        if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
        const int size = 400;
        Camera camera =
            perspective_camera({0.0f, 4.5f, 7.5f}, {0, 0.4f, 0}, {0, 1, 0}, 40.0f, size, size);
        RgbImage color(size, size);
        FloatImage depth(size, size);
        FrameBand band = full_frame_band(color.view(), depth.view());
        clear_band(band, Rgb8{210, 225, 240});
        const Vec3 light = normalize(Vec3{-0.6f, 0.5f, 0.4f});
        auto shader = [&](const Fragment& f) {
            const Vec3 c = f.color * (0.25f + 0.75f * std::fabs(dot(f.normal, light)));
            return Rgb8{std::uint8_t(255 * c.x), std::uint8_t(255 * c.y), std::uint8_t(255 * c.z)};
        };
        DrawOptions opt;
        opt.cull = CullMode::none;
        s = draw_mesh(camera, band, wm.mesh.view(), opt, shader);
        char name[64];
        std::snprintf(name, sizeof name, "superposed_delta_%.2f.png", double(delta));
        if (s) s = write_png(name, color.view());
        if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
        std::printf("wrote %s (%d triangles)\n", name, wm.mesh.triangle_count());
    }
    return 0;
}
