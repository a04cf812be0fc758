// Lesson 30: a wrinkly surface (fujimoto2000 §3, eq. 15).
// Figures: paper_figures/fujimoto2000/fig14_15_ist_surfaces.cpp,
//   paper_figures/fujimoto2000/fig16_external_shuffles.cpp.
//
// A wrinkly (WR) surface starts like any B-spline surface: a grid of control points gives a
// smooth base surface P(u, v), and a height h_i per control point gives a smooth height
// function H(u, v). The twist is the Iterated Shuffle Transformation (IST): before reading
// H at (u, v) we read it at F^{-1}(u), F^{-1}(v), which shuffles small intervals of the
// parameter axes in a self-similar way. Displacing P along its normal by that shuffled height,
//     R(u, v) = P(u, v) + H(F_U^{-1}(u), F_V^{-1}(v)) N(u, v),
// gives a surface that is rough at every scale yet still follows its control points: change
// one h_i and only the nearby part of the surface changes (the fully-connected IST is local).
//
// Build and run:  make examples   (writes build/examples/out/wrinkly_surface.png and .obj)
#include <cmath>
#include <cstdio>

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/geom/obj.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"

using namespace shitsukan;

int main() {
    // 1. A 7 x 7 control mesh on the plane y = 0 (4 x 4 knot spans of a cubic B-spline):
    //    heights grow towards the middle, colours go from red (left) to blue (right).
    WrControlMesh mesh = make_control_mesh(7, 7);
    for (int r = 0; r < 7; ++r)
        for (int c = 0; c < 7; ++c) {
            WrControlPoint& p = mesh.at(c, r);
            p.position = {float(c) - 3.0f, 0.0f, 3.0f - float(r)};
            p.height =
                0.2f + 0.6f * det_expf(-0.15f * float((c - 3) * (c - 3) + (r - 3) * (r - 3)));
            p.color = {1.0f - float(c) / 6.0f, 0.3f, float(c) / 6.0f};
        }
    WrSurface surface;
    Status s = make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;

    // 2. The IST on both axes: fully-connected, N = 3, one base interval per knot span, open
    //    ends ("translation axis"). WrIstAxis keeps F^k for k = 0..3.
    IstAxis ist;
    s = ist_fully_connected_axis(3, 1, surface.spans_u(), IstEnds::translation, ist);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    WrIstAxis axis;
    s = make_wr_ist_axis(ist, 3, axis);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    s = surface.set_axes(axis.axis(), axis.axis());  // spans_u == spans_v: one axis serves both
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;

    // 3. Polygonise eq. (15) with K = 3: vertices at the midpoints of the 4·27 small intervals.
    WrTessellationOptions o;
    o.form = WrSurfaceForm::wr;
    o.levels = 3;
    o.grid_level = 3;
    o.subdivisions = 2;
    WrMesh wm;
    s = tessellate_wr_surface(surface, nullptr, o, wm);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("%d triangles\n", wm.mesh.triangle_count());

    // 4. Render it (two-sided Lambert on the vertex colours) and export it.
    const int size = 400;
    Camera camera =
        perspective_camera({0.0f, 5.0f, 6.0f}, {0, 0.3f, 0}, {0, 1, 0}, 40.0f, size, size);
    RgbImage color(size, size);
    FloatImage depth(size, size);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{255, 255, 255});
    const Vec3 light = normalize(Vec3{-0.5f, 0.7f, 0.4f});
    auto shader = [&](const Fragment& f) {
        const float l = 0.3f + 0.7f * std::fabs(dot(f.normal, light));
        const Vec3 c = f.color * l;
        return Rgb8{std::uint8_t(255 * c.x), std::uint8_t(255 * c.y), std::uint8_t(255 * c.z)};
    };
    DrawOptions opt;
    opt.cull = CullMode::none;
    s = draw_mesh(camera, band, wm.mesh.view(), opt, shader);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    s = write_png("wrinkly_surface.png", color.view());
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    s = write_obj("wrinkly_surface.obj", wm.mesh);
    if (!s) return std::fprintf(stderr, "%s\n", s.message()), 1;
    std::printf("wrote wrinkly_surface.png and wrinkly_surface.obj\n");
    return 0;
}
