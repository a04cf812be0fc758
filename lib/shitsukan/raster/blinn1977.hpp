// shitsukan/raster/blinn1977.hpp — Blinn's 1977 reflection model ("Models of light reflection
// for computer synthesized pictures", SIGGRAPH '77), the shading tokai1994 §5 uses, with point
// lights (tokai1994 §5: two point lights, no shadows).
//
// Manual
//   Blinn1977Material leather;                 // defaults below (a dark-brown glossy leather)
//   PointLight lights[2] = {{{4, 5, 6}, {0.8f, 0.8f, 0.8f}}, {{-5, 2, 3}, {0.4f, 0.4f, 0.45f}}};
//   Vec3 point{0, 0, 0}, normal{0, 0, 1}, eye{0, 1, 5};
//   Vec3 rgb = shade_blinn1977(leather, point, normal, eye, lights, 2);   // linear, may be > 1
//   Vec3 n = normal, l = normalize(Vec3{4, 5, 6}), e = normalize(eye);
//   float s = blinn1977_specular(leather, n, l, e);     // the D·G·F/(N·E) term
//
// The model (Blinn 1977, after Torrance and Sparrow): with unit N, L (to the light), E (to the
// eye) and H = (L + E)/|L + E|,
//   I = Ka·color + sum over lights  light·(Kd·color·(N·L) + Ks·specular_color·D·G·F/(N·E))
//   D: the distribution of microfacet slopes, one of Blinn's three
//      D1 = (N·H)^c1                             (Phong's, on H)
//      D2 = exp(-(alpha·c2)^2), alpha = angle(N, H)   (Gaussian)
//      D3 = (c3^2 / ((N·H)^2 (c3^2 - 1) + 1))^2       (Trowbridge-Reitz ellipsoids)
//      each 1 at alpha = 0. Default D3: Blinn found it fits measured data best, and its
//      long tail gives the broad sheen of polished leather; the clasp uses D3 with small c3.
//   G = min(1, 2(N·H)(N·E)/(E·H), 2(N·H)(N·L)/(E·H))   (masking and shadowing by facets)
//   F = Fresnel reflectance for refractive index n at c = E·H:
//       F = 1/2 (g - c)^2/(g + c)^2 (1 + (c(g + c) - 1)^2/(c(g - c) + 1)^2), g^2 = n^2 + c^2 - 1,
//      divided here by its value at normal incidence ((n - 1)/(n + 1))^2, so Ks is the
//      specular strength seen head-on (chosen here: Blinn leaves the scale of F to Ks).
// N·E is clamped at 0.05 below: the 1/(N·E) factor would blow up at silhouettes, where the
// interpolated and bump-mapped normals are least exact. No distance attenuation (Blinn 1977
// and tokai1994 use directional intensity only). No shadows (tokai1994 §5).
// Defaults (Blinn1977Material): color (0.35, 0.17, 0.08), Ka 0.25, Kd 0.8, Ks 0.5,
// specular_color (1, 1, 1), distribution D3, c1 = 40, c2 = 4, c3 = 0.3, n = 1.5.
// Small-device: float, no allocation.
#pragma once

#include "shitsukan/core/vec.hpp"

namespace shitsukan {

enum class BlinnDistribution { d1_phong, d2_gaussian, d3_trowbridge_reitz };

struct Blinn1977Material {
    Vec3 color{0.35f, 0.17f, 0.08f};  // diffuse reflectance (linear RGB)
    Vec3 specular_color{1.0f, 1.0f, 1.0f};
    float ka = 0.25f, kd = 0.8f, ks = 0.5f;
    BlinnDistribution distribution = BlinnDistribution::d3_trowbridge_reitz;
    float c1 = 40.0f;  // D1 exponent
    float c2 = 4.0f;   // D2 width (1/radians)
    float c3 = 0.3f;   // D3 eccentricity, 0 (mirror) .. 1 (diffuse)
    float refractive_index = 1.5f;
};

struct PointLight {
    Vec3 position{0, 0, 0};
    Vec3 intensity{1, 1, 1};
};

// D of the material at cos(alpha) = N·H.
float blinn1977_distribution(const Blinn1977Material& m, float n_dot_h);
// G of Blinn 1977.
float blinn1977_geometry(float n_dot_h, float n_dot_e, float n_dot_l, float e_dot_h);
// F of Blinn 1977 divided by its normal-incidence value.
float blinn1977_fresnel(float e_dot_h, float refractive_index);
// D·G·F/(N·E) for unit n, l, e (0 when the light or the eye is behind the surface).
float blinn1977_specular(const Blinn1977Material& m, Vec3 n, Vec3 l, Vec3 e);

// The full model at a surface point p with unit normal n, seen from eye_position.
Vec3 shade_blinn1977(const Blinn1977Material& m, Vec3 p, Vec3 n, Vec3 eye_position,
                     const PointLight* lights, int light_count);

}  // namespace shitsukan
