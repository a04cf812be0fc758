// shitsukan/core/vec.hpp — small vectors and a 4x4 matrix.
//
// Manual
//   Vec3 a{1, 2, 3}, b{0, 1, 0};   // Vec2, Vec3, Vec4 (float); Vec2d, Vec3d (double, for the
//   float s = 2.0f;                 // papers' 8-byte splines)
//   Vec3 c = a + b - a * s + s * a - a / s - (-a);  float ax = a[0];
//   float d = dot(a, b), l = length(a), l2 = length_squared(a);
//   Vec3 n = normalize(cross(a, b));  // normalize returns a unchanged when its length is 0
//   Vec3 lo = vmin(a, b), hi = vmax(a, b);  bool f = is_finite(a);
//   // Mat4: row-major m[row][col], acting on column vectors: p' = M·p.
//   Mat4 M = Mat4::translate({1, 0, 0}) * Mat4::rotate_y(0.5f) * Mat4::scale({2, 2, 2});
//   Vec3 p = transform_point(M, a);   // with the divide by w
//   Vec3 v = transform_vector(M, b);  // w = 0
//   bool ok = false;
//   Mat4 Mi = inverse(transpose(M), &ok);  // general 4x4, cofactors; ok = false when singular
// Everything is constexpr-free plain code so a reader can follow it; no allocation.
#pragma once

#include <cmath>

#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

template <class T> struct TVec2 {
    T x = 0, y = 0;
    T& operator[](int i) { return i == 0 ? x : y; }
    T operator[](int i) const { return i == 0 ? x : y; }
};

template <class T> struct TVec3 {
    T x = 0, y = 0, z = 0;
    T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

template <class T> struct TVec4 {
    T x = 0, y = 0, z = 0, w = 0;
    T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w)); }
    T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w)); }
};

using Vec2 = TVec2<float>;
using Vec3 = TVec3<float>;
using Vec4 = TVec4<float>;
using Vec2d = TVec2<double>;
using Vec3d = TVec3<double>;

// ---- Vec2 ----
template <class T> inline TVec2<T> operator+(TVec2<T> a, TVec2<T> b) {
    return {a.x + b.x, a.y + b.y};
}
template <class T> inline TVec2<T> operator-(TVec2<T> a, TVec2<T> b) {
    return {a.x - b.x, a.y - b.y};
}
template <class T> inline TVec2<T> operator-(TVec2<T> a) { return {-a.x, -a.y}; }
template <class T> inline TVec2<T> operator*(TVec2<T> a, T s) { return {a.x * s, a.y * s}; }
template <class T> inline TVec2<T> operator*(T s, TVec2<T> a) { return {a.x * s, a.y * s}; }
template <class T> inline TVec2<T> operator/(TVec2<T> a, T s) { return {a.x / s, a.y / s}; }
template <class T> inline bool operator==(TVec2<T> a, TVec2<T> b) {
    return a.x == b.x && a.y == b.y;
}
template <class T> inline bool operator!=(TVec2<T> a, TVec2<T> b) { return !(a == b); }
template <class T> inline T dot(TVec2<T> a, TVec2<T> b) { return a.x * b.x + a.y * b.y; }
template <class T> inline T cross(TVec2<T> a, TVec2<T> b) {
    return a.x * b.y - a.y * b.x;
}  // z of 3D cross
template <class T> inline T length_squared(TVec2<T> a) { return dot(a, a); }
template <class T> inline T length(TVec2<T> a) { return std::sqrt(dot(a, a)); }
template <class T> inline TVec2<T> normalize(TVec2<T> a) {
    T l = length(a);
    return l > T(0) ? a / l : a;
}
template <class T> inline bool is_finite(TVec2<T> a) { return is_finite(a.x) && is_finite(a.y); }

