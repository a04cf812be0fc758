// shitsukan/raster/rasterizer.hpp — the tiny scanline rasterizer (CONTRACT; see below).
//
// Manual
//   RgbImage color(512, 512); FloatImage depth(512, 512);   // image/image.hpp (host), or any
//                                                           // caller memory as RgbView/FloatView
//   FrameBand band = full_frame_band(color.view(), depth.view());   // or any band of rows
//   clear_band(band, Rgb8{0, 0, 0});
//   Camera camera = perspective_camera({0, 1, 4}, {0, 0, 0}, {0, 1, 0}, 35.0f, 512, 512);
//   TriangleMesh mesh;
//   Status s = make_torus(1.0f, 0.35f, 64, 32, mesh);
//   DrawOptions opt;  opt.model = Mat4::rotate_y(0.3f);  opt.cull = CullMode::back;
//   auto shader = [&](const Fragment& f) { return to_rgb8(0.5f * (f.normal + Vec3{1, 1, 1})); };
//   RasterStats stats;
//   if (s) s = draw_mesh(camera, band, mesh.view(), opt, shader, &stats);
//   // See also: shading.hpp (lights, Lambert, Blinn-Phong), wireframe.hpp (edges as lines),
//   // clip.hpp (the homogeneous clipper), camera.hpp.
//   return s;
//   #include "shitsukan/geom/mesh_builders.hpp"
//   #include "shitsukan/image/image.hpp"
//   #include "shitsukan/raster/shading.hpp"
//
// CONVENTIONS (small3dlib-style)
//   - Right-handed world; camera looks down -z of eye space; counter-clockwise = front face.
//   - Screen: x right, y down, pixel (x, y) covers [x, x+1) x [y, y+1), sampled at its
//     centre (x + 0.5, y + 0.5). Vertices keep sub-pixel positions: snapped to 1/256 pixel,
//     after which coverage is decided with exact 64-bit integer arithmetic.
//   - Fill rule: top-left. A pixel centre exactly on a shared edge belongs to exactly one
//     of the two triangles; a grid of triangles tiling the screen covers each pixel once.
//   - Depth: z in [0, 1] (0 = near plane), float Z-buffer, a fragment is kept when its depth
//     is strictly less than the stored one (and not beyond the far plane, z <= 1). The test
//     runs before the shader (early z). clear_band sets depth to +inf.
//   - Near-plane clipping in homogeneous clip space before the divide (a triangle with a
//     vertex at w <= 0 is clipped, never dropped whole and never wrapped around); a guard
//     band 8x the view volume clips huge triangles (raster/clip.hpp). The clipped polygon is
//     drawn as a fan; its pieces tile it exactly (same fill rule).
//   - Facing: decided once per mesh triangle: from the sign of its snapped screen area, or,
//     when it was clipped, from the orientation of its clip-space corners (which every piece
//     of the clipped polygon shares, so a near-plane sliver is never culled or labelled apart
//     from the rest). CullMode::back (the default) skips clockwise-on-screen triangles.
//   - Interpolation: object position, normal, uv and colour are perspective-correct
//     (attributes / w interpolated linearly in screen space, then divided by 1/w).
//   - Bands: a FrameBand is the rows [y0, y0 + color.height) of a frame of
//     frame_width x frame_height pixels. Rendering all bands of a frame and stacking them
//     gives the full frame bit for bit. The rasterizer allocates nothing. Many bands: bin the
//     mesh once (bin_mesh, below) so that each band sets up only its own triangles.
#pragma once

#include <cstdint>
#include <utility>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/geom/mesh_view.hpp"
#include "shitsukan/image/image_view.hpp"
#include "shitsukan/raster/camera.hpp"

