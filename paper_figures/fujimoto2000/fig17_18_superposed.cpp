// fujimoto2000 figs. 17 and 18: superposed IST-Bezier (unit-IST N = 3) and superposed
// IST-B-spline (fully-connected N = 3) surfaces. Panels: (1) control mesh, the sticks with a
// dot at the tip are the heights h_i; (2) conventional surface; (3) WR surface, eq. (15);
// (4), (5) superposed WR surfaces, eq. (20) (hierarchical sampling), with a constant ratio
// function delta: small delta smooth, large delta rough "mountain ranges" (§4.1), against the
// "spiky" plain WR surface of (3).
// Row (a) is the surface as designed; row (b) the same surface after a few heights h_i change
// (§4.1: (a-1) -> (b-1) deforms (a-4,5) -> (b-4,5) "like an avalanche", 雪崩式変形). Each (b)
// panel's note measures how far the change reaches: the share of the surface that moved by
// more than 0.1 % of max|h_i| between (a) and (b). A Bezier control point acts on the whole
// patch; a B-spline one on 4 x 4 spans, and the IST carries that change to the places it maps
// there (every small interval whose source lies in the changed region).
// Each panel (4)(5) measures its shape (measure_shape): how far it departs from (2), the
// relief's anisotropy and repetition, its step share and its flat-step share against eq. (16)
// evaluated directly (fig. 19(b)'s staircase, which §4.2's hierarchical sampling avoids).
// Why fig. 18 terraced (measured): the sampling was already §4.2's (one sample per small
// region at its midpoint, fig. 19(b)'s dots, interpolated as in fig. 19(c)/(d)); what made the
// blocky terraces is the fully-connected IST itself. At every step k >= 2 the three small
// intervals of each triple take H from x, x + 1/24 and x + 1/8 of the patch (eq. 12: a base
// interval and its neighbours), so every H^k is the same ramp-ramp-drop sawtooth, of the
// amplitude of H's change across one base interval, on the slopes of the range; the IST acts
// on u and v separately (a direct product, §6), so the teeth of all steps line up along u and
// v into rectangular blocks. §5 builds its models the way fig. 18 is built (superposed
// IST-B-spline, n = 3, fully-connected IST) and gives the sample values Gaussian randomness
// "to add naturalness" (§5); fig. 18 now does the same, at fig. 21's terrain deviation. The
// teeth no longer line up: the flat-step share of (a-4) / (a-5) falls from 0.150 / 0.173 (eq.
// (16) directly: 0.173 / 0.263) to 0.116 / 0.122, and the blocks are gone from the image.
// Why fig. 17 was a regular quilt (measured): the unit-IST reverses the digits (eq. 7), so
// each step k >= 2 tiles the Bezier patch with N^(k-1) x N^(k-1) small copies of the whole H,
// and the superposed relief was a lattice of bumps at every scale (spectral-line share of
// (a-5) 0.29 against fig. 18's 0.05), with (a-4) hardly told from the dome (departure 0.23).
// Fig. 17 now takes §5's jitter too, at a deviation chosen to break the lattice (kJitterFig17):
// line share 0.05 and departure 0.35 / 0.58 for (a-4) / (a-5).
// Example: examples/31_superposed_mountains.cpp.
#include <algorithm>
#include <cmath>

#include "driver/figure.hpp"
#include "fujimoto2000/spectral_lines.hpp"
#include "fujimoto2000/wr_figure_common.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"
#include "shitsukan/core/detmath.hpp"
#include "shitsukan/wrinkly/superposition.hpp"

