// shitsukan/raster/gouraud.hpp — Gouraud shading of a host-side TriangleMesh.
//
// Manual
//   TriangleMesh mesh;
//   Status s = make_uv_sphere(1.0f, 32, 16, mesh);
//   Camera camera = perspective_camera({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 35.0f, 128, 128);
//   Light lights[1] = {directional_light({-1, 1, 1})};
//   int light_count = 1;
//   Material material;
//   Vec3 base_color{0.8f, 0.6f, 0.4f};
//   Mat4 model = Mat4::identity();
//   TriangleMesh lit = mesh;
//   if (s) s = apply_gouraud(lit, model, material, base_color, camera.eye, lights, light_count);
//   auto shader = [](const Fragment& f) { return to_rgb8(f.color); };   // colours interpolated
//   RgbImage color(128, 128); FloatImage depth(128, 128);
//   FrameBand band = full_frame_band(color.view(), depth.view());
//   clear_band(band, Rgb8{0, 0, 0});
//   if (s) s = draw_mesh(camera, band, lit.view(), DrawOptions{}, shader);
//   return s;
//   #include "shitsukan/geom/mesh_builders.hpp"
//   #include "shitsukan/image/image.hpp"
//   #include "shitsukan/raster/rasterizer.hpp"
// Lights every vertex once with Blinn-Phong (shading.hpp) and stores the result in
// mesh.colors (replacing them). Host side: resizes a std::vector.
#pragma once

#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/raster/shading.hpp"

namespace shitsukan {

Status apply_gouraud(TriangleMesh& mesh, const Mat4& model, const Material& material,
                     Vec3 base_color, Vec3 eye, const Light* lights, int light_count);

}  // namespace shitsukan
