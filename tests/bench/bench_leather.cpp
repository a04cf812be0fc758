// bench: the leather relief of tokai1994 §3.2 and the fig. 18 frame.
//
// 1. The 512 x 512 height + normal map of the fig. 7 pattern (fig. 13 section), per pixel,
//    against the polygon lookup alone (the label image the maps are built from): what the
//    relief itself (ray to the edge, Bezier inversion, eq. (4)) costs on top of knowing the
//    polygon.
// 3. The tileable belly pattern (tileable.hpp: the 3 x 3 block of tiles, then the middle one)
//    against the plain fig. 7 pattern: what seamless tiling costs.
// 2. The fig. 18 handbag frame (512 x 512, 7 patches at 32 x 32 quads + 2 knobs, bump-mapped
//    Blinn 1977, two point lights) against the same frame shaded without bump mapping.
#include <cmath>
#include <cstdint>
#include <vector>

#include "bench.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/geom/bezier_patch_mesh.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/products.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/scale_labels.hpp"
#include "shitsukan/leather/tileable.hpp"
#include "shitsukan/raster/blinn1977.hpp"
#include "shitsukan/raster/bump_mapping.hpp"
#include "shitsukan/raster/rasterizer.hpp"

using namespace shitsukan;

namespace {

struct Part {
    TriangleMesh mesh;
    std::vector<Vec3> dpdx, dpdy;
};

struct BagShader {
    const Camera* camera;
    const LeatherMaps* maps;  // nullptr: no bump mapping
    const Part* part;
    Blinn1977Material material;
    PointLight lights[2] = {{{-3.5f, 4.0f, 3.5f}, {1.05f, 1.0f, 0.95f}},
                            {{4.5f, 1.0f, 1.5f}, {0.30f, 0.33f, 0.40f}}};
    Rgb8 operator()(const Fragment& f) const {
        Vec3 n = f.front_facing ? f.normal : -f.normal;
        if (maps && part && f.front_facing) {
            TangentFrame t = orthonormal_tangent_frame(n, part->dpdx[std::size_t(f.triangle)],
                                                       part->dpdy[std::size_t(f.triangle)]);
            Vec2 q{f.uv.x - std::floor(f.uv.x), f.uv.y - std::floor(f.uv.y)};
            n = perturb_normal(t, normal_at(*maps, q));
        }
        Vec3 c = shade_blinn1977(material, f.world_position, n, camera->eye, lights, 2);
        return Rgb8{to_byte(c.x), to_byte(c.y), to_byte(c.z)};
    }
};

}  // namespace

SHITSUKAN_BENCH(leather_tileable_pattern) {
    bool ok = true;
    ScalePattern plain, torus;
    TileParams tp;
    const bench::Pair t = bench::in_turns(
        [&] {
            ok &= generate_tileable_pattern(tp, torus).ok();
            bench::sink(torus.polygon_count());
        },
        [&] {
            ok &= generate_scale_pattern(ScaleParams{}, plain).ok();
            bench::sink(plain.polygon_count());
        });
    if (!bench::timed_calls_ok(ok, "tileable pattern")) return;
    bench::report("tileable belly pattern (fig. 7 parameters, seamless along x and y)", t,
                  "plain fig. 7 pattern");
}

SHITSUKAN_BENCH(leather_maps) {
    ScalePattern pattern;
    if (!bench::set_up(generate_scale_pattern(ScaleParams{}, pattern), "leather maps")) return;
    const int size = 512;
    std::vector<std::int32_t> labels(std::size_t(size) * size);
    LeatherMaps maps;
    const BezierChain section = table1_section(Table1Section::convex);
    bool ok = true;
    if (!rasterize_scale_labels(pattern, size, size, labels.data()).ok()) ok = false;
    const bench::Pair t = bench::in_turns(
        [&] {
            ok &= make_leather_maps(pattern, labels.data(), size, size, section, ReliefOptions{},
                                    maps)
                      .ok();
            bench::sink(maps.max_height);
        },
        [&] {
            ok &= rasterize_scale_labels(pattern, size, size, labels.data()).ok();
            bench::sink(labels[12345]);
        });
    if (!bench::timed_calls_ok(ok, "leather maps")) return;
    bench::report(
        "leather height + normal map 512x512 (fig. 7 pattern, fig. 13 section), per "
        "pixel",
        bench::per(t, double(size) * size), "polygon lookup alone (label image)");

    // The fig. 18 frame.
    std::vector<std::int32_t> big(std::size_t(1536) * 1536);
    Status s = rasterize_scale_labels(pattern, 1536, 1536, big.data());
    if (s) s = make_leather_maps(pattern, big.data(), 1536, 1536, section, ReliefOptions{}, maps);
    Handbag bag = make_handbag();
    Part parts[3];
    PatchStripOptions opt;
    opt.segments_u = opt.segments_v = 32;
    opt.texture_scale = 0.8f;
    opt.anchor = 1.5f;  // left, front, right, back: the front's middle
    opt.texture_origin = {0.5f, 0.12f};
    const BezierPatch tube[4] = {bag.patches[3], bag.patches[0], bag.patches[1], bag.patches[2]};
    if (s) s = tessellate_patch_strip(tube, 4, opt, parts[0].mesh);
    opt.anchor = 0.0f;
    if (s) s = tessellate_patch_strip(bag.patches + 4, 1, opt, parts[1].mesh);
    if (s) s = tessellate_patch_strip(bag.patches + 5, 2, opt, parts[2].mesh);
    for (Part& p : parts) {
        const int n = p.mesh.triangle_count();
        p.dpdx.resize(std::size_t(n));
        p.dpdy.resize(std::size_t(n));
        if (s) s = mesh_texture_tangents(p.mesh.view(), p.dpdx.data(), p.dpdy.data(), n);
    }
    TriangleMesh knobs[2];
    for (int k = 0; k < 2; ++k)
        if (s) s = make_spherical_segment(bag.clasp[k], 32, 16, knobs[k]);
    if (!bench::set_up(s, "fig. 18 handbag frame")) return;
    Camera cam =
        perspective_camera({2.25f, 1.50f, 2.55f}, {0.04f, 0.64f, 0.0f}, {0, 1, 0}, 30.0f, 512, 512);
    RgbImage color(512, 512);
    FloatImage depth(512, 512);
    FrameBand band = full_frame_band(color.view(), depth.view());
    auto frame = [&](bool bump) {
        clear_band(band, Rgb8{206, 210, 214});
        DrawOptions d;
        d.cull = CullMode::none;
        for (const Part& p : parts) {
            BagShader shader{&cam, bump ? &maps : nullptr, &p, Blinn1977Material{}};
            ok &= draw_mesh(cam, band, p.mesh.view(), d, shader).ok();
        }
        for (const TriangleMesh& k : knobs) {
            BagShader shader{&cam, nullptr, nullptr, Blinn1977Material{}};
            ok &= draw_mesh(cam, band, k.view(), d, shader).ok();
        }
        bench::sink(color.at(256, 256).r);
    };
    const bench::Pair frames = bench::in_turns([&] { frame(true); }, [&] { frame(false); });
    if (!bench::timed_calls_ok(ok, "fig. 18 handbag frame")) return;
    bench::report("fig. 18 handbag frame 512x512, bump-mapped Blinn 1977, per frame", frames,
                  "same frame without bump mapping");
}
