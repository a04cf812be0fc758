#include "shitsukan/wrinkly/hierarchical_sampling.hpp"

#include <cmath>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"
#include "shitsukan/wrinkly/superposition.hpp"

namespace shitsukan {

namespace {

// B N^k, saturated just above kMaxHierarchicalSamples (the product overflowed a long for
// large k); -1 for arguments without intervals (B < 1, N < 1, k < 0).
long small_intervals(int base_intervals, int division, int k) {
    if (base_intervals < 1 || division < 1 || k < 0) return -1;
    long m = base_intervals;
    for (int i = 0; i < k && m <= kMaxHierarchicalSamples; ++i) m *= division;
    return m > kMaxHierarchicalSamples ? kMaxHierarchicalSamples + 1 : m;
}

// Hash streams for the jitter of each attribute (hash.hpp: one stream per independent use).
enum : std::uint32_t { kStreamHeight = 20, kStreamColor = 21, kStreamTransparency = 24 };

}  // namespace

std::vector<float> hierarchical_sample_positions(int base_intervals, int division, int k) {
    const long m = small_intervals(base_intervals, division, k);
    if (m < 1 || m > kMaxHierarchicalSamples) return {};  // see the header
    std::vector<float> x(std::size_t(m + 2));
    x[0] = 0.0f;  // boundary sample (fig. 20: the surface is open)
    for (long i = 0; i < m; ++i) x[std::size_t(i + 1)] = float((double(i) + 0.5) / double(m));
    x[std::size_t(m + 1)] = 1.0f;
    return x;
}

void sample_interpolation_weights(const float* x, int n, float u, SampleInterpolation mode,
                                  int* first, float weights[4]) {
    SHITSUKAN_ASSERT(n >= 2);
    // Interval [x_i, x_{i+1}] holding u (binary search: the end intervals are half as wide).
    int lo = 0, hi = n - 1;
    u = u >= x[0] ? (u <= x[n - 1] ? u : x[n - 1]) : x[0];  // clamped; NaN -> x[0]
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (x[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    const int i = lo;
    const float d = x[i + 1] - x[i];
    const float t = d > 0 ? (u - x[i]) / d : 0.0f;
    for (int s = 0; s < 4; ++s) weights[s] = 0;
    *first = i - 1;  // slots: i-1, i, i+1, i+2
    if (mode == SampleInterpolation::linear) {
        weights[1] = 1.0f - t;  // fig. 19(c)
        weights[2] = t;
        return;
    }
    // fig. 19(d): cubic Hermite on [x_i, x_{i+1}] with tangents m_j from the neighbouring
    // samples, m_j = (y_{j+1} - y_{j-1}) / (x_{j+1} - x_{j-1}) (one-sided at the ends); the
    // spacing is uneven next to the boundary samples, so the tangents use true distances.
    const float t2 = t * t, t3 = t2 * t;
    const float h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t;
    const float h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
    weights[1] += h00;
    weights[2] += h01;
    auto add_tangent = [&](int j, float scale) {
        int a = j - 1, b = j + 1;
        if (a < 0) a = j;
        if (b > n - 1) b = j;
        const float c = scale / (x[b] - x[a]);
        weights[b - (i - 1)] += c;
        weights[a - (i - 1)] -= c;
    };
    add_tangent(i, d * h10);
    add_tangent(i + 1, d * h11);
}

const HierarchicalSampling::Level& HierarchicalSampling::level(int k) const {
    SHITSUKAN_ASSERT(k >= 1 && k <= levels_);
    return levels_data_[std::size_t(k - 1)];
}

const float* HierarchicalSampling::sample(int k, int i, int j) const {
    const Level& l = level(k);
    SHITSUKAN_ASSERT(i >= 0 && i < int(l.pos_u.size()) && j >= 0 && j < int(l.pos_v.size()));
    return l.values.data() +
           (std::size_t(j) * l.pos_u.size() + std::size_t(i)) * kWrAttributeChannels;
}

long HierarchicalSampling::sample_count() const {
    long n = 0;
    for (const Level& l : levels_data_) n += long(l.pos_u.size() * l.pos_v.size());
    return n;
}

WrAttributes HierarchicalSampling::interpolate(int k, float u, float v) const {
    return interpolate(k, weights_u(k, u), weights_v(k, v));
}

SampleWeights HierarchicalSampling::weights_u(int k, float u) const {
    const Level& l = level(k);
    SampleWeights r;
    sample_interpolation_weights(l.pos_u.data(), int(l.pos_u.size()), u, interpolation_, &r.first,
                                 r.w);
    return r;
}

SampleWeights HierarchicalSampling::weights_v(int k, float v) const {
    const Level& l = level(k);
    SampleWeights r;
    sample_interpolation_weights(l.pos_v.data(), int(l.pos_v.size()), v, interpolation_, &r.first,
                                 r.w);
    return r;
}

WrAttributes HierarchicalSampling::interpolate(int k, const SampleWeights& su,
                                               const SampleWeights& sv) const {
    const Level& l = level(k);
    const int nu = int(l.pos_u.size());
    const int fu = su.first, fv = sv.first;
    const float* wu = su.w;
    const float* wv = sv.w;
    float acc[kWrAttributeChannels] = {0};
    for (int b = 0; b < 4; ++b) {
        if (wv[b] == 0.0f) continue;
        const int j = fv + b;
        for (int a = 0; a < 4; ++a) {
            if (wu[a] == 0.0f) continue;
            const float w = wu[a] * wv[b];
            const float* s =
                l.values.data() +
                (std::size_t(j) * std::size_t(nu) + std::size_t(fu + a)) * kWrAttributeChannels;
            // Channel by channel, written out so that the compiler may do four at once (the
            // same product and sum per channel).
            static_assert(kWrAttributeChannels == 8, "two blocks of four channels");
            for (int c = 0; c < kWrAttributeChannels; c += 4) {
                acc[c] += w * s[c];
                acc[c + 1] += w * s[c + 1];
                acc[c + 2] += w * s[c + 2];
                acc[c + 3] += w * s[c + 3];
            }
        }
    }
    return attributes_from_channels(acc);
}

Status sample_hierarchy(const WrSurface& surface, const HierarchicalOptions& o,
                        HierarchicalSampling& out) {
    if (o.levels < 0 || o.levels > kMaxWrLevel)
        return Status::error(StatusCode::invalid_argument, "levels K must be in 0..%d (got %d)",
                             kMaxWrLevel, o.levels);
    if (!(o.jitter_height >= 0) || !(o.jitter_color >= 0) || !(o.jitter_transparency >= 0) ||
        !is_finite(o.jitter_height) || !is_finite(o.jitter_color) ||
        !is_finite(o.jitter_transparency))
        return Status::error(StatusCode::invalid_argument,
                             "jitter deviations must be finite and >= 0 (got %g, %g, %g)",
                             double(o.jitter_height), double(o.jitter_color),
                             double(o.jitter_transparency));
    if (o.jitter_height > kMaxJitterHeight)
        return Status::error(StatusCode::invalid_argument,
                             "jitter_height must be <= %g (got %g)", double(kMaxJitterHeight),
                             double(o.jitter_height));
    if (o.levels > surface.max_level())
        return Status::error(StatusCode::invalid_argument,
                             "levels K = %d exceeds the IST steps the surface's axes hold (%d): "
                             "build them with make_wr_ist_axis(..., max_level >= K, ...)",
                             o.levels, surface.max_level());
    const WrAxis& au = surface.axis_u();
    const WrAxis& av = surface.axis_v();
    for (int k = 1; k <= o.levels; ++k) {
        const double n = double(small_intervals(au.base_intervals, au.division, k) + 2) *
                         double(small_intervals(av.base_intervals, av.division, k) + 2);
        if (n > double(kMaxHierarchicalSamples))
            return Status::error(StatusCode::too_large,
                                 "step k = %d needs %.0f samples (%.0f MB); the limit is %ld", k, n,
                                 n * kWrAttributeChannels * 4 / 1e6, kMaxHierarchicalSamples);
    }
    HierarchicalSampling hs;
    hs.levels_ = o.levels;
    hs.interpolation_ = o.interpolation;
    hs.levels_data_.resize(std::size_t(o.levels));
    for (int k = 1; k <= o.levels; ++k) {
        HierarchicalSampling::Level& l = hs.levels_data_[std::size_t(k - 1)];
        l.pos_u = hierarchical_sample_positions(au.base_intervals, au.division, k);
        l.pos_v = hierarchical_sample_positions(av.base_intervals, av.division, k);
        // The IST acts on each axis separately (a direct product, §6): invert once per axis.
        std::vector<float> src_u(l.pos_u.size()), src_v(l.pos_v.size());
        for (std::size_t i = 0; i < src_u.size(); ++i) src_u[i] = surface.inverse_u(l.pos_u[i], k);
        for (std::size_t j = 0; j < src_v.size(); ++j) src_v[j] = surface.inverse_v(l.pos_v[j], k);
        // The spline bases depend on one parameter each: located once per column and row.
        std::vector<WrBasisAt> basis_u(src_u.size()), basis_v(src_v.size());
        for (std::size_t i = 0; i < src_u.size(); ++i) basis_u[i] = surface.basis_u(src_u[i]);
        for (std::size_t j = 0; j < src_v.size(); ++j) basis_v[j] = surface.basis_v(src_v[j]);
        l.values.resize(src_u.size() * src_v.size() * kWrAttributeChannels);
        for (std::size_t j = 0; j < src_v.size(); ++j) {
            for (std::size_t i = 0; i < src_u.size(); ++i) {
                // The sample: H((F_U^k)^{-1}(u_s), (F_V^k)^{-1}(v_s)) and the other attributes.
                WrAttributes a = surface.attributes(basis_u[i], basis_v[j]);
                const int ii = int(i), jj = int(j);
                if (o.jitter_height > 0) {
                    const float g =
                        1.0f + o.jitter_height * hash_gaussian(o.seed, kStreamHeight, ii, jj, k);
                    a.height *= g;
                    a.vector *= g;
                }
                if (o.jitter_color > 0) {
                    for (int c = 0; c < 3; ++c)
                        a.color[c] = clamp(
                            a.color[c] + o.jitter_color *
                                             hash_gaussian(o.seed, kStreamColor + std::uint32_t(c),
                                                           ii, jj, k),
                            0.0f, 1.0f);
                }
                if (o.jitter_transparency > 0)
                    a.transparency = clamp(
                        a.transparency + o.jitter_transparency *
                                             hash_gaussian(o.seed, kStreamTransparency, ii, jj, k),
                        0.0f, 1.0f);
                attributes_to_channels(
                    a, l.values.data() + (j * src_u.size() + i) * kWrAttributeChannels);
            }
        }
    }
    out = std::move(hs);
    return Status::success();
}

SuperposedSample superposed_sampled(const WrSurface& surface, const HierarchicalSampling& hs,
                                    float u, float v, float tail_tolerance) {
    return superposed_sampled(surface, hs, surface.basis_u(u), surface.basis_v(v), nullptr, nullptr,
                              u, v, tail_tolerance);
}

SuperposedSample superposed_sampled(const WrSurface& surface, const HierarchicalSampling& hs,
                                    const WrBasisAt& bu, const WrBasisAt& bv,
                                    const SampleWeights* wu, const SampleWeights* wv, float u,
                                    float v, float tail_tolerance) {
    SuperposedSample r;
    r.base = surface.base_point(bu, bv, u, v);
    const float delta = r.base.delta;
    const float hmax = surface.max_abs_height();
    // k = 0: F^0 is the identity, H^0 = H (chosen here: nothing to sample away).
    WrAttributes a0 = surface.attributes(bu, bv);
    float w = superposition_weight(delta, 0);
    WrAttributes sum;
    sum.height = w * a0.height;
    sum.vector = a0.vector * w;
    sum.color = a0.color * w;
    sum.transparency = w * a0.transparency;
    float wsum = w;
    float tail = delta * hmax;  // delta^k · max|h|: bounds sum_{j>=k} W^j |H^j|
    int used = 0;
    for (int k = 1; k <= hs.levels(); ++k) {
        if (tail < tail_tolerance) break;  // adaptive end of the sum (§4.2)
        // eq. (20): + W^k(u,v) H^k(u,v)
        w = superposition_weight(delta, k);
        const WrAttributes a =
            wu && wv ? hs.interpolate(k, wu[k - 1], wv[k - 1]) : hs.interpolate(k, u, v);
        sum.height += w * a.height;
        sum.vector += a.vector * w;
        sum.color += a.color * w;
        sum.transparency += w * a.transparency;
        wsum += w;
        used = k;
        tail *= delta;
    }
    // eq. (18) on the finite sum k = 0..used: divide by the weights used, 1 - delta^(used+1)
    // (superposition.hpp). The total height stays the one H sets; delta only redistributes it.
    sum.height /= wsum;
    sum.vector = sum.vector / wsum;
    sum.color = sum.color / wsum;
    sum.transparency /= wsum;
    r.attributes = sum;
    r.levels_used = used;
    r.position = surface.displace(r.base, sum);
    return r;
}

}  // namespace shitsukan
