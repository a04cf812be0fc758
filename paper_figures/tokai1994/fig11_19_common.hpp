// paper_figures/tokai1994/fig11_19_common.hpp — what figs. 11-19 of tokai1994 share: the
// leather look (Blinn 1977 material and the two point lights of §5, chosen here in one place),
// the crocodile pattern of fig. 7 and its maps, flat-texture shading, simple plot axes.
#pragma once

#include <string>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/scale_pattern.hpp"
#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/raster/blinn1977.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"

namespace shitsukan::figures::tokai_relief {

// The leather and metal materials and the two point lights (tokai1994 §5: "reflection
// parameters found by trial and error", two point lights). Chosen here.
Blinn1977Material leather_material();
Blinn1977Material metal_material();
Blinn1977Material suede_material();  // the unbumped back of the belt
// Records the materials and the reflection-model choice in the figure's parameter table.
void record_shading(FigureContext& ctx);

// Records the relief choices (edge_r, height unit, normal rule) of ReliefOptions{}.
void record_relief(FigureContext& ctx);

// Linear RGB -> 8-bit with the display gamma 1/2.2 (chosen here), clamped.
Rgb8 to_display(Vec3 linear);

// The crocodile-belly pattern of fig. 7 (d = 1.0 D, a = 0.25, p = 0.015), from the
// scale-pattern module; records its parameters.
Status crocodile_pattern(FigureContext& ctx, ScalePattern* out);
// The snake pattern of fig. 3(b): triangle-lattice seeds, single Voronoi division.
Status snake_pattern(FigureContext& ctx, float width, float height, ScalePattern* out);

// Labels at w x h (the pattern module's label function), then make_leather_maps.
Status leather_maps(const ScalePattern& pattern, int w, int h, const BezierChain& section,
                    const ReliefOptions& options, LeatherMaps* out);

// The leather texture seen from straight above (figs. 13b-15b, 19): every pixel of `out`
// shows the pattern rectangle [x0, x1] x [y0, y1] (image top = y1), shaded by Blinn 1977 with
// the map's normal and the two lights placed relative to that window. key_height is the key
// light's height above the texture in window spans (kDefaultKeyHeight: about 21 degrees above
// the window's centre); a lower, grazing key light brings out shallow slopes.
constexpr float kDefaultKeyHeight = 0.55f;
// Those two lights for the window [lo, hi], the key light first.
void flat_texture_lights(Vec2 lo, Vec2 hi, float key_height, PointLight out[2]);
void shade_flat_texture(const LeatherMaps& maps, Vec2 lo, Vec2 hi, const RgbView& out,
                        const Blinn1977Material& material = leather_material(),
                        float key_height = kDefaultKeyHeight);

// ---- 3D scenes (figs. 16-19) ----

// The two point lights of the product scenes (chosen here): a key light high at the front
// left, a weaker fill light low from the right.
void scene_lights(PointLight out[2]);
Rgb8 background_color();

// A tessellated surface ready for bump mapping: per-triangle dP/dx, dP/dy of the texture.
struct BumpSurface {
    TriangleMesh mesh;
    std::vector<Vec3> dpdx, dpdy;
};
Status compute_texture_tangents(BumpSurface* surface);

// Texture lookup with mirrored repetition outside the pattern rectangle (the normal's x or y
// is negated in a mirrored copy, so the bumps stay consistent).
Vec3 mirrored_normal(const LeatherMaps& maps, Vec2 texture_point);

// Per-pixel shader: Blinn 1977 with the leather normal map bump-mapped in the orthonormal
// tangent frame (Blinn 1978); back faces (the inside, the belt's back) in `back` unbumped.
struct LeatherShader {
    const Camera* camera = nullptr;
    const LeatherMaps* maps = nullptr;  // nullptr: no bumps
    const BumpSurface* surface = nullptr;
    Blinn1977Material front, back;
    PointLight lights[2];
    Rgb8 operator()(const Fragment& f) const;
};

// Minimal axes for the section plots: maps data (r, z) to pixels with equal scale.
struct PlotFrame {
    float x0, y0, scale;  // pixel of data (0, 0), pixels per data unit
    Vec2 to_pixel(Vec2 d) const { return {x0 + d.x * scale, y0 - d.y * scale}; }
};
void draw_axes(Canvas& c, const PlotFrame& f, Vec2 data_min, Vec2 data_max, float tick,
               const char* x_label, const char* y_label);

}  // namespace shitsukan::figures::tokai_relief
