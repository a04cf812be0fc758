// fuzz/fuzz_wr_tessellation.cpp — wrinkly surfaces (fujimoto2000 §3, §4): a control mesh of
// any size and values (make_control_mesh, validate_control_mesh via make_wr_surface), IST
// axes of any N, K and kind (make_wr_ist_axis, set_axes), the hierarchical sampling
// (sample_hierarchy) and tessellate_wr_surface with any form, levels, grid and window.
// Contract: a non-ok Status, or a mesh whose positions, normals, uvs and colours are finite,
// whose uvs lie in the window, whose indices are in range, with one transparency per vertex
// and grid_u x grid_v vertices. Sizes are kept small (a few thousand vertices) so one input
// runs in milliseconds.
#include <cmath>
#include <cstdint>

#include "fuzz_input.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/ist_axis.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "shitsukan/wrinkly/wr_surface.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"

using namespace shitsukan;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    const SurfaceBasis basis = (in.take<std::uint8_t>() & 1) ? SurfaceBasis::bezier
                                                            : SurfaceBasis::bspline;
    const int degree = int(in.take<std::uint8_t>() % 9) - 1;
    const int cols = int(in.take<std::uint8_t>() % 10) - 1, rows = int(in.take<std::uint8_t>() % 10) - 1;
    WrControlMesh mesh = make_control_mesh(cols, rows);
    for (WrControlPoint& p : mesh.points) {
        p.position = {in.value(), in.value(), in.value()};
        p.height = in.value();
        if (in.take<std::uint8_t>() & 1) {
            p.color = {in.value(), in.value(), in.value()};
            p.transparency = in.value();
            p.delta = in.value();
            p.direction = {in.value(), in.value(), in.value()};
        }
    }
    // validate_control_mesh refuses coordinates beyond kMaxWrCoordinate (finding_nonfinite_mesh,
    // now in the corpus: 3.4e35 overflowed the derivative products).
    WrSurface surface;
    if (!make_wr_surface(mesh, basis, degree, surface).ok()) return 0;
    if (in.take<std::uint8_t>() & 1) surface.set_displacement(DisplacementMode::direction);
    const int n = int(in.take<std::uint8_t>() % 8), k = int(in.take<std::uint8_t>() % 6);
    const IstEnds ends = (in.take<std::uint8_t>() & 1) ? IstEnds::translation : IstEnds::cyclic;
    IstAxis ist_u, ist_v;
    WrIstAxis axis_u, axis_v;
    Status s = ist_fully_connected_axis(n, 1, surface.spans_u(), ends, ist_u);
    if (s) s = ist_fully_connected_axis(n, 1, surface.spans_v(), ends, ist_v);
    if (s) s = make_wr_ist_axis(ist_u, k, axis_u);
    if (s) s = make_wr_ist_axis(ist_v, k, axis_v);
    if (s) s = surface.set_axes(axis_u.axis(), axis_v.axis());
    if (!s) return 0;
    WrTessellationOptions o;
    o.form = WrSurfaceForm(in.take<std::uint8_t>() % 5);
    o.levels = int(in.take<std::uint8_t>() % 8) - 1;
    o.grid_level = int(in.take<std::uint8_t>() % 4);
    o.subdivisions = 1 + in.take<std::uint8_t>() % 4;
    if (in.take<std::uint8_t>() & 1) {
        o.u0 = in.value(), o.u1 = in.value(), o.v0 = in.value(), o.v1 = in.value();
    }
    o.tail_tolerance = in.value();
    HierarchicalSampling hs;
    const HierarchicalSampling* sampling = nullptr;
    if (o.form == WrSurfaceForm::superposed) {
        HierarchicalOptions ho;
        ho.levels = int(in.take<std::uint8_t>() % 5);
        ho.interpolation = SampleInterpolation(in.take<std::uint8_t>() & 1);
        ho.jitter_height = in.value();
        ho.seed = in.take<std::uint32_t>();
        // sample_hierarchy refuses jitter_height above kMaxJitterHeight
        // (finding_jitter_height_overflow, in the corpus: 3.4e38 gave infinite positions).
        // (found: B N^levels samples a side squared exceeded the 1 s timeout under the
        // sanitizers: work that grows with the request; keep a step's grid to 64 x 64)
        const double per_axis = double(surface.spans_u() > surface.spans_v() ? surface.spans_u()
                                                                             : surface.spans_v()) *
                                    std::pow(double(n < 1 ? 1 : n), ho.levels) +
                                2;
        if (per_axis > 64) return 0;
        if (!sample_hierarchy(surface, ho, hs).ok()) return 0;
        sampling = &hs;
    }
    // Keep one input cheap: at most (B N^L s + 2)^2 vertices with B, N, L, s small.
    const double side = double(surface.spans_u() > surface.spans_v() ? surface.spans_u()
                                                                      : surface.spans_v()) *
                            std::pow(double(n < 1 ? 1 : n), o.grid_level) * o.subdivisions +
                        2;
    // (found: 200 x 200 vertices of the direct superposition exceeded the 1 s timeout under
    // the sanitizers: work that grows with the request, not a defect; 64 keeps inputs fast)
    if (side > 64) return 0;
    // The work is not the grid alone: every vertex sums (degree + 1)^2 control points for its
    // base point (P, dP/du, dP/dv: 12 channels) and again for each attribute evaluation (8
    // channels): one for eq. (15) or the plain surface, K + 1 for eq. (16), 1 + K' for eq. (20).
    // (found: timeout_ist_inverse_per_vertex, 53 x 53 vertices of eq. (15) on a bicubic patch,
    // about 0.9 M of these units, 40 ms under the sanitizers, timed out on a loaded machine;
    // the IST inverse it pointed at is < 0.1 % of the time, evaluated once per grid line.
    // A degree-7 patch with eq. (16), K = 5, 56 x 56 vertices is 12 M units, 0.46 s. Keep an
    // input to 2 M units, under 0.1 s.)
    const int evaluations = o.form == WrSurfaceForm::base                ? 0
                            : o.form == WrSurfaceForm::superposed_direct ? o.levels + 1
                            : o.form == WrSurfaceForm::superposed        ? 1 + hs.levels()
                                                                         : 1;
    const double points = double(degree + 1) * double(degree + 1);
    if (side * side * points * (12.0 + 8.0 * evaluations) > 2e6) return 0;
    WrMesh wm;
    if (!tessellate_wr_surface(surface, sampling, o, wm).ok()) return 0;
    const TriangleMesh& m = wm.mesh;
    const std::size_t nv = m.positions.size();
    FUZZ_REQUIRE(nv == std::size_t(wm.grid_u) * std::size_t(wm.grid_v));
    FUZZ_REQUIRE(wm.transparency.size() == nv);
    FUZZ_REQUIRE(m.normals.size() == nv);
    FUZZ_REQUIRE(m.uvs.size() == nv && m.colors.size() == nv);
    FUZZ_REQUIRE(m.indices.size() % 3 == 0);
    for (std::uint32_t i : m.indices) FUZZ_REQUIRE(i < nv);
    for (std::size_t i = 0; i < nv; ++i) {
        FUZZ_REQUIRE(fuzz::finite3(m.positions[i]) && fuzz::finite3(m.normals[i]) && fuzz::finite3(m.colors[i]));
        FUZZ_REQUIRE(std::isfinite(wm.transparency[i]));
        const Vec2 uv = m.uvs[i];
        FUZZ_REQUIRE(uv.x >= o.u0 && uv.x <= o.u1 && uv.y >= o.v0 && uv.y <= o.v1);
    }
    return 0;
}
