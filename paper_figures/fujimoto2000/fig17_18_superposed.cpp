// fujimoto2000 figs. 17 and 18: superposed IST-Bezier (unit-IST N = 3) and superposed
// IST-B-spline (fully-connected N = 3) surfaces. Panels: (1) control mesh, the sticks with a
// dot at the tip are the heights h_i; (2) conventional surface; (3) WR surface, eq. (15);
// (4), (5) superposed WR surfaces, eq. (20) (hierarchical sampling), with a constant ratio
// function delta: small delta smooth, large delta rough "mountain ranges" (§4.1), against the
// "spiky" plain WR surface of (3).
#include <algorithm>
#include <cmath>

#include "driver/figure.hpp"
#include "fujimoto2000/wr_figure_common.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan::fujimoto2000 {
namespace {

using figures::FigureContext;
using figures::fmt;

// Chosen in one place for both figures: the two ratio values of panels (4) and (5).
constexpr float kDeltaSmooth = 0.35f, kDeltaRough = 0.65f;

Vec3 height_color(float h, float hmax) {
    const Vec3 low{0.50f, 0.58f, 0.34f}, high{0.88f, 0.84f, 0.78f};
    return lerp(low, high, clamp(h / hmax, 0.0f, 1.0f));
}

// fig. 17 (chosen): 4 x 4 Bezier points on [-1.2, 1.2]^2 (flat), a ridge of heights up to 1.2.
WrControlMesh fig17_mesh() {
    static const float h[4][4] = {{0.05f, 0.35f, 0.45f, 0.10f},
                                  {0.30f, 1.10f, 0.80f, 0.20f},
                                  {0.20f, 0.85f, 1.20f, 0.45f},
                                  {0.05f, 0.30f, 0.45f, 0.10f}};
    return square_control_mesh(4, 1.2f, [](int c, int r, float, float, WrControlPoint& p) {
        p.height = h[r][c];
        p.color = height_color(p.height, 1.2f);
    });
}

// fig. 18 (chosen): 11 x 11 B-spline points on [-1.5, 1.5]^2 (8 x 8 spans), flat; a winding
// mountain range through the middle (heights up to 0.7) with a hashed variation (seed 18).
WrControlMesh fig18_mesh() {
    return square_control_mesh(11, 1.5f, [](int c, int r, float x, float z, WrControlPoint& p) {
        const float d = z + 0.1f - 0.35f * std::sin(1.6f * x);  // distance from a winding ridge
        p.height =
            0.05f + 0.55f * std::exp(-3.0f * d * d) * (0.65f + 0.6f * hash_uniform(18, 0, c, r));
        p.color = height_color(p.height, 0.65f);
    });
}

struct SuperFigure {
    SurfaceBasis basis;
    IstKind kind;
    WrControlMesh (*mesh)();
    int wr_levels;  // K of panel (3)
    int max_level;  // cap of the adaptive choice
    Shot shot;
};

const SuperFigure kFig17{SurfaceBasis::bezier,
                         IstKind::unit,
                         fig17_mesh,
                         4,
                         5,
                         Shot{{0.4f, 2.7f, 3.1f}, {0.0f, 0.25f, 0.0f}, {0, 1, 0}, 40.0f}};
const SuperFigure kFig18{SurfaceBasis::bspline,
                         IstKind::fully_connected,
                         fig18_mesh,
                         3,
                         4,
                         Shot{{0.3f, 3.0f, 3.6f}, {0.0f, 0.2f, 0.0f}, {0, 1, 0}, 40.0f}};

Status run_panel(FigureContext& ctx, const SuperFigure& f, int panel) {
    const bool quick = ctx.quick();
    const int size = quick ? 128 : 512;
    ctx.given("base surface",
              f.basis == SurfaceBasis::bezier ? "Bezier n = 3" : "uniform B-spline n = 3",
              "§4.1, figs. 17-18");
    ctx.given("weights", "W^k = (1 - delta) delta^k", "eq. (19)");
    ctx.chosen("IST", f.kind == IstKind::unit ? "unit-IST N = 3" : "fully-connected IST N = 3",
               "the ISTs of figs. 14/15");
    ctx.chosen("control mesh",
               f.basis == SurfaceBasis::bezier
                   ? "4 x 4 flat, ridge of heights 0.05..1.2"
                   : "11 x 11 flat (8 x 8 spans), winding range up to 0.7",
               "not printed");
    ctx.chosen("image size", fmt("%d x %d", size, size), "not given");
    WrControlMesh mesh = f.mesh();
    const float delta = panel == 4 ? kDeltaSmooth : kDeltaRough;
    for (WrControlPoint& p : mesh.points) p.delta = delta;  // constant ratio function (§4.1)
    WrSurface surface;
    SHITSUKAN_TRY(make_wr_surface(mesh, f.basis, 3, &surface));
    AxisPair axes;
    SHITSUKAN_TRY(make_axes(surface, f.kind, "fully", 3, kMaxWrLevel, &axes));
    SHITSUKAN_TRY(surface.set_axes(axes.u.axis(), axes.v.axis()));
    RgbImage img(size, size);
    Shading shading;
    const Camera camera = shot_camera(f.shot, size, size);
    if (panel == 1) {
        draw_control_mesh(img.view(), camera, mesh, surface, true, shading.background);
        return ctx.save_png(img.view());
    }
    WrTessellationOptions o;
    HierarchicalSampling hs;
    if (panel == 2) {
        o.form = WrSurfaceForm::plain;
        o.grid_level = quick ? 2 : 3;
        o.subdivisions = 2;
    } else if (panel == 3) {
        o.form = WrSurfaceForm::wr;
        o.levels = quick ? 2 : f.wr_levels;
        o.grid_level = o.levels;
        o.subdivisions = quick ? 1 : 2;
        ctx.chosen("K", fmt("%d", o.levels), "small intervals of a few pixels");
    } else {
        // Adaptive sampling: grid cells of <= 2 pixels, the sum stops when the rest of it is
        // below half a pixel (§4.2), both capped.
        const float ppu = shot_pixels_per_unit(f.shot, size);
        const AdaptiveLevels a =
            choose_adaptive_levels(surface, mesh, ppu, 2.0f, 0.5f, quick ? 2 : f.max_level);
        HierarchicalOptions ho;
        ho.levels = std::max(a.sum_levels, 1);
        ho.interpolation = SampleInterpolation::hermite;
        SHITSUKAN_TRY(sample_hierarchy(surface, ho, &hs));
        o.form = WrSurfaceForm::superposed;
        o.grid_level = a.grid_level;
        o.subdivisions = 1;
        o.tail_tolerance = a.world_tolerance;
        ctx.chosen("delta", fmt("%.2f (constant)", double(delta)),
                   "one smooth and one rough value; the paper does not print them");
        ctx.chosen("sample interpolation", "Hermite",
                   "fig. 19(d); the paper does not say for figs. 17-18");
        ctx.chosen("adaptive sampling",
                   fmt("grid level %d, K = %d, tail tolerance %.4f", a.grid_level, ho.levels,
                       double(a.world_tolerance)),
                   "cells <= 2 px, omitted rest of the sum < 0.5 px");
    }
    WrMesh wm;
    SHITSUKAN_TRY(tessellate_wr_surface(surface, panel >= 4 ? &hs : nullptr, o, &wm));
    RasterStats stats;
    SHITSUKAN_TRY(render_opaque(camera, wm.mesh, img.view(), shading, &stats));
    ctx.note(fmt("%d triangles; superposition steps used: max %d, mean %.2f.",
                 wm.mesh.triangle_count(), wm.max_levels_used, wm.mean_levels_used));
    return ctx.save_png(img.view());
}

}  // namespace

