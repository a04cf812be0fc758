// fujimoto2000 eqs. (15), (20) as height and colour maps (see terrain_maps.hpp).
#include "shitsukan/wrinkly/terrain_maps.hpp"

#include <algorithm>
#include <cmath>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/wrinkly/superposition.hpp"

namespace shitsukan {

namespace {

// Cyclic weights over the M centre samples (index + 1 in the sampling's positions).
SampleWeights cyclic_weights(int m, float u, SampleInterpolation mode) {
    const float x = u * float(m) - 0.5f;
    const float f = std::floor(x), t = x - f;
    const int i0 = int(f);
    SampleWeights w;
    w.first = i0 - 1;  // the four samples i0 - 1 .. i0 + 2 (wrapped by the caller)
    if (mode == SampleInterpolation::linear) {
        w.w[1] = 1.0f - t, w.w[2] = t;
    } else {  // Hermite with finite-difference tangents on uniform samples (Catmull-Rom)
        const float t2 = t * t, t3 = t2 * t;
        w.w[0] = 0.5f * (-t3 + 2.0f * t2 - t);
        w.w[1] = 0.5f * (3.0f * t3 - 5.0f * t2 + 2.0f);
        w.w[2] = 0.5f * (-3.0f * t3 + 4.0f * t2 + t);
        w.w[3] = 0.5f * (t3 - t2);
    }
    return w;
}

// H^k (all channels) at (u, v), interpolated cyclically.
WrAttributes cyclic_interpolate(const HierarchicalSampling& hs, int k, float u, float v) {
    const int mu = int(hs.positions_u(k).size()) - 2, mv = int(hs.positions_v(k).size()) - 2;
    const SampleWeights wu = cyclic_weights(mu, u, hs.interpolation());
    const SampleWeights wv = cyclic_weights(mv, v, hs.interpolation());
    float ch[kWrAttributeChannels] = {};
    for (int b = 0; b < 4; ++b) {
        if (wv.w[b] == 0.0f) continue;
        const int j = ((wv.first + b) % mv + mv) % mv + 1;
        for (int a = 0; a < 4; ++a) {
            if (wu.w[a] == 0.0f) continue;
            const int i = ((wu.first + a) % mu + mu) % mu + 1;
            const float* s = hs.sample(k, i, j);
            const float w = wu.w[a] * wv.w[b];
            for (int c = 0; c < kWrAttributeChannels; ++c) ch[c] += w * s[c];
        }
    }
    return attributes_from_channels(ch);
}

// eq. (20) with cyclic steps; weights renormalised on the finite sum (eq. 18).
WrAttributes superposed_periodic(const WrSurface& s, const HierarchicalSampling& hs, float u,
                                 float v) {
    const float delta = s.base_point(u, v).delta;
    float sum[kWrAttributeChannels], ch[kWrAttributeChannels];
    attributes_to_channels(s.attributes(u, v), sum);
    float w = superposition_weight(delta, 0), wsum = w;
    for (float& c : sum) c *= w;
    for (int k = 1; k <= hs.levels(); ++k) {
        w = superposition_weight(delta, k);
        attributes_to_channels(cyclic_interpolate(hs, k, u, v), ch);
        for (int c = 0; c < kWrAttributeChannels; ++c) sum[c] += w * ch[c];
        wsum += w;
    }
    for (float& c : sum) c /= wsum;
    return attributes_from_channels(sum);
}

}  // namespace

Status make_terrain_maps(const WrSurface& s, const HierarchicalSampling* hs,
                         const TerrainMapOptions& o, TerrainMaps& out) {
    if (o.width < 1 || o.width > 16384 || o.height < 1 || o.height > 16384)
        return Status::error(StatusCode::invalid_argument,
                             "terrain maps: size %d x %d outside [1, 16384]", o.width, o.height);
    const bool superposed = o.form == WrSurfaceForm::superposed;
    if ((superposed && !hs) || o.form == WrSurfaceForm::base ||
        (o.form == WrSurfaceForm::wr && (o.levels < 0 || o.levels > s.max_level())))
        return Status::error(StatusCode::invalid_argument,
                             "terrain maps: a superposed map needs the sampling, a WR map levels "
                             "in 0..%d (got %d), the base form has no height",
                             s.max_level(), o.levels);
    const std::uint64_t n = std::uint64_t(o.width) * std::uint64_t(o.height);
    SHITSUKAN_TRY(check_memory_budget(budget_mul(n, sizeof(float) + sizeof(Vec3)),
                                      "terrain maps"));
    out = TerrainMaps{};
    out.width = o.width, out.height = o.height;
    out.heights.resize(n);
    out.color.resize(n);
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            const float u = (float(x) + 0.5f) / float(o.width);
            const float v = (float(y) + 0.5f) / float(o.height);
            WrAttributes a;
            if (o.form == WrSurfaceForm::plain) a = s.attributes(u, v);
            else if (o.form == WrSurfaceForm::wr) a = s.wr_attributes(u, v, o.levels);
            else if (o.periodic) a = superposed_periodic(s, *hs, u, v);
            else a = superposed_sampled(s, *hs, u, v).attributes;
            const std::size_t i = std::size_t(y) * std::size_t(o.width) + std::size_t(x);
            out.heights[i] = a.height;
            out.color[i] = a.color;
        }
    const auto mm = std::minmax_element(out.heights.begin(), out.heights.end());
    out.lo = *mm.first, out.hi = *mm.second;
    return Status::success();
}

}  // namespace shitsukan
