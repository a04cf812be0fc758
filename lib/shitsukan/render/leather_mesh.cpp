#include "shitsukan/render/leather_mesh.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>

#include "shitsukan/core/scalar.hpp"
#include "shitsukan/raster/bump_mapping.hpp"

namespace shitsukan {

Blinn1977Material tokai1994_leather_material() {
    Blinn1977Material m;  // a tan crocodile leather with a polished finish (chosen here)
    m.color = {0.36f, 0.17f, 0.07f};
    m.ka = 0.18f;
    m.kd = 0.75f;
    m.ks = 0.35f;
    m.distribution = BlinnDistribution::d3_trowbridge_reitz;
    m.c3 = 0.25f;
    m.refractive_index = 1.5f;
    return m;
}

Blinn1977Material tokai1994_metal_material() {
    Blinn1977Material m;  // the brass clasp: little diffuse, a tight coloured highlight
    m.color = {0.55f, 0.42f, 0.16f};
    m.specular_color = {1.0f, 0.85f, 0.5f};
    m.ka = 0.35f;
    m.kd = 0.45f;
    m.ks = 1.2f;
    m.distribution = BlinnDistribution::d3_trowbridge_reitz;
    m.c3 = 0.08f;
    m.refractive_index = 8.0f;  // metals: high index, so F stays near 1 at all angles
    return m;
}

Blinn1977Material tokai1994_suede_material() {
    Blinn1977Material m;
    m.color = {0.50f, 0.36f, 0.24f};
    m.ka = 0.25f;
    m.kd = 0.8f;
    m.ks = 0.05f;
    m.c3 = 0.6f;
    return m;
}

void tokai1994_scene_lights(PointLight out[2]) {
    out[0] = {{-3.5f, 4.0f, 3.5f}, {1.05f, 1.0f, 0.95f}};
    out[1] = {{4.5f, 1.0f, 1.5f}, {0.30f, 0.33f, 0.40f}};
}

Rgb8 to_display_gamma(Vec3 c) {
    auto g = [](float v) { return to_byte(det_pow(clamp(v, 0.0f, 1.0f), 1.0f / 2.2f)); };
    return Rgb8{g(c.x), g(c.y), g(c.z)};
}

Status compute_texture_tangents(const MeshView& mesh, TextureTangents& out) {
    const int n = mesh.triangle_count;
    if (n < 0)
        return Status::error(StatusCode::invalid_argument,
                             "compute_texture_tangents: triangle count %d < 0", n);
    out.dpdu.assign(std::size_t(n), Vec3{});
    out.dpdv.assign(std::size_t(n), Vec3{});
    return mesh_texture_tangents(mesh, out.dpdu.data(), out.dpdv.data(), n);
}

Rgb8 shade_leather_fragment(const Fragment& f, Vec3 eye, const Blinn1977Material& front,
                            const Blinn1977Material& back, const PointLight* lights,
                            int light_count, const LeatherMaps* maps, Vec3 dpdu, Vec3 dpdv,
                            Vec2 uv_scale) {
    if (!f.front_facing) {  // the inside or the back: unbumped, normal turned to the viewer
        const Vec3 n = -f.normal;
        return to_display_gamma(
            shade_blinn1977(back, f.world_position, n, eye, lights, light_count));
    }
    Vec3 n = f.normal;
    if (maps != nullptr) {
        // Blinn 1978 in the orthonormalised frame of the texture's u, v on the surface.
        const TangentFrame frame = orthonormal_tangent_frame(n, dpdu, dpdv);
        const Vec2 t{f.uv.x * uv_scale.x, f.uv.y * uv_scale.y};
        n = perturb_normal(frame, mirrored_normal_at(*maps, t));
    }
    return to_display_gamma(shade_blinn1977(front, f.world_position, n, eye, lights, light_count));
}

Rgb8 LeatherShader::operator()(const Fragment& f) const {
    const bool bumps = maps != nullptr && dpdu != nullptr && dpdv != nullptr;
    const std::size_t t = std::size_t(f.triangle);
    return shade_leather_fragment(f, eye, shading.front, shading.back, shading.lights,
                                  shading.light_count, bumps ? maps : nullptr,
                                  bumps ? dpdu[t] : Vec3{}, bumps ? dpdv[t] : Vec3{},
                                  shading.uv_scale);
}

Status draw_leather_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                         const DrawOptions& options, const LeatherMaps& maps,
                         const TextureTangents& tangents, const LeatherShading& shading,
                         RasterStats* stats) {
    if (tangents.dpdu.size() != std::size_t(mesh.triangle_count) ||
        tangents.dpdv.size() != std::size_t(mesh.triangle_count))
        return Status::error(StatusCode::invalid_argument,
                             "draw_leather_mesh: %zu tangents for %d triangles (call "
                             "compute_texture_tangents on this mesh)",
                             tangents.dpdu.size(), mesh.triangle_count);
    if (shading.light_count < 0 || shading.light_count > 2)
        return Status::error(StatusCode::invalid_argument,
                             "draw_leather_mesh: light_count %d outside 0..2", shading.light_count);
    if (maps.width < 1 || maps.height < 1 ||
        maps.normals.size() != std::size_t(maps.width) * std::size_t(maps.height))
        return Status::error(StatusCode::invalid_argument,
                             "draw_leather_mesh: the leather maps are empty (was "
                             "make_leather_maps' Status checked?)");
    LeatherShader shader;
    shader.eye = camera.eye;
    shader.maps = &maps;
    shader.dpdu = tangents.dpdu.data();
    shader.dpdv = tangents.dpdv.data();
    shader.shading = shading;
    return draw_mesh(camera, band, mesh, options, shader, stats);
}

}  // namespace shitsukan
