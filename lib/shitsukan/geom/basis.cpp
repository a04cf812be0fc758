// small-device: yes (no allocation, no exceptions)
#include "shitsukan/geom/basis.hpp"

#include "shitsukan/core/assert.hpp"

namespace shitsukan {

namespace {

// Bernstein polynomials by the triangular recurrence B_{i,k} = (1-t)B_{i,k-1} + t B_{i-1,k-1}
// (numerically stable, as de Casteljau).
template <class T>
void bernstein_up_to(int n, T t, T* b) {
    b[0] = T(1);
    for (int k = 1; k <= n; ++k) {
        T saved = T(0);
        for (int i = 0; i < k; ++i) {
            T tmp = b[i];
            b[i] = saved + (T(1) - t) * tmp;
            saved = t * tmp;
        }
        b[k] = saved;
    }
}

template <class T>
void bernstein_impl(int n, T t, T* b, T* db) {
    SHITSUKAN_ASSERT(n >= 0 && n <= kMaxBasisDegree);
    if (db) {
        T lower[kMaxBasisDegree + 1];
        if (n == 0) {
            db[0] = T(0);
        } else {
            bernstein_up_to(n - 1, t, lower);
            for (int i = 0; i <= n; ++i) {
                T left = i > 0 ? lower[i - 1] : T(0);
                T right = i < n ? lower[i] : T(0);
                db[i] = T(n) * (left - right);
            }
        }
    }
    bernstein_up_to(n, t, b);
}

// Uniform B-spline blending functions: N_{i,n}(t) for the n+1 control points of a span, by
// the Cox-de Boor recurrence on integer knots (local parameter t in [0, 1]).
template <class T>
void bspline_up_to(int n, T t, T* b) {
    // After step k, b[0..k] are the degree-k functions of the k+1 control points whose
    // support covers the span, leftmost first.
    b[0] = T(1);
    for (int k = 1; k <= n; ++k) {
        T next[kMaxBasisDegree + 1];
        for (int i = 0; i <= k; ++i) {
            // Cox-de Boor with knot j = i - k: N_{j,k} = (t - j)/k · N_{j,k-1}
            //                                          + (j + k + 1 - t)/k · N_{j+1,k-1};
            // N_{j,k-1} is b[i - 1] and N_{j+1,k-1} is b[i] (absent outside 0..k-1).
            T left = i > 0 ? (t + T(k - i)) * b[i - 1] : T(0);
            T right = i < k ? (T(i + 1) - t) * b[i] : T(0);
            next[i] = (left + right) / T(k);
        }
        for (int i = 0; i <= k; ++i) b[i] = next[i];
    }
}

template <class T>
void bspline_impl(int n, T t, T* b, T* db) {
    SHITSUKAN_ASSERT(n >= 0 && n <= kMaxBasisDegree);
    if (db) {
        if (n == 0) {
            db[0] = T(0);
        } else {
            T lower[kMaxBasisDegree + 1];
            bspline_up_to(n - 1, t, lower);
            // d/dt N_{i,n} = N_{i,n-1}(shifted) - N_{i+1,n-1}: uniform knots, spacing 1.
            for (int i = 0; i <= n; ++i) {
                T left = i > 0 ? lower[i - 1] : T(0);
                T right = i < n ? lower[i] : T(0);
                db[i] = left - right;
            }
        }
    }
    bspline_up_to(n, t, b);
}

}  // namespace

void bernstein_basis(int degree, float t, float* b, float* db) { bernstein_impl(degree, t, b, db); }
void bernstein_basis(int degree, double t, double* b, double* db) {
    bernstein_impl(degree, t, b, db);
}
void bspline_basis(int degree, float t, float* b, float* db) { bspline_impl(degree, t, b, db); }
void bspline_basis(int degree, double t, double* b, double* db) { bspline_impl(degree, t, b, db); }

}  // namespace shitsukan
