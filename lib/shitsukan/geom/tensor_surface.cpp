// small-device: yes (no allocation, no exceptions)
#include "shitsukan/geom/tensor_surface.hpp"

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/scalar.hpp"
#include "shitsukan/geom/basis.hpp"

namespace shitsukan {

const char* surface_basis_name(SurfaceBasis basis) {
    return basis == SurfaceBasis::bezier ? "Bezier" : "uniform B-spline";
}

int tensor_span_count(SurfaceBasis basis, int degree, int points) {
    return basis == SurfaceBasis::bezier ? 1 : points - degree;
}

Status validate_tensor_grid(SurfaceBasis basis, int degree, const TensorGrid& grid) {
    if (degree < 1 || degree > kMaxBasisDegree)
        return Status::error(StatusCode::invalid_argument, "degree must be in 1..%d (got %d)",
                             kMaxBasisDegree, degree);
    if (grid.channels < 1 || grid.channels > kMaxTensorChannels)
        return Status::error(StatusCode::invalid_argument, "channels must be in 1..%d (got %d)",
                             kMaxTensorChannels, grid.channels);
    if (basis == SurfaceBasis::bezier) {
        if (grid.cols != degree + 1 || grid.rows != degree + 1)
            return Status::error(
                StatusCode::invalid_argument,
                "a degree-%d Bezier patch needs %d x %d control points (got %d x %d)", degree,
                degree + 1, degree + 1, grid.cols, grid.rows);
    } else if (grid.cols < degree + 1 || grid.rows < degree + 1) {
        return Status::error(
            StatusCode::invalid_argument,
            "a degree-%d B-spline needs at least %d x %d control points (got %d x %d)", degree,
            degree + 1, degree + 1, grid.cols, grid.rows);
    }
    if (!grid.values) return Status::error(StatusCode::invalid_argument, "control values are null");
    const int n = grid.cols * grid.rows * grid.channels;
    for (int i = 0; i < n; ++i)
        if (!is_finite(grid.values[i]))
            return Status::error(StatusCode::invalid_argument,
                                 "control value %d (point %d, channel %d) is not finite", i,
                                 i / grid.channels, i % grid.channels);
    return Status::success();
}

namespace {

// u clamped to [0, 1]; NaN -> 0 (clamp() lets NaN through, and int(NaN) is no span index).
float unit_parameter(float u) { return u >= 0.0f ? (u <= 1.0f ? u : 1.0f) : 0.0f; }

}  // namespace

void tensor_locate(int spans, float u, int* span, float* t) {
    float s = unit_parameter(u) * float(spans);
    int i = int(s);
    if (i > spans - 1) i = spans - 1;  // u = 1 belongs to the last span
    *span = i;
    *t = s - float(i);
}

TensorBasisAt locate_tensor_basis(SurfaceBasis basis, int degree, int points, float x) {
    SHITSUKAN_ASSERT(degree >= 1 && degree <= kMaxBasisDegree);
    TensorBasisAt r;
    if (basis == SurfaceBasis::bezier) {
        bernstein_basis(degree, unit_parameter(x), r.b, r.db);
    } else {
        const int spans = points - degree;
        float t = 0;
        tensor_locate(spans, x, &r.span, &t);
        bspline_basis(degree, t, r.b, r.db);  // span s is influenced by points s .. s + degree
        r.scale = float(spans);
    }
    return r;
}

namespace {

// acc[0..4) += w·p[0..4), written out channel by channel so that the compiler may do the four
// at once: the same product and sum per channel either way.
inline void add_scaled4(float* acc, float w, const float* p) {
    acc[0] += w * p[0];
    acc[1] += w * p[1];
    acc[2] += w * p[2];
    acc[3] += w * p[3];
}

// The sums of evaluate_tensor_located over channel blocks of 4 (ch = 4 or 8: the WR surfaces'
// geometry and attributes), in local sums, each channel's terms added in the same order.
template <int CH>
void located_blocks(int degree, const TensorGrid& grid, const TensorBasisAt& bu,
                    const TensorBasisAt& bv, float* out, float* du, float* dv) {
    float o[CH] = {}, a[CH] = {}, d[CH] = {};
    for (int j = 0; j <= degree; ++j) {
        for (int i = 0; i <= degree; ++i) {
            const float* p = grid.values + ((bv.span + j) * grid.cols + (bu.span + i)) * CH;
            const float w = bu.b[i] * bv.b[j];
            for (int c = 0; c < CH; c += 4) add_scaled4(o + c, w, p + c);
            if (du) {
                const float wu = bu.db[i] * bv.b[j] * bu.scale;
                for (int c = 0; c < CH; c += 4) add_scaled4(a + c, wu, p + c);
            }
            if (dv) {
                const float wv = bu.b[i] * bv.db[j] * bv.scale;
                for (int c = 0; c < CH; c += 4) add_scaled4(d + c, wv, p + c);
            }
        }
    }
    for (int c = 0; c < CH; ++c) {
        out[c] = o[c];
        if (du) du[c] = a[c];
        if (dv) dv[c] = d[c];
    }
}

}  // namespace

// S(u, v) = sum_ij B_i(u) B_j(v) P_ij and its derivatives, with B located beforehand.
void evaluate_tensor_located(int degree, const TensorGrid& grid, const TensorBasisAt& bu,
                             const TensorBasisAt& bv, float* out, float* du, float* dv) {
    SHITSUKAN_ASSERT(degree >= 1 && degree <= kMaxBasisDegree);
    SHITSUKAN_ASSERT(grid.channels >= 1 && grid.channels <= kMaxTensorChannels);
    const int ch = grid.channels;
    if (ch == 4) return located_blocks<4>(degree, grid, bu, bv, out, du, dv);
    if (ch == 8) return located_blocks<8>(degree, grid, bu, bv, out, du, dv);
    for (int c = 0; c < ch; ++c) {
        out[c] = 0;
        if (du) du[c] = 0;
        if (dv) dv[c] = 0;
    }
    for (int j = 0; j <= degree; ++j) {
        for (int i = 0; i <= degree; ++i) {
            const float* p = grid.values + ((bv.span + j) * grid.cols + (bu.span + i)) * ch;
            const float w = bu.b[i] * bv.b[j];
            for (int c = 0; c < ch; ++c) out[c] += w * p[c];
            if (du) {
                const float wu = bu.db[i] * bv.b[j] * bu.scale;
                for (int c = 0; c < ch; ++c) du[c] += wu * p[c];
            }
            if (dv) {
                const float wv = bu.b[i] * bv.db[j] * bv.scale;
                for (int c = 0; c < ch; ++c) dv[c] += wv * p[c];
            }
        }
    }
}

void evaluate_tensor_surface(SurfaceBasis basis, int degree, const TensorGrid& grid, float u,
                             float v, float* out, float* du, float* dv) {
    const TensorBasisAt bu = locate_tensor_basis(basis, degree, grid.cols, u);
    const TensorBasisAt bv = locate_tensor_basis(basis, degree, grid.rows, v);
    evaluate_tensor_located(degree, grid, bu, bv, out, du, dv);
}

}  // namespace shitsukan
