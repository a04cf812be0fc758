// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/vec.hpp"
#include "shitsukan/core/detmath.hpp"

namespace shitsukan {

Mat4 Mat4::identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1.0f;
    return r;
}

Mat4 Mat4::translate(Vec3 t) {
    Mat4 r = identity();
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
}

Mat4 Mat4::scale(Vec3 s) {
    Mat4 r = identity();
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
}

Mat4 Mat4::rotate_x(float a) {
    Mat4 r = identity();
    float c = det_cos(a), s = det_sin(a);
    r.m[1][1] = c;
    r.m[1][2] = -s;
    r.m[2][1] = s;
    r.m[2][2] = c;
    return r;
}

Mat4 Mat4::rotate_y(float a) {
    Mat4 r = identity();
    float c = det_cos(a), s = det_sin(a);
    r.m[0][0] = c;
    r.m[0][2] = s;
    r.m[2][0] = -s;
    r.m[2][2] = c;
    return r;
}

Mat4 Mat4::rotate_z(float a) {
    Mat4 r = identity();
    float c = det_cos(a), s = det_sin(a);
    r.m[0][0] = c;
    r.m[0][1] = -s;
    r.m[1][0] = s;
    r.m[1][1] = c;
    return r;
}

Mat4 operator*(const Mat4& a, const Mat4& b) {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            float s = 0.0f;
            for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

Vec4 operator*(const Mat4& a, Vec4 v) {
    Vec4 r;
    for (int i = 0; i < 4; ++i)
        r[i] = a.m[i][0] * v.x + a.m[i][1] * v.y + a.m[i][2] * v.z + a.m[i][3] * v.w;
    return r;
}

Vec3 transform_point(const Mat4& a, Vec3 p) {
    Vec4 r = a * Vec4{p.x, p.y, p.z, 1.0f};
    if (r.w != 0.0f && r.w != 1.0f) return {r.x / r.w, r.y / r.w, r.z / r.w};
    return {r.x, r.y, r.z};
}

Vec3 transform_vector(const Mat4& a, Vec3 v) {
    Vec4 r = a * Vec4{v.x, v.y, v.z, 0.0f};
    return {r.x, r.y, r.z};
}

Mat4 transpose(const Mat4& a) {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
    return r;
}

namespace {
// The cofactor of entry (row, col) of the 4x4 matrix s (row-major, in double): (-1)^(row+col)
// times the determinant of the 3x3 minor without that row and column, expanded along the
// minor's first column as six products (x·y)·z summed left to right:
//   + a0·b1·c2 - a0·b2·c1 - b0·a1·c2 + b0·a2·c1 + c0·a1·b2 - c0·a2·b1
// (a, b, c: the minor's rows; 0, 1, 2: its columns; each product's first factor from column
// 0, then the rest by row). A negative cofactor negates every product instead (-x·y·z is
// (-x)·y·z exactly), and a - p is a + (-p) in IEEE arithmetic: the same roundings, in the
// same order, as the formula written out term by term (which cost 3.6 KB of Cortex-M0 flash).
double cofactor(const double* s, int row, int col) {
    const double* r[3];  // the minor's rows and columns
    int c[3];
    for (int i = 0, nr = 0, nc = 0; i < 4; ++i) {
        if (i != row) r[nr++] = s + 4 * i;
        if (i != col) c[nc++] = i;
    }
    const bool negative = ((row + col) & 1) != 0;
    double sum = 0.0;
    for (int first = 0; first < 3; ++first) {  // the row of the column-0 factor
        const int lo = first == 0 ? 1 : 0, hi = first == 2 ? 1 : 2;  // the other two rows
        for (int swap = 0; swap < 2; ++swap) {
            const double p = r[first][c[0]] * r[lo][c[1 + swap]] * r[hi][c[2 - swap]];
            const bool minus = (((first & 1) != 0) != (swap != 0)) != negative;
            const double term = minus ? -p : p;
            sum = first == 0 && swap == 0 ? term : sum + term;
        }
    }
    return sum;
}
}  // namespace

// Inverse by cofactors (Cramer's rule), computed in double for a stable determinant: the
// adjugate inv[4i + j] is the cofactor of entry (j, i).
Mat4 inverse(const Mat4& a, bool* ok) {
    double s[16], inv[16];
    for (int i = 0; i < 16; ++i) s[i] = a.m[i / 4][i % 4];
    for (int i = 0; i < 16; ++i) inv[i] = cofactor(s, i % 4, i / 4);
    double det = s[0] * inv[0] + s[1] * inv[4] + s[2] * inv[8] + s[3] * inv[12];
    Mat4 r;
    if (det == 0.0 || !std::isfinite(det)) {
        if (ok) *ok = false;
        return Mat4::identity();
    }
    for (int i = 0; i < 16; ++i) r.m[i / 4][i % 4] = float(inv[i] / det);
    if (ok) *ok = true;
    return r;
}

}  // namespace shitsukan
