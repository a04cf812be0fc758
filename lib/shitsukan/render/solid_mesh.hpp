// shitsukan/render/solid_mesh.hpp — a solid texture (marble, wood) on any mesh, drawn by the
// scanline rasterizer: the shader of the okada1987 / okada1989 object figures, as a library
// call. render/ is where paper modules meet the rasterizer (they never include raster/).
//
// Manual
//   FractalLattice lattice;
//   Status s = lattice.build(okada1987_lattice_params());          // solid/okada1987_presets
//   TriangleMesh mesh;
//   if (s) s = make_torus(0.64f, 0.28f, 48, 24, mesh);
//   if (s) s = fit_mesh_to_cube(mesh, 0.92f);                     // any mesh into [-1, 1]^3
//   Camera cam = perspective_camera({1.9f, 2.4f, 4.2f}, {0, 0, 0}, {0, 1, 0}, 30, 128, 128);
//   RgbImage img;
//   if (s) s = render_solid_texture(cam, mesh.view(), lattice.view(), okada1987_marble(), img);
//   return s;
//   #include "shitsukan/geom/mesh_builders.hpp"
//   #include "shitsukan/geom/mesh_fit.hpp"
//   #include "shitsukan/solid/lattice_store.hpp"
//   #include "shitsukan/solid/okada1987_presets.hpp"
//
//   // or band by band / several meshes into one frame:
//   SolidShading shading;                       // light, ambient, diffuse, object mapping
//   s = draw_solid_textured_mesh(cam, band, mesh.view(), DrawOptions{}, lattice.view(),
//                                okada1987_wood(), shading);
//
// Per pixel: the fragment's OBJECT-space position (so the texture moves with the object
// and a DrawOptions::model only places it) goes through shading.mapping into the lattice
// (object_to_lattice), solid_color gives the eq. (12) colour (0..255), and a Lambert term
// lights it: colour·(ambient + diffuse·max(0, n·l)), the normal turned to the viewer on back
// faces. Defaults (chosen here, as the okada1987 figures: the paper does not describe its
// shading): l = normalize(0.3, 0.8, 0.55) (upper front, slightly right), ambient 0.3,
// diffuse 0.7; bytes rounded to nearest, no gamma.
// Errors: what draw_mesh refuses (camera, band, mesh, model), an invalid material, an empty
// lattice view, a non-finite light. Host side for render_solid_texture (it owns the depth
// buffer); draw_solid_textured_mesh allocates nothing.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh_view.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/object_mapping.hpp"
#include "shitsukan/solid/solid_material.hpp"

namespace shitsukan {

struct SolidShading {
    ObjectToLattice mapping;                          // object -> lattice (R = 6 default)
    Vec3 light = normalize(Vec3{0.3f, 0.8f, 0.55f});  // towards the light, world space
    float ambient = 0.3f;
    float diffuse = 0.7f;
};

// The per-pixel shader (a functor for draw_mesh).
struct SolidTextureShader {
    LatticeView lattice;
    SolidMaterial material;
    SolidShading shading;
    Rgb8 operator()(const Fragment& f) const;
};

// Draws one mesh into a band with the solid texture (several calls fill one frame).
Status draw_solid_textured_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                                const DrawOptions& options, const LatticeView& lattice,
                                const SolidMaterial& material,
                                const SolidShading& shading = SolidShading{},
                                RasterStats* stats = nullptr);

// One call: resizes out to the camera's frame, clears it to `background`, draws the mesh.
Status render_solid_texture(const Camera& camera, const MeshView& mesh, const LatticeView& lattice,
                            const SolidMaterial& material, RgbImage& out,
                            const SolidShading& shading = SolidShading{},
                            Rgb8 background = Rgb8{24, 26, 32},
                            const DrawOptions& options = DrawOptions{});

}  // namespace shitsukan
