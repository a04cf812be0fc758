// cli/cmd_wrinkly.cpp — `shitsukan wrinkly` (fujimoto2000 §3: the WR surface of eq. (15);
// §4: the superposed surface of eqs. (16)-(20)) from a control-mesh file or a height map (the
// shell), written as a mesh, a picture and a map set (height, colour, normals).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "commands.hpp"
#include "flags.hpp"
#include "preview.hpp"
#include "shitsukan/core/output_file.hpp"
#include "shitsukan/core/scalar.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/geom/obj.hpp"
#include "shitsukan/image/height_map.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/wrinkly/control_mesh_read.hpp"
#include "shitsukan/wrinkly/terrain_maps.hpp"
#include "shitsukan/wrinkly/terrain_mesh.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"

namespace shitsukan::cli {
namespace {

// A part [lo, hi] of the command's progress bar, filled by one library step's own 0 .. 1.
struct ProgressPart {
    Progress whole;
    float lo, hi;
};

void report_part(float fraction, void* user) {
    const auto* part = static_cast<const ProgressPart*>(user);
    part->whole.report(part->lo + (part->hi - part->lo) * fraction);
}

struct WrinklyArgs {
    int basis = 1, degree = 3, form = 0, N = 3, K = 3, grid_level = 3, subdivisions = 2;
    int size = 512, interpolation = 1, points = 16, map_size = 512;
    float delta = -1.0f, extent = 6.0f, height_scale = 1.5f;
    float jitter_height = 0.0f, jitter_color = 0.0f;
    // chosen here: fig. 21's shot (paper_figures/fujimoto2000/fig21_terrain.cpp): diagonal,
    // 45 degrees to u and v (along one parameter the product IST's stripes line up into
    // corrugations), 28 degrees above, 2.7 bounding radii away, 41 degrees field of view
    float azimuth = 45.0f, elevation = 28.0f, distance = 2.7f, fov = 41.0f;
    std::uint32_t seed = 21;
    bool periodic = false;
    std::string mesh_path, height_map, ramp = "terrain", preview;
    MapFlags maps;  // -o: the prefix of every file (map set: docs/TOOL.md)
};

void add_wrinkly_flags(FlagSet& f, WrinklyArgs& a) {
    f.text("mesh", &a.mesh_path, "the control-mesh file (or --height-map)");
    f.text("height-map", &a.height_map,
           "the shell from a height map (16-bit PNG or PFM): --points^2 control points");
    f.choice("basis", &a.basis, "bezier|bspline", "§3.1: basis of P and H (Bezier: (n+1)^2 points)");
    f.integer("degree", &a.degree, 1, 7, "§3.1: degree n of the basis");
    f.choice("form", &a.form, "wr|superposed", "§3 eq. (15) or §4 eq. (20)");
    f.integer("N", &a.N, 2, 32, "§2: interval division number N of the IST");
    f.integer("K", &a.K, 0, 12, "§2: iterations K of the IST (superposed: steps 0..K)");
    f.number("delta", &a.delta, -1, 0.999,
             "§4 eq. (19): ratio value for every point (-1 = the file's, default 0.5)");
    f.integer("grid-level", &a.grid_level, 0, 12, "§4.2: sample grid level L");
    f.integer("subdivisions", &a.subdivisions, 1, 16, "vertices per sample interval");
    f.choice("interpolation", &a.interpolation, "linear|hermite",
             "§4.2: interpolation of the hierarchical samples");
    f.number("jitter-height", &a.jitter_height, 0, 100,
             "§5: Gaussian jitter of the height samples, relative (fig. 21: 0.12)");
    f.number("jitter-color", &a.jitter_color, 0, 1,
             "§5: Gaussian jitter of the colour samples (fig. 21: 0.035)");
    f.seed(&a.seed, "the jitter (chosen 21, fig. 21's)");
    f.integer("points", &a.points, 4, 1024, "--height-map: control points a side (chosen 16)");
    f.number("extent", &a.extent, 0.001, 1e4, "--height-map: world side of the terrain");
    f.number("height-scale", &a.height_scale, 0, 1e4, "--height-map: world height of the map's 1");
    f.text("ramp", &a.ramp, "--height-map: colours by height, terrain|grey|sand or t:r,g,b;...");
    f.toggle("periodic", &a.periodic,
             "the shell is one period (B-spline wrapped, cyclic IST): the maps tile");
    f.number("azimuth", &a.azimuth, -360, 360, "camera around the vertical, degrees (0: from +z)");
    f.number("elevation", &a.elevation, 1, 89, "camera above the horizon, degrees");
    f.number("distance", &a.distance, 0.5, 50, "camera distance, in bounding radii");
    f.number("fov", &a.fov, 5, 120, "vertical field of view, degrees");
    f.integer("size", &a.size, 8, 8192, "picture side in pixels");
    f.integer("map-size", &a.map_size, 8, 8192, "side of the maps written (a power of two)");
    a.maps.prefix = "wrinkly";
    add_map_flags(f, a.maps);
    f.text("preview", &a.preview, "also the map set on a lit sphere and plane, one PNG");
}

int check_wrinkly_args(FlagSet& f, WrinklyArgs& a) {
    if (int e = check_map_flags(f, a.maps)) return e;
    if (!a.preview.empty())
        if (int e = f.check_output("preview", a.preview, ".png")) return e;
    if (a.mesh_path.empty() == a.height_map.empty())
        return f.fail("--mesh is required (a control-mesh file; see --help), or --height-map "
                      "instead, not both");
    if (a.delta != -1.0f && !(a.delta > 0.0f))
        return f.fail("--delta must be in (0, 1) or -1 (got %g)", double(a.delta));
    if ((a.map_size & (a.map_size - 1)) != 0)
        return f.fail("--map-size must be a power of two in [8, 8192] (got %d)", a.map_size);
    if (a.periodic && a.basis != 1)
        return f.fail("--periodic needs --basis bspline (a Bezier patch does not repeat)");
    const char* map_only[] = {"points", "extent", "height-scale", "ramp"};
    for (const char* name : map_only)
        if (f.given(name) && a.height_map.empty())
            return f.fail("--%s shapes the shell made from --height-map; add --height-map", name);
    if (a.form == 0 && (f.given("jitter-height") || f.given("jitter-color")))
        return f.fail("--jitter-height and --jitter-color jitter the samples of --form superposed");
    ColorRamp ramp;
    if (!a.height_map.empty()) {
        Status s = parse_color_ramp(a.ramp.c_str(), ramp);
        if (!s) return f.fail("--ramp: %s", s.message());
    }
    return 0;
}

// The shell: the file's control mesh (wrapped with --periodic: the grid's own spacing is the
// step to the next period) or one made from the height map.
Status load_shell(const WrinklyArgs& a, WrControlMesh& mesh) {
    if (!a.height_map.empty()) {
        std::vector<float> map;
        int w = 0, h = 0;
        SHITSUKAN_TRY(read_height_map(a.height_map.c_str(), map, w, h));
        TerrainMeshOptions o;
        o.points = a.points, o.extent = a.extent, o.height_scale = a.height_scale;
        o.delta = a.delta > 0.0f ? a.delta : 0.5f;
        o.periodic = a.periodic, o.degree = a.degree;
        SHITSUKAN_TRY(parse_color_ramp(a.ramp.c_str(), o.ramp));
        return control_mesh_from_height_map(map.data(), w, h, o, mesh);
    }
    SHITSUKAN_TRY(read_control_mesh(a.mesh_path.c_str(), mesh));
    if (a.delta > 0.0f)
        for (WrControlPoint& q : mesh.points) q.delta = a.delta;
    if (!a.periodic) return Status::success();
    if (mesh.cols < 2 || mesh.rows < 2)
        return Status::error(StatusCode::invalid_argument,
                             "--periodic: the mesh needs at least 2 x 2 points (got %d x %d)",
                             mesh.cols, mesh.rows);
    const Vec3 pu = (mesh.at(1, 0).position - mesh.at(0, 0).position) * float(mesh.cols);
    const Vec3 pv = (mesh.at(0, 1).position - mesh.at(0, 0).position) * float(mesh.rows);
    WrControlMesh period = std::move(mesh);
    return wrap_control_mesh(period, a.degree, pu, pv, mesh);
}

Status build_surface(const WrinklyArgs& a, const WrControlMesh& mesh, WrSurface& surface,
                     WrIstAxis& axis_u, WrIstAxis& axis_v) {
    SHITSUKAN_TRY(make_wr_surface(mesh, SurfaceBasis(a.basis), a.degree, surface));
    const IstEnds ends = a.periodic ? IstEnds::cyclic : IstEnds::translation;
    IstAxis ist_u, ist_v;
    SHITSUKAN_TRY(ist_fully_connected_axis(a.N, 1, surface.spans_u(), ends, ist_u));
    SHITSUKAN_TRY(ist_fully_connected_axis(a.N, 1, surface.spans_v(), ends, ist_v));
    SHITSUKAN_TRY(make_wr_ist_axis(ist_u, std::max(a.K, 1), axis_u));
    SHITSUKAN_TRY(make_wr_ist_axis(ist_v, std::max(a.K, 1), axis_v));
    return surface.set_axes(axis_u.axis(), axis_v.axis());
}

std::uint8_t byte(float v) { return std::uint8_t(clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

// The map set (image/map_set.hpp) of H and the carried colour; the normal and AO at the true
// slope unless --strength is given (H's range over `world_px`, world units per pixel along
// u), wrapped when periodic.
int write_terrain_maps(const FlagSet& f, const WrinklyArgs& a, const TerrainMaps& m,
                       float world_px, std::vector<std::string>& written) {
    std::vector<Rgb8> albedo(m.heights.size());
    for (std::size_t i = 0; i < albedo.size(); ++i)
        albedo[i] = Rgb8{byte(m.color[i].x), byte(m.color[i].y), byte(m.color[i].z)};
    MapSetOptions options = map_set_options(a.maps, a.periodic);
    if (!f.given("strength")) options.strength = (m.hi - m.lo) / world_px;
    const MapSetInput input{albedo.data(), m.heights.data(), m.width, m.height};
    if (int e = write_maps(f, a.maps, input, options, &written)) return e;
    if (!a.preview.empty()) {
        const Status s = write_map_preview(a.preview.c_str(), input, options);
        if (!s) return f.fail_status(s);
        written.push_back(a.preview);
    }
    return 0;
}

// The periodic surface as a mesh: one period of the maps on the base surface (P + H·N), at
// most 257 x 257 vertices (uv = (u, v), vertex colours), closed rows and columns included.
Status periodic_mesh(const WrSurface& surface, const TerrainMaps& m, TriangleMesh& mesh) {
    const int g = std::min(m.width, 256), n = g + 1, step = m.width / g;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float u = float(i) / float(g), v = float(j) / float(g);
            const std::size_t p = std::size_t((j * step) % m.height) * std::size_t(m.width) +
                                  std::size_t((i * step) % m.width);
            const BasePoint b = surface.base_point(u, v);
            mesh.add_vertex(b.position + b.normal * m.heights[p], {}, {u, v});
            mesh.colors.push_back(m.color[p]);
        }
    for (int j = 0; j < g; ++j)
        for (int i = 0; i < g; ++i) {
            const std::uint32_t q = std::uint32_t(j * n + i);
            mesh.add_triangle(q, q + 1, q + std::uint32_t(n) + 1);
            mesh.add_triangle(q, q + std::uint32_t(n) + 1, q + std::uint32_t(n));
        }
    return compute_vertex_normals(mesh);
}

// A picture: the mesh's bounding box seen by the camera flags, light from above (fig. 21's),
// two-sided Lambert on the vertex colours, a sky background (fig. 21's).
Status render_picture(const WrinklyArgs& a, const TriangleMesh& mesh) {
    Vec3 lo = mesh.positions[0], hi = lo;
    for (const Vec3& q : mesh.positions) lo = vmin(lo, q), hi = vmax(hi, q);
    const Vec3 centre = (lo + hi) * 0.5f;
    const float radius = std::fmax(1e-3f, length(hi - lo) * 0.5f);
    const float az = a.azimuth * 0.0174532925f, el = a.elevation * 0.0174532925f;
    const Vec3 dir{std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
    const int size = a.size;
    Camera camera = perspective_camera(centre + dir * (radius * a.distance), centre, {0, 1, 0},
                                       a.fov, size, size, 0.01f * radius,
                                       (a.distance + 2.0f) * radius);
    RgbImage color(size, size);
    FloatImage depth(size, size);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{196, 216, 236});
    const Vec3 light = normalize(Vec3{0.25f, 1.0f, 0.45f});
    auto shader = [&](const Fragment& frag) {
        const Vec3 c = frag.color * (0.32f + 0.68f * std::fabs(dot(frag.normal, light)));
        return Rgb8{byte(c.x), byte(c.y), byte(c.z)};
    };
    DrawOptions dopt;
    dopt.cull = CullMode::none;
    SHITSUKAN_TRY(draw_mesh(camera, band, mesh.view(), dopt, shader));
    return write_png((a.maps.prefix + ".png").c_str(), color.view());
}

// The surface sampled (superposed: §4.2's hierarchy) and tessellated as §4.2 does (open) or
// as one period of the maps (periodic); the maps at --map-size.
Status wrinkly_outputs(const WrinklyArgs& a, const WrSurface& surface, Progress& progress,
                       TriangleMesh& mesh, TerrainMaps& maps) {
    HierarchicalSampling hs;
    if (a.form == 1) {
        HierarchicalOptions ho;
        ho.levels = a.K;
        ho.interpolation = SampleInterpolation(a.interpolation);
        ho.jitter_height = a.jitter_height;
        ho.jitter_color = a.jitter_color;
        ho.seed = a.seed;
        SHITSUKAN_TRY(sample_hierarchy(surface, ho, hs));
    }
    progress.report(0.4f);
    TerrainMapOptions mo;
    mo.width = mo.height = a.map_size;
    mo.form = a.form == 0 ? WrSurfaceForm::wr : WrSurfaceForm::superposed;
    mo.levels = a.K;
    mo.periodic = a.periodic;
    SHITSUKAN_TRY(make_terrain_maps(surface, a.form == 1 ? &hs : nullptr, mo, maps));
    progress.report(0.55f);
    if (a.periodic) return periodic_mesh(surface, maps, mesh);
    WrTessellationOptions o;
    o.grid_level = a.grid_level;
    o.subdivisions = a.subdivisions;
    o.form = a.form == 0 ? WrSurfaceForm::wr : WrSurfaceForm::superposed;
    o.levels = a.K;
    ProgressPart tessellation{progress, 0.55f, 0.7f};  // the grid rows as they are sampled
    o.progress = Progress{report_part, &tessellation};
    WrMesh wm;
    SHITSUKAN_TRY(tessellate_wr_surface(surface, a.form == 0 ? nullptr : &hs, o, wm));
    mesh = std::move(wm.mesh);
    return Status::success();
}

}  // namespace

int run_wrinkly(int argc, char** argv) {
    WrinklyArgs a;
    FlagSet f("wrinkly",
              "fujimoto2000 §3.1: a WR control mesh (positions x_i, heights h_i, colours c_i) makes a\n"
              "base surface P(u, v) and a height H(u, v); the Iterated Shuffle Transformation F^K (§2,\n"
              "fully-connected, N sub-intervals, one base interval per knot span) shuffles H along\n"
              "both axes: the WR surface P + H(F^K(u), F^K(v))·N (eq. (15)). --form superposed adds\n"
              "the steps k = 0..K with weights (1 - delta)·delta^k (eq. (19)), hierarchically sampled\n"
              "(eq. (20), §4.2). The shell: a control-mesh file (\"cols rows\", then one point a line:\n"
              "x y z h [r g b [delta]]) or --height-map. Writes <o>.obj (uv = (u, v), vertex\n"
              "colours), <o>.png (shaded) and the map set of H and the colour over u, v in\n"
              "[0, 1): <o>_albedo.png, _height16.png, _height.exr, _normal.png, _roughness.png,\n"
              "_ao.png (docs/TOOL.md).",
              "shitsukan wrinkly --mesh control.txt | --height-map h.png [flags] [-o prefix]");
    add_wrinkly_flags(f, a);
    const int rc = f.parse(argc, argv);
    if (rc != kParsed) return rc;
    if (int e = check_wrinkly_args(f, a)) return e;
    WrControlMesh mesh;
    Status s = load_shell(a, mesh);
    if (!s) return f.fail_status(s);
    Progress progress = f.progress("surface");
    progress.report(0.0f);
    WrSurface surface;
    WrIstAxis axis_u, axis_v;
    if (!(s = build_surface(a, mesh, surface, axis_u, axis_v))) return f.fail_status(s);
    progress.report(0.2f);
    TriangleMesh tri;
    TerrainMaps maps;
    if (!(s = wrinkly_outputs(a, surface, progress, tri, maps))) return f.fail_status(s);
    progress.report(0.7f);
    const float world_u = length(surface.base_point(1.0f, 0.5f).position -
                                 surface.base_point(0.0f, 0.5f).position);
    OutputSet files;  // the OBJ, the picture and the maps appear together, or none
    const std::string& o = a.maps.prefix;
    std::vector<std::string> written{o + ".obj", o + ".png"};
    s = write_obj((o + ".obj").c_str(), tri);
    if (s) s = render_picture(a, tri);
    if (!s) return f.fail_status(s);
    const float world_px = std::fmax(1e-6f, world_u) / float(a.map_size);
    if (int e = write_terrain_maps(f, a, maps, world_px, written)) return e;
    if (!(s = files.commit())) return f.fail_status(s);
    progress.report(1.0f);
    std::string list;
    for (const std::string& name : written) list += (list.empty() ? "" : ", ") + name;
    std::fprintf(stderr, "shitsukan wrinkly: %d triangles, heights %.4g .. %.4g%s; wrote %s\n",
                 tri.triangle_count(), double(maps.lo), double(maps.hi),
                 a.periodic ? " (periodic: the maps tile)" : "", list.c_str());
    return 0;
}

}  // namespace shitsukan::cli
