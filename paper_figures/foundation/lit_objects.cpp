// Foundation demo figures: a lit sphere, cube and torus, one per shading style.
//   lit_sphere  per-pixel Blinn-Phong (interpolated vertex normals)
//   lit_cube    flat shading (each triangle's plane normal)
//   lit_torus   Gouraud shading (vertices lit once, colours interpolated)
// They exercise the camera, the rasterizer, the shading helpers and the mesh builders.
// Examples: examples/02_lit_cube.cpp, examples/03_bands.cpp.
#include "driver/figure.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/raster/gouraud.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

// The lighting all three share (chosen here: a warm key light from the upper left and a
// cool, weaker fill from the right, the usual three-quarter studio set-up).
struct Studio {
    Light lights[2] = {directional_light({-0.5f, 0.9f, 0.6f}, {1.0f, 0.96f, 0.9f}, 1.0f),
                       point_light({4.0f, 0.5f, 2.0f}, {0.55f, 0.65f, 0.9f}, 0.35f)};
    Material material;
    Studio() {
        material.ambient = 0.1f;
        material.diffuse = 0.85f;
        material.specular = 0.4f;
        material.shininess = 48.0f;
    }
    void record(FigureContext& ctx, const char* shading) const {
        ctx.chosen("shading", shading, "one shading style per object, to show all three");
        ctx.chosen("key light", "directional towards (-0.5, 0.9, 0.6), colour (1, 0.96, 0.9)",
                   "three-quarter studio lighting");
        ctx.chosen("fill light", "point at (4, 0.5, 2), colour (0.55, 0.65, 0.9), intensity 0.35",
                   "softens the shadow side");
        ctx.chosen("material", "k_a 0.1, k_d 0.85, k_s 0.4, shininess 48", "a glazed ceramic look");
        ctx.chosen("gamma", "none (linear values stored as bytes)", "as the papers' 8-bit frames");
    }
};

struct Target {
    RgbImage color;
    FloatImage depth;
    FrameBand band;
    explicit Target(int size) : color(size, size), depth(size, size) {
        band = full_frame_band(color.view(), depth.view());
        clear_band(band, Rgb8{22, 24, 30});
    }
};

int frame_size(const FigureContext& ctx) { return ctx.quick() ? 128 : 512; }

}  // namespace

SHITSUKAN_FIGURE(foundation_lit_sphere, "foundation", "lit_sphere",
                 "A UV sphere, per-pixel Blinn-Phong shading (interpolated normals)") {
    const int size = frame_size(ctx), slices = 64, stacks = 32;
    TriangleMesh sphere;
    SHITSUKAN_TRY(make_uv_sphere(1.0f, slices, stacks, sphere));
    Camera cam = perspective_camera({0.6f, 1.2f, 3.6f}, {0, 0, 0}, {0, 1, 0}, 38.0f, size, size);
    Studio studio;
    studio.record(ctx, "per pixel (Blinn-Phong with the interpolated, renormalised normal)");
    ctx.chosen("sphere", fmt("radius 1, %d slices x %d stacks", slices, stacks),
               "smooth silhouette at 512 px");
    ctx.chosen("frame", fmt("%d x %d, fov 38 deg", size, size), "the papers' 512 x 512");
    Vec3 base{0.75f, 0.22f, 0.18f};
    auto shader = [&](const Fragment& f) {
        return to_rgb8(shade_blinn_phong(studio.material, base, f.world_position, f.normal,
                                         cam.eye, studio.lights, 2));
    };
    Target t(size);
    RasterStats stats;
    SHITSUKAN_TRY(draw_mesh(cam, t.band, sphere.view(), DrawOptions{}, shader, &stats));
    ctx.note(fmt("%ld of %ld triangles drawn (back faces culled), %ld pixels shaded.",
                 stats.triangles_drawn, stats.triangles_in, stats.fragments_shaded));
    return ctx.save_png(t.color.view());
}

SHITSUKAN_FIGURE(foundation_lit_cube, "foundation", "lit_cube",
                 "A cube, flat shading (each triangle lit with its plane normal)") {
    const int size = frame_size(ctx);
    TriangleMesh cube;
    SHITSUKAN_TRY(make_box({-1, -1, -1}, {1, 1, 1}, cube));
    Camera cam = perspective_camera({3.2f, 2.6f, 4.4f}, {0, 0, 0}, {0, 1, 0}, 38.0f, size, size);
    Studio studio;
    studio.record(ctx, "flat (flat_normal of the triangle; the same colour over a face)");
    ctx.chosen("cube", "edge 2, turned -0.35 rad about y", "three faces in view");
    ctx.chosen("frame", fmt("%d x %d, fov 38 deg", size, size), "the papers' 512 x 512");
    DrawOptions opt;
    opt.model = Mat4::rotate_y(-0.35f);
    MeshView mesh = cube.view();
    Vec3 base{0.85f, 0.6f, 0.25f};
    auto shader = [&](const Fragment& f) {
        Vec3 n = flat_normal(mesh, f.triangle, opt.model);
        return to_rgb8(shade_blinn_phong(studio.material, base, f.world_position, n, cam.eye,
                                         studio.lights, 2));
    };
    Target t(size);
    SHITSUKAN_TRY(draw_mesh(cam, t.band, mesh, opt, shader));
    return ctx.save_png(t.color.view());
}

SHITSUKAN_FIGURE(foundation_lit_torus, "foundation", "lit_torus",
                 "A torus, Gouraud shading (vertices lit once, colours interpolated)") {
    const int size = frame_size(ctx), major = 64, minor = 32;
    TriangleMesh torus;
    SHITSUKAN_TRY(make_torus(1.0f, 0.38f, major, minor, torus));
    Camera cam =
        perspective_camera({0.0f, 2.3f, 3.4f}, {0, -0.1f, 0}, {0, 1, 0}, 40.0f, size, size);
    Studio studio;
    studio.record(ctx, "Gouraud (apply_gouraud: Blinn-Phong per vertex)");
    ctx.chosen("torus", fmt("R 1, r 0.38, %d x %d segments, tilted 0.3 rad about x", major, minor),
               "coarse enough that Gouraud's interpolated highlight shows its facets");
    ctx.chosen("frame", fmt("%d x %d, fov 40 deg", size, size), "the papers' 512 x 512");
    DrawOptions opt;
    opt.model = Mat4::rotate_x(0.3f);
    SHITSUKAN_TRY(apply_gouraud(torus, opt.model, studio.material, {0.2f, 0.55f, 0.6f}, cam.eye,
                                studio.lights, 2));
    auto shader = [](const Fragment& f) { return to_rgb8(f.color); };
    Target t(size);
    SHITSUKAN_TRY(draw_mesh(cam, t.band, torus.view(), opt, shader));
    return ctx.save_png(t.color.view());
}