#define SUPER_PANEL(fig, row, i, figure, caption)                                  \
    SHITSUKAN_FIGURE(fig##row##i##_panel, "fujimoto2000", #fig #row #i, caption) { \
        return run_panel(ctx, figure, i);                                          \
    }

SUPER_PANEL(fig17, a, 1, kFig17, "Superposed IST-Bezier: (a-1) control mesh with heights h_i")
SUPER_PANEL(fig17, a, 2, kFig17, "Superposed IST-Bezier: (a-2) conventional Bezier surface")
SUPER_PANEL(fig17, a, 3, kFig17, "Superposed IST-Bezier: (a-3) WR surface, eq. (15)")
SUPER_PANEL(fig17, a, 4, kFig17, "Superposed IST-Bezier: (a-4) superposed, small delta (smooth)")
SUPER_PANEL(fig17, a, 5, kFig17, "Superposed IST-Bezier: (a-5) superposed, large delta (rough)")
SUPER_PANEL(fig18, b, 1, kFig18, "Superposed IST-B-spline: (b-1) control mesh with heights h_i")
SUPER_PANEL(fig18, b, 2, kFig18, "Superposed IST-B-spline: (b-2) conventional B-spline surface")
SUPER_PANEL(fig18, b, 3, kFig18, "Superposed IST-B-spline: (b-3) WR surface, eq. (15)")
SUPER_PANEL(fig18, b, 4, kFig18, "Superposed IST-B-spline: (b-4) superposed, small delta (smooth)")
SUPER_PANEL(fig18, b, 5, kFig18, "Superposed IST-B-spline: (b-5) superposed, large delta (rough)")

}  // namespace shitsukan::fujimoto2000