namespace shitsukan::fujimoto2000 {
namespace {

using figures::FigureContext;
using figures::fmt;

// Chosen in one place for both figures: the two ratio values of panels (4) and (5). The text
// prints none for figs. 17-18; it says only "the smaller delta the smoother, the larger the
// rougher" (§4.1) and that delta sets the fractal dimension as in ordinary fractals (eq. 17);
// fig. 22 prints 0.25 / 0.50 / 0.75 and fig. 23 0.60. These are fig. 22's two larger values:
// with the unit-IST of fig. 17 the first step is the identity (a one-digit reversal, eq. 7),
// so steps 0 and 1 both carry the smooth H and hold W^0 + W^1 = 1 - delta^2 of the weight:
// 88 % at the former 0.35, where (a-4) departed from the plain (a-2) by only 0.11 of its
// height variation (measured, notes); 75 % at 0.5 (0.23) and 44 % at 0.75.
constexpr float kDeltaSmooth = 0.5f, kDeltaRough = 0.75f;

// Chosen: §5 gives the sample values of its superposed models Gaussian randomness "to add
// naturalness" and prints no deviation; both figures here take it (height x (1 + s g)).
// Fig. 18: fig. 21's terrain deviation s = 0.12 (fig21_terrain.cpp), enough to keep the
// fully-connected IST's teeth from lining up into terraces (top of this file).
// Fig. 17: s = 0.5. Without it the unit-IST Bezier panels (4)(5) were a regular quilt, not
// §4.1's "mountain ranges": the unit-IST reverses the digits (eq. 7), so every step k >= 2
// tiles the patch with N^(k-1) x N^(k-1) small copies of the whole H (a lattice whose period
// is three small regions), each copy with H's full height variation, and the sum is a
// lattice at every step: measured spectral-line share (measure_shape) 0.19 / 0.29 for
// (a-4) / (a-5), 0.15 / 0.28 for (b-4) / (b-5), against fig. 18's 0.02 to 0.05. Relative
// jitter has to compete with the copies' full height variation: s = 0.12 left 0.09 to 0.25,
// 0.3 left 0.06 to 0.13, 0.4 left 0.02 to 0.09; 0.5 brings every panel within fig. 18's
// range (0.01 to 0.05) and lifts (a-4)'s departure from the plain (a-2) from 0.23 to 0.35.
constexpr float kJitterFig18 = 0.12f, kJitterFig17 = 0.5f;

Vec3 height_color(float h, float hmax) {
    const Vec3 low{0.50f, 0.58f, 0.34f}, high{0.88f, 0.84f, 0.78f};
    return lerp(low, high, clamp(h / hmax, 0.0f, 1.0f));
}

// fig. 17 (chosen): 4 x 4 Bezier points on [-1.2, 1.2]^2 (flat), a diagonal ridge of heights
// up to 1.2 running away from the camera. The unit-IST spreads copies of the whole H over the
// patch (§2.2.1): a single hump made them a quilt of humps (relief anisotropy of (a-5) 0.22
// on a 243-cell grid, at delta 0.65); a ridge makes ranges with one strike (0.66 on that grid
// at delta 0.75; the notes measure on 162 cells). Row (b): the front corner (column 3, row 3) is
// raised from 0.05 to 1.0, the ridge point at column 1, row 2 lowered from 1.10 to 0.5.
WrControlMesh fig17_mesh(bool changed) {
    static const float h[4][4] = {{0.05f, 0.15f, 0.50f, 1.00f},
                                  {0.15f, 0.60f, 1.20f, 0.45f},
                                  {0.40f, 1.10f, 0.55f, 0.10f},
                                  {0.90f, 0.50f, 0.20f, 0.05f}};
    return square_control_mesh(4, 1.2f, [changed](int c, int r, float, float, WrControlPoint& p) {
        p.height = h[r][c];
        if (changed && r == 3 && c == 3) p.height = 1.0f;
        if (changed && r == 2 && c == 1) p.height = 0.5f;
        p.color = height_color(p.height, 1.2f);
    });
}

// fig. 18 (chosen): 11 x 11 B-spline points on [-1.5, 1.5]^2 (8 x 8 spans), flat; a winding
// mountain range through the middle (heights up to 0.7) with a hashed variation (seed 18).
// Row (b): four points beside the ridge (columns 7-8, rows 2-3, towards the camera) raised by
// 0.45: a new spur off the range.
WrControlMesh fig18_mesh(bool changed) {
    return square_control_mesh(
        11, 1.5f, [changed](int c, int r, float x, float z, WrControlPoint& p) {
            const float d = z + 0.1f - 0.35f * det_sin(1.6f * x);  // distance from a winding ridge
            p.height = 0.05f +
                       0.55f * det_expf(-3.0f * d * d) * (0.65f + 0.6f * hash_uniform(18, 0, c, r));
            if (changed && (r == 2 || r == 3) && (c == 7 || c == 8)) p.height += 0.45f;
            p.color = height_color(p.height, 0.65f);
        });
}

struct SuperFigure {
    SurfaceBasis basis;
    IstKind kind;
    WrControlMesh (*mesh)(bool changed);
    int wr_levels;  // K of panel (3)
    int max_level;  // cap of the adaptive choice
    Shot shot;
    // §5's Gaussian jitter on the height samples of (4)(5) (relative deviation; 0 = none).
    float jitter_height;
};

const SuperFigure kFig17{SurfaceBasis::bezier,
                         IstKind::unit,
                         fig17_mesh,
                         4,
                         5,
                         Shot{{2.9f, 2.6f, 2.9f}, {0.0f, 0.3f, 0.0f}, {0, 1, 0}, 36.0f},
                         kJitterFig17};
const SuperFigure kFig18{SurfaceBasis::bspline,
                         IstKind::fully_connected,
                         fig18_mesh,
                         3,
                         4,
                         Shot{{3.3f, 3.0f, 3.3f}, {0.0f, 0.15f, 0.0f}, {0, 1, 0}, 35.0f},
                         kJitterFig18};

// The surface of one row (changed = row b) with its axes, ready to tessellate.
struct RowSurface {
    WrControlMesh mesh;
    WrSurface surface;
    AxisPair axes;
};
Status make_row_surface(const SuperFigure& f, bool changed, float delta, RowSurface* out) {
    out->mesh = f.mesh(changed);
    for (WrControlPoint& p : out->mesh.points) p.delta = delta;  // constant ratio function
    SHITSUKAN_TRY(make_wr_surface(out->mesh, f.basis, 3, out->surface));
    SHITSUKAN_TRY(make_axes(out->surface, f.kind, "fully", 3, kMaxWrLevel, &out->axes));
    return out->surface.set_axes(out->axes.u.axis(), out->axes.v.axis());
}

// Tessellation options of panel 2..5 (and the sampling of 4, 5). `coarse`: a grid for measuring.
Status panel_options(const SuperFigure& f, const RowSurface& rs, int panel, bool quick, bool coarse,
                     int size, WrTessellationOptions* o, HierarchicalSampling* hs,
                     std::string* chosen) {
    if (panel == 2) {
        o->form = WrSurfaceForm::plain;
        o->grid_level = quick || coarse ? 2 : 3;
        o->subdivisions = coarse ? 1 : 2;
    } else if (panel == 3) {
        o->form = WrSurfaceForm::wr;
        o->levels = quick ? 2 : f.wr_levels;
        o->grid_level = o->levels;
        o->subdivisions = quick || coarse ? 1 : 2;
        *chosen = fmt("K = %d", o->levels);
    } else {
        // Adaptive sampling: grid cells of <= 2 pixels, the sum stops when the rest of it is
        // below half a pixel (§4.2), both capped.
        const float ppu = shot_pixels_per_unit(f.shot, size);
        const AdaptiveLevels a =
            choose_adaptive_levels(rs.surface, rs.mesh, ppu, 2.0f, 0.5f, quick ? 2 : f.max_level);
        HierarchicalOptions ho;
        ho.levels = std::max(a.sum_levels, 1);
        ho.interpolation = SampleInterpolation::hermite;
        ho.jitter_height = f.jitter_height;
        ho.seed = f.basis == SurfaceBasis::bezier ? 17 : 18;
        SHITSUKAN_TRY(sample_hierarchy(rs.surface, ho, *hs));
        o->form = WrSurfaceForm::superposed;
        o->grid_level = coarse ? std::min(a.grid_level, 3) : a.grid_level;
        o->subdivisions = 1;
        o->tail_tolerance = a.world_tolerance;
        *chosen = fmt("grid level %d, K = %d, tail tolerance %.4f", a.grid_level, ho.levels,
                      double(a.world_tolerance));
    }
    return Status::success();
}

// How far the change (a) -> (b) reaches in panel 2..5: the share of grid vertices (uniform in
// u, v) that moved by more than 0.1 % of max|h_i|, and the largest move.
Status measure_reach(const SuperFigure& f, int panel, float delta, bool quick, int size,
                     double* share, double* largest) {
    WrMesh m[2];
    float hmax = 0;
    for (int row = 0; row < 2; ++row) {
        RowSurface rs;
        SHITSUKAN_TRY(make_row_surface(f, row == 1, delta, &rs));
        hmax = std::max(hmax, rs.surface.max_abs_height());
        WrTessellationOptions o;
        HierarchicalSampling hs;
        std::string unused;
        SHITSUKAN_TRY(panel_options(f, rs, panel, quick, true, size, &o, &hs, &unused));
        SHITSUKAN_TRY(evaluate_wr_grid(rs.surface, panel >= 4 ? &hs : nullptr, o, m[row]));
    }
    long moved = 0;
    double big = 0;
    const std::size_t n = m[0].mesh.positions.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double d = length(m[1].mesh.positions[i] - m[0].mesh.positions[i]);
        if (d > 0.001 * hmax) ++moved;
        big = std::max(big, d);
    }
    *share = n ? double(moved) / double(n) : 0.0;
    *largest = big;
    return Status::success();
}

// What panels (4)(5) must show, measured on the displacement height of eq. (20) over a
// 162 x 162 grid of (u, v) (cell centres; the panel's own hierarchical samples, no tail cut):
//   departure:   RMS of (superposed - conventional height) over the RMS variation of the
//                conventional height: about 0 when (4) cannot be told from the plain (2);
//   anisotropy:  of the relief r = superposed - conventional, from its gradient's structure
//                tensor J = sum (grad r)(grad r)^T: sqrt((Jxx - Jyy)^2 + 4 Jxy^2) / (Jxx + Jyy),
//                0 for bumps alike in every direction (a quilt), towards 1 for ridges with
//                one strike (ranges);
//   repetition:  the correlation of r with r shifted by a third of the patch along u, the
//                period of the unit-IST's copies (a regular quilt repeats: near 1);
//   step_share:  the share of the relief's squared differences between neighbouring grid
//                cells (along u and v) carried by the 3 % largest ones: near 0.03 for smooth
//                slopes, large when the relief is made of flat treads and walls (fig. 19(b)'s
//                staircase); step_share_direct: the same for eq. (16) evaluated directly at
//                the same steps, the staircase §4.2's hierarchical sampling is to avoid.
//   flat_share:  the terrace measure (a histogram of slopes, its near-zero bin): along 16
//                profiles in u and 16 in v, each sampled 3 N^K / 2 times per base interval
//                span (finer than the step-K small intervals, so eq. (16)'s treads show), the
//                share of steps |dh| below a tenth of the mean |dh|; flat_share_direct: the
//                same for eq. (16) evaluated directly (fig. 19(b)'s naive sampling).
//   line_share:  regular quilt or irregular ranges: the share of the relief's power spectrum
//                (wavenumbers >= 3 cycles per patch) held by isolated spectral lines, bins
//                over 30 times the mean of the ring two bins around them (spectral_lines.hpp).
//                A regular lattice of bumps is a few lines (fig. 17 without jitter: 0.15 to
//                0.29), an irregular relief a spread spectrum (fig. 18: 0.02 to 0.05).
// Chosen (measured on both figures): the line threshold 30 and the wavenumber floor 3 (a third
// of the patch, the unit-IST's first copies). At 10 the B-spline relief's ridges along u
// counted as lines too (0.35 to 0.55).
constexpr double kLineMinWavenumber = 3.0, kLineFactor = 30.0;
struct ShapeStats {
    double departure = 0, anisotropy = 0, repetition = 0, step_share = 0, step_share_direct = 0;
    double flat_share = 0, flat_share_direct = 0, line_share = 0;
};
double top_share(std::vector<double> d2) {
    std::sort(d2.begin(), d2.end());
    double total = 0, top = 0;
    for (std::size_t i = 0; i < d2.size(); ++i) {
        total += d2[i];
        if (i >= d2.size() - d2.size() * 3 / 100) top += d2[i];
    }
    return total > 0 ? top / total : 0.0;
}
// One parameter value located once along u or v: its spline basis, its sample weights for
// k = 1..K and the bases at its IST inverses for k = 0..K (eq. (16) directly). Evaluating from
// these gives the same bits as evaluating at the point (hierarchical_sampling.hpp,
// superposition.hpp); the measures below evaluate on grids and profiles, so they locate each
// parameter once.
struct ParamAt {
    float x = 0;
    WrBasisAt basis;
    std::vector<SampleWeights> weights;
    std::vector<WrBasisAt> inverse;
};
std::vector<ParamAt> locate_params(const WrSurface& surface, const HierarchicalSampling& hs,
                                   int axis, const std::vector<float>& xs) {
    std::vector<ParamAt> out(xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
        ParamAt& p = out[i];
        p.x = xs[i];
        p.basis = axis == 0 ? surface.basis_u(p.x) : surface.basis_v(p.x);
        for (int k = 1; k <= hs.levels(); ++k)
            p.weights.push_back(axis == 0 ? hs.weights_u(k, p.x) : hs.weights_v(k, p.x));
        for (int k = 0; k <= hs.levels(); ++k)
            p.inverse.push_back(axis == 0 ? surface.basis_u(surface.inverse_u(p.x, k))
                                          : surface.basis_v(surface.inverse_v(p.x, k)));
    }
    return out;
}
// (i + 1/2) / n for i = 0 .. n - 1.
std::vector<float> cell_centres(int n) {
    std::vector<float> x(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) x[std::size_t(i)] = (float(i) + 0.5f) / float(n);
    return x;
}
double plain_height(const WrSurface& surface, const ParamAt& pu, const ParamAt& pv) {
    return double(surface.attributes(pu.basis, pv.basis).height);
}
double sampled_height(const WrSurface& surface, const HierarchicalSampling& hs, const ParamAt& pu,
                      const ParamAt& pv) {
    return double(superposed_sampled(surface, hs, pu.basis, pv.basis, pu.weights.data(),
                                     pv.weights.data(), pu.x, pv.x, 0.0f)
                      .attributes.height);
}
double direct_height(const WrSurface& surface, int levels, const ParamAt& pu, const ParamAt& pv) {
    const float delta = surface.base_point(pu.basis, pv.basis, pu.x, pv.x).delta;
    return double(
        superposed_attributes_direct(surface, delta, pu.inverse.data(), pv.inverse.data(), levels)
            .height);
}

double direct_step_share(const WrSurface& surface, int levels, const std::vector<ParamAt>& pu,
                         const std::vector<ParamAt>& pv) {
    const int n = int(pu.size());
    std::vector<double> r(std::size_t(n) * n), d2;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            r[std::size_t(j) * n + i] =
                direct_height(surface, levels, pu[std::size_t(i)], pv[std::size_t(j)]) -
                plain_height(surface, pu[std::size_t(i)], pv[std::size_t(j)]);
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const std::size_t k = std::size_t(j) * n + i;
            d2.push_back((r[k + 1] - r[k]) * (r[k + 1] - r[k]));
            d2.push_back((r[k + n] - r[k]) * (r[k + n] - r[k]));
        }
    return top_share(d2);
}

