// small-device: yes (no allocation, no exceptions)
#include "shitsukan/raster/blinn1977.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>

namespace shitsukan {

float blinn1977_distribution(const Blinn1977Material& m, float n_dot_h) {
    float c = clamp(n_dot_h, 0.0f, 1.0f);
    switch (m.distribution) {
        case BlinnDistribution::d1_phong:
            return det_pow(c, m.c1);  // D1 = cos^c1(alpha)
        case BlinnDistribution::d2_gaussian: {
            float alpha = det_acos(c);
            float a = alpha * m.c2;
            return det_expf(-a * a);  // D2 = exp(-(alpha c2)^2)
        }
        case BlinnDistribution::d3_trowbridge_reitz: {
            float c3sq = m.c3 * m.c3;
            float q = c3sq / (c * c * (c3sq - 1.0f) + 1.0f);  // D3 = (c3^2/(cos^2(c3^2-1)+1))^2
            return q * q;
        }
    }
    return 0.0f;
}

float blinn1977_geometry(float n_dot_h, float n_dot_e, float n_dot_l, float e_dot_h) {
    if (!(e_dot_h > 0.0f)) return 0.0f;
    float masked = 2.0f * n_dot_h * n_dot_e / e_dot_h;    // Gb: reflected light blocked
    float shadowed = 2.0f * n_dot_h * n_dot_l / e_dot_h;  // Gc: incident light blocked
    float g = 1.0f;
    if (masked < g) g = masked;
    if (shadowed < g) g = shadowed;
    return g > 0.0f ? g : 0.0f;
}

namespace {
float fresnel_raw(float c, float n) {
    float g = std::sqrt(std::fmax(n * n + c * c - 1.0f, 0.0f));
    float a = (g - c) / (g + c);
    float b = (c * (g + c) - 1.0f) / (c * (g - c) + 1.0f);
    return 0.5f * a * a * (1.0f + b * b);
}
}  // namespace

float blinn1977_fresnel(float e_dot_h, float refractive_index) {
    float c = clamp(e_dot_h, 0.0f, 1.0f);
    float f0 = fresnel_raw(1.0f, refractive_index);
    return f0 > 0.0f ? fresnel_raw(c, refractive_index) / f0 : 1.0f;
}

float blinn1977_specular(const Blinn1977Material& m, Vec3 n, Vec3 l, Vec3 e) {
    float n_dot_l = dot(n, l), n_dot_e = dot(n, e);
    if (!(n_dot_l > 0.0f) || !(n_dot_e > 0.0f)) return 0.0f;
    Vec3 h = normalize(l + e);
    float n_dot_h = dot(n, h), e_dot_h = dot(e, h);
    float d = blinn1977_distribution(m, n_dot_h);
    float g = blinn1977_geometry(n_dot_h, n_dot_e, n_dot_l, e_dot_h);
    float f = blinn1977_fresnel(e_dot_h, m.refractive_index);
    return d * g * f / std::fmax(n_dot_e, 0.05f);  // s = D G F / (N·E)
}

Vec3 shade_blinn1977(const Blinn1977Material& m, Vec3 p, Vec3 n, Vec3 eye_position,
                     const PointLight* lights, int light_count) {
    Vec3 e = normalize(eye_position - p);
    Vec3 out = m.color * m.ka;
    for (int i = 0; i < light_count; ++i) {
        Vec3 l = normalize(lights[i].position - p);
        float n_dot_l = dot(n, l);
        if (!(n_dot_l > 0.0f)) continue;
        float s = blinn1977_specular(m, n, l, e);
        Vec3 lit = m.color * (m.kd * n_dot_l) + m.specular_color * (m.ks * s);
        out += lit * lights[i].intensity;
    }
    return out;
}

}  // namespace shitsukan
