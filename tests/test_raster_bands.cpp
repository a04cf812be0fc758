// Tests for lib/shitsukan/raster/rasterizer.cpp: band rendering. Rendering a frame band by
// band (any band height) and stacking the bands gives the full frame bit for bit, colour and
// depth; so does binning the meshes once (bin_mesh) and drawing each band with
// draw_binned_mesh, which hands a band only the triangles whose rows meet it.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include "raster_test_scenes.hpp"

using namespace shitsukan;
using namespace raster_test;

namespace {

struct Scene {
    TriangleMesh sphere = sphere_mesh(0.8f, 24, 12);
    TriangleMesh box = box_mesh({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f});
    TriangleMesh floor;
    Camera cam = perspective_camera({0.4f, 0.9f, 3.2f}, {0, 0, 0}, {0, 1, 0}, 50.0f, 101, 77);
    Scene() {
        // A floor reaching behind the eye: exercises near-plane clipping in every band.
        floor.add_vertex({-6, -0.8f, 6}, {0, 1, 0}, {0, 0});
        floor.add_vertex({6, -0.8f, 6}, {0, 1, 0}, {1, 0});
        floor.add_vertex({0, -0.8f, -8}, {0, 1, 0}, {0.5f, 1});
        floor.add_triangle(0, 1, 2);
    }
};

// FNV-1a (64 bits) of the bytes of v, folded into *h.
constexpr std::uint64_t kFnvBasis = 14695981039346656037ull;
template <class T>
void fnv1a(std::uint64_t* h, const T& v) {
    unsigned char bytes[sizeof v];
    std::memcpy(bytes, &v, sizeof v);
    for (unsigned char b : bytes) *h = (*h ^ b) * 1099511628211ull;
}

// The bits of every field of a fragment, hashed (field by field: no padding bytes).
std::uint64_t fragment_hash(const Fragment& f) {
    std::uint64_t h = kFnvBasis;
    for (const Vec3& v : {f.object_position, f.world_position, f.normal, f.object_normal, f.color}) {
        fnv1a(&h, v.x);
        fnv1a(&h, v.y);
        fnv1a(&h, v.z);
    }
    fnv1a(&h, f.uv.x);
    fnv1a(&h, f.uv.y);
    fnv1a(&h, f.x);
    fnv1a(&h, f.y);
    fnv1a(&h, f.depth);
    fnv1a(&h, f.triangle);
    fnv1a(&h, f.front_facing);
    return h;
}

// The tests' shader: the colour is the fragment's hash, so a difference in any field of the
// last fragment of a pixel shows in the pixel; with a user pointer (a std::uint64_t) every
// fragment's hash is folded into it in the order the fragments come, so a difference in any
// fragment shaded (hidden later or not) shows there.
Rgb8 shade(const Fragment& f, void* user) {
    const std::uint64_t h = fragment_hash(f);
    if (user != nullptr) fnv1a(static_cast<std::uint64_t*>(user), h);
    return Rgb8{std::uint8_t(h), std::uint8_t(h >> 8), std::uint8_t(h >> 16)};
}

// The scene's three draws; with `bins` (three arrays, one per mesh, from bin_scene) each goes
// through draw_binned_mesh.
DrawOptions scene_options(int mesh, CullMode cull) {
    DrawOptions opt;
    opt.cull = cull;
    if (mesh == 0) opt.model = Mat4::translate({-0.6f, 0, 0}) * Mat4::rotate_y(0.4f);
    if (mesh == 1)
        opt.model = Mat4::translate({0.7f, 0, -0.3f}) * Mat4::rotate_x(0.3f) * Mat4::rotate_y(-0.6f);
    return opt;
}
const TriangleMesh& scene_mesh(const Scene& s, int mesh) {
    return mesh == 0 ? s.sphere : (mesh == 1 ? s.box : s.floor);
}
RasterStats draw_scene(const Scene& s, const FrameBand& band, CullMode cull = CullMode::back,
                       const std::vector<TriangleRows>* bins = nullptr) {
    RasterStats stats;
    clear_band(band, Rgb8{10, 20, 30});
    for (int m = 0; m < 3; ++m) {
        const MeshView mesh = scene_mesh(s, m).view();
        const DrawOptions opt = scene_options(m, cull);
        if (bins != nullptr)
            CHECK(draw_binned_mesh(s.cam, band, mesh, opt, bins[m].data(), int(bins[m].size()),
                                   shade, nullptr, &stats)
                      .ok());
        else
            CHECK(draw_mesh(s.cam, band, mesh, opt, shade, nullptr, &stats).ok());
    }
    return stats;
}
void bin_scene(const Scene& s, CullMode cull, std::vector<TriangleRows> bins[3]) {
    for (int m = 0; m < 3; ++m) {
        const MeshView mesh = scene_mesh(s, m).view();
        bins[m].assign(std::size_t(mesh.triangle_count), TriangleRows{});
        REQUIRE(bin_mesh(s.cam, mesh, scene_options(m, cull), bins[m].data(), int(bins[m].size())).ok());
    }
}

}  // namespace