// The flat-step share of one height function along 16 profiles in u and 16 in v (see above);
// height(pu, pv) from located parameters.
template <class Height> double flat_step_share(const WrSurface& surface,
                                               const HierarchicalSampling& hs, int n,
                                               Height height) {
    const std::vector<float> along = cell_centres(n), across = cell_centres(16);
    const std::vector<ParamAt> along_u = locate_params(surface, hs, 0, along),
                               along_v = locate_params(surface, hs, 1, along),
                               across_u = locate_params(surface, hs, 0, across),
                               across_v = locate_params(surface, hs, 1, across);
    std::vector<double> d;
    d.reserve(std::size_t(32) * std::size_t(n));
    for (int p = 0; p < 16; ++p) {
        for (int axis = 0; axis < 2; ++axis) {
            double prev = 0;
            for (int i = 0; i < n; ++i) {
                const double h = axis == 0
                                     ? height(along_u[std::size_t(i)], across_v[std::size_t(p)])
                                     : height(across_u[std::size_t(p)], along_v[std::size_t(i)]);
                if (i > 0) d.push_back(std::fabs(h - prev));
                prev = h;
            }
        }
    }
    double mean = 0;
    for (double x : d) mean += x;
    mean /= double(d.size());
    long flat = 0;
    for (double x : d) flat += x < 0.1 * mean;
    return d.empty() ? 0.0 : double(flat) / double(d.size());
}
void measure_flat_steps(const WrSurface& surface, const HierarchicalSampling& hs, ShapeStats* st) {
    long n = surface.axis_v().base_intervals;
    for (int k = 0; k < hs.levels(); ++k) n *= surface.axis_v().division;
    n = n * 3 / 2;
    st->flat_share = flat_step_share(
        surface, hs, int(n),
        [&](const ParamAt& pu, const ParamAt& pv) { return sampled_height(surface, hs, pu, pv); });
    st->flat_share_direct =
        flat_step_share(surface, hs, int(n), [&](const ParamAt& pu, const ParamAt& pv) {
            return direct_height(surface, hs.levels(), pu, pv);
        });
}

