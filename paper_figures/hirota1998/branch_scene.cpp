// paper_figures/hirota1998/branch_scene.cpp — fig. 11's grown branch, its crack ribbons and one
// view of them (branch_scene.hpp).
#include "hirota1998/branch_scene.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "shitsukan/core/scalar.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"

namespace shitsukan::figures::bark {

BranchScene branch_scene(const BranchBark& b, float t, const Vec3* W, float min_width) {
    BranchScene out;
    const int n = b.mesh.vertex_count();
    out.grown = b.mesh;
    for (int i = 0; i < n; ++i)
        out.grown.positions[std::size_t(i)] = branch_node_position(b, std::uint32_t(i), t, W);
    const std::vector<std::uint8_t> cracked = cracked_springs(b, t);
    std::vector<Vec3> centroid(b.triangles.size());
    for (std::size_t k = 0; k < b.triangles.size(); ++k) {
        const ConnectionTriangle& ct = b.triangles[k];
        centroid[k] = (out.grown.positions[ct.node[0]] + out.grown.positions[ct.node[1]] +
                       out.grown.positions[ct.node[2]]) * (1.0f / 3.0f);
    }
    for (std::size_t s = 0; s < b.net.springs.size(); ++s) {
        const BarkSpring& sp = b.net.springs[s];
        if (!cracked[s]) continue;
        out.broken += !sp.intact();
        const Vec3 xi = out.grown.positions[sp.i], xj = out.grown.positions[sp.j];
        const float l = length(xj - xi), w = std::max(l - sp.l0, min_width);
        const Vec3 along = (xj - xi) * (1.0f / l), m = (xi + xj) * 0.5f;
        const Vec3 lift = normalize(b.mesh.normals[sp.i] + b.mesh.normals[sp.j]) * 0.01f;
        const std::int32_t* tr = &b.spring_triangles[2 * s];
        for (int k = 0; k < 2 && tr[k] >= 0; ++k) {
            const Vec3 end = centroid[std::size_t(tr[k])];
            const Vec3 h = along * (0.5f * w);
            const std::uint32_t a = out.cracks.add_vertex(end - h + lift, lift);
            const std::uint32_t bb = out.cracks.add_vertex(m - h + lift, lift);
            const std::uint32_t cc = out.cracks.add_vertex(m + h + lift, lift);
            const std::uint32_t d = out.cracks.add_vertex(end + h + lift, lift);
            out.cracks.add_triangle(a, bb, cc), out.cracks.add_triangle(a, cc, d);
        }
    }
    return out;
}

Camera fig11_camera(int view, int size) {
    const Vec3 eyes[2] = {{1.5f, 9.0f, 37.0f}, {26.0f, 21.0f, 22.0f}};
    return perspective_camera(eyes[view == 1 ? 1 : 0], {2.0f, 8.0f, 0.0f}, {0, 1, 0}, 34.0f, size, size);
}

Status draw_branch_view(const BranchScene& scene, const Camera& cam, const Mat4& turn, RgbView target) {
    FloatImage depth(target.width, target.height);
    FrameBand band = full_frame_band(target, depth.view());
    clear_band(band, Rgb8{236, 238, 240});
    const Vec3 pivot{2.0f, 8.0f, 0.0f};
    DrawOptions opt;
    opt.model = Mat4::translate(pivot) * turn * Mat4::translate(pivot * -1.0f) * Mat4::rotate_x(-0.5f * kPi);
    opt.cull = CullMode::none;
    const Light light = directional_light({-0.5f, 0.6f, 0.8f});
    Material mat;
    mat.ambient = 0.25f, mat.diffuse = 0.8f;
    const Vec3 bark_colour{0.60f, 0.50f, 0.40f}, crack_colour{0.10f, 0.07f, 0.05f};
    auto shade = [&](Vec3 base) {
        return [&, base](const Fragment& f) {
            const Vec3 nrm = face_forward(f.normal, f.world_position, cam.eye);
            return to_rgb8(shade_lambert(mat, base, f.world_position, nrm, &light, 1));
        };
    };
    auto bark_shader = shade(bark_colour);
    auto crack_shader = shade(crack_colour);
    SHITSUKAN_TRY(draw_mesh(cam, band, scene.grown.view(), opt, bark_shader));
    return draw_mesh(cam, band, scene.cracks.view(), opt, crack_shader);
}

}  // namespace shitsukan::figures::bark
