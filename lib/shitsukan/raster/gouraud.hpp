// shitsukan/raster/gouraud.hpp — Gouraud shading of a host-side TriangleMesh.
//
// Manual
//   TriangleMesh lit = mesh;
//   apply_gouraud(&lit, model, material, base_color, camera.eye, lights, light_count);
//   auto shader = [](const Fragment& f) { return to_rgb8(f.color); };   // colours interpolated
// Lights every vertex once with Blinn-Phong (shading.hpp) and stores the result in
// mesh->colors (replacing them). Host side: resizes a std::vector.
#pragma once

#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/raster/shading.hpp"

namespace shitsukan {

Status apply_gouraud(TriangleMesh* mesh, const Mat4& model, const Material& material,
                     Vec3 base_color, Vec3 eye, const Light* lights, int light_count);

}  // namespace shitsukan