TEST_CASE("bands == full frame, bit for bit (band heights 16, 7 and 1)") {
    Scene scene;
    const int W = scene.cam.width, H = scene.cam.height;
    RgbImage full(W, H);
    FloatImage full_depth(W, H);
    RasterStats full_stats = draw_scene(scene, full_frame_band(full.view(), full_depth.view()));
    CHECK(full_stats.triangles_clipped >= 1);
    CHECK(full_stats.fragments_shaded > W * H / 3);

    for (int band_height : {16, 7, 1}) {
        RgbImage stacked(W, H);
        FloatImage stacked_depth(W, H);
        RgbImage band_color(W, band_height);  // the only frame memory a band render needs
        FloatImage band_depth(W, band_height);
        long fragments = 0;
        for (int y0 = 0; y0 < H; y0 += band_height) {
            int h = std::min(band_height, H - y0);
            FrameBand band = make_band(band_color.view().subview(0, 0, W, h),
                                       band_depth.view().subview(0, 0, W, h), y0, W, H);
            fragments += draw_scene(scene, band).fragments_shaded;
            for (int y = 0; y < h; ++y) {
                std::memcpy(stacked.view().row(y0 + y), band.color.row(y), sizeof(Rgb8) * W);
                std::memcpy(stacked_depth.view().row(y0 + y), band.depth.row(y), sizeof(float) * W);
            }
        }
        INFO("band height " << band_height);
        CHECK(std::memcmp(stacked.data(), full.data(), sizeof(Rgb8) * W * H) == 0);
        CHECK(std::memcmp(stacked_depth.data(), full_depth.data(), sizeof(float) * W * H) == 0);
        CHECK(fragments == full_stats.fragments_shaded);
    }
}

TEST_CASE("binned bands == full frame, bit for bit, and a band is handed only its triangles") {
    Scene scene;
    const int W = scene.cam.width, H = scene.cam.height;
    for (CullMode cull : {CullMode::back, CullMode::none, CullMode::front}) {
        RgbImage full(W, H);
        FloatImage full_depth(W, H);
        const RasterStats full_stats =
            draw_scene(scene, full_frame_band(full.view(), full_depth.view()), cull);
        std::vector<TriangleRows> bins[3];
        bin_scene(scene, cull, bins);
        // The floor reaches behind the eye: clipped, it keeps every row.
        CHECK(bins[2][0].begin == 0);
        CHECK(bins[2][0].end == H);
        for (int band_height : {16, 7, 1}) {
            RgbImage band_color(W, band_height);
            FloatImage band_depth(W, band_height);
            long fragments = 0, handed = 0, unbinned_handed = 0;
            bool same = true;
            for (int y0 = 0; y0 < H; y0 += band_height) {
                const int h = std::min(band_height, H - y0);
                const FrameBand band = make_band(band_color.view().subview(0, 0, W, h),
                                                 band_depth.view().subview(0, 0, W, h), y0, W, H);
                const RasterStats st = draw_scene(scene, band, cull, bins);
                fragments += st.fragments_shaded;
                handed += st.triangles_in;
                unbinned_handed += full_stats.triangles_in;
                for (int y = 0; y < h; ++y)
                    same = same &&
                           std::memcmp(band.color.row(y), full.view().row(y0 + y), sizeof(Rgb8) * W) == 0 &&
                           std::memcmp(band.depth.row(y), full_depth.view().row(y0 + y), sizeof(float) * W) == 0;
            }
            INFO("cull " << int(cull) << ", band height " << band_height);
            CHECK(same);
            CHECK(fragments == full_stats.fragments_shaded);
            CHECK(handed * 2 < unbinned_handed);  // most triangles miss most bands
        }
    }
}

TEST_CASE("bin_mesh and draw_binned_mesh refuse too few rows") {
    Scene scene;
    const MeshView box = scene.box.view();
    std::vector<TriangleRows> rows(std::size_t(box.triangle_count - 1));
    const Status s = bin_mesh(scene.cam, box, DrawOptions{}, rows.data(), int(rows.size()));
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("room for 11 triangles' rows, the mesh has 12") != std::string::npos);
    RgbImage color(scene.cam.width, scene.cam.height);
    FloatImage depth(scene.cam.width, scene.cam.height);
    const Status d = draw_binned_mesh(scene.cam, full_frame_band(color.view(), depth.view()), box,
                                      DrawOptions{}, nullptr, 0, shade, nullptr);
    CHECK(d.code() == StatusCode::invalid_argument);
}