ShapeStats measure_shape(const WrSurface& surface, const HierarchicalSampling& hs) {
    const int n = 162;  // a third of the patch is 54 cells
    const std::vector<ParamAt> pu = locate_params(surface, hs, 0, cell_centres(n)),
                               pv = locate_params(surface, hs, 1, cell_centres(n));
    std::vector<double> r(std::size_t(n) * n), h(r.size());
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const ParamAt &a = pu[std::size_t(i)], &b = pv[std::size_t(j)];
            const double plain = plain_height(surface, a, b);
            h[std::size_t(j) * n + i] = plain;
            r[std::size_t(j) * n + i] = sampled_height(surface, hs, a, b) - plain;
        }
    double mh = 0, mr = 0;
    for (std::size_t i = 0; i < r.size(); ++i) mh += h[i], mr += r[i];
    mh /= double(h.size());
    mr /= double(r.size());
    double vh = 0, vr = 0, jxx = 0, jyy = 0, jxy = 0, c = 0, c0 = 0, c1 = 0;
    std::vector<double> du2;
    const int shift = n / 3;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t k = std::size_t(j) * n + i;
            vh += (h[k] - mh) * (h[k] - mh);
            vr += (r[k] - mr) * (r[k] - mr);
            if (i + 1 < n && j + 1 < n) {
                const double gx = r[k + 1] - r[k], gy = r[k + n] - r[k];
                jxx += gx * gx, jyy += gy * gy, jxy += gx * gy;
                du2.push_back(gx * gx);
                du2.push_back(gy * gy);
            }
            if (i + shift < n) {
                const double a = r[k] - mr, b = r[k + shift] - mr;
                c += a * b, c0 += a * a, c1 += b * b;
            }
        }
    ShapeStats st;
    st.departure = vh > 0 ? std::sqrt(vr / vh) : 0.0;
    st.anisotropy =
        jxx + jyy > 0 ? std::sqrt((jxx - jyy) * (jxx - jyy) + 4 * jxy * jxy) / (jxx + jyy) : 0.0;
    st.repetition = c0 > 0 && c1 > 0 ? c / std::sqrt(c0 * c1) : 0.0;
    st.step_share = top_share(std::move(du2));
    st.line_share = spectral_line_share(r, n, kLineMinWavenumber, kLineFactor);
    st.step_share_direct = direct_step_share(surface, hs.levels(), pu, pv);
    measure_flat_steps(surface, hs, &st);
    return st;
}

