// shitsukan/wrinkly/hierarchical_sampling.hpp — fujimoto2000 §4.2, eq. (20): the superposed WR
// surface without the staircase of fig. 19(b).
//
//   R_D^inf(u,v) = P(u,v) + { sum_k W^k(u,v) H^k(u,v) } N(u,v)                         (20)
//
// At step k the parameter plane of each base interval is cut into N^k x N^k small regions
// (u small interval x v small interval, fig. 20). One point is sampled per region, at its
// centre — the midpoints of fig. 19(b) — plus points on the boundary where the surface is open
// (fig. 20: "sampling points also on the boundary edges"). Each sample takes the
// IST-transformed value H((F_U^k)^{-1}(u_s), (F_V^k)^{-1}(v_s)), optionally with Gaussian
// jitter (§5, figs. 22-23), and the samples are interpolated linearly or by Hermite
// interpolation with tangents from the neighbouring samples into H^k (fig. 19c, d).
// Colour and transparency are sampled and superposed the same way ("any attribute", §4.2).
//
// Manual
//   WrControlMesh mesh = make_control_mesh(8, 8);          // control_mesh.hpp
//   for (int r = 0; r < 8; ++r)
//       for (int c = 0; c < 8; ++c)
//           mesh.at(c, r).position = {c / 7.0f, r / 7.0f, 0.0f}, mesh.at(c, r).height = 0.05f;
//   WrSurface surface;
//   Status s = make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface);
//   if (!s) return s;
//   float u = 0.3f, v = 0.6f, tol = 1e-4f;
//   HierarchicalOptions o;  o.levels = 3;  o.interpolation = SampleInterpolation::hermite;
//   HierarchicalSampling hs;
//   Status st = sample_hierarchy(surface, o, hs);
//   if (!st) return st;
//   SuperposedSample p = superposed_sampled(surface, hs, u, v);       // eq. (20), k = 0..K
//   SuperposedSample q = superposed_sampled(surface, hs, u, v, tol);  // stop when the rest of
//                                                                     // the sum is below tol
//   #include "shitsukan/wrinkly/wr_surface.hpp"
// Choices made here (no value in the paper), each stated where it is used:
//   - H^0 = H itself: F^0 is the identity (eq. 16), so step 0 has no staircase to avoid.
//   - Jitter: height samples are scaled by (1 + jitter_height·g) (direction kept), colour and
//     transparency get + jitter·g per channel (clamped to [0, 1]); g ~ N(0,1) from the
//     coordinate hash of (sample i, j, step k), so it does not depend on evaluation order.
//   - eq. (18) is kept on the finite sum: every attribute (height and vector too) is divided by
//     the weights actually used, 1 - delta^(k_last + 1) (superposition.hpp). The omitted tail
//     would otherwise lower the surface by delta^(K+1) of its height (fig. 21 (g): 23 %).
// Ranges: levels (K) in 0..surface.max_level() (<= kMaxWrLevel), jitters >= 0 (jitter_height
// <= kMaxJitterHeight), sample count per step at most kMaxHierarchicalSamples (too_large
// otherwise).
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/wrinkly/wr_surface.hpp"

