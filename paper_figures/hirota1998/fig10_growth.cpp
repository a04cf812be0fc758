// hirota1998 fig. 10: anisotropic growth of trunk and branch = isotropic scaling + normal
// offset (§5.2), shown on the branch shape of §5 (docs/papers/hirota1998.md §6).
//   (a) the section of the mesh by the plane y = 0, four outlines: original, isotropic scaling
//       only, normal offset only, both (growth magnified: s = 1.25, d = 0.6 cm);
//   (b) the mesh coloured by the growth rate ε̂·T for the fig11 parameters (per vertex: the
//       mean over its edges), (c) a close-up of the crotch with every edge in its own ε̂·T.
// Example: none of its own; examples/60_two_layer_bark.cpp teaches the growth of the cylinder.
#include <chrono>
#include <cmath>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/bark/branch_shape.hpp"
#include "shitsukan/geom/mesh_topology.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/image/colormap.hpp"
#include "shitsukan/image/plot.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/raster/rasterizer.hpp"
#include "shitsukan/raster/shading.hpp"
#include "shitsukan/raster/wireframe.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

// Fig. 10's magnified growth (chosen here: large enough to see at figure scale).
constexpr float kShowScale = 1.25f;
constexpr float kShowOffset = 0.6f;  // cm
// The fig11 growth (docs/papers/hirota1998.md §6): r_h = 0.010, r_r(trunk) = 0.030
// -> r_n = (r_r - r_h) R_t.
constexpr float kRh = 0.010f;
constexpr float kRr = 0.030f;
constexpr float kT = 100.0f;

struct Segment {
    Vec2 a, b;  // (x, z)
};

// The intersection of the mesh (with vertices moved to `pos`) and the plane y = 0.
std::vector<Segment> section_y0(const TriangleMesh& mesh, const std::vector<Vec3>& pos) {
    std::vector<Segment> out;
    for (int t = 0; t < mesh.triangle_count(); ++t) {
        Vec2 hits[3];
        int n = 0;
        for (int k = 0; k < 3 && n < 2; ++k) {
            Vec3 p = pos[mesh.indices[3 * t + k]], q = pos[mesh.indices[3 * t + (k + 1) % 3]];
            // Half-open rule (y >= 0 is "above") so a vertex on the plane is counted once.
            if ((p.y >= 0.0f) == (q.y >= 0.0f)) continue;
            float s = p.y / (p.y - q.y);
            hits[n++] = Vec2{p.x + (q.x - p.x) * s, p.z + (q.z - p.z) * s};
        }
        if (n == 2) out.push_back({hits[0], hits[1]});
    }
    return out;
}

// Width of the trunk in an outline at height z: the extent of the crossings of z = const on
// the trunk's side (crossings beyond x_limit belong to the branch).
float trunk_width(const std::vector<Segment>& segs, float z, float x_limit) {
    float lo = 1e30f, hi = -1e30f;
    for (const Segment& s : segs) {
        if ((s.a.y >= z) == (s.b.y >= z)) continue;
        float x = s.a.x + (s.b.x - s.a.x) * (z - s.a.y) / (s.b.y - s.a.y);
        if (x > x_limit) continue;
        lo = std::fmin(lo, x);
        hi = std::fmax(hi, x);
    }
    return hi - lo;
}

// The highest point of the trunk's outline (x < x_limit leaves the branch out).
float trunk_top(const std::vector<Segment>& segs, float x_limit) {
    float z = -1e30f;
    for (const Segment& s : segs)
        for (Vec2 p : {s.a, s.b})
            if (p.x < x_limit) z = std::fmax(z, p.y);
    return z;
}

struct EdgeRates {
    std::vector<WireEdge> edges;
    std::vector<float> rate;  // ε̂·T per edge
};

