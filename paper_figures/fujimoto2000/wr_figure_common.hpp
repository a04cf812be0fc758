// paper_figures/fujimoto2000/wr_figure_common.hpp — what figs. 14-23 and Tables 2-4 share:
// cameras and zooms, Lambert shading of vertex-coloured WR meshes, the transparent (flame)
// renderer, the control-mesh drawing of the "(a)" panels, span colours, stage timings.
#pragma once

#include <array>
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/wrinkly/control_mesh.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "shitsukan/wrinkly/wr_surface.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"

namespace shitsukan::fujimoto2000 {

struct Shot {
    Vec3 eye{0, 2, 4};
    Vec3 target{0, 0, 0};
    Vec3 up{0, 1, 0};
    float fov_degrees = 30.0f;
};

Camera shot_camera(const Shot& shot, int width, int height);
// Pixels covered by one world unit at the target distance (for adaptive sampling).
float shot_pixels_per_unit(const Shot& shot, int height);
// The same viewing direction and distance aimed at `target`, magnified `factor` times.
Shot zoom_shot(const Shot& shot, Vec3 target, float factor);

struct Shading {
    Vec3 light{-0.6f, 0.55f, 0.35f};  // towards the light (normalised inside)
    float ambient = 0.28f;
    Rgb8 background{255, 255, 255};
    // render_transparent: true = mostly emissive (flames give light, fig. 23); false = the
    // Lambert shading of render_opaque (fig. 22's water).
    bool emissive = false;
};

// Opaque: Z-buffer, two-sided Lambert on the vertex colours.
Status render_opaque(const Camera& camera, const TriangleMesh& mesh, RgbView target,
                     const Shading& shading, RasterStats* stats = nullptr);
// Transparent (fig. 23): triangles sorted back to front by their centroid depth, drawn with the
// Z-buffer, each fragment blended over what is there: out = (1 - t)·c + t·dst with the
// interpolated transparency t. Shading: with shading.emissive (flames give light) colour x
// (0.85 + 0.25 Lambert), else render_opaque's. The target is cleared to the background first.
// What the transparency shows, measured while blending (the optional `seen` of
// render_transparent): coverage = share of the frame's pixels the surface covers; see_through
// = mean, over the covered pixels, of the share of the final colour that comes from layers of
// the surface behind the front-most one (0: nothing shows through, as an opaque surface);
// see_through_pixels = share of the covered pixels where that share exceeds 0.15.
// background = mean, over the covered pixels, of the share of the colour that is still the
// background's (what shows through the whole surface).
struct TransparencySeen {
    double coverage = 0, see_through = 0, see_through_pixels = 0, background = 0;
    // The mean background share (what shows through) in the outer tenth of each row's covered
    // span, at either side, and in its middle half: a surface fading at its edges shows more
    // of what is behind there than in its core.
    double edge_background = 0, core_background = 0;
};
Status render_transparent(const Camera& camera, const WrMesh& mesh, RgbView target,
                          const Shading& shading, RasterStats* stats = nullptr,
                          TransparencySeen* seen = nullptr);

// The "(a)" panels: the control polygon, points in their colours, and for each point a stick
// of its height h_i along the displacement direction with a dot at the tip (fig. 17 caption).
void draw_control_mesh(RgbView target, const Camera& camera, const WrControlMesh& mesh,
                       const WrSurface& surface, bool sticks, Rgb8 background);

// The layout of every chosen control mesh of figs. 14-18: n x n points over [-half, half]^2 in
// the x-z plane (column c along +x, row r from the back z = +half to the front), each placed
// at (x, 0, z) and then handed to shape(c, r, x, z, point) to set its height, colour and y.
template <class Shape> WrControlMesh square_control_mesh(int n, float half, Shape shape) {
    WrControlMesh m = make_control_mesh(n, n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const float x = -half + 2.0f * half * float(c) / float(n - 1);
            const float z = half - 2.0f * half * float(r) / float(n - 1);
            WrControlPoint& p = m.at(c, r);
            p.position = {x, 0.0f, z};
            shape(c, r, x, z, p);
        }
    return m;
}

// Distinct colours for base interval (i, j) (figs. 16b, 22y, 23x).
Vec3 span_color(int i, int j);
// Colours every vertex by the base interval its parameter comes from at step k:
// span_color(floor(B_u·(F_U^k)^{-1}(u)), floor(B_v·(F_V^k)^{-1}(v))) (the original colour is
// replaced). k = 0: the span the vertex lies in (fig. 16b).
void color_by_source_span(WrMesh* mesh, const WrSurface& surface, int k);

// Axis helpers: an IST-carrying WrAxis that stays alive with the figure.
struct AxisPair {
    WrIstAxis u, v;
};
Status make_axes(const WrSurface& surface, IstKind kind, const char* shuffle_name, int n,
                 int max_level, AxisPair* out);

// Stage timings (Tables 2-4: sampling, polygonisation, rendering) shared between figures.
struct StageTimes {
    double sampling = 0, polygonisation = 0, rendering = 0;
    long triangles = 0;
    int grid_level = 0, levels = 0;
    bool quick = false;
    double mean_offset = 0;        // mean |R(u,v) - P(u,v)| over the vertices (see mean_offset)
    double relief_anisotropy = 0;  // fig. 22's superposed panels: relief_shape there
    double relief_repetition[2] = {0, 0};
    TransparencySeen seen;  // transparent panels: what shows through (render_transparent)
};
// Mean distance of the displaced vertices from the base surface (every 7th vertex): the total
// height a panel carries, to compare superposed panels with the plain one (eq. 18).
double mean_offset(const WrSurface& surface, const WrMesh& mesh);
void record_stage_times(const std::string& key, const StageTimes& t);
bool find_stage_times(const std::string& key, StageTimes* t);

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Tables 2-4: one row per stage (sam., pol., ren., total) and the triangle count, the paper's
// min:sec beside our seconds, one column pair per panel.
std::string stage_table(const std::vector<std::string>& names, const std::vector<StageTimes>& ours,
                        const std::vector<std::array<const char*, 4>>& paper);

// One column pair of Tables 3-4: a panel label ("(a-2)") and the paper's sam., pol., ren., total.
struct PaperTimes {
    const char* label;
    std::array<const char*, 4> paper;
};
// stage_table for the panels of a composite figure (figs. 22, 23): our times of each row from
// `times` (label -> times, as the composite's builder filled them); rows missing there are
// taken from what an earlier run recorded under `figure` + label (record_stage_times).
std::string stage_table(const std::string& figure, const std::vector<PaperTimes>& rows,
                        const std::map<std::string, StageTimes>& times);

// "1.23 s", "0.045 s", "3.10 ms": a stage time that keeps its digits when it is small.
std::string format_seconds(double seconds);

// A full-size panel shrunk into a cell of an overview composite (box filter).
void downsample_into(const RgbView& src, RgbView dst);

// Blit a panel label ("(a-1)") in the top-left corner.
void label_panel(RgbView target, const std::string& text, Rgb8 color);

}  // namespace shitsukan::fujimoto2000
