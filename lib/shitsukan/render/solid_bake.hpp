// shitsukan/render/solid_bake.hpp — a solid texture baked onto a mesh's UV map, and a flat
// slice of it: the images a game engine or a 3D print service takes (okada1987 §4: the
// texture is a function of the object's own coordinates, so the bake samples it at the
// surface point behind each texel).
//
// Manual
//   TriangleMesh mesh;  Status s = make_uv_sphere(1.0f, 24, 12, mesh);  // or read_obj (obj_read)
//   if (s) s = fit_mesh_to_cube(mesh, 0.92f);                         // into [-1, 1]^3
//   FractalLattice lattice;
//   if (s) s = lattice.build(okada1987_lattice_params());
//   RgbImage texture;
//   if (s) s = bake_solid_texture(mesh.view(), lattice.view(), okada1987_marble(),
//                                 object_to_lattice_mapping(6), 128, 128, texture);
//   FloatImage heights;                       // G' as floats: a height map with no 8-bit steps
//   if (s) s = bake_solid_texture(mesh.view(), lattice.view(), okada1987_marble(),
//                                 object_to_lattice_mapping(6), 128, 128, texture, heights);
//   return s;
//   #include "shitsukan/geom/mesh_builders.hpp"
//   #include "shitsukan/geom/mesh_fit.hpp"
//   #include "shitsukan/solid/lattice_store.hpp"
//   #include "shitsukan/solid/okada1987_presets.hpp"
//
//   SolidSlice slice;                          // the plane y = 32 of the lattice, x right, z up
//   s = render_solid_slice(lattice.view(), okada1987_marble(), slice, 512, 512, texture);
//
// Bake: texel (i, j) is the uv point ((i + 0.5)/W, 1 - (j + 0.5)/H) (row 0 = v near 1, the OBJ
// convention). Each triangle is scan-converted in uv space; a texel centre inside it (edge
// functions, top-left rule) gets the barycentric mix of the triangle's OBJECT positions, then
// object_to_lattice and solid_color (eq. (12)). Texels no triangle covers are filled from
// covered neighbours, `dilate` rings (chosen 4: mip-mapping and bilinear lookups at chart
// borders then never fetch the background); the rest stay `background`. Overlapping uv
// charts: the later triangle wins.
// Slice: pixel (i, j) is the lattice point origin + (i + 0.5)·du·u + (j' + 0.5)·dv·v with
// j' = H - 1 - j (image up = +v), du = extent/W, dv = extent/H. With a PeriodicLattice
// (solid/periodic_lattice.hpp), extent = 2^R and a periodic material, the image tiles.
// Errors: a mesh without uv (say so), an invalid material, an empty lattice, sizes outside
// 1..16384, non-finite slice values. Progress: fraction of triangles (bake) or rows (slice).
// Host side (owns the image).
#pragma once

#include "shitsukan/core/progress.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh_view.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/object_mapping.hpp"
#include "shitsukan/solid/solid_material.hpp"

namespace shitsukan {

struct SolidSlice {
    Vec3 origin{0.0f, 32.0f, 0.0f};  // lattice point at the image's lower-left corner
    Vec3 u{1, 0, 0}, v{0, 0, 1};     // unit directions: image right, image up
    float extent = 64.0f;            // lattice units across the image (both directions)
    bool wrap = false;               // sample the lattice repeated every 2^R (periodic use)
};

Status bake_solid_texture(const MeshView& mesh, const LatticeView& lattice,
                          const SolidMaterial& material, const ObjectToLattice& mapping, int width,
                          int height, RgbImage& out, Rgb8 background = Rgb8{0, 0, 0},
                          int dilate = 4, Progress progress = Progress{});
// The same, with the densities G' (eq. (12), in [0, 1]) as floats in `density` (resized): a
// height map with no 8-bit steps. Dilated like the colours; texels beyond the rings
// get the covered texels' mean G' (chosen here: flat, so no cliff at the gutter's edge).
Status bake_solid_texture(const MeshView& mesh, const LatticeView& lattice,
                          const SolidMaterial& material, const ObjectToLattice& mapping, int width,
                          int height, RgbImage& out, FloatImage& density,
                          Rgb8 background = Rgb8{0, 0, 0}, int dilate = 4,
                          Progress progress = Progress{});

// Colours of the slice into out (resized); densities G' too when `density` is not null.
Status render_solid_slice(const LatticeView& lattice, const SolidMaterial& material,
                          const SolidSlice& slice, int width, int height, RgbImage& out,
                          FloatImage* density = nullptr, Progress progress = Progress{});

}  // namespace shitsukan