// Panels (4)(5): the measured shape in the notes, and the checks of §4.1 and §4.2.
Status note_and_check_shape(FigureContext& ctx, const SuperFigure& f, const WrSurface& surface,
                            const HierarchicalSampling& hs, int panel) {
    const bool quick = ctx.quick();
    const bool bezier = f.basis == SurfaceBasis::bezier;
    const ShapeStats st = measure_shape(surface, hs);
    ctx.note(
        fmt("Shape (measured on eq. (20)'s height): departure from (2) %.2f, relief "
            "anisotropy %.2f, repetition at a third of the patch %.2f, step share %.2f "
            "against eq. (16) directly %.2f, flat-step share %.3f against eq. (16) directly "
            "%.3f, spectral-line share %.3f (a regular quilt towards 1, irregular ranges "
            "towards 0; definitions: measure_shape in the source).",
            st.departure, st.anisotropy, st.repetition, st.step_share, st.step_share_direct,
            st.flat_share, st.flat_share_direct, st.line_share));
    // §4.1: (4) and (5) are not the conventional surface, and fig. 17's read as ranges.
    // §4.2: hierarchical sampling avoids eq. (16)'s staircase (fig. 19(b)); fig. 18's
    // fully-connected IST adds its own ramp-ramp-drop teeth at every step (see the top of
    // this file), which §5's jitter keeps from lining up into terraces.
    // The checks hold the full run (--quick sums fewer steps on a coarser grid).
    if (!quick && st.step_share > 0.8 * st.step_share_direct)
        return Status::error(StatusCode::not_supported,
                             "superposed panel (%d): step share %.2f against eq. (16)'s "
                             "%.2f: the hierarchical sampling does not avoid the staircase",
                             panel, st.step_share, st.step_share_direct);
    // §4.2: no staircase. Every panel has fewer flat steps than eq. (16); fig. 18, whose
    // teeth lined up into terraces without §5's jitter, under 0.75 of eq. (16)'s.
    const double flat_limit = f.kind == IstKind::fully_connected ? 0.75 : 1.0;
    if (!quick && st.flat_share > flat_limit * st.flat_share_direct)
        return Status::error(StatusCode::not_supported,
                             "superposed panel (%d): flat-step share %.3f against eq. (16)'s "
                             "%.3f: terraces (fig. 19(b)'s staircase) remain",
                             panel, st.flat_share, st.flat_share_direct);
    // §4.1: "mountain ranges", not the plain surface and not a regular quilt of bumps. Fig.
    // 17's (4) departs from (2) by at least 0.3 of its height variation (0.23 without §5's
    // jitter, cannot be told from the dome); every panel's spectral-line share stays under
    // 0.08 (fig. 18: 0.02 to 0.05; fig. 17 without the jitter 0.15 to 0.29).
    const double min_departure = bezier ? 0.3 : 0.15;
    if (!quick && (st.departure < min_departure || st.line_share > 0.08 ||
                   (bezier && panel == 5 && st.anisotropy < 0.4)))
        return Status::error(StatusCode::not_supported,
                             "superposed panel (%d): departure %.2f, spectral-line share %.3f, "
                             "anisotropy %.2f: does not read as §4.1's mountain ranges",
                             panel, st.departure, st.line_share, st.anisotropy);
    return Status::success();
}