Status edge_rates(const TriangleMesh& mesh, const AnisotropicGrowth& g, EdgeRates* out) {
    std::vector<int> opp;
    SHITSUKAN_TRY(
        halfedge_opposites(mesh.indices.data(), mesh.triangle_count(), mesh.vertex_count(), opp));
    for (int h = 0; h < int(opp.size()); ++h) {
        if (opp[std::size_t(h)] >= 0 && opp[std::size_t(h)] < h) continue;
        std::uint32_t i = mesh.indices[std::size_t(h)];
        std::uint32_t j = mesh.indices[std::size_t(h % 3 == 2 ? h - 2 : h + 1)];
        out->edges.push_back({i, j});
        out->rate.push_back(edge_growth_rate(g, mesh.positions[i], mesh.positions[j],
                                             mesh.normals[i], mesh.normals[j]) *
                            g.duration);
    }
    return Status::success();
}

const Rgb8 kOutlineColors[4] = {{0, 0, 0}, {40, 90, 220}, {20, 150, 60}, {210, 40, 30}};
const char* const kOutlineNames[4] = {"original", "scaling only (s = 1.25)",
                                      "offset only (d = 0.6 cm)", "both"};
constexpr int kW = 1350, kH = 620;  // the figure's size [px]

void record_fig10(FigureContext& ctx, const BranchShapeParams& shape, float L0) {
    ctx.given("growth",
              "isotropic enlargement of the whole (length) + enlargement along the "
              "normal (thickness), Fig. 10",
              "hirota1998 §5.2");
    ctx.given("r_h, r_r (fig11)", "rates along the length and around the trunk",
              "hirota1998 §5.3 (values not legible: chosen below)");
    ctx.chosen("shape",
               "trunk R_t = 2.5 cm, z in [0, 16]; branch R_b = 1.5 cm from (0, 0, 6) "
               "at 40 deg from vertical in the x-z plane; smooth-min blend k = 1 cm",
               "no scan: an implicit trunk + branch (docs/papers/hirota1998.md §6)");
    ctx.chosen("mesh",
               fmt("marching tetrahedra at L0/2, isotropic remeshing to L0 = %.2f cm "
                   "(8 passes)%s",
                   double(L0), ctx.quick() ? " [quick]" : ""),
               "the bubble-mesh substitute: near-uniform node spacing (§5.1)");
    ctx.chosen("c (scaling centre)", "(0, 0, 0), the base centre of the trunk",
               "docs/papers/hirota1998.md §6");
    ctx.chosen("panel (a) growth",
               fmt("s = %.2f, d = %.1f cm", double(kShowScale), double(kShowOffset)),
               "magnified so the four outlines separate at figure scale");
    ctx.chosen("panels (b, c) growth",
               fmt("r_h = %.3f, r_r = %.3f, T = %.0f -> r_n = (r_r - "
                   "r_h) R_t = %.3f cm",
                   double(kRh), double(kRr), double(kT), double((kRr - kRh) * shape.trunk_radius)),
               "the fig11 values (docs/papers/hirota1998.md §6)");
}

// Panel (a): the four outlines and what is measured on them.
struct Outlines {
    std::vector<Segment> outline[4];
    int folded_shown = 0, folded_fig11 = 0;          // triangles the offset turns over
    float width[4], width_expect[4], width_err = 0;  // the trunk's width at z = 3
    float height_iso = 0, height_both = 0;           // the trunk's top: scaling only, both
};

// Triangles whose normal turns around when every vertex moves d along its normal (where the
// offset exceeds the radius of a concave fold: the crotch).
int folded_triangles(const TriangleMesh& mesh, float d) {
    int n = 0;
    for (int t = 0; t < mesh.triangle_count(); ++t) {
        Vec3 p[3], q[3];
        for (int k = 0; k < 3; ++k) {
            std::uint32_t v = mesh.indices[3 * t + k];
            p[k] = mesh.positions[v];
            q[k] = p[k] + mesh.normals[v] * d;
        }
        n += dot(cross(p[1] - p[0], p[2] - p[0]), cross(q[1] - q[0], q[2] - q[0])) <= 0.0f;
    }
    return n;
}

