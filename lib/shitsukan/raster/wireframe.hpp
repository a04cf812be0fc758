// shitsukan/raster/wireframe.hpp — a mesh's edges as lines, band by band.
//
// Manual
//   TriangleMesh mesh;
//   Status s = make_box({-1, -1, -1}, {1, 1, 1}, mesh);
//   Camera camera = perspective_camera({3, 2, 4}, {0, 0, 0}, {0, 1, 0}, 35.0f, 128, 128);
//   RgbImage color(128, 128); FloatImage depth(128, 128);
//   FrameBand band = full_frame_band(color.view(), depth.view());
//   clear_band(band, Rgb8{0, 0, 0});
//   std::vector<WireEdge> edges(3 * std::size_t(mesh.view().triangle_count));  // 3 per triangle
//   int n = 0;
//   if (s) s = collect_edges(mesh.view(), edges.data(), int(edges.size()), n);   // once per mesh
//   WireOptions w;  w.color = {255, 255, 255};  w.depth_test = true;    // hidden lines
//   DrawOptions opt;
//   auto fill_shader = [](const Fragment&) { return Rgb8{40, 40, 40}; };
//   if (s) s = draw_mesh(camera, band, mesh.view(), opt, fill_shader);  // fills the Z-buffer
//   if (s) s = draw_edges(camera, band, mesh.view(), edges.data(), n, w);  // then the lines
//   return s;
//   #include "shitsukan/geom/mesh_builders.hpp"
//   #include "shitsukan/image/image.hpp"
//
// collect_edges keeps each edge once: two triangles sharing an edge, or two faces with their
// own copies of the corner vertices (a box with per-face normals), give one edge. Edges are
// compared by their end POSITIONS (sorted in place, no allocation); edges with a NaN/inf or
// coincident end are left out.
//
// draw_edges clips each edge against the near plane and the guard band in clip space (as the
// triangles are: clip.hpp) and draws a one-pixel line: along the major axis, one pixel per
// column (or row) whose centre lies in [start, end), the other coordinate sampled there
// exactly and floored. Each pixel depends only on the edge and the pixel, so bands stack
// into the full frame bit for bit.
// With depth_test, a line pixel is drawn when its eye distance is at most the Z-buffer's
// distance there times (1 + depth_tolerance): lines on the visible surface show, lines
// behind it do not (hidden-line pictures). The Z-buffer is not written.
// Defaults: white, no depth test, depth_tolerance 0.01 (chosen here: a line sampled up to
// half a pixel off the triangle it lies on differs in depth by about the surface's slope;
// 1 % of the distance hides back faces of any object thicker than that).
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/mesh_view.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"

namespace shitsukan {

struct WireEdge {
    std::uint32_t a = 0, b = 0;  // vertex indices into the mesh
};

struct WireOptions {
    Mat4 model = Mat4::identity();
    Rgb8 color{255, 255, 255};
    bool depth_test = false;
    float depth_tolerance = 0.01f;  // relative, see above
};

// Unique edges of the mesh into edges[0 .. count). capacity >= 3·triangle_count.
Status collect_edges(const MeshView& mesh, WireEdge* edges, int capacity, int& count);

// Draws edges[0 .. count) of `mesh`. *pixels_written (optional) is increased by the number
// of pixels drawn.
Status draw_edges(const Camera& camera, const FrameBand& band, const MeshView& mesh,
                  const WireEdge* edges, int count, const WireOptions& options,
                  long* pixels_written = nullptr);

// Eye distance of a window depth in [0, 1] under the camera's projection (perspective or
// orthographic): used for the depth tolerance.
float view_distance(const Camera& camera, float depth);

}  // namespace shitsukan
