// shitsukan/core/scalar.hpp — clamp, lerp, smoothstep, pi, finiteness checks.
//
// Manual
//   float x = clamp(1.5f, 0.0f, 1.0f);           // 1
//   float m = lerp(2.0f, 4.0f, 0.25f);            // a + (b - a)·t = 2.5
//   float s = smoothstep(0.0f, 1.0f, 0.5f);       // cubic Hermite 3t^2 - 2t^3: 0.5
//   bool ok = is_finite(x) && !is_finite(kPi / 0.0f);  // false for NaN and ±inf (the Makefile
//                                                 // builds without -ffast-math, which it needs)
//   double turn = 2.0 * kPiD;                     // kPi, kTwoPi float; kPiD double
#pragma once

#include <cmath>

namespace shitsukan {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kTwoPi = 6.28318530717958647692f;
constexpr double kPiD = 3.14159265358979323846;

template <class T>
constexpr T clamp(T x, T lo, T hi) {
    return x < lo ? lo : (hi < x ? hi : x);
}

template <class T, class U>
constexpr T lerp(T a, T b, U t) {
    return a + (b - a) * t;
}

// 0 below e0, 1 above e1, 3t^2 - 2t^3 in between.
inline float smoothstep(float e0, float e1, float x) {
    float t = clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

inline bool is_finite(float x) { return std::isfinite(x); }
inline bool is_finite(double x) { return std::isfinite(x); }

}  // namespace shitsukan