namespace {

// Small triangles, slivers (thin to exactly collinear), triangles off every side of the view,
// across the near plane, either winding (back-facing half), some vertices with a zero normal;
// from a fixed linear congruential sequence.
TriangleMesh edge_case_mesh() {
    TriangleMesh m;
    std::uint32_t state = 12345u;
    auto next = [&state](float lo, float hi) {
        state = state * 1664525u + 1013904223u;
        return lo + (hi - lo) * float(state >> 8) / 16777216.0f;
    };
    for (int i = 0; i < 400; ++i) {
        const Vec3 p{next(-2.5f, 2.5f), next(-2.0f, 2.0f), next(-1.5f, 3.5f)};  // z 3.5: behind
        const Vec3 e{next(-0.4f, 0.4f), next(-0.4f, 0.4f), next(-0.2f, 0.2f)};
        Vec3 q = p + Vec3{next(-0.4f, 0.4f), next(-0.4f, 0.4f), next(-0.2f, 0.2f)};
        const int kind = i % 4;
        if (kind == 1) q = p + e * 2.0f + Vec3{0.0f, next(-1e-6f, 1e-6f), 0.0f};  // sliver
        if (kind == 2) q = p + e * 2.0f;  // collinear in floats or nearly: both kinds occur
        const Vec3 n = kind == 3 ? Vec3{0, 0, 0} : Vec3{0, 0, 1};
        const std::uint32_t a = m.add_vertex(p, n, {next(0, 1), next(0, 1)});
        const std::uint32_t b = m.add_vertex(p + e, Vec3{0, 1, 0}, {next(0, 1), next(0, 1)});
        const std::uint32_t c = m.add_vertex(q, Vec3{1, 0, 0}, {next(0, 1), next(0, 1)});
        for (int k = 0; k < 3; ++k) m.colors.push_back({next(0, 1), next(0, 1), next(0, 1)});
        if (i % 2 == 0) m.add_triangle(a, b, c);
        else m.add_triangle(a, c, b);
    }
    // Floors and a wall reaching behind the eye: clipped at the near plane.
    for (float y : {-0.8f, -0.3f}) {
        const std::uint32_t a = m.add_vertex({-6, y, 6}, {0, 1, 0}, {0, 0});
        const std::uint32_t b = m.add_vertex({6, y, 6}, {0, 1, 0}, {1, 0});
        const std::uint32_t c = m.add_vertex({0, y, -8}, {0, 1, 0}, {0.5f, 1});
        m.add_triangle(a, b, c);
    }
    const std::uint32_t a = m.add_vertex({0.9f, -3, 6}, {-1, 0, 0}, {0, 0});
    const std::uint32_t b = m.add_vertex({0.9f, 0, -6}, {-1, 0, 0}, {1, 0});
    const std::uint32_t c = m.add_vertex({0.9f, 3, 6}, {-1, 0, 0}, {0, 1});
    m.add_triangle(a, b, c);
    while (m.colors.size() < m.positions.size()) m.colors.push_back({0.2f, 0.7f, 0.4f});
    return m;
}

// One band drawn three ways (draw_mesh; draw_binned_mesh; draw_binned_mesh with the kept
// vertices) into buffers of its own, with the statistics and the fold of the fragments' hashes
// of each.
struct BandDraw {
    std::vector<Rgb8> color;
    std::vector<float> depth;
    RasterStats stats;
    std::uint64_t fragments = kFnvBasis;
};
void draw_band_way(int way, const Camera& cam, const MeshView& view, const DrawOptions& opt,
                   const std::vector<TriangleRows>& rows, const std::vector<BinnedVertex>& kept,
                   int y0, int h, BandDraw* d) {
    const int W = cam.width;
    d->color.assign(std::size_t(W * h), Rgb8{});
    d->depth.assign(std::size_t(W * h), 0.0f);
    const FrameBand band = make_band(RgbView{d->color.data(), W, h, W},
                                     FloatView{d->depth.data(), W, h, W}, y0, W, cam.height);
    clear_band(band, Rgb8{10, 20, 30});
    Status s;
    if (way == 0) s = draw_mesh(cam, band, view, opt, shade, &d->fragments, &d->stats);
    if (way == 1)
        s = draw_binned_mesh(cam, band, view, opt, rows.data(), int(rows.size()), shade,
                             &d->fragments, &d->stats);
    if (way == 2)
        s = draw_binned_mesh(cam, band, view, opt, rows.data(), int(rows.size()), kept.data(),
                             int(kept.size()), shade, &d->fragments, &d->stats);
    REQUIRE(s.ok());
}

struct BinnedComparison {
    bool same_rows = true;       // bin_mesh's rows, the vertices kept or not
    bool same_pixels = true;     // every band of each way == the full frame, colour and depth
    bool same_fragments = true;  // per band, the three ways' fragments, every field, in order
    bool same_stats = true;      // binned with kept vertices == binned; fragments and triangles
                                 // drawn == draw_mesh on the band; fragments summed == full frame
    RasterStats full;            // draw_mesh on the full frame
    long kept_rejected = 0, kept_clipped = 0;  // with the kept vertices, over the bands
};

// draw_mesh on the full frame against draw_mesh, draw_binned_mesh and draw_binned_mesh with the
// vertices kept in `kept` (grown to the mesh, NOT cleared: whatever an earlier bin_mesh left in
// it stays for this one to overwrite), band by band.
BinnedComparison compare_binned(const Camera& cam, const MeshView& view, const DrawOptions& opt,
                                std::vector<BinnedVertex>& kept,
                                std::initializer_list<int> band_heights = {16, 5, 1}) {
    const int W = cam.width, H = cam.height;
    BinnedComparison r;
    RgbImage full(W, H);
    FloatImage full_depth(W, H);
    const FrameBand whole = full_frame_band(full.view(), full_depth.view());
    clear_band(whole, Rgb8{10, 20, 30});
    REQUIRE(draw_mesh(cam, whole, view, opt, shade, nullptr, &r.full).ok());
    std::vector<TriangleRows> rows(std::size_t(view.triangle_count)), kept_rows = rows;
    if (kept.size() < std::size_t(view.vertex_count)) kept.resize(std::size_t(view.vertex_count));
    REQUIRE(bin_mesh(cam, view, opt, rows.data(), int(rows.size())).ok());
    REQUIRE(bin_mesh(cam, view, opt, kept_rows.data(), int(kept_rows.size()), kept.data(),
                     int(kept.size()))
                .ok());
    for (std::size_t t = 0; t < rows.size(); ++t)
        r.same_rows = r.same_rows && rows[t].begin == kept_rows[t].begin &&
                      rows[t].end == kept_rows[t].end;
    for (int band_height : band_heights) {
        long fragments[3] = {0, 0, 0};
        for (int y0 = 0; y0 < H; y0 += band_height) {
            const int h = std::min(band_height, H - y0);
            BandDraw d[3];
            for (int way = 0; way < 3; ++way) {
                draw_band_way(way, cam, view, opt, kept_rows, kept, y0, h, &d[way]);
                fragments[way] += d[way].stats.fragments_shaded;
                for (int y = 0; y < h; ++y)
                    r.same_pixels =
                        r.same_pixels &&
                        std::memcmp(&d[way].color[std::size_t(y * W)], full.view().row(y0 + y),
                                    sizeof(Rgb8) * W) == 0 &&
                        std::memcmp(&d[way].depth[std::size_t(y * W)],
                                    full_depth.view().row(y0 + y), sizeof(float) * W) == 0;
            }
            r.same_fragments = r.same_fragments && d[0].fragments == d[1].fragments &&
                               d[1].fragments == d[2].fragments;
            const RasterStats &a = d[0].stats, &b = d[1].stats, &k = d[2].stats;
            r.same_stats = r.same_stats && k.triangles_in == b.triangles_in &&
                           k.triangles_drawn == b.triangles_drawn &&
                           k.triangles_rejected == b.triangles_rejected &&
                           k.triangles_clipped == b.triangles_clipped &&
                           k.fragments_shaded == b.fragments_shaded &&
                           a.fragments_shaded == b.fragments_shaded &&
                           a.triangles_drawn == b.triangles_drawn;
            r.kept_rejected += k.triangles_rejected;
            r.kept_clipped += k.triangles_clipped;
        }
        for (long f : fragments) r.same_stats = r.same_stats && f == r.full.fragments_shaded;
    }
    return r;
}

void check_same(const BinnedComparison& r) {
    CHECK(r.same_rows);
    CHECK(r.same_pixels);
    CHECK(r.same_fragments);
    CHECK(r.same_stats);
}

}  // namespace

