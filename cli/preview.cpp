// cli/preview.cpp — see preview.hpp.
#include "preview.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/normal_map.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"

namespace shitsukan::cli {
namespace {

float srgb_to_linear(float c) { return std::pow(c / 255.0f, 2.2f); }
std::uint8_t linear_to_srgb(float c) {
    return std::uint8_t(std::lround(255.0f * std::pow(std::min(1.0f, std::max(0.0f, c)),
                                                      1.0f / 2.2f)));
}

// The maps in float, ready for bilinear lookups.
struct Maps {
    int w = 0, h = 0;
    std::vector<Vec3> albedo, normal;  // linear albedo; tangent-space normal (OpenGL)
    std::vector<float> rough, ao;
    template <class T> T bilinear(const std::vector<T>& m, Vec2 uv) const {
        const float x = uv.x * float(w) - 0.5f, y = (1.0f - uv.y) * float(h) - 0.5f;  // v up
        const float fx = std::floor(x), fy = std::floor(y);
        const float tx = x - fx, ty = y - fy;
        auto at = [&](int i, int j) {
            i = ((i % w) + w) % w, j = ((j % h) + h) % h;
            return m[std::size_t(j) * std::size_t(w) + std::size_t(i)];
        };
        const int i = int(fx), j = int(fy);
        return (at(i, j) * (1 - tx) + at(i + 1, j) * tx) * (1 - ty) +
               (at(i, j + 1) * (1 - tx) + at(i + 1, j + 1) * tx) * ty;
    }
};

Status prepare(const MapSetInput& in, const MapSetOptions& options, Maps& m) {
    std::vector<float> h01;
    SHITSUKAN_TRY(normalise_heights(in.height, in.width, in.height_rows, h01));
    m.w = in.width, m.h = in.height_rows;
    HeightNormalOptions n;
    n.strength = options.strength;
    n.wrap = options.wrap;
    m.normal.resize(h01.size());
    SHITSUKAN_TRY(height_map_normals(h01.data(), m.w, m.h, n, m.normal.data()));
    SHITSUKAN_TRY(derive_ambient_occlusion(h01, m.w, m.h, options, m.ao));
    derive_roughness(h01, m.ao, options, m.rough);
    m.albedo.resize(h01.size());
    for (std::size_t i = 0; i < h01.size(); ++i) {
        const Rgb8 c = in.albedo ? in.albedo[i] : Rgb8{180, 180, 180};
        m.albedo[i] = Vec3{srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)};
    }
    return Status::success();
}

struct Scene {
    const Maps* maps;
    Vec3 eye, light;
    Vec2 repeat;       // texture repeats across the object's uv
    bool sphere;       // tangent frame from the sphere's normal, else the plane's
    Vec3 plane_t, plane_b;
};

Rgb8 shade(const Fragment& f, const Scene& s) {
    const Vec2 uv{f.uv.x * s.repeat.x, f.uv.y * s.repeat.y};
    Vec3 n = normalize(f.normal), t = s.plane_t, b = s.plane_b;
    if (s.sphere) {  // u around +y (phi), v from the north pole down (theta): image up = v up
        t = normalize(Vec3{n.z, 0.0f, -n.x} + Vec3{1e-6f, 0.0f, 0.0f});
        b = normalize(cross(n, t));
    }
    const Vec3 tn = s.maps->bilinear(s.maps->normal, uv);
    const Vec3 nn = normalize(t * tn.x + b * tn.y + n * tn.z);
    const Vec3 v = normalize(s.eye - f.world_position), hv = normalize(s.light + v);
    const float r = std::max(0.05f, s.maps->bilinear(s.maps->rough, uv));
    const float exponent = 2.0f / (r * r * r * r) - 2.0f;
    const float diffuse = std::max(0.0f, dot(nn, s.light));
    const float spec = diffuse > 0.0f ? 0.04f * (exponent + 8.0f) / 25.1f *
                                            std::pow(std::max(0.0f, dot(nn, hv)), exponent)
                                      : 0.0f;
    const Vec3 a = s.maps->bilinear(s.maps->albedo, uv);
    const float ambient = 0.18f * s.maps->bilinear(s.maps->ao, uv);
    const Vec3 c = a * (0.95f * diffuse + ambient) + Vec3{spec, spec, spec};
    return Rgb8{linear_to_srgb(c.x), linear_to_srgb(c.y), linear_to_srgb(c.z)};
}

// A square of side 2 tilted back by `tilt` about x, centred at `centre`.
void make_plane(Vec3 centre, float tilt, TriangleMesh& mesh, Vec3* t, Vec3* b) {
    *t = Vec3{1, 0, 0};
    *b = Vec3{0, std::cos(tilt), -std::sin(tilt)};
    const Vec3 n = cross(*t, *b);
    const int steps = 16;
    for (int j = 0; j <= steps; ++j)
        for (int i = 0; i <= steps; ++i) {
            const float u = float(i) / steps, v = float(j) / steps;
            mesh.add_vertex(centre + *t * (2.0f * u - 1.0f) + *b * (2.0f * v - 1.0f), n, Vec2{u, v});
        }
    for (int j = 0; j < steps; ++j)
        for (int i = 0; i < steps; ++i) {
            const std::uint32_t a = std::uint32_t(j * (steps + 1) + i), c = a + steps + 1;
            mesh.add_triangle(a, a + 1, c + 1);
            mesh.add_triangle(a, c + 1, c);
        }
}

}  // namespace

Status write_map_preview(const char* path, const MapSetInput& input, const MapSetOptions& options) {
    Maps maps;
    SHITSUKAN_TRY(prepare(input, options, maps));
    const int W = 1024, H = 512;
    RgbImage color(W, H);
    FloatImage depth(W, H);
    const FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{46, 48, 52});
    const Vec3 eye{0.0f, 0.6f, 5.2f};
    const Camera camera = perspective_camera(eye, {0, 0, 0}, {0, 1, 0}, 30.0f, W, H);
    // A tileable set repeats: twice around the sphere, 2 x 2 on the plane (a seam would show);
    // any other set once (its borders are not meant to meet).
    const float repeat = options.wrap ? 2.0f : 1.0f;
    Scene scene{&maps, eye, normalize(Vec3{-0.5f, 0.6f, 0.65f}), Vec2{repeat, 1}, true, {}, {}};
    TriangleMesh sphere, plane;
    SHITSUKAN_TRY(make_uv_sphere(1.0f, 96, 48, sphere));
    for (Vec3& p : sphere.positions) p = p + Vec3{-1.2f, 0.0f, 0.0f};
    auto shader = [&](const Fragment& f) { return shade(f, scene); };
    DrawOptions draw;
    SHITSUKAN_TRY(draw_mesh(camera, band, sphere.view(), draw, shader));
    make_plane(Vec3{1.2f, 0.0f, 0.0f}, 0.5f, plane, &scene.plane_t, &scene.plane_b);
    scene.sphere = false;
    scene.repeat = Vec2{repeat, repeat};
    SHITSUKAN_TRY(draw_mesh(camera, band, plane.view(), draw, shader));
    return write_png(path, color.view());
}

}  // namespace shitsukan::cli
