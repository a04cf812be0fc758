// ports/web/api/api_fujimoto2000_terrain.cpp — the C API of the fujimoto2000 terrain panel
// (§5, fig. 21): the figure's control mesh (paper_figures/fujimoto2000/terrain_mesh.cpp), an
// IST-B-spline surface on the fully-connected IST N = 3, sampled hierarchically with §5's
// Gaussian jitter on the sample values (sample_hierarchy: jitter and its seed), tessellated
// (tessellate_wr_surface) and drawn by the library's rasterizer (draw_mesh) from the figure's
// camera and light, turned by yaw and pitch. State: the last tessellation (only the view
// changes while the mouse turns it).
#include <cmath>
#include <cstdio>
#include <string>

#include "api_common.hpp"
#include "fujimoto2000/terrain_mesh.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/ist.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"

using namespace shitsukan;
using namespace shitsukan::fujimoto2000;

namespace {

struct TerrainScene {
    WrControlMesh mesh;
    WrSurface surface;
    WrIstAxis u, v;
};
TerrainScene g_scene;  // the WR surface points into its own axes: built in place, never moved
float g_scene_delta = -1.0f;
WrMesh g_mesh;
struct TerrainKey {
    int form = -1, K = -1;
    float delta = -1, jitter_height = -1, jitter_color = -1;
    unsigned seed = 0;
    bool operator==(const TerrainKey& o) const {
        return form == o.form && K == o.K && delta == o.delta && jitter_height == o.jitter_height &&
               jitter_color == o.jitter_color && seed == o.seed;
    }
};
TerrainKey g_key;  // of g_mesh (form -1: none)

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

// The surface of fig. 21: B-spline of degree 3 on the figure's mesh, fully-connected IST N = 3
// with translation ends on both parameters (as the figure's make_axes).
Status make_terrain(float delta) {
    g_scene_delta = -1.0f;
    g_scene.mesh = terrain_control_mesh(delta);
    Status s = make_wr_surface(g_scene.mesh, SurfaceBasis::bspline, 3, g_scene.surface);
    IstAxis iu, iv;
    if (s) s = ist_fully_connected_axis(3, 1, g_scene.surface.spans_u(), IstEnds::translation, iu);
    if (s) s = ist_fully_connected_axis(3, 1, g_scene.surface.spans_v(), IstEnds::translation, iv);
    if (s) s = make_wr_ist_axis(iu, kMaxWrLevel, g_scene.u);
    if (s) s = make_wr_ist_axis(iv, kMaxWrLevel, g_scene.v);
    if (s) s = g_scene.surface.set_axes(g_scene.u.axis(), g_scene.v.axis());
    if (s) g_scene_delta = delta;
    return s;
}

// The tessellation for a key: form 0 the conventional surface (fig. 21c), 1 the WR surface of
// eq. (15) (21d), 2 superposed (eq. 20) with linear sampling and the jitter (21e-g), as the
// figure samples. Chosen here: grid level K with 9, 3, 1 vertices per sample interval at
// K = 1, 2, >= 3 (the figure's adaptive level needs the driver; the browser's K is the user's).
Status tessellate(const TerrainKey& k) {
    if (g_scene_delta != k.delta) SHITSUKAN_TRY(make_terrain(k.delta));
    WrTessellationOptions o;
    o.progress = skweb::progress();
    o.levels = k.K;
    o.grid_level = k.K;
    o.subdivisions = k.K >= 3 ? 1 : (k.K == 2 ? 3 : 9);
    HierarchicalSampling hs;
    if (k.form == 0) {
        o.form = WrSurfaceForm::plain;
    } else if (k.form == 1) {
        o.form = WrSurfaceForm::wr;
    } else {
        HierarchicalOptions ho;
        ho.levels = k.K;
        ho.interpolation = SampleInterpolation::linear;
        ho.jitter_height = k.jitter_height;
        ho.jitter_color = k.jitter_color;
        ho.seed = k.seed;
        SHITSUKAN_TRY(sample_hierarchy(g_scene.surface, ho, hs));
        o.form = WrSurfaceForm::superposed;
    }
    g_key = TerrainKey{};
    SHITSUKAN_TRY(tessellate_wr_surface(g_scene.surface, k.form == 2 ? &hs : nullptr, o, g_mesh));
    g_key = k;
    return Status::success();
}

}  // namespace

