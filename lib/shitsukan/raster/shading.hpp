// shitsukan/raster/shading.hpp — lights, a material, Lambert + ambient and Blinn-Phong.
//
// Manual
//   Camera camera = perspective_camera({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 35.0f, 64, 64);
//   Light lights[2] = {directional_light({-1, 1, 1}), point_light({2, 3, 4}, {1, 0.9f, 0.8f})};
//   Material mat;                          // ambient 0.1, diffuse 0.9, specular 0, shininess 32
//   Vec3 base_color{0.7f, 0.7f, 0.7f};
//   auto shader = [&](const Fragment& f) {
//       Vec3 c = shade_blinn_phong(mat, base_color, f.world_position, f.normal, camera.eye,
//                                  lights, 2);
//       return to_rgb8(c);
//   };
//   Fragment f;  f.normal = {0, 0, 1};
//   Rgb8 px = shader(f);
//   #include "shitsukan/raster/rasterizer.hpp"
// The three classic ways to get the normal used above:
//   flat      flat_normal(mesh, f.triangle, model): the triangle's plane (or draw a mesh
//             without normals: the rasterizer then hands the plane normal in f.normal),
//   Gouraud   light the vertices once (light_vertices, or gouraud.hpp on a TriangleMesh),
//             and return to_rgb8(f.color): the lit colours are interpolated,
//   per pixel f.normal (interpolated vertex normals, normalised): the default above.
//
// Models (colours are linear RGB, components in [0, 1]; base_color is the surface albedo,
// e.g. a solid texture's value):
//   Lambert + ambient   L = k_a·base + Σ_i I_i·C_i · k_d·base·max(0, n·l_i)
//   Blinn-Phong         L = Lambert + Σ_i I_i·C_i · k_s·S·max(0, n·h_i)^shininess,
//                       h_i = normalize(l_i + v), v the unit vector to the eye,
//                       the specular term only where n·l_i > 0.
//   l_i: unit vector from the surface point to the light (point light) or the light's
//   `direction` (directional light: pointing from the scene TOWARDS the light). No distance
//   attenuation (chosen here: the papers' figures are lit by distant lamps).
//   Normals are used as given (the rasterizer hands them normalised); a normal facing away
//   from the eye is not flipped: call face_forward() for two-sided surfaces.
// Output: to_rgb8 clamps to [0, 1] and rounds to bytes WITHOUT gamma correction (chosen
// here: the papers' 8-bit frames store linear intensities; keeps the maths readable).
// Ranges: k_a, k_d, k_s >= 0; shininess >= 1; intensity >= 0; light count >= 0.
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh_view.hpp"
#include "shitsukan/image/image_view.hpp"

namespace shitsukan {

enum class LightKind : std::uint8_t { directional, point };

struct Light {
    LightKind kind = LightKind::directional;
    Vec3 position{0, 0, 0};   // point light: world position
    Vec3 direction{0, 0, 1};  // directional light: towards the light (normalised when used)
    Vec3 color{1, 1, 1};      // C_i
    float intensity = 1.0f;   // I_i
};

Light directional_light(Vec3 towards_light, Vec3 color = {1, 1, 1}, float intensity = 1.0f);
Light point_light(Vec3 position, Vec3 color = {1, 1, 1}, float intensity = 1.0f);

struct Material {
    float ambient = 0.1f;     // k_a
    float diffuse = 0.9f;     // k_d
    float specular = 0.0f;    // k_s (0: pure Lambert)
    float shininess = 32.0f;  // Blinn-Phong exponent
    Vec3 specular_color{1, 1, 1};  // S: white highlights (dielectrics)
};

// The unit vector from `position` to the light.
Vec3 light_vector(const Light& light, Vec3 position);

Vec3 shade_lambert(const Material& material, Vec3 base_color, Vec3 position, Vec3 normal,
                   const Light* lights, int light_count);
Vec3 shade_blinn_phong(const Material& material, Vec3 base_color, Vec3 position, Vec3 normal,
                       Vec3 eye, const Light* lights, int light_count);

// The normal turned to face the eye (for surfaces seen from both sides).
Vec3 face_forward(Vec3 normal, Vec3 position, Vec3 eye);

// Flat shading: the world-space plane normal of triangle `triangle` (counter-clockwise
// front), transformed by `model`'s normal matrix; (0, 0, 0) for a degenerate triangle.
// The caller guarantees 0 <= triangle < mesh.triangle_count (asserted).
Vec3 flat_normal(const MeshView& mesh, int triangle, const Mat4& model);

// Gouraud shading: Blinn-Phong at every vertex (world position and normal under `model`),
// written to out_colors[0 .. mesh.vertex_count). Needs per-vertex normals. Pass the result
// as the mesh's colors and return to_rgb8(f.color) from the shader.
Status light_vertices(const MeshView& mesh, const Mat4& model, const Material& material,
                      Vec3 base_color, Vec3 eye, const Light* lights, int light_count,
                      Vec3* out_colors, int out_capacity);

// Linear [0, 1] -> bytes: clamped, rounded, no gamma (see above).
Rgb8 to_rgb8(Vec3 color);

}  // namespace shitsukan