TEST_CASE("binned bands == full frame on edge cases (slivers, off-screen, back faces), kept") {
    // Every field of every fragment (world position, normals, uv, colour included: what the
    // kept path builds on its own) and every pixel: draw_mesh, draw_binned_mesh, and
    // draw_binned_mesh with the kept vertices, band by band (16, 5 and 1 rows).
    const Camera cam = perspective_camera({0.4f, 0.9f, 3.2f}, {0, 0, 0}, {0, 1, 0}, 50.0f, 101, 77);
    const TriangleMesh mesh = edge_case_mesh();
    for (int arrays = 0; arrays < 3; ++arrays) {
        MeshView view = mesh.view();
        REQUIRE(view.colors != nullptr);
        if (arrays == 1) view.normals = nullptr;  // the plane's normal, made on first use
        if (arrays == 2) view.uvs = nullptr, view.colors = nullptr;  // (0, 0) and white
        for (CullMode cull : {CullMode::back, CullMode::none, CullMode::front}) {
            DrawOptions opt;
            opt.cull = cull;
            opt.model = Mat4::rotate_y(0.2f);
            std::vector<BinnedVertex> kept;
            const BinnedComparison r = compare_binned(cam, view, opt, kept);
            INFO("arrays " << arrays << ", cull " << int(cull));
            check_same(r);
            CHECK(r.full.triangles_rejected > 0);  // the collinear ones
            CHECK(r.full.triangles_clipped > 0);   // across the near plane
            CHECK(r.full.fragments_shaded > 1000);
            CHECK(r.kept_rejected > 0);
            CHECK(r.kept_clipped > 0);
        }
    }
}