namespace shitsukan {

// What the per-pixel shader receives: the interpolated surface point.
struct Fragment {
    Vec3 object_position;  // object space (before DrawOptions::model): solid textures use this
    Vec3 world_position;   // after model
    Vec3 normal;           // world space, interpolated and normalised (geometric if no normals)
    Vec3 object_normal;    // object space, interpolated and normalised
    Vec2 uv;               // (0, 0) when the mesh has none
    Vec3 color;            // interpolated vertex colour, (1, 1, 1) when the mesh has none
    int x = 0, y = 0;      // pixel in the full frame
    float depth = 0;       // [0, 1]
    int triangle = 0;      // index of the triangle in the mesh
    bool front_facing = true;
};

// A per-pixel shader: plain function pointer + user pointer (no std::function, no heap).
using FragmentShader = Rgb8 (*)(const Fragment& fragment, void* user);

enum class CullMode : std::uint8_t { none, back, front };

struct DrawOptions {
    Mat4 model = Mat4::identity();  // object -> world
    CullMode cull = CullMode::back;
};

struct FrameBand {
    RgbView color;       // band-sized colour buffer (width = frame width)
    FloatView depth;     // band-sized depth buffer, same size as color
    int y0 = 0;          // first frame row held by this band
    int frame_width = 0, frame_height = 0;
};

// Counters of one or more draw calls: draw_mesh() ADDS to them, so one RasterStats can sum
// a whole frame (note that a mesh drawn band by band is counted once per band).
struct RasterStats {
    long triangles_in = 0;       // triangles submitted
    long triangles_drawn = 0;    // after culling and clipping, touching this band
    long triangles_clipped = 0;  // that needed near-plane clipping
    long triangles_rejected = 0; // degenerate (zero area, NaN/inf vertices)
    long fragments_shaded = 0;   // shader calls that passed the depth test
};

// Largest frame side accepted (chosen here: keeps the 8-bit sub-pixel fixed-point screen
// coordinates, guard band included, far inside 64-bit products).
constexpr int kMaxFrameSize = 16384;

FrameBand full_frame_band(const RgbView& color, const FloatView& depth);
FrameBand make_band(const RgbView& color, const FloatView& depth, int y0, int frame_width,
                    int frame_height);
void clear_band(const FrameBand& band, Rgb8 background);

// The checks draw_mesh() (and draw_edges()) run before drawing anything, for callers
// that want them up front: the camera (validate_camera, camera.hpp); buffer sizes and strides
// and the band's place in the camera's frame; counts,
// pointers and every index of the mesh; a finite, invertible model matrix (and its normal
// matrix, the inverse transpose).
Status validate_band(const Camera& camera, const FrameBand& band);
Status validate_mesh(const MeshView& mesh);
// validate_mesh without the indices (counts and arrays only): draw_binned_mesh runs it per band
// and checks the indices of the triangles it is handed (bin_mesh checked them all).
Status validate_mesh_arrays(const MeshView& mesh);
Status validate_model(const Mat4& model, Mat4& normal_matrix);

// Draws the mesh into the band. Shades only fragments that pass the depth test
// (early z: a pixel is shaded again only by a fragment nearer than all before it, and its
// final colour and depth come from the nearest fragment; for a closed convex mesh with back
// faces culled that is exactly one shading per covered pixel, while a non-convex one (a
// torus) can shade a pixel once per front-facing layer that arrives nearer).
// Returns invalid_argument for a camera that fails validate_camera, a band whose buffers
// disagree in size, a mesh with out-of-range indices, etc. Degenerate triangles (zero area,
// NaN/inf) are skipped and counted, not an error. Normals are normalised (any finite non-zero
// length); uvs and colours are interpolated as given (NaN in, NaN out) and stay finite for
// values within +-1e30 (chosen here: the interpolation works from the differences q - p,
// which overflow for values near the float maximum, 3.4e38).
Status draw_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                 const DrawOptions& options, FragmentShader shader, void* user,
                 RasterStats* stats = nullptr);

// Convenience for lambdas and functors taking (const Fragment&) (no allocation: passes &f as
// the user pointer). A captureless lambda taking (const Fragment&, void*) goes to the
// function-pointer overload above.
template <class F, class = decltype(std::declval<F&>()(std::declval<const Fragment&>()))>
Status draw_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                 const DrawOptions& options, F& shader, RasterStats* stats = nullptr) {
    return draw_mesh(
        camera, band, mesh, options,
        [](const Fragment& f, void* u) -> Rgb8 { return (*static_cast<F*>(u))(f); }, &shader,
        stats);
}

