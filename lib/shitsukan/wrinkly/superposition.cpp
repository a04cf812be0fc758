#include "shitsukan/wrinkly/superposition.hpp"

namespace shitsukan {

float superposition_weight(float delta, int k) {
    // eq. (19): W^k = (1 - delta) delta^k
    float p = 1.0f;
    for (int i = 0; i < k; ++i) p *= delta;
    return (1.0f - delta) * p;
}

float superposition_weight_sum(float delta, int levels_k) {
    float p = delta;
    for (int i = 0; i < levels_k; ++i) p *= delta;
    return 1.0f - p;
}

float superposition_weight_truncated(float delta, int k, int levels_k) {
    // eqs. (17) + (18) over k = 0..K: delta_0 = (1 - delta) / (1 - delta^(K+1))
    return superposition_weight(delta, k) / superposition_weight_sum(delta, levels_k);
}

WrAttributes superposed_attributes_direct(const WrSurface& s, float u, float v, int levels_k) {
    WrBasisAt bu[kMaxWrLevel + 1], bv[kMaxWrLevel + 1];
    for (int k = 0; k <= levels_k; ++k) {
        bu[k] = s.basis_u(s.inverse_u(u, k));
        bv[k] = s.basis_v(s.inverse_v(v, k));
    }
    return superposed_attributes_direct(s, s.base_point(u, v).delta, bu, bv, levels_k);
}

WrAttributes superposed_attributes_direct(const WrSurface& s, float delta, const WrBasisAt* bu,
                                          const WrBasisAt* bv, int levels_k) {
    WrAttributes sum;
    sum.height = 0;
    sum.color = {0, 0, 0};
    sum.transparency = 0;
    sum.vector = {0, 0, 0};
    float wsum = 0;
    for (int k = 0; k <= levels_k; ++k) {
        const float w = superposition_weight(delta, k);
        const WrAttributes a = s.attributes(bu[k], bv[k]);  // at the F^k inverses of u, v
        sum.height += w * a.height;
        sum.vector += a.vector * w;
        sum.color += a.color * w;
        sum.transparency += w * a.transparency;
        wsum += w;
    }
    // eq. (18) on the finite sum: the weights used add up to 1 (delta_0 = (1 - delta) /
    // (1 - delta^(K+1))), so the total height is still set by H and colour and transparency
    // stay in [0, 1]. Without this the missing tail delta^(K+1) lowers the whole surface.
    sum.height /= wsum;
    sum.vector = sum.vector / wsum;
    sum.color = sum.color / wsum;
    sum.transparency /= wsum;
    return sum;
}

Vec3 superposed_point_direct(const WrSurface& s, float u, float v, int levels_k) {
    // eq. (16): P + {sum_k W^k H((F_U^k)^{-1}(u), (F_V^k)^{-1}(v))} N
    return s.displace(s.base_point(u, v), superposed_attributes_direct(s, u, v, levels_k));
}

}  // namespace shitsukan
