#include "shitsukan/render/solid_mesh.hpp"

#include <cmath>

#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {
std::uint8_t to_byte_rounded(float v) {
    return std::uint8_t(v <= 0.0f ? 0 : (v >= 255.0f ? 255 : int(v + 0.5f)));
}

Status validate_solid_inputs(const LatticeView& lattice, const SolidMaterial& material,
                             const SolidShading& shading) {
    if (lattice.values == nullptr || lattice.side < 2)
        return Status::error(StatusCode::invalid_argument,
                             "solid texture: the lattice view is empty (was the lattice built, "
                             "and its Status checked?)");
    SHITSUKAN_TRY(validate_solid_material(material));
    const Vec3 l = shading.light;
    if (!is_finite(l.x) || !is_finite(l.y) || !is_finite(l.z) || !is_finite(shading.ambient) ||
        !is_finite(shading.diffuse) || !is_finite(shading.mapping.centre) ||
        !is_finite(shading.mapping.scale))
        return Status::error(StatusCode::invalid_argument,
                             "solid texture: light, ambient, diffuse and mapping must be finite");
    return Status::success();
}
}  // namespace

Rgb8 SolidTextureShader::operator()(const Fragment& f) const {
    const Vec3 p = object_to_lattice(f.object_position, shading.mapping);
    const Vec3 c = solid_color(material, lattice, p);  // eqs. (6)-(12)
    Vec3 n = f.normal;
    if (!f.front_facing) n = -n;  // the inside of a cut object faces the viewer
    const float lambert = std::fmax(0.0f, dot(n, shading.light));
    const float light = shading.ambient + shading.diffuse * lambert;
    return Rgb8{to_byte_rounded(c.x * light), to_byte_rounded(c.y * light),
                to_byte_rounded(c.z * light)};
}

Status draw_solid_textured_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                                const DrawOptions& options, const LatticeView& lattice,
                                const SolidMaterial& material, const SolidShading& shading,
                                RasterStats* stats) {
    SHITSUKAN_TRY(validate_solid_inputs(lattice, material, shading));
    SolidTextureShader shader{lattice, material, shading};
    return draw_mesh(camera, band, mesh, options, shader, stats);
}

Status render_solid_texture(const Camera& camera, const MeshView& mesh, const LatticeView& lattice,
                            const SolidMaterial& material, RgbImage& out,
                            const SolidShading& shading, Rgb8 background,
                            const DrawOptions& options) {
    SHITSUKAN_TRY(validate_camera(camera));
    SHITSUKAN_TRY(validate_solid_inputs(lattice, material, shading));
    if (camera.width > kMaxFrameSize || camera.height > kMaxFrameSize)
        return Status::error(StatusCode::too_large,
                             "render_solid_texture: frame %d x %d exceeds %d x %d", camera.width,
                             camera.height, kMaxFrameSize, kMaxFrameSize);
    out.resize(camera.width, camera.height, background);
    FloatImage depth(camera.width, camera.height);
    const FrameBand band = full_frame_band(out.view(), depth.view());
    clear_band(band, background);
    return draw_solid_textured_mesh(camera, band, mesh, options, lattice, material, shading);
}

}  // namespace shitsukan