// ---- Binning: a frame drawn in many bands sets each triangle up once ----
//   TriangleRows rows[kMaxTriangles];                        // caller memory, 4 bytes each
//   Status s = bin_mesh(camera, mesh, opt, rows, kMaxTriangles);      // once per frame
//   for (each band) s = draw_binned_mesh(camera, band, mesh, opt, rows, kMaxTriangles, shader);
// bin_mesh transforms, projects, snaps and culls every triangle once and keeps the rows it can
// touch; draw_binned_mesh hands a band only the triangles whose rows meet it (a triangle is
// set up again only in the bands it covers). Same pixels as draw_mesh, bit for bit: the rows
// come from the same clip-space corners and snapping (a triangle that needs near-plane or
// guard-band clipping keeps every row). The rows must come from bin_mesh with the same
// camera, mesh and options. RasterStats: triangles_in counts the triangles handed to the band.
// draw_binned_mesh checks the camera, band, model and the mesh's counts up front, and the
// indices of each triangle it is handed before reading them (bin_mesh checked every index): a
// mesh changed since with a bad index gives invalid_argument, possibly after part of the band.
struct TriangleRows {
    // frame rows [begin, end); end 0: nothing to draw, and begin then counts the triangles
    // from this one on that have nothing to draw (a band's walk steps over them at once)
    std::uint16_t begin = 0, end = 0;
};
Status bin_mesh(const Camera& camera, const MeshView& mesh, const DrawOptions& options,
                TriangleRows* rows, int capacity);
Status draw_binned_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                        const DrawOptions& options, const TriangleRows* rows, int capacity,
                        FragmentShader shader, void* user, RasterStats* stats = nullptr);

// With the vertices kept (56 bytes per vertex of caller memory more): bin_mesh transforms,
// divides and snaps each vertex once (a vertex is shared by about six triangles) and keeps its
// screen position, and for each vertex of a triangle that can be drawn its world position and
// normals; draw_binned_mesh then sets a triangle up from its vertices' kept values instead of
// its corners again (a triangle with a vertex that needs clipping or cannot be mapped takes the
// general path). Same pixels and statistics as draw_mesh.
// The kept array drawn must be the one the same bin_mesh call wrote, for the same mesh, camera
// and options, unchanged since: bin_mesh marks every vertex slot of the mesh it bins anew (an
// array may be binned again, for another mesh, camera or frame: no old value is read), but a
// mesh grown after bin_mesh reaches slots that call never wrote, possibly an older frame's (not
// supported: bin it again). BinnedVertex's fields are public for their size and layout only:
// draw_binned_mesh trusts the values bin_mesh writes (|x|, |y| < 2^28, so the differences of
// two fit 32 bits; the set-up subtracts them in int32) and checks none of them.
//   BinnedVertex kept[kMaxVertices];
//   s = bin_mesh(camera, mesh, opt, rows, kMaxTriangles, kept, kMaxVertices);
//   s = draw_binned_mesh(camera, band, mesh, opt, rows, kMaxTriangles, kept, kMaxVertices, shader,
//                        user);
struct BinnedVertex {  // written by bin_mesh; read by draw_binned_mesh (never by hand)
    std::int32_t x = 0, y = 0;   // snapped screen position (1/256 pixel, |x|, |y| < 2^28), or
                                 // "not kept"
    float z = 0, inv_w = 0;      // depth and 1 / w_clip
    std::uint16_t outcode = 0;   // the clip-space outcode
    std::uint8_t normals = 0;    // which normals the triangle's plane supplies, or "not made"
    std::uint8_t near_world = 0; // 1: world position within +-2^126 (differences stay finite)
    Vec3 world_position;         // the model matrix times the position
    Vec3 normal, object_normal;  // the mesh's normal, normalised, in world and object space
};
Status bin_mesh(const Camera& camera, const MeshView& mesh, const DrawOptions& options,
                TriangleRows* rows, int capacity, BinnedVertex* vertices, int vertex_capacity);
Status draw_binned_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                        const DrawOptions& options, const TriangleRows* rows, int capacity,
                        const BinnedVertex* vertices, int vertex_capacity, FragmentShader shader,
                        void* user, RasterStats* stats = nullptr);
template <class F, class = decltype(std::declval<F&>()(std::declval<const Fragment&>()))>
Status draw_binned_mesh(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                        const DrawOptions& options, const TriangleRows* rows, int capacity,
                        F& shader, RasterStats* stats = nullptr) {
    return draw_binned_mesh(
        camera, band, mesh, options, rows, capacity,
        [](const Fragment& f, void* u) -> Rgb8 { return (*static_cast<F*>(u))(f); }, &shader,
        stats);
}

}  // namespace shitsukan