TEST_CASE("draw_binned_mesh checks the indices of the triangles it is handed, and only those") {
    Scene scene;
    TriangleMesh box = scene.box;
    const MeshView good = box.view();
    std::vector<TriangleRows> rows(std::size_t(good.triangle_count));
    REQUIRE(bin_mesh(scene.cam, good, DrawOptions{}, rows.data(), int(rows.size())).ok());
    // A mesh changed after bin_mesh: one index out of range, in a binned-away triangle (culled:
    // empty rows) and then in a drawn one.
    int culled = -1, drawn = -1;
    for (int t = 0; t < good.triangle_count; ++t) {
        if (rows[std::size_t(t)].begin >= rows[std::size_t(t)].end) culled = t;
        else drawn = t;
    }
    REQUIRE(culled >= 0);
    REQUIRE(drawn >= 0);
    RgbImage color(scene.cam.width, scene.cam.height);
    FloatImage depth(scene.cam.width, scene.cam.height);
    const FrameBand band = full_frame_band(color.view(), depth.view());
    for (int t : {culled, drawn}) {
        TriangleMesh broken = box;
        broken.indices[3 * std::size_t(t) + 1] = std::uint32_t(good.vertex_count);
        const Status s = draw_binned_mesh(scene.cam, band, broken.view(), DrawOptions{},
                                          rows.data(), int(rows.size()), shade, nullptr);
        INFO("triangle " << t);
        if (t == culled) CHECK(s.ok());  // never read: bin_mesh checked the mesh it binned
        else CHECK(s.code() == StatusCode::invalid_argument);
    }
}

TEST_CASE("clear_band == fill, row by row, for any width and a stride wider than the band") {
    for (int width = 1; width <= 13; ++width) {
        const int stride = width + 3, height = 3;
        std::vector<Rgb8> color(std::size_t(stride * height), Rgb8{1, 2, 3});
        std::vector<Rgb8> expected_color = color;
        std::vector<float> depth(std::size_t(stride * height), 7.0f), expected_depth = depth;
        const RgbView cv{color.data(), width, height, stride};
        const FloatView dv{depth.data(), width, height, stride};
        clear_band(make_band(cv, dv, 0, width, height), Rgb8{24, 26, 32});
        fill(RgbView{expected_color.data(), width, height, stride}, Rgb8{24, 26, 32});
        fill(FloatView{expected_depth.data(), width, height, stride},
             std::numeric_limits<float>::infinity());
        INFO("width " << width);
        CHECK(std::memcmp(color.data(), expected_color.data(), sizeof(Rgb8) * color.size()) == 0);
        CHECK(std::memcmp(depth.data(), expected_depth.data(), sizeof(float) * depth.size()) == 0);
    }
}

TEST_CASE("clear_band on rows that overlap (stride below the width) fills them, defined") {
    // A view validate_band refuses, but clear_band checks nothing: each row is filled on its
    // own (a copy of row 0 onto an overlapping row would be memcpy of overlapping ranges,
    // which the sanitizer build reports).
    for (int stride : {0, 1, 5, 7}) {
        const int width = 8, height = 3, used = stride * (height - 1) + width;
        std::vector<Rgb8> color(std::size_t(used + 4), Rgb8{1, 2, 3});
        std::vector<float> depth(std::size_t(used + 4), 7.0f);
        clear_band(make_band(RgbView{color.data(), width, height, stride},
                             FloatView{depth.data(), width, height, stride}, 0, width, height),
                   Rgb8{24, 26, 32});
        bool filled = true;
        for (std::size_t i = 0; i < color.size(); ++i) {
            const bool inside = i < std::size_t(used);
            const Rgb8 want = inside ? Rgb8{24, 26, 32} : Rgb8{1, 2, 3};
            const float want_depth = inside ? std::numeric_limits<float>::infinity() : 7.0f;
            filled = filled && std::memcmp(&color[i], &want, sizeof want) == 0 &&
                     depth[i] == want_depth;
        }
        INFO("stride " << stride);
        CHECK(filled);
    }
}