void measure_outlines(const TriangleMesh& mesh, const BranchShapeParams& shape, Outlines* out) {
    AnisotropicGrowth show;
    show.r_h = kShowScale - 1.0f;
    show.r_n = kShowOffset;
    show.duration = 1.0f;
    show.centre = branch_base_centre(shape);
    std::vector<Vec3> pos(mesh.positions.size());
    for (int k = 0; k < 4; ++k) {
        AnisotropicGrowth g = show;
        if (k == 0 || k == 2) g.r_h = 0.0f;  // no scaling
        if (k == 0 || k == 1) g.r_n = 0.0f;  // no offset
        for (std::size_t v = 0; v < pos.size(); ++v)
            pos[v] = anisotropic_growth_anchor(g, mesh.positions[v], mesh.normals[v], 1.0f);
        out->outline[k] = section_y0(mesh, pos);
    }
    out->folded_shown = folded_triangles(mesh, kShowOffset);  // the shown d and fig11's
    out->folded_fig11 = folded_triangles(mesh, (kRr - kRh) * shape.trunk_radius);
    const float Rt = shape.trunk_radius, z_probe = 3.0f;
    const float expect[4] = {2 * Rt, 2 * kShowScale * Rt, 2 * (Rt + kShowOffset),
                             2 * (kShowScale * Rt + kShowOffset)};
    for (int k = 0; k < 4; ++k) {
        out->width_expect[k] = expect[k];
        out->width[k] = trunk_width(out->outline[k], z_probe, 6.0f);  // the branch: x > 6 at z = 3
        out->width_err = std::fmax(out->width_err, std::fabs(out->width[k] / expect[k] - 1.0f));
    }
    // The trunk's normals are horizontal, so only the scaling lifts its top: 16 s. (The branch's
    // rim, tilted, rises by d sin 40° more.)
    out->height_iso = trunk_top(out->outline[1], 6.0f);
    out->height_both = trunk_top(out->outline[3], 6.0f);
}

Status draw_outlines(RgbImage& img, const Outlines& o) {
    RasterCanvas pa(img.view().subview(0, 30, 470, kH - 30));
    // Equal scales on x and z: 18 cm x 22 cm in a 380 x 464 px data area.
    PlotMargins mg;
    mg.left = 46;
    mg.right = 470 - 46 - 380;
    mg.top = 36;
    mg.bottom = float(kH - 30) - 36 - 464;
    Axes ax = axes_in(pa, -4.5, 13.5, -0.5, 21.5, mg);
    AxesStyle st;
    st.title_scale = 1;
    SHITSUKAN_TRY(draw_axes(pa, ax, {"(a) section y = 0 (cm)", "x", "z"}, st));
    for (int k = 0; k < 4; ++k)
        for (const Segment& s : o.outline[k])
            pa.line(ax.to_pixel(s.a.x, s.a.y), ax.to_pixel(s.b.x, s.b.y), kOutlineColors[k],
                    k == 0 ? 1.6f : 1.3f);
    // The scaling centre c.
    pa.marker(ax.to_pixel(0, 0), MarkerShape::plus, 9, Rgb8{0, 0, 0});
    pa.text(ax.to_pixel(0.3, 0.3) + Vec2{0, -12}, "c", Rgb8{0, 0, 0});
    // Legend and measured widths in the empty lower right corner.
    for (int k = 0; k < 4; ++k) {
        Vec2 p = ax.to_pixel(5.2, 5.2) + Vec2{0.0f, 12.0f * float(k)};
        pa.fill_rect(p + Vec2{0, 3}, {14, 3}, kOutlineColors[k]);
        pa.text(p + Vec2{18, 0}, kOutlineNames[k], Rgb8{0, 0, 0});
    }
    pa.text(ax.to_pixel(5.2, 2.0),
            fmt("trunk width at z = 3 (cm):\n%.2f / %.2f / %.2f / %.2f", double(o.width[0]),
                double(o.width[1]), double(o.width[2]), double(o.width[3])),
            Rgb8{0, 0, 0});
    return Status::success();
}

// Panels (b, c): the mean rate of the trunk's hoop and axial edges below the crotch and of the
// branch's hoop edges (checked against r_h + r_n/R and r_h).
struct RateChecks {
    double hoop_t = 0, axial_t = 0, hoop_b = 0;
    int n_hoop_t = 0, n_axial_t = 0, n_hoop_b = 0;
};

