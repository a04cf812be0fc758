// shitsukan/render/leather_mesh.hpp — tokai1994 §4-5: leather maps bump-mapped onto any mesh
// with texture coordinates, lit by Blinn's 1977 model and two point lights (the shader of
// the tokai1994 product figures, as a library call), plus the figures' chosen materials.
//
// Manual
//   ScaleParams prm;  ScalePattern pattern;                    // leather/scale_division.hpp
//   Status s = generate_scale_pattern(prm, pattern);
//   LeatherMaps maps;                                          // leather/maps.hpp
//   if (s) s = make_leather_maps(pattern, 128, 128, table1_section(Table1Section::convex),
//                                ReliefOptions{}, maps);
//   TriangleMesh mesh;
//   if (s) s = make_uv_sphere(1.0f, 32, 16, mesh);
//   TextureTangents tangents;                                  // per triangle dP/du, dP/dv
//   if (s) s = compute_texture_tangents(mesh.view(), tangents);
//   Camera camera = perspective_camera({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 35.0f, 96, 96);
//   RgbImage color(96, 96); FloatImage depth(96, 96);
//   FrameBand band = full_frame_band(color.view(), depth.view());
//   clear_band(band, Rgb8{0, 0, 0});
//   LeatherShading shading;                                    // tokai1994 leather, 2 lights
//   if (s) s = draw_leather_mesh(camera, band, mesh.view(), DrawOptions{}, maps, tangents,
//                                shading);
//   return s;
//   #include "shitsukan/leather/scale_division.hpp"
//   #include "shitsukan/geom/mesh_builders.hpp"
//   #include "shitsukan/image/image.hpp"
//
// Per pixel (front faces): the map's normal at the fragment's uv, read in pattern units
// (uv · uv_scale) with mirrored tiling (mirrored_normal_at: any uv, no seams), is turned
// into the surface's orthonormalised tangent frame (Blinn 1978; raster/bump_mapping.hpp) and
// lit by Blinn 1977 (raster/blinn1977.hpp) from the camera's eye. Back faces (the inside of a
// bag, the back of a belt) are lit unbumped with `back`, their normal turned to the viewer.
// maps == nullptr (draw_leather_mesh's overload without maps) draws the material unbumped.
// Output: linear RGB -> bytes with the display gamma 1/2.2 (to_display_gamma), clamped.
// Chosen here (tokai1994 §5 says only "reflection parameters found by trial and error" and
// "two point lights"): the materials below and the lights of tokai1994_scene_lights.
// Host side (TextureTangents owns its arrays); the shader itself allocates nothing.
#pragma once

#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh_view.hpp"
#include "shitsukan/image/image_view.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/raster/blinn1977.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"

namespace shitsukan {

// Tan crocodile leather with a polished finish: colour (0.36, 0.17, 0.07), Ka 0.18, Kd 0.75,
// Ks 0.35, D3 with c3 0.25, n 1.5.
Blinn1977Material tokai1994_leather_material();
// Brass for a clasp: little diffuse, a tight coloured highlight, n 8 (F near 1 everywhere).
Blinn1977Material tokai1994_metal_material();
// Suede for unbumped backs and linings.
Blinn1977Material tokai1994_suede_material();
// The two point lights of the product scenes: a key light high at the front left
// (-3.5, 4, 3.5), a weaker, bluish fill light low from the right (4.5, 1, 1.5).
void tokai1994_scene_lights(PointLight out[2]);

// Linear RGB -> 8-bit with the display gamma 1/2.2, clamped to [0, 1] first.
Rgb8 to_display_gamma(Vec3 linear);

// dP/du and dP/dv of every triangle (raster/bump_mapping.hpp's mesh_texture_tangents).
struct TextureTangents {
    std::vector<Vec3> dpdu, dpdv;
};
Status compute_texture_tangents(const MeshView& mesh, TextureTangents& out);

struct LeatherShading {
    Blinn1977Material front = tokai1994_leather_material();
    Blinn1977Material back = tokai1994_suede_material();
    PointLight lights[2];
    int light_count = 2;
    Vec2 uv_scale{1.0f, 1.0f};  // uv -> pattern units for the map lookup
    LeatherShading() { tokai1994_scene_lights(lights); }
};

// One fragment, everything explicit (the figures' own shader structs call this). maps null:
// no bumps; dpdu / dpdv are the fragment's triangle's tangents.
Rgb8 shade_leather_fragment(const Fragment& f, Vec3 eye, const Blinn1977Material& front,
                            const Blinn1977Material& back, const PointLight* lights,
                            int light_count, const LeatherMaps* maps = nullptr, Vec3 dpdu = {},
                            Vec3 dpdv = {}, Vec2 uv_scale = Vec2{1.0f, 1.0f});

// The per-pixel shader (a functor for draw_mesh). maps or tangents null: no bumps.
struct LeatherShader {
    Vec3 eye;
    const LeatherMaps* maps = nullptr;
    const Vec3* dpdu = nullptr;
    const Vec3* dpdv = nullptr;
    LeatherShading shading;
    Rgb8 operator()(const Fragment& f) const;
};

// Draws a mesh with uvs, bump-mapped with the leather maps. invalid_argument when the
// tangents were not computed for this mesh (count differs), light_count is not 0..2, or
// what draw_mesh refuses.
Status draw_leather_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                         const DrawOptions& options, const LeatherMaps& maps,
                         const TextureTangents& tangents,
                         const LeatherShading& shading = LeatherShading{},
                         RasterStats* stats = nullptr);

}  // namespace shitsukan
