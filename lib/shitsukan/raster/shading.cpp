// small-device: yes (no allocation, no exceptions)
#include "shitsukan/raster/shading.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>

#include "shitsukan/core/assert.hpp"

namespace shitsukan {

Light directional_light(Vec3 towards_light, Vec3 color, float intensity) {
    Light l;
    l.kind = LightKind::directional;
    l.direction = towards_light;
    l.color = color;
    l.intensity = intensity;
    return l;
}

Light point_light(Vec3 position, Vec3 color, float intensity) {
    Light l;
    l.kind = LightKind::point;
    l.position = position;
    l.color = color;
    l.intensity = intensity;
    return l;
}

Vec3 light_vector(const Light& light, Vec3 position) {
    return light.kind == LightKind::point ? normalize(light.position - position)
                                          : normalize(light.direction);
}

// L = k_a·base + Σ I·C·k_d·base·max(0, n·l)
Vec3 shade_lambert(const Material& m, Vec3 base, Vec3 position, Vec3 normal,
                   const Light* lights, int light_count) {
    SHITSUKAN_ASSERT(light_count >= 0 && (light_count == 0 || lights != nullptr));
    Vec3 sum = base * m.ambient;
    for (int i = 0; i < light_count; ++i) {
        float n_dot_l = dot(normal, light_vector(lights[i], position));
        if (n_dot_l <= 0.0f) continue;  // the light is behind the surface
        sum += lights[i].color * base * (lights[i].intensity * m.diffuse * n_dot_l);
    }
    return sum;
}

// Lambert + Σ I·C·k_s·S·max(0, n·h)^shininess with the half vector h = normalize(l + v).
Vec3 shade_blinn_phong(const Material& m, Vec3 base, Vec3 position, Vec3 normal, Vec3 eye,
                       const Light* lights, int light_count) {
    Vec3 sum = shade_lambert(m, base, position, normal, lights, light_count);
    if (m.specular <= 0.0f) return sum;
    Vec3 v = normalize(eye - position);
    for (int i = 0; i < light_count; ++i) {
        Vec3 l = light_vector(lights[i], position);
        if (dot(normal, l) <= 0.0f) continue;  // no highlight on the unlit side
        float n_dot_h = dot(normal, normalize(l + v));
        if (n_dot_h <= 0.0f) continue;
        float highlight = det_pow(n_dot_h, m.shininess);
        sum += lights[i].color * m.specular_color * (lights[i].intensity * m.specular * highlight);
    }
    return sum;
}

Vec3 face_forward(Vec3 normal, Vec3 position, Vec3 eye) {
    return dot(normal, eye - position) < 0.0f ? -normal : normal;
}

Vec3 flat_normal(const MeshView& mesh, int triangle, const Mat4& model) {
    SHITSUKAN_ASSERT(triangle >= 0 && triangle < mesh.triangle_count);
    const std::uint32_t* t = mesh.indices + 3 * triangle;
    Vec3 a = transform_point(model, mesh.positions[t[0]]);
    Vec3 b = transform_point(model, mesh.positions[t[1]]);
    Vec3 c = transform_point(model, mesh.positions[t[2]]);
    return normalize(cross(b - a, c - a));  // counter-clockwise: towards the viewer
}

Status light_vertices(const MeshView& mesh, const Mat4& model, const Material& material,
                      Vec3 base_color, Vec3 eye, const Light* lights, int light_count,
                      Vec3* out_colors, int out_capacity) {
    if (mesh.vertex_count == 0) return Status::success();
    if (mesh.normals == nullptr || mesh.positions == nullptr)
        return Status::error(StatusCode::invalid_argument,
                             "light_vertices: Gouraud shading needs per-vertex positions and "
                             "normals");
    if (out_colors == nullptr || out_capacity < mesh.vertex_count)
        return Status::error(StatusCode::buffer_too_small,
                             "light_vertices: room for %d colours, the mesh has %d vertices",
                             out_colors ? out_capacity : 0, mesh.vertex_count);
    if (light_count < 0 || (light_count > 0 && lights == nullptr))
        return Status::error(StatusCode::invalid_argument,
                             "light_vertices: %d lights given at %p", light_count,
                             static_cast<const void*>(lights));
    bool ok = false;
    Mat4 normal_matrix = transpose(inverse(model, &ok));
    if (!ok)
        return Status::error(StatusCode::invalid_argument,
                             "light_vertices: the model matrix is singular");
    for (int i = 0; i < mesh.vertex_count; ++i) {
        Vec3 p = transform_point(model, mesh.positions[i]);
        Vec3 n = normalize(transform_vector(normal_matrix, mesh.normals[i]));
        out_colors[i] = shade_blinn_phong(material, base_color, p, n, eye, lights, light_count);
    }
    return Status::success();
}

Rgb8 to_rgb8(Vec3 c) { return Rgb8{to_byte(c.x), to_byte(c.y), to_byte(c.z)}; }

}  // namespace shitsukan
