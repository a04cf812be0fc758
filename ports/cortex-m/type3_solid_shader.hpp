// ports/cortex-m/type3_solid_shader.hpp — render/solid_mesh.hpp's SolidTextureShader with D(P)
// from a Type III lattice (solid/lattice_type3.hpp, okada1989 §3-3: no table) instead of the
// 1.1 MB Type I table: for a device whose RAM cannot hold the table (a Cortex-M0 with 16 KB).
// The same operations in the same order as SolidTextureShader::operator() (solid_color =
// solid_density_color(solid_density_at(p, D(P)))), so with a hash-noise lattice (Types I
// and III agree at every node) it gives the same bytes; `make test-mcu` compares them.
#pragma once

#include <cmath>
#include <cstdint>

#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/render/solid_mesh.hpp"
#include "shitsukan/solid/lattice_type3.hpp"
#include "shitsukan/solid/object_mapping.hpp"
#include "shitsukan/solid/solid_material.hpp"

namespace shitsukan::port {

struct TypeIIISolidShader {
    TypeIIILattice* lattice;
    SolidMaterial material;
    SolidShading shading;
    Rgb8 operator()(const Fragment& f) const {
        const Vec3 p = object_to_lattice(f.object_position, shading.mapping);
        const Vec3 c =
            solid_density_color(material, solid_density_at(material, p, lattice->turbulence(p)));
        Vec3 n = f.normal;
        if (!f.front_facing) n = -n;
        const float lambert = std::fmax(0.0f, dot(n, shading.light));
        const float light = shading.ambient + shading.diffuse * lambert;
        auto byte = [](float v) {
            return std::uint8_t(v <= 0.0f ? 0 : (v >= 255.0f ? 255 : int(v + 0.5f)));
        };
        return Rgb8{byte(c.x * light), byte(c.y * light), byte(c.z * light)};
    }
};

}  // namespace shitsukan::port