TEST_CASE("bin_mesh and draw_binned_mesh refuse too few kept vertices") {
    Scene scene;
    const MeshView box = scene.box.view();
    std::vector<TriangleRows> rows(std::size_t(box.triangle_count));
    std::vector<BinnedVertex> kept(std::size_t(box.vertex_count - 1));
    const Status s = bin_mesh(scene.cam, box, DrawOptions{}, rows.data(), int(rows.size()),
                              kept.data(), int(kept.size()));
    CHECK(s.code() == StatusCode::invalid_argument);
    CHECK(std::string(s.message()).find("room for 23 vertices, the mesh has 24") !=
          std::string::npos);
    RgbImage color(scene.cam.width, scene.cam.height);
    FloatImage depth(scene.cam.width, scene.cam.height);
    const Status d = draw_binned_mesh(scene.cam, full_frame_band(color.view(), depth.view()), box,
                                      DrawOptions{}, rows.data(), int(rows.size()), kept.data(),
                                      int(kept.size()), shade, nullptr);
    CHECK(d.code() == StatusCode::invalid_argument);
}

TEST_CASE("bin_mesh: a binned-away triangle counts the binned-away triangles from it on") {
    Scene scene;
    const MeshView sphere = scene.sphere.view();
    const DrawOptions opt = scene_options(0, CullMode::back);
    std::vector<TriangleRows> rows(std::size_t(sphere.triangle_count)), kept_rows = rows;
    std::vector<BinnedVertex> kept(std::size_t(sphere.vertex_count));
    REQUIRE(bin_mesh(scene.cam, sphere, opt, rows.data(), int(rows.size())).ok());
    REQUIRE(bin_mesh(scene.cam, sphere, opt, kept_rows.data(), int(kept_rows.size()), kept.data(),
                     int(kept.size()))
                .ok());
    for (const std::vector<TriangleRows>* r : {&rows, &kept_rows}) {
        // The walk of draw_binned_mesh steps over a whole run at once: begin is the run's length
        // from this triangle (the back faces of a sphere come in runs of many).
        bool counted = true;
        int longest = 0;
        const int n = int(r->size());
        for (int t = 0; t < n; ++t) {
            const TriangleRows& row = (*r)[std::size_t(t)];
            if (row.end != 0) continue;
            const int next = t + 1 < n && (*r)[std::size_t(t + 1)].end == 0
                                 ? (*r)[std::size_t(t + 1)].begin
                                 : 0;
            counted = counted && row.begin == next + 1;
            longest = row.begin > longest ? row.begin : longest;
        }
        CHECK(counted);
        CHECK(longest > 10);
    }
}

TEST_CASE("bin_mesh keeps the world position and normals of each vertex of a drawn triangle") {
    Scene scene;
    const MeshView sphere = scene.sphere.view();
    const DrawOptions opt = scene_options(0, CullMode::back);  // rotated and moved
    std::vector<TriangleRows> rows(std::size_t(sphere.triangle_count));
    std::vector<BinnedVertex> kept(std::size_t(sphere.vertex_count));
    REQUIRE(bin_mesh(scene.cam, sphere, opt, rows.data(), int(rows.size()), kept.data(),
                     int(kept.size()))
                .ok());
    CHECK(sizeof(BinnedVertex) == 56);  // the RAM ports/PORTING.md states per vertex
    int checked = 0;
    bool world = true, normals = true;
    for (int t = 0; t < sphere.triangle_count; ++t) {
        if (rows[std::size_t(t)].end == 0) continue;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = sphere.indices[3 * t + k];
            const BinnedVertex& v = kept[i];
            const Vec3 w = transform_point(opt.model, sphere.positions[i]);  // the same bits
            world = world && std::memcmp(&v.world_position, &w, sizeof w) == 0 && v.near_world;
            normals = normals && v.normals == 0;  // made, from the mesh's own normals
            ++checked;
        }
    }
    CHECK(checked > 100);
    CHECK(world);
    CHECK(normals);
    // The kept normals are the values prepare() makes, bit for bit: every fragment's normal and
    // object normal (interpolated from them) is compared with draw_mesh's, for each mesh of the
    // scene (the sphere's normals are not axis-aligned, and its model rotates them).
    for (int m = 0; m < 3; ++m)
        for (CullMode cull : {CullMode::back, CullMode::none}) {
            std::vector<BinnedVertex> scratch;
            const BinnedComparison r =
                compare_binned(scene.cam, scene_mesh(scene, m).view(), scene_options(m, cull),
                               scratch, {16, 3});
            INFO("mesh " << m << ", cull " << int(cull));
            check_same(r);
            CHECK(r.full.fragments_shaded > 100);
        }
}

