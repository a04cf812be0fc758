// Lesson 52: bump mapping a leather normal map onto a curved Bezier patch (tokai1994 §4-5,
// Blinn 1978), and why the tangent frame must be orthonormal.
// Figures: paper_figures/tokai1994/fig16_bezier_patch.cpp,
//   paper_figures/tokai1994/fig17_18_handbag.cpp, paper_figures/tokai1994/fig19_belt.cpp.
//
// The leather normal map stores normals in the texture's own frame: x, y along the texture,
// z out of it. On the surface, texture x and y run along dP/dx and dP/dy, which are neither
// unit length nor perpendicular to each other or to the interpolated normal when the mapping
// shears. Gram-Schmidt makes them a proper frame (T, B, N); using them raw tilts the bumps.
// The left half of the picture uses the orthonormal frame, the right half the raw vectors.
//
// Build and run:  make examples   (writes build/examples/out/bump_mapped_patch.png)
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "shitsukan/geom/bezier_patch_mesh.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/scale_labels.hpp"
#include "shitsukan/raster/blinn1977.hpp"
#include "shitsukan/raster/bump_mapping.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/core/detmath.hpp"

using namespace shitsukan;

static int fail(const Status& s) { return std::fprintf(stderr, "%s\n", s.message()), 1; }

struct Shader {
    const Camera* camera;
    const LeatherMaps* maps;
    const TriangleMesh* mesh;
    const std::vector<Vec3>* dpdx;
    const std::vector<Vec3>* dpdy;
    bool orthonormal;
    double* angle_sum;  // how far the raw frame's normal is from the orthonormal one
    long* count;
    Rgb8 operator()(const Fragment& f) const {
        Vec3 m = normal_at(*maps, {f.uv.x - std::floor(f.uv.x), f.uv.y - std::floor(f.uv.y)});
        Vec3 tx = (*dpdx)[std::size_t(f.triangle)], ty = (*dpdy)[std::size_t(f.triangle)];
        // 1. The right way: T = dP/dx made perpendicular to N, B = N x T (Gram-Schmidt).
        Vec3 good = perturb_normal(orthonormal_tangent_frame(f.normal, tx, ty), m);
        // 2. The frequent bug: the raw directions as if they were a frame.
        TangentFrame raw;
        raw.t = normalize(tx);
        raw.b = normalize(ty);
        raw.n = f.normal;
        Vec3 bad = perturb_normal(raw, m);
        *angle_sum += det_acos(clamp(dot(good, bad), -1.0f, 1.0f));
        ++*count;
        Blinn1977Material leather;
        PointLight lights[2] = {{{-3, 4, 4}, {1, 1, 1}}, {{4, 1, 2}, {0.3f, 0.3f, 0.35f}}};
        Vec3 c = shade_blinn1977(leather, f.world_position, orthonormal ? good : bad, camera->eye,
                                 lights, 2);
        auto g = [](float v) { return to_byte(det_pow(clamp(v, 0.0f, 1.0f), 1.0f / 2.2f)); };
        return Rgb8{g(c.x), g(c.y), g(c.z)};
    }
};

int main() {
    // 1. The leather: fig. 7 pattern, fig. 13 section, 512 x 512 maps.
    ScalePattern pattern;
    Status s = generate_scale_pattern(ScaleParams{}, pattern);
    if (!s) return fail(s);
    std::vector<std::int32_t> labels(512 * 512);
    if (!(s = rasterize_scale_labels(pattern, 512, 512, labels.data()))) return fail(s);
    LeatherMaps maps;
    s = make_leather_maps(pattern, labels.data(), 512, 512, table1_section(Table1Section::convex),
                          ReliefOptions{}, maps);
    if (!s) return fail(s);

    // 2. A curved patch whose plain (u, v) are strongly sheared, mapped with plain (u, v) so
    //    that dP/dx and dP/dy are far from perpendicular.
    BezierPatch patch;
    const float bulge[4] = {0.0f, 0.25f, 0.25f, 0.0f};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)  // rows along x, columns slanted 60 degrees away from them
            patch.p[i][j] = Vec3{-1.2f, 0.0f, 0.45f} + Vec3{0.55f, 0.0f, 0.0f} * float(i) +
                            Vec3{0.33f, 0.0f, -0.33f} * float(j) +
                            Vec3{0.0f, bulge[i] + bulge[j], 0.0f};
    PatchStripOptions opt;
    opt.segments_u = opt.segments_v = 24;
    opt.arc_length = false;
    opt.texture_scale = 0.6f;  // the pattern square covers the patch about once
    TriangleMesh mesh;
    if (!(s = tessellate_patch_strip(&patch, 1, opt, mesh))) return fail(s);
    // dP/dx, dP/dy of the texture, once per triangle (raster/bump_mapping.hpp).
    std::vector<Vec3> dpdx(std::size_t(mesh.triangle_count())), dpdy(dpdx.size());
    if (!(s = mesh_texture_tangents(mesh.view(), dpdx.data(), dpdy.data(), int(dpdx.size()))))
        return fail(s);

    // 3. Render twice, side by side.
    RgbImage image(640, 320);
    double angle_sum = 0;
    long count = 0;
    for (int half = 0; half < 2; ++half) {
        RgbView view = image.view().subview(320 * half, 0, 320, 320);
        FloatImage depth(320, 320);
        FrameBand band = full_frame_band(view, depth.view());
        clear_band(band, Rgb8{200, 204, 208});
        Camera cam = perspective_camera({0.12f, 3.0f, 1.6f}, {0.12f, 0.2f, -0.05f}, {0, 1, 0},
                                        52.0f, 320, 320);
        Shader shader{&cam, &maps, &mesh, &dpdx, &dpdy, half == 0, &angle_sum, &count};
        DrawOptions d;
        d.cull = CullMode::none;
        if (!(s = draw_mesh(cam, band, mesh.view(), d, shader))) return fail(s);
    }
    if (!(s = write_png("bump_mapped_patch.png", image.view()))) return fail(s);
    std::printf(
        "left: orthonormal frame, right: raw dP/dx, dP/dy; the raw frame tilts the "
        "bumped normal by %.1f degrees on average\n",
        angle_sum / double(count > 0 ? count : 1) * 180.0 / kPiD);
    return 0;
}
