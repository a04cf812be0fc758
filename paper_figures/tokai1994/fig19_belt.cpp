// tokai1994 fig. 19: a snake-leather belt (the fig. 3(b) pattern with the fig. 13(a) section)
// and the leather texture used.
// Example: examples/52_bump_mapped_patch.cpp.
#include <algorithm>
#include <chrono>

#include "driver/figure.hpp"
#include "shitsukan/geom/bezier_patch_mesh.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/leather/products.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "tokai1994/fig11_19_common.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

SHITSUKAN_FIGURE(
    tokai1994_fig19, "tokai1994", "fig19",
    "Snake-leather belt (fig. 3(b) pattern, fig. 13(a) section) and the texture used") {
    tokai_relief::record_shading(ctx);
    tokai_relief::record_relief(ctx);
    ctx.given("leather", "fig. 3(b) pattern (triangle lattice) + fig. 13(a) section",
              "tokai1994 §5");
    const BeltDesign design;
    ctx.chosen(
        "belt",
        fmt("width %.2f, coiled on its edge from r = %.2f to %.2f over %.2f turns, "
            "one bicubic patch per quarter turn",
            double(design.width), double(design.r0), double(design.r1), double(design.turns)),
        "the paper shows a belt but prints no shape");
    const int size = ctx.quick() ? 128 : 512;
    const float texels_per_unit = ctx.quick() ? 120.0f : 420.0f;

    // The belt's strip, texture = arc length (one texture unit per world unit).
    std::vector<BezierPatch> patches;
    SHITSUKAN_TRY(make_belt(design, patches));
    tokai_relief::BumpSurface belt;
    PatchStripOptions opt;
    opt.segments_u = 24;
    opt.segments_v = 4;
    SHITSUKAN_TRY(tessellate_patch_strip(patches.data(), int(patches.size()), opt, belt.mesh));
    SHITSUKAN_TRY(tokai_relief::compute_texture_tangents(&belt));
    float length = 0.0f, width = 0.0f;
    for (Vec2 t : belt.mesh.uvs) {
        length = std::max(length, t.x);
        width = std::max(width, t.y);
    }
    // The snake pattern covers exactly the belt's texture rectangle: no repetition.
    ScalePattern pattern;
    SHITSUKAN_TRY(tokai_relief::snake_pattern(ctx, length, width, &pattern));
    LeatherMaps maps;
    int mw = int(length * texels_per_unit), mh = int(width * texels_per_unit);
    SHITSUKAN_TRY(tokai_relief::leather_maps(pattern, mw, mh, table1_section(Table1Section::convex),
                                             ReliefOptions{}, &maps));
    ctx.chosen("texture",
               fmt("%.2f x %.2f pattern units = the belt's arc length x width; maps "
                   "%d x %d",
                   double(length), double(width), mw, mh),
               "one texture unit per world unit along the belt (§4 arc length)");

    Blinn1977Material snake = tokai_relief::leather_material();
    snake.color = {0.30f, 0.22f, 0.12f};  // a darker, greyer snake leather (chosen here)
    RgbImage img(2 * size, size, Rgb8{255, 255, 255});
    // Left: the belt.
    {
        RgbView left = img.view().subview(0, 0, size, size);
        Camera cam = perspective_camera({0.5f, 2.0f, 3.0f}, {0.0f, 0.1f, 0.05f}, {0, 1, 0}, 42.0f,
                                        size, size);
        FloatImage depth(size, size);
        FrameBand band = full_frame_band(left, depth.view());
        clear_band(band, tokai_relief::background_color());
        tokai_relief::LeatherShader shader;
        shader.camera = &cam;
        shader.maps = &maps;
        shader.surface = &belt;
        shader.front = snake;
        shader.back = tokai_relief::suede_material();
        tokai_relief::scene_lights(shader.lights);
        DrawOptions draw;
        draw.cull = CullMode::none;  // the inside of the coil shows the belt's suede back
        auto t0 = std::chrono::steady_clock::now();
        SHITSUKAN_TRY(draw_mesh(cam, band, belt.mesh.view(), draw, shader));
        double frame = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ctx.note(
            fmt("Belt frame time %.3f s; %d scales on the belt.", frame, pattern.polygon_count()));
    }
    // Right: the texture used, two consecutive pieces of the belt's texture seen flat.
    {
        const float piece = 2.0f * width;
        for (int k = 0; k < 2; ++k) {
            RgbView panel = img.view().subview(size, k * size / 2, size, size / 2);
            tokai_relief::shade_flat_texture(maps, {float(k) * piece, 0.0f},
                                             {float(k + 1) * piece, width}, panel, snake);
        }
        RasterCanvas canvas(img.view());
        Canvas& cv = canvas;
        cv.line({float(size), float(size / 2)}, {float(2 * size), float(size / 2)},
                Rgb8{255, 255, 255}, 2.0f);
        cv.text({float(size) + 6, 6}, fmt("texture used: belt x = 0 .. %.2f", double(piece)),
                Rgb8{255, 255, 255}, 1);
        cv.text({float(size) + 6, float(size / 2) + 6},
                fmt("x = %.2f .. %.2f", double(piece), double(2 * piece)), Rgb8{255, 255, 255}, 1);
    }
    return ctx.save_png(img.view());
}