RateChecks measure_rates(const TriangleMesh& mesh, const BranchShapeParams& shape,
                         const EdgeRates& er) {
    RateChecks r;
    const Vec3 u = branch_axis_direction(shape);
    for (std::size_t e = 0; e < er.edges.size(); ++e) {
        Vec3 a = mesh.positions[er.edges[e].a], b = mesh.positions[er.edges[e].b];
        Vec3 d = normalize(b - a), m = (a + b) * 0.5f;
        LimbDistances ld = limb_distances(shape, m);
        if (m.z < 4.0f && ld.f_trunk < ld.f_branch - 0.5f) {  // trunk below the crotch
            if (std::fabs(d.z) < 0.15f) {
                r.hoop_t += er.rate[e];
                ++r.n_hoop_t;
            } else if (std::fabs(d.z) > 0.97f) {
                r.axial_t += er.rate[e];
                ++r.n_axial_t;
            }
        }
        if (m.z > 11.0f && ld.f_branch < ld.f_trunk - 0.5f && std::fabs(dot(d, u)) < 0.15f) {
            r.hoop_b += er.rate[e];
            ++r.n_hoop_b;
        }
    }
    r.hoop_t /= r.n_hoop_t > 0 ? r.n_hoop_t : 1;
    r.axial_t /= r.n_axial_t > 0 ? r.n_axial_t : 1;
    r.hoop_b /= r.n_hoop_b > 0 ? r.n_hoop_b : 1;
    return r;
}

// Per vertex: the mean of its edges' rate, through the colour map.
TriangleMesh coloured_by_rate(const TriangleMesh& mesh, const EdgeRates& er, ValueRange range) {
    std::vector<float> vsum(mesh.positions.size(), 0.0f);
    std::vector<int> vcount(mesh.positions.size(), 0);
    for (std::size_t e = 0; e < er.edges.size(); ++e)
        for (std::uint32_t v : {er.edges[e].a, er.edges[e].b}) {
            vsum[v] += er.rate[e];
            ++vcount[v];
        }
    TriangleMesh colored = mesh;
    colored.colors.resize(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        float t = (vsum[v] / float(vcount[v]) - range.lo) / (range.hi - range.lo);
        Rgb8 c = colormap(ColorMap::perceptual, t);
        colored.colors[v] = Vec3{c.r / 255.0f, c.g / 255.0f, c.b / 255.0f};
    }
    return colored;
}

// The mesh Lambert-lit by two lights, in its own colours or light grey, both sides.
Status render_mesh(const TriangleMesh& m, const Camera& cam, const RgbView& view,
                   bool colored_faces, FloatImage* depth_out) {
    const Light lights[2] = {directional_light({-0.4f, -1.0f, 0.6f}, {1, 1, 1}, 0.75f),
                             directional_light({1.0f, -0.3f, 0.4f}, {1, 1, 1}, 0.3f)};
    Material mat;
    mat.ambient = 0.35f;
    mat.diffuse = 0.75f;
    FloatImage depth(view.width, view.height);
    FrameBand band = full_frame_band(view, depth.view());
    clear_band(band, Rgb8{255, 255, 255});
    auto shader = [&](const Fragment& f) {
        Vec3 n = face_forward(f.normal, f.world_position, cam.eye);
        Vec3 base = colored_faces ? f.color : Vec3{0.93f, 0.93f, 0.93f};
        return to_rgb8(shade_lambert(mat, base, f.world_position, n, lights, 2));
    };
    DrawOptions opt;
    opt.cull = CullMode::none;  // open ends: the inside shows through them
    SHITSUKAN_TRY(draw_mesh(cam, band, m.view(), opt, shader));
    if (depth_out) *depth_out = std::move(depth);
    return Status::success();
}