// ---- Vec3 ----
template <class T> inline TVec3<T> operator+(TVec3<T> a, TVec3<T> b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T> inline TVec3<T> operator-(TVec3<T> a, TVec3<T> b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T> inline TVec3<T> operator-(TVec3<T> a) { return {-a.x, -a.y, -a.z}; }
template <class T> inline TVec3<T> operator*(TVec3<T> a, T s) {
    return {a.x * s, a.y * s, a.z * s};
}
template <class T> inline TVec3<T> operator*(T s, TVec3<T> a) {
    return {a.x * s, a.y * s, a.z * s};
}
template <class T> inline TVec3<T> operator*(TVec3<T> a, TVec3<T> b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
template <class T> inline TVec3<T> operator/(TVec3<T> a, T s) {
    return {a.x / s, a.y / s, a.z / s};
}
template <class T> inline TVec3<T>& operator+=(TVec3<T>& a, TVec3<T> b) { return a = a + b; }
template <class T> inline TVec3<T>& operator-=(TVec3<T>& a, TVec3<T> b) { return a = a - b; }
template <class T> inline TVec3<T>& operator*=(TVec3<T>& a, T s) { return a = a * s; }
template <class T> inline bool operator==(TVec3<T> a, TVec3<T> b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}
template <class T> inline bool operator!=(TVec3<T> a, TVec3<T> b) { return !(a == b); }
template <class T> inline T dot(TVec3<T> a, TVec3<T> b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T> inline TVec3<T> cross(TVec3<T> a, TVec3<T> b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T> inline T length_squared(TVec3<T> a) { return dot(a, a); }
template <class T> inline T length(TVec3<T> a) { return std::sqrt(dot(a, a)); }
template <class T> inline TVec3<T> normalize(TVec3<T> a) {
    T l = length(a);
    return l > T(0) ? a / l : a;
}
template <class T> inline TVec3<T> vmin(TVec3<T> a, TVec3<T> b) {
    return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
template <class T> inline TVec3<T> vmax(TVec3<T> a, TVec3<T> b) {
    return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}
template <class T> inline bool is_finite(TVec3<T> a) {
    return is_finite(a.x) && is_finite(a.y) && is_finite(a.z);
}
template <class T> inline TVec3<T> lerp(TVec3<T> a, TVec3<T> b, T t) { return a + (b - a) * t; }

// ---- Vec4 ----
template <class T> inline TVec4<T> operator+(TVec4<T> a, TVec4<T> b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
}
template <class T> inline TVec4<T> operator-(TVec4<T> a, TVec4<T> b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w};
}
template <class T> inline TVec4<T> operator*(TVec4<T> a, T s) {
    return {a.x * s, a.y * s, a.z * s, a.w * s};
}
template <class T> inline TVec4<T> lerp(TVec4<T> a, TVec4<T> b, T t) { return a + (b - a) * t; }
template <class T> inline TVec3<T> xyz(TVec4<T> a) { return {a.x, a.y, a.z}; }

inline Vec3 to_float(Vec3d a) { return {float(a.x), float(a.y), float(a.z)}; }
inline Vec2 to_float(Vec2d a) { return {float(a.x), float(a.y)}; }

// ---- Mat4: row-major, column vectors ----
struct Mat4 {
    float m[4][4] = {{0}};

    static Mat4 identity();
    static Mat4 translate(Vec3 t);
    static Mat4 scale(Vec3 s);
    static Mat4 rotate_x(float radians);
    static Mat4 rotate_y(float radians);
    static Mat4 rotate_z(float radians);
};

Mat4 operator*(const Mat4& a, const Mat4& b);
Vec4 operator*(const Mat4& a, Vec4 v);
Vec3 transform_point(const Mat4& a, Vec3 p);   // (x, y, z, 1), divided by w when w != 0
Vec3 transform_vector(const Mat4& a, Vec3 v);  // (x, y, z, 0)
Mat4 transpose(const Mat4& a);
Mat4 inverse(const Mat4& a, bool* ok = nullptr);

}  // namespace shitsukan