Status run_panel(FigureContext& ctx, const SuperFigure& f, char row, int panel) {
    const bool quick = ctx.quick();
    const int size = quick ? 128 : 512;
    const bool bezier = f.basis == SurfaceBasis::bezier;
    ctx.given("base surface", bezier ? "Bezier n = 3" : "uniform B-spline n = 3",
              "§4.1, figs. 17-18");
    ctx.given("weights", "W^k = (1 - delta) delta^k", "eq. (19)");
    ctx.chosen("IST", f.kind == IstKind::unit ? "unit-IST N = 3" : "fully-connected IST N = 3",
               "the ISTs of figs. 14/15");
    ctx.chosen("control mesh",
               bezier ? "4 x 4 flat, diagonal ridge of heights 0.05..1.2"
                      : "11 x 11 flat (8 x 8 spans), winding range up to 0.7",
               "not printed");
    if (row == 'b')
        ctx.chosen("height change (a-1) -> (b-1)",
                   bezier ? "front corner 0.05 -> 1.0, ridge point (1, 2) 1.10 -> 0.5"
                          : "four points beside the ridge (columns 7-8, rows 2-3) +0.45",
                   "the paper changes some h_i and does not print them");
    ctx.chosen("image size", fmt("%d x %d", size, size), "not given");
    const float delta = panel == 4 ? kDeltaSmooth : kDeltaRough;
    RowSurface rs;
    SHITSUKAN_TRY(make_row_surface(f, row == 'b', delta, &rs));
    RgbImage img(size, size);
    Shading shading;
    // Chosen: a diagonal view (45 degrees to u and v) and light from above and the left, so
    // neither parameter's IST stripes line up with the view.
    shading.light = Vec3{-0.6f, 1.0f, 0.2f};
    const Camera camera = shot_camera(f.shot, size, size);
    if (panel == 1) {
        // Wider than the surface panels: the control polygon reaches beyond the surface.
        const Camera wide = shot_camera(zoom_shot(f.shot, f.shot.target, 0.8f), size, size);
        draw_control_mesh(img.view(), wide, rs.mesh, rs.surface, true, shading.background);
        return ctx.save_png(img.view());
    }
    WrTessellationOptions o;
    HierarchicalSampling hs;
    std::string chosen;
    SHITSUKAN_TRY(panel_options(f, rs, panel, quick, false, size, &o, &hs, &chosen));
    if (panel == 3) ctx.chosen("K", chosen, "small intervals of a few pixels");
    if (panel >= 4) {
        ctx.chosen("delta", fmt("%.2f (constant)", double(delta)),
                   "fig. 22's 0.50 / 0.75 (§4.1: smaller smoother, larger rougher; no value "
                   "printed for figs. 17-18); the unit-IST's first step is the identity, so "
                   "1 - delta^2 of the weight stays on the smooth H");
        if (f.jitter_height > 0)
            ctx.chosen("jitter",
                       fmt("height samples x (1 + %.2f g), g ~ N(0, 1)", double(f.jitter_height)),
                       bezier ? "§5's Gaussian randomness on the sample values; without it the "
                                "unit-IST's copies of H tile the patch into a regular quilt "
                                "(spectral-line share 0.15 to 0.29; deviation chosen so it falls "
                                "within fig. 18's 0.02 to 0.05)"
                              : "§5's Gaussian randomness on the sample values of its superposed "
                                "IST-B-spline models, at fig. 21's deviation; without it the "
                                "fully-connected IST's teeth line up into terraces");
        ctx.chosen("sample interpolation", "Hermite",
                   "fig. 19(d); the paper does not say for figs. 17-18");
        ctx.chosen("adaptive sampling", chosen, "cells <= 2 px, omitted rest of the sum < 0.5 px");
    }
    WrMesh wm;
    SHITSUKAN_TRY(tessellate_wr_surface(rs.surface, panel >= 4 ? &hs : nullptr, o, wm));
    RasterStats stats;
    SHITSUKAN_TRY(render_opaque(camera, wm.mesh, img.view(), shading, &stats));
    ctx.note(fmt("%d triangles; superposition steps used: max %d, mean %.2f.",
                 wm.mesh.triangle_count(), wm.max_levels_used, wm.mean_levels_used));
    if (panel >= 4) {
        SHITSUKAN_TRY(note_and_check_shape(ctx, f, rs.surface, hs, panel));
    }
    if (row == 'b') {
        double share = 0, largest = 0;
        SHITSUKAN_TRY(measure_reach(f, panel, delta, quick, size, &share, &largest));
        ctx.note(
            fmt("Reach of the height change (a) -> (b): %.1f %% of the surface moved by more "
                "than 0.1 %% of max|h_i| (largest move %.3f).",
                100.0 * share, largest));
    }
    return ctx.save_png(img.view());
}

}  // namespace