namespace {

// The edge cases, and triangles out along the view at 1 to 1e38 units (the vertices of some far
// apart: a model that sends them out by 2^125 puts their differences beyond the float range),
// and one at 3e38.
TriangleMesh far_mesh() {
    TriangleMesh m = edge_case_mesh();
    const Vec3 ahead{-0.37f, -0.82f, -2.86f};  // about the view direction, 3 units from the origin
    for (float scale : {1.0f, 2.5f, 1e30f, 1e38f})
        for (float half_width : {0.2f, 0.6f, 4.2f})
            for (float y : {-0.3f, 0.4f}) {
                const Vec3 c = ahead + Vec3{0.3f * y, y, 0.0f};
                const Vec3 n{0.1f, 0.2f, 1.0f};
                const std::uint32_t a = m.add_vertex((c + Vec3{-half_width, -0.2f, 0}) * scale, n,
                                                     {0, 0});
                const std::uint32_t b = m.add_vertex((c + Vec3{half_width, -0.1f, 0.1f}) * scale,
                                                     Vec3{0, 1, 0}, {1, 0});
                const std::uint32_t d = m.add_vertex((c + Vec3{0.1f, 0.3f, -0.1f}) * scale, n,
                                                     {0, 1});
                if (y < 0) m.add_triangle(a, b, d);
                else m.add_triangle(a, d, b);
            }
    const std::uint32_t a = m.add_vertex({0, 0, -3e38f}, {0, 0, 1}, {0, 0});
    const std::uint32_t b = m.add_vertex({3e37f, 0, -3e38f}, {0, 0, 1}, {1, 0});
    const std::uint32_t c = m.add_vertex({0, 3e37f, -3e38f}, {0, 0, 1}, {0, 1});
    m.add_triangle(a, b, c);
    while (m.colors.size() < m.positions.size()) m.colors.push_back({0.9f, 0.1f, 0.5f});
    return m;
}

// A model matrix whose w row scales by 2^-125: world positions 2^125 times the object ones (a
// vertex 2 units out is beyond 2^126), clip positions finite (points nearly at infinity, in
// view with a far plane at 1e38).
Mat4 far_out_model() {
    Mat4 m = Mat4::rotate_y(0.1f);
    m.m[3][3] = 0x1p-125f;
    return m;
}
// A projective model: w = 1 + 0.3 x - 0.2 y (through 0, and negative, over the mesh).
Mat4 projective_model() {
    Mat4 m = Mat4::identity();
    m.m[3][0] = 0.3f;
    m.m[3][1] = -0.2f;
    return m;
}

// Kept vertices that a drawn triangle uses (normals made, from the mesh) with a world position
// beyond 2^126 (near_world 0): the kept path must then test the world positions (in_world).
int far_kept_vertices(const std::vector<BinnedVertex>& kept, int vertex_count) {
    int n = 0;
    for (int i = 0; i < vertex_count; ++i)
        n += kept[std::size_t(i)].normals == 0 && kept[std::size_t(i)].near_world == 0;
    return n;
}

}  // namespace

// The edge cases' camera with its far plane at 1e38 (points at infinity in view at depth 1).
Camera far_camera() {
    return perspective_camera({0.4f, 0.9f, 3.2f}, {0, 0, 0}, {0, 1, 0}, 50.0f, 101, 77, 0.05f,
                              1e38f);
}

TEST_CASE("binned with kept vertices == draw_mesh: world beyond 2^126, huge and projective") {
    const Camera cam = far_camera();
    REQUIRE(validate_camera(cam).ok());
    const TriangleMesh mesh = far_mesh();
    const MeshView view = mesh.view();
    int far_vertices[3] = {0, 0, 0};
    for (int model = 0; model < 3; ++model)
        for (CullMode cull : {CullMode::back, CullMode::none}) {
            DrawOptions opt;
            opt.cull = cull;
            opt.model = model == 0 ? Mat4::rotate_y(0.2f)
                                   : (model == 1 ? far_out_model() : projective_model());
            std::vector<BinnedVertex> kept;
            const BinnedComparison r = compare_binned(cam, view, opt, kept, {16, 5});
            INFO("model " << model << ", cull " << int(cull));
            check_same(r);
            CHECK(r.full.fragments_shaded > 500);
            CHECK(r.kept_rejected > 0);
            far_vertices[model] = far_kept_vertices(kept, view.vertex_count);
            CHECK(far_vertices[model] > 0);  // the in_world fallback of the kept path
        }
    CHECK(far_vertices[1] > far_vertices[0] + 10);  // the model sends the near ones out too
}