namespace shitsukan {

enum class SampleInterpolation : std::uint8_t { linear, hermite };

// Largest relative height jitter (chosen here: 100; a deviation of 100 times the height already
// turns a hill into noise, and with heights <= kMaxWrCoordinate the scaled samples stay far inside
// float: fuzz_wr_tessellation found infinite positions at 3.4e38).
constexpr float kMaxJitterHeight = 100.0f;

struct HierarchicalOptions {
    int levels = 3;  // K: steps k = 0..K are superposed
    SampleInterpolation interpolation = SampleInterpolation::linear;
    float jitter_height = 0;        // relative std. dev. of the height samples (<= 100)
    float jitter_color = 0;         // absolute std. dev. per colour channel
    float jitter_transparency = 0;  // absolute std. dev.
    std::uint32_t seed = 1;
};

constexpr long kMaxHierarchicalSamples = 8L * 1024 * 1024;  // per step, both axes

// Sample positions of step k along one axis, in the surface parameter [0, 1]:
// 0, (i + 1/2)/(B·N^k) for i = 0 .. B·N^k - 1, and 1 (B base intervals, N division).
// Empty when B < 1, N < 1, k < 0 or B·N^k > kMaxHierarchicalSamples (no overflow, no huge
// allocation).
std::vector<float> hierarchical_sample_positions(int base_intervals, int division, int k);

// Weights of the samples first .. first+3 for interpolating at u (sample positions `x`, count
// n >= 2). Linear uses two, Hermite (finite-difference tangents, one-sided at the ends) four.
void sample_interpolation_weights(const float* x, int n, float u, SampleInterpolation mode,
                                  int* first, float weights[4]);

// sample_interpolation_weights' result for one parameter: a grid computes it once per column
// (u) and row (v) and step k.
struct SampleWeights {
    int first = 0;
    float w[4] = {0, 0, 0, 0};
};

struct SuperposedSample {
    Vec3 position;            // R_D^inf(u, v)
    BasePoint base;           // P, N, delta at (u, v)
    WrAttributes attributes;  // summed height / vector; averaged colour and transparency
    int levels_used = 0;      // highest k added
};

class HierarchicalSampling {
public:
    int levels() const { return levels_; }
    SampleInterpolation interpolation() const { return interpolation_; }
    const std::vector<float>& positions_u(int k) const { return level(k).pos_u; }
    const std::vector<float>& positions_v(int k) const { return level(k).pos_v; }
    // The kWrAttributeChannels values of sample (i, j) of step k >= 1.
    const float* sample(int k, int i, int j) const;
    // H^k (and the other attributes) at (u, v); k >= 1.
    WrAttributes interpolate(int k, float u, float v) const;
    // The same from weights found once (weights_u(k, u), weights_v(k, v)): the same bits.
    SampleWeights weights_u(int k, float u) const;
    SampleWeights weights_v(int k, float v) const;
    WrAttributes interpolate(int k, const SampleWeights& wu, const SampleWeights& wv) const;
    long sample_count() const;  // all steps

private:
    friend Status sample_hierarchy(const WrSurface&, const HierarchicalOptions&,
                                   HierarchicalSampling&);
    struct Level {
        std::vector<float> pos_u, pos_v;
        std::vector<float> values;  // (j·|pos_u| + i)·channels
    };
    const Level& level(int k) const;
    int levels_ = 0;
    SampleInterpolation interpolation_ = SampleInterpolation::linear;
    std::vector<Level> levels_data_;  // index k - 1
};

Status sample_hierarchy(const WrSurface& surface, const HierarchicalOptions& options,
                        HierarchicalSampling& out);

// eq. (20) at (u, v), with the weights of the steps used renormalised to sum to 1 (eq. 18).
// tail_tolerance (world units, >= 0): stop before step k once delta^k·max|h_i| — a bound on
// the weight of everything still to be added times the largest height — is below it (the
// adaptive end of the sum, §4.2); 0 = add every sampled step. Renormalising moves the result
// by at most twice that bound. With jitter_height > 0 the samples may exceed max|h_i| by the
// factor (1 + jitter_height·g), so the bound is then approximate.
SuperposedSample superposed_sampled(const WrSurface& surface, const HierarchicalSampling& hs,
                                    float u, float v, float tail_tolerance = 0);
// The same with the bases at (u, v) located once (surface.basis_u(u), basis_v(v)) and, unless
// null, the sample weights of steps k = 1..hs.levels() at index k - 1 (hs.weights_u(k, u),
// weights_v(k, v)): a grid finds them per column and row. Same bits.
SuperposedSample superposed_sampled(const WrSurface& surface, const HierarchicalSampling& hs,
                                    const WrBasisAt& bu, const WrBasisAt& bv,
                                    const SampleWeights* wu, const SampleWeights* wv, float u,
                                    float v, float tail_tolerance);

}  // namespace shitsukan