#define SUPER_PANEL(fig, row, i, figure, caption)                                  \
    SHITSUKAN_FIGURE(fig##row##i##_panel, "fujimoto2000", #fig #row #i, caption) { \
        return run_panel(ctx, figure, (#row)[0], i);                               \
    }

#define SUPER_ROW(fig, row, figure, name, plain, when)                                            \
    SUPER_PANEL(fig, row, 1, figure, name ": (" #row "-1) control mesh with heights h_i" when)    \
    SUPER_PANEL(fig, row, 2, figure, name ": (" #row "-2) conventional " plain " surface" when)   \
    SUPER_PANEL(fig, row, 3, figure, name ": (" #row "-3) WR surface, eq. (15)" when)             \
    SUPER_PANEL(fig, row, 4, figure, name ": (" #row "-4) superposed, small delta (smooth)" when) \
    SUPER_PANEL(fig, row, 5, figure, name ": (" #row "-5) superposed, large delta (rough)" when)

SUPER_ROW(fig17, a, kFig17, "Superposed IST-Bezier", "Bezier", "")
SUPER_ROW(fig17, b, kFig17, "Superposed IST-Bezier", "Bezier", ", after some h_i change")
SUPER_ROW(fig18, a, kFig18, "Superposed IST-B-spline", "B-spline", "")
SUPER_ROW(fig18, b, kFig18, "Superposed IST-B-spline", "B-spline", ", after some h_i change")

}  // namespace shitsukan::fujimoto2000
