// fuzz/fuzz_raster.cpp — draw_mesh (raster/rasterizer.hpp) with any camera (built by the
// checked builders or raw matrices), any band of any frame, any model matrix and any mesh
// (positions with NaN/inf/huge values, optional normals/uvs/colours, any indices).
// Contract: a non-ok Status, or a draw in which every fragment handed to the shader lies in
// the band and the frame, has depth in [0, 1], finite positions and, for a mesh whose
// normals are finite and not 0 and whose uvs and colours lie within +-1e30 (the bound
// rasterizer.hpp states), finite interpolants and normals of unit length;
// afterwards every depth is +inf or in [0, 1]; the pixels of the buffers' padding (stride
// beyond width, rows beyond the band) are untouched.
#include <cmath>
#include <cstdint>
#include <vector>

#include "fuzz_input.hpp"
#include "shitsukan/raster/rasterizer.hpp"

using namespace shitsukan;

namespace {

float value(fuzz::Input& in) {  // a plausible scene value half of the time, raw bits otherwise
    const std::uint8_t mode = in.take<std::uint8_t>();
    if (mode & 1) return in.take<float>();
    return float(in.take<std::int16_t>()) / float(1 << (mode >> 4));
}
Vec3 vec3(fuzz::Input& in) { return {value(in), value(in), value(in)}; }

struct Check {
    int y0, rows, frame_w, frame_h;
    bool attributes_finite;  // normals finite and not 0, uvs and colours within +-1e30
};

Rgb8 shader(const Fragment& f, void* user) {
    const Check& c = *static_cast<const Check*>(user);
    FUZZ_REQUIRE(f.x >= 0 && f.x < c.frame_w && f.y >= c.y0 && f.y < c.y0 + c.rows);
    FUZZ_REQUIRE(f.y < c.frame_h);
    FUZZ_REQUIRE(f.depth >= 0.0f && f.depth <= 1.0f);
    FUZZ_REQUIRE(fuzz::finite3(f.object_position) && fuzz::finite3(f.world_position));
    // Attributes are interpolated as given: NaN colours give NaN fragments (garbage in), so
    // their finiteness is only required of meshes whose attributes are finite.
    if (c.attributes_finite) {
        FUZZ_REQUIRE(fuzz::finite3(f.color));
        FUZZ_REQUIRE(std::isfinite(f.uv.x) && std::isfinite(f.uv.y));
        FUZZ_REQUIRE(fuzz::finite3(f.normal) && fuzz::finite3(f.object_normal));
        FUZZ_REQUIRE(std::fabs(length(f.normal) - 1.0f) < 1e-3f);
        FUZZ_REQUIRE(std::fabs(length(f.object_normal) - 1.0f) < 1e-3f);
    }
    return Rgb8{std::uint8_t(f.x), std::uint8_t(f.y), 7};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    const int w = 1 + in.take<std::uint8_t>() % 48, h = 1 + in.take<std::uint8_t>() % 48;
    Camera camera;
    const std::uint8_t cam_mode = in.take<std::uint8_t>() % 3;
    if (cam_mode == 2) {  // raw matrices: validate_camera must catch the bad ones
        for (auto& row : camera.view.m)
            for (float& x : row) x = value(in);
        for (auto& row : camera.projection.m)
            for (float& x : row) x = value(in);
        camera.eye = vec3(in);
        camera.orthographic = in.take<std::uint8_t>() & 1;
        camera.width = w;
        camera.height = h;
    } else {
        const Vec3 eye = vec3(in), target = vec3(in), up = vec3(in);
        const float a = value(in), near_plane = value(in), far_plane = value(in);
        Status s = cam_mode == 0 ? make_perspective_camera(eye, target, up, a, w, h, near_plane,
                                                           far_plane, camera)
                                 : make_orthographic_camera(eye, target, up, a, w, h,
                                                            near_plane, far_plane, camera);
        if (!s) return 0;
    }
    // A band of rows [y0, y0 + rows) of the frame, in buffers with padding around it.
    const int y0 = in.take<std::uint8_t>() % h;
    const int rows = 1 + in.take<std::uint8_t>() % (h - y0);
    const int stride = w + in.take<std::uint8_t>() % 4, pad_rows = 2;
    const Rgb8 fill{1, 2, 3};
    std::vector<Rgb8> color(std::size_t(stride * (rows + pad_rows)), fill);
    std::vector<float> depth(color.size(), -5.0f);
    RgbView cv{color.data(), w, rows, stride};
    FloatView dv{depth.data(), w, rows, stride};
    FrameBand band = make_band(cv, dv, y0, w, h);
    clear_band(band, Rgb8{0, 0, 0});
    DrawOptions opt;
    opt.cull = CullMode(in.take<std::uint8_t>() % 3);
    if (in.take<std::uint8_t>() & 1) {
        for (auto& row : opt.model.m)
            for (float& x : row) x = value(in);
        // Projective models are allowed; a corner sent to w ~ 0 (whose world position
        // overflows) rejects its triangle (finding_projective_model_nan_world, in the corpus).
    }
    const int nv = in.take<std::uint8_t>() % 12;
    std::vector<Vec3> positions, normals;
    std::vector<Vec2> uvs;
    std::vector<Vec3> colors;
    const std::uint8_t has = in.take<std::uint8_t>();
    for (int i = 0; i < nv; ++i) {
        positions.push_back(vec3(in));
        if (has & 1) normals.push_back(vec3(in));
        if (has & 2) uvs.push_back({value(in), value(in)});
        if (has & 4) colors.push_back(vec3(in));
    }
    std::vector<std::uint32_t> indices;
    while (in.left() >= 3 && indices.size() < 3 * 32)
        for (int c = 0; c < 3; ++c) {
            const std::uint8_t x = in.take<std::uint8_t>();
            indices.push_back(x == 255 ? 0xffffffffu : std::uint32_t(x % (nv + 1)));
        }
    MeshView mesh;
    mesh.positions = positions.empty() ? nullptr : positions.data();
    mesh.normals = normals.empty() ? nullptr : normals.data();
    mesh.uvs = uvs.empty() ? nullptr : uvs.data();
    mesh.colors = colors.empty() ? nullptr : colors.data();
    mesh.vertex_count = nv;
    mesh.indices = indices.empty() ? nullptr : indices.data();
    mesh.triangle_count = int(indices.size() / 3);
    // draw_mesh's promise (rasterizer.hpp): finite interpolants for uvs and colours within
    // +-1e30 (finding_raster_colour_overflow: colours of +-3e38 overflow q - p).
    auto bounded = [](float v) { return std::fabs(v) <= 1e30f; };
    bool attributes_finite = true;
    for (const Vec3& n : normals) attributes_finite = attributes_finite && fuzz::finite3(n) && length(n) > 1e-3f;
    for (const Vec2& t : uvs) attributes_finite = attributes_finite && bounded(t.x) && bounded(t.y);
    for (const Vec3& c : colors)
        attributes_finite = attributes_finite && bounded(c.x) && bounded(c.y) && bounded(c.z);
    Check check{y0, rows, w, h, attributes_finite};
    RasterStats stats;
    Status s = draw_mesh(camera, band, mesh, opt, shader, &check, &stats);
    for (int y = 0; y < rows + pad_rows; ++y)
        for (int x = 0; x < stride; ++x) {
            const std::size_t i = std::size_t(y * stride + x);
            if (x < w && y < rows) {
                FUZZ_REQUIRE(depth[i] == INFINITY || (depth[i] >= 0.0f && depth[i] <= 1.0f));
            } else {
                FUZZ_REQUIRE(depth[i] == -5.0f);
                FUZZ_REQUIRE(color[i].r == fill.r && color[i].g == fill.g && color[i].b == fill.b);
            }
        }
    if (s) FUZZ_REQUIRE(stats.triangles_in == mesh.triangle_count);
    return 0;
}
