// cli/cmd_wrinkly.cpp — `shitsukan wrinkly` (fujimoto2000 §3: the WR surface of eq. (15);
// §4: the superposed surface of eqs. (16)-(20)) from a control-mesh file.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "commands.hpp"
#include "flags.hpp"
#include "shitsukan/core/output_file.hpp"
#include "shitsukan/geom/obj.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/wrinkly/control_mesh_read.hpp"
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

}  // namespace

int run_wrinkly(int argc, char** argv) {
    int basis = 1, degree = 3, form = 0, N = 3, K = 3, grid_level = 3, subdivisions = 2;
    int size = 512, interpolation = 1;
    float delta = -1.0f;
    std::string mesh_path, out = "wrinkly";
    FlagSet f("wrinkly",
              "fujimoto2000 §3.1: a WR control mesh (positions x_i, heights h_i, colours c_i) makes a\n"
              "base surface P(u, v) and a height H(u, v); the Iterated Shuffle Transformation F^K (§2,\n"
              "fully-connected, N sub-intervals, one base interval per knot span) shuffles H along\n"
              "both axes: the WR surface P + H(F^K(u), F^K(v))·N (eq. (15)). --form superposed adds\n"
              "the steps k = 0..K with weights (1 - delta)·delta^k (eq. (19)), hierarchically sampled\n"
              "(eq. (20), §4.2). Writes <o>.obj (uv = (u, v), vertex colours) and <o>.png (shaded).\n"
              "Control-mesh file: \"cols rows\", then one point a line: x y z h [r g b [delta]].",
              "shitsukan wrinkly --mesh control.txt [flags] [-o prefix]");
    f.text("mesh", &mesh_path, "the control-mesh file (required)");
    f.choice("basis", &basis, "bezier|bspline", "§3.1: basis of P and H (Bezier: (n+1)^2 points)");
    f.integer("degree", &degree, 1, 7, "§3.1: degree n of the basis");
    f.choice("form", &form, "wr|superposed", "§3 eq. (15) or §4 eq. (20)");
    f.integer("N", &N, 2, 32, "§2: interval division number N of the IST");
    f.integer("K", &K, 0, 12, "§2: iterations K of the IST (superposed: steps 0..K)");
    f.number("delta", &delta, -1, 0.999,
             "§4 eq. (19): ratio value for every point (-1 = the file's, default 0.5)");
    f.integer("grid-level", &grid_level, 0, 12, "§4.2: sample grid level L");
    f.integer("subdivisions", &subdivisions, 1, 16, "vertices per sample interval");
    f.choice("interpolation", &interpolation, "linear|hermite",
             "§4.2: interpolation of the hierarchical samples");
    f.integer("size", &size, 8, 8192, "picture side in pixels");
    f.text("o", &out, "output prefix");
    const int rc = f.parse(argc, argv);
    if (rc != kParsed) return rc;
    if (int e = f.check_prefix("o", out)) return e;
    if (mesh_path.empty()) return f.fail("--mesh is required (a control-mesh file; see --help)");
    if (delta != -1.0f && !(delta > 0.0f))
        return f.fail("--delta must be in (0, 1) or -1 (got %g)", double(delta));

    WrControlMesh mesh;
    Status s = read_control_mesh(mesh_path.c_str(), mesh);
    if (!s) return f.fail_status(s);
    if (delta > 0.0f)
        for (WrControlPoint& q : mesh.points) q.delta = delta;
    Progress progress = f.progress("surface");
    progress.report(0.0f);
    WrSurface surface;
    s = make_wr_surface(mesh, SurfaceBasis(basis), degree, surface);
    IstAxis ist_u, ist_v;
    WrIstAxis axis_u, axis_v;
    if (s) s = ist_fully_connected_axis(N, 1, surface.spans_u(), IstEnds::translation, ist_u);
    if (s) s = ist_fully_connected_axis(N, 1, surface.spans_v(), IstEnds::translation, ist_v);
    if (s) s = make_wr_ist_axis(ist_u, std::max(K, 1), axis_u);
    if (s) s = make_wr_ist_axis(ist_v, std::max(K, 1), axis_v);
    if (s) s = surface.set_axes(axis_u.axis(), axis_v.axis());
    if (!s) return f.fail_status(s);
    progress.report(0.2f);
    HierarchicalSampling hs;
    WrTessellationOptions o;
    o.grid_level = grid_level;
    o.subdivisions = subdivisions;
    if (form == 0) {
        o.form = WrSurfaceForm::wr;
        o.levels = K;
    } else {
        HierarchicalOptions ho;
        ho.levels = K;
        ho.interpolation = SampleInterpolation(interpolation);
        if (!(s = sample_hierarchy(surface, ho, hs))) return f.fail_status(s);
        o.form = WrSurfaceForm::superposed;
    }
    progress.report(0.4f);
    ProgressPart tessellation{progress, 0.4f, 0.7f};  // the grid rows as they are sampled
    o.progress = Progress{report_part, &tessellation};
    WrMesh wm;
    if (!(s = tessellate_wr_surface(surface, form == 0 ? nullptr : &hs, o, wm)))
        return f.fail_status(s);
    progress.report(0.7f);
    OutputSet files;  // the OBJ and the picture appear together, or neither
    if (!(s = write_obj((out + ".obj").c_str(), wm.mesh))) return f.fail_status(s);
    // A picture: the mesh's bounding box seen from above-front, two-sided Lambert on the vertex
    // colours (light and view chosen here, as examples/30).
    Vec3 lo = wm.mesh.positions[0], hi = lo;
    for (const Vec3& q : wm.mesh.positions) {
        lo = {std::fmin(lo.x, q.x), std::fmin(lo.y, q.y), std::fmin(lo.z, q.z)};
        hi = {std::fmax(hi.x, q.x), std::fmax(hi.y, q.y), std::fmax(hi.z, q.z)};
    }
    const Vec3 centre = (lo + hi) * 0.5f;
    const float radius = std::fmax(1e-3f, length(hi - lo) * 0.5f);
    Camera camera = perspective_camera(centre + Vec3{0.0f, 1.3f, 1.6f} * (radius * 1.6f), centre,
                                       {0, 1, 0}, 40.0f, size, size, 0.01f * radius,
                                       10.0f * radius);
    RgbImage color(size, size);
    FloatImage depth(size, size);
    FrameBand band = full_frame_band(color.view(), depth.view());
    clear_band(band, Rgb8{255, 255, 255});
    const Vec3 light = normalize(Vec3{-0.5f, 0.7f, 0.4f});
    auto shader = [&](const Fragment& frag) {
        const float l = 0.3f + 0.7f * std::fabs(dot(frag.normal, light));
        const Vec3 c = frag.color * l;
        auto byte = [](float v) { return std::uint8_t(v <= 0 ? 0 : v >= 1 ? 255 : int(255 * v + 0.5f)); };
        return Rgb8{byte(c.x), byte(c.y), byte(c.z)};
    };
    DrawOptions dopt;
    dopt.cull = CullMode::none;
    s = draw_mesh(camera, band, wm.mesh.view(), dopt, shader);
    if (s) s = write_png((out + ".png").c_str(), color.view());
    if (s) s = files.commit();
    if (!s) return f.fail_status(s);
    progress.report(1.0f);
    std::fprintf(stderr, "shitsukan wrinkly: %d triangles; wrote %s.obj, %s.png\n",
                 wm.mesh.triangle_count(), out.c_str(), out.c_str());
    return 0;
}

}  // namespace shitsukan::cli