// (b) the coloured mesh; (c) the crotch with every edge in its own rate: one draw_edges call
// per colour bin, depth-tested against the surface.
Status draw_rate_panels(RgbImage& img, RasterCanvas& canvas, const TriangleMesh& mesh,
                        const TriangleMesh& colored, const EdgeRates& er, ValueRange range) {
    const int PW = 390, PH = 540;
    {
        RgbView vb = img.view().subview(475, 50, PW, PH);
        Camera cam =
            perspective_camera({8.0f, -38.0f, 15.0f}, {4.0f, 0.0f, 8.3f}, {0, 0, 1}, 32.0f, PW, PH);
        SHITSUKAN_TRY(render_mesh(colored, cam, vb, true, nullptr));
        canvas.text({480, 36}, "(b) vertex mean of edge rates (fig11 growth)", Rgb8{0, 0, 0});
    }
    RgbView vc = img.view().subview(475 + PW + 5, 50, PW, PH);
    Camera cam =
        perspective_camera({6.5f, -19.0f, 11.0f}, {3.0f, 0.0f, 8.2f}, {0, 0, 1}, 36.0f, PW, PH);
    FloatImage depth;
    SHITSUKAN_TRY(render_mesh(mesh, cam, vc, false, &depth));
    FrameBand band = full_frame_band(vc, depth.view());
    constexpr int kBins = 48;
    std::vector<WireEdge> bin;
    for (int b = 0; b < kBins; ++b) {
        bin.clear();
        for (std::size_t e = 0; e < er.edges.size(); ++e) {
            float t = (er.rate[e] - range.lo) / (range.hi - range.lo);
            int k = int(std::floor(t * kBins));
            k = k < 0 ? 0 : (k >= kBins ? kBins - 1 : k);
            if (k == b) bin.push_back(er.edges[e]);
        }
        if (bin.empty()) continue;
        WireOptions w;
        w.depth_test = true;
        w.color = colormap(ColorMap::perceptual, (float(b) + 0.5f) / kBins);
        SHITSUKAN_TRY(draw_edges(cam, band, mesh.view(), bin.data(), int(bin.size()), w));
    }
    canvas.text({480 + PW + 5, 36}, "(c) crotch: every edge in its own rate", Rgb8{0, 0, 0});
    return Status::success();
}

}  // namespace