TEST_CASE("kept vertices binned again into the same array: nothing of the earlier bin is read") {
    Scene scene;
    std::vector<BinnedVertex> kept;  // one array for every bin below, never cleared
    const TriangleMesh far = far_mesh();
    const MeshView sphere = scene.sphere.view(), box = scene.box.view(), edges = far.view();
    // A near plane that cuts the sphere (its nearest vertices before it: not mapped, their
    // triangles clipped), and the eye on the other side (the vertices drawn before face away).
    const Camera close = perspective_camera({-0.6f, 0.05f, 1.2f}, {-0.6f, 0, 0}, {0, 1, 0}, 60.0f,
                                            101, 77, 0.5f, 100.0f);
    const Camera behind =
        perspective_camera({-1.0f, -0.6f, -3.0f}, {-0.6f, 0, 0}, {0, 1, 0}, 50.0f, 101, 77);
    DrawOptions near_model, far_model;
    near_model.model = Mat4::rotate_y(0.2f);
    far_model.model = far_out_model();
    struct Step {
        const Camera* camera;
        const MeshView* mesh;
        DrawOptions options;
    };
    const Camera far_cam = far_camera();
    const Step steps[] = {{&scene.cam, &sphere, scene_options(0, CullMode::back)},
                          {&close, &sphere, scene_options(0, CullMode::back)},
                          {&scene.cam, &sphere, scene_options(0, CullMode::back)},
                          {&behind, &sphere, scene_options(0, CullMode::back)},
                          {&far_cam, &edges, near_model},  // grows the array
                          {&far_cam, &edges, far_model},   // world positions now beyond 2^126
                          {&scene.cam, &sphere, scene_options(0, CullMode::none)},
                          {&scene.cam, &box, scene_options(1, CullMode::back)}};
    for (int k = 0; k < int(sizeof steps / sizeof steps[0]); ++k) {
        const Step& s = steps[k];
        const BinnedComparison r = compare_binned(*s.camera, *s.mesh, s.options, kept, {16, 5});
        INFO("step " << k);
        check_same(r);
        CHECK(r.full.fragments_shaded > 100);
        if (k == 1) CHECK(r.full.triangles_clipped > 4);
    }
}

TEST_CASE("a run of more than 65,535 binned-away triangles: counted up to 65,535, stepped over") {
    const Camera cam = perspective_camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 50.0f, 40, 24);
    TriangleMesh m;
    const std::uint32_t a = m.add_vertex({-1, -1, 0}, {0, 0, 1}, {0, 0});
    const std::uint32_t b = m.add_vertex({1, -1, 0}, {0, 0, 1}, {1, 0});
    const std::uint32_t c = m.add_vertex({0, 1, 0}, {0, 0, 1}, {0, 1});
    const std::uint32_t d = m.add_vertex({-1, 0.5f, -0.5f}, {0, 0, 1}, {0, 0});
    const std::uint32_t e = m.add_vertex({1, 0.5f, -0.5f}, {0, 0, 1}, {1, 0});
    const std::uint32_t f = m.add_vertex({0, -1, -0.5f}, {0, 0, 1}, {0, 1});
    const int run = 70000;
    for (int t = 0; t < run; ++t) m.add_triangle(a, c, b);  // back-facing: binned away
    m.add_triangle(d, f, e);                                 // the first drawn one
    for (int t = 0; t < 100; ++t) m.add_triangle(d, e, f);
    m.add_triangle(a, b, c);
    const MeshView view = m.view();
    DrawOptions opt;
    std::vector<TriangleRows> rows(std::size_t(view.triangle_count));
    REQUIRE(bin_mesh(cam, view, opt, rows.data(), int(rows.size())).ok());
    CHECK(rows[0].end == 0);
    CHECK(rows[0].begin == 65535);
    CHECK(rows[std::size_t(run - 65535)].begin == 65535);
    CHECK(rows[std::size_t(run - 65534)].begin == 65534);
    CHECK(rows[std::size_t(run - 1)].begin == 1);
    CHECK(rows[std::size_t(run)].end != 0);
    CHECK(rows[std::size_t(run + 1)].begin == 100);
    std::vector<BinnedVertex> kept;
    const BinnedComparison r = compare_binned(cam, view, opt, kept, {16, 5});
    check_same(r);
    CHECK(r.full.fragments_shaded > 100);
}