// Fig. 21's terrain: form 0 conventional, 1 WR (spiky), 2 superposed with delta (eq. 19) in the
// mountains, K levels (1..4), §5's jitter (height x(1 + jitter_height g), colour + jitter_color
// g; g Gaussian from the library's hash of seed), drawn size x size from the figure's camera,
// the model turned by yaw (about the vertical) and pitch. Text: vertices, triangles, grid,
// deepest step used, milliseconds (live, never hashed).
SK_API int sk_fujimoto2000_terrain(int form, float delta, int K, float jitter_height, float jitter_color,
                                   unsigned seed, float yaw, float pitch, int size) {
    Status s = Status::success();
    if (form < 0 || form > 2)
        s = Status::error(StatusCode::invalid_argument, "form must be 0 (conventional), 1 (WR) or 2 (superposed) (got %d)", form);
    if (s && (size < 64 || size > 1024))
        s = Status::error(StatusCode::invalid_argument, "size must be in 64..1024 px (got %d)", size);
    if (s && (K < 1 || K > 4))  // chosen here: K = 4 is 568^2 vertices, about a second in WASM
        s = Status::error(StatusCode::out_of_range, "K must be in 1..4 in the browser (got %d)", K);
    if (s && !(delta > 0.0f && delta < 1.0f))
        s = Status::error(StatusCode::out_of_range, "delta must be in (0, 1) (eq. 19) (got %g)", double(delta));
    if (!s) return skweb::finish(s);
    const double t0 = skweb::now_ms();
    TerrainKey key;
    key.form = form, key.K = K, key.delta = delta, key.seed = seed;
    key.jitter_height = form == 2 ? jitter_height : 0.0f;
    key.jitter_color = form == 2 ? jitter_color : 0.0f;
    if (!(key == g_key)) {
        s = tessellate(key);
        if (!s) return skweb::finish(s);
    }
    const double t1 = skweb::now_ms();
    Camera cam;
    s = make_perspective_camera(kTerrainEye, kTerrainTarget, Vec3{0, 1, 0}, kTerrainFovDegrees, size, size, 0.05f,
                                200.0f, cam);
    if (!s) return skweb::finish(s);
    RgbImage img(size, size);
    FloatImage depth(size, size);
    FrameBand band = full_frame_band(img.view(), depth.view());
    clear_band(band, Rgb8{196, 216, 236});  // the figure's sky
    const Vec3 light = normalize(kTerrainLight);
    const float ambient = 0.32f;  // the figure's shading (fig21_terrain.cpp)
    auto shader = [&](const Fragment& f) {
        const float lambert = std::fabs(dot(f.normal, light));  // two-sided: spikes flip
        return to_rgb8(f.color * (ambient + (1.0f - ambient) * lambert));
    };
    DrawOptions opt;
    opt.cull = CullMode::none;
    opt.model = Mat4::rotate_x(pitch) * Mat4::rotate_y(yaw);
    s = draw_mesh(cam, band, g_mesh.mesh.view(), opt, shader);
    if (!s) return skweb::finish(s);
    skweb::set_picture(img);
    skweb::text() = "{\"vertices\":" + std::to_string(g_mesh.mesh.positions.size()) +
                    ",\"triangles\":" + std::to_string(g_mesh.mesh.triangle_count()) + ",\"grid\":[" +
                    std::to_string(g_mesh.grid_u) + "," + std::to_string(g_mesh.grid_v) + "]" +
                    ",\"levels_used\":" + std::to_string(g_mesh.max_levels_used) +
                    ",\"tessellate_ms\":" + number(t1 - t0) + ",\"draw_ms\":" + number(skweb::now_ms() - t1) + "}";
    return skweb::finish(Status::success());
}