SHITSUKAN_FIGURE(hirota1998_fig10, "hirota1998", "fig10",
                 "Anisotropic growth of trunk and branch: isotropic scaling + normal offset "
                 "(section y = 0), and the per-edge growth rate on the branch mesh") {
    const BranchShapeParams shape;
    const float L0 = ctx.quick() ? 0.6f : 0.33f;
    record_fig10(ctx, shape, L0);
    auto t0 = std::chrono::steady_clock::now();
    TriangleMesh mesh;
    BranchMeshStats ms;
    SHITSUKAN_TRY(make_branch_mesh(shape, L0, mesh, &ms));
    const double mesh_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const MeshQuality& q = ms.remesh.after;

    // ---- (a) the four outlines ----
    Outlines o;
    measure_outlines(mesh, shape, &o);
    RgbImage img(kW, kH, Rgb8{255, 255, 255});
    RasterCanvas canvas(img.view());
    canvas.text({12, 8},
                "hirota1998 fig. 10 - anisotropic growth = isotropic scaling + "
                "normal offset",
                Rgb8{0, 0, 0}, 2);
    SHITSUKAN_TRY(draw_outlines(img, o));

    // ---- (b), (c): the fig11 growth rate ----
    AnisotropicGrowth g;
    g.r_h = kRh;
    g.r_n = (kRr - kRh) * shape.trunk_radius;
    g.duration = kT;
    g.centre = branch_base_centre(shape);
    SHITSUKAN_TRY(validate_growth(g));
    EdgeRates er;
    SHITSUKAN_TRY(edge_rates(mesh, g, &er));
    const ValueRange range{kRh, kRh + g.r_n / shape.branch_radius + 0.004f};
    const TriangleMesh colored = coloured_by_rate(mesh, er, range);
    const RateChecks r = measure_rates(mesh, shape, er);
    const double hoop_t_expect = double(g.r_h + g.r_n / shape.trunk_radius);
    const double hoop_b_expect = double(g.r_h + g.r_n / shape.branch_radius);
    SHITSUKAN_TRY(draw_rate_panels(img, canvas, mesh, colored, er, range));
    SHITSUKAN_TRY(draw_colorbar(canvas, {float(kW - 80), 70.0f}, {16.0f, 380.0f},
                                ColorMap::perceptual, range));
    canvas.text({float(kW - 84), 52.0f}, "eps*T", Rgb8{0, 0, 0});
    canvas.text({480, float(kH - 26)},
                fmt("trunk hoop edges %.4f (r_h + r_n/R_t = %.4f), axial %.4f (r_h = %.3f); "
                    "branch hoop %.4f (r_h + r_n/R_b = %.4f)",
                    r.hoop_t, hoop_t_expect, r.axial_t, double(g.r_h), r.hoop_b, hoop_b_expect),
                Rgb8{0, 0, 0});

    const bool widths_ok = o.width_err < 0.01f;
    const bool height_ok = std::fabs(o.height_iso / (kShowScale * shape.height) - 1.0f) < 1e-4f &&
                           std::fabs(o.height_both / (kShowScale * shape.height) - 1.0f) < 1e-4f;
    const bool hoop_ok = std::fabs(r.hoop_t / hoop_t_expect - 1.0) < 0.05;
    const bool axial_ok = std::fabs(r.axial_t / double(g.r_h) - 1.0) < 0.05;
    const bool branch_ok = std::fabs(r.hoop_b / hoop_b_expect - 1.0) < 0.05;
    ctx.note(fmt(
        "Mesh: %d nodes, %d triangles (marching tetrahedra gave %d / %d), edge mean "
        "%.3f cm, CV %.3f, min angle %.1f deg, %.2f %% of triangles above 25 deg; "
        "%d boundary loops, Euler characteristic %d; built in %.3f s.",
        q.vertices, q.triangles, ms.marching_vertices, ms.marching_triangles, q.edge_length_mean,
        q.edge_length_cv, q.min_angle_degrees, 100.0 * q.fraction_angle_above_25, ms.boundary_loops,
        ms.euler_characteristic, mesh_seconds));
    ctx.note(
        fmt("(a) trunk width at z = 3 cm: %.3f / %.3f / %.3f / %.3f cm, expected 2R, 2sR, "
            "2(R + d), 2(sR + d) = %.3f / %.3f / %.3f / %.3f (largest error %.2f %%, %s); "
            "trunk height %.3f (scaling only) and %.3f (both) = s x 16 = %.1f (%s).",
            double(o.width[0]), double(o.width[1]), double(o.width[2]), double(o.width[3]),
            double(o.width_expect[0]), double(o.width_expect[1]), double(o.width_expect[2]),
            double(o.width_expect[3]), 100.0 * double(o.width_err), widths_ok ? "ok" : "FAIL",
            double(o.height_iso), double(o.height_both), double(kShowScale * shape.height),
            height_ok ? "ok" : "FAIL"));
    ctx.note(fmt(
        "(b, c) eps*T on the trunk below the crotch: hoop edges (|e.z| < 0.15, %d) "
        "%.4f vs r_h + r_n/R_t = %.4f (%s), axial edges (|e.z| > 0.97, %d) %.4f vs "
        "r_h = %.4f (%s); branch hoop edges (|e.u| < 0.15, %d) %.4f vs r_h + r_n/R_b "
        "= %.4f (%s): the thinner limb grows faster around (sec. 5.2's drawback).",
        r.n_hoop_t, r.hoop_t, hoop_t_expect, hoop_ok ? "ok" : "FAIL", r.n_axial_t, r.axial_t,
        double(g.r_h), axial_ok ? "ok" : "FAIL", r.n_hoop_b, r.hoop_b, hoop_b_expect,
        branch_ok ? "ok" : "FAIL"));
    ctx.note(fmt(
        "The magnified offset d = %.1f cm exceeds the concave radius of curvature in the "
        "upper crotch, where the offset outline folds into a small swallowtail (%d "
        "triangles turn over); at fig11's d(T) = %.2f cm %d do.",
        double(kShowOffset), o.folded_shown, double((kRr - kRh) * shape.trunk_radius),
        o.folded_fig11));
    ctx.note(
        "Look for: (a) scaling alone stretches the whole shape away from c (taller and "
        "wider), the normal offset alone thickens both limbs by the same distance, both "
        "together give the anisotropic growth; (b, c) the branch is hotter than the trunk, "
        "and on each limb the edges around it are hotter than those along it.");
    if (!ctx.quick() && !(widths_ok && height_ok && hoop_ok && axial_ok && branch_ok))
        return Status::error(StatusCode::invalid_argument,
                             "fig10: a measured check failed (see the notes)");
    return ctx.save_png(img.view());
}
