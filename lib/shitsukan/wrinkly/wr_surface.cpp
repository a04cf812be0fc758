#include "shitsukan/wrinkly/wr_surface.hpp"

#include <cmath>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

void attributes_to_channels(const WrAttributes& a, float* channels) {
    const float v[kWrAttributeChannels] = {a.height,       a.color.x,  a.color.y,  a.color.z,
                                           a.transparency, a.vector.x, a.vector.y, a.vector.z};
    for (int c = 0; c < kWrAttributeChannels; ++c) channels[c] = v[c];
}

WrAttributes attributes_from_channels(const float* a) {
    WrAttributes r;
    r.height = a[0];
    r.color = {a[1], a[2], a[3]};
    r.transparency = a[4];
    r.vector = {a[5], a[6], a[7]};
    return r;
}

Status make_wr_surface(const WrControlMesh& mesh, SurfaceBasis basis, int degree, WrSurface& out) {
    SHITSUKAN_TRY(validate_control_mesh(mesh, basis, degree));
    WrSurface s;
    s.basis_ = basis;
    s.degree_ = degree;
    s.cols_ = mesh.cols;
    s.rows_ = mesh.rows;
    s.spans_u_ = tensor_span_count(basis, degree, mesh.cols);
    s.spans_v_ = tensor_span_count(basis, degree, mesh.rows);
    s.axis_u_ = identity_axis(s.spans_u_);
    s.axis_v_ = identity_axis(s.spans_v_);
    bool any_direction = false;
    for (const WrControlPoint& p : mesh.points) {
        s.geometry_.insert(s.geometry_.end(), {p.position.x, p.position.y, p.position.z, p.delta});
        const Vec3 hv = p.direction * p.height;  // h_i · d_i (figs. 22-23)
        WrAttributes attr;                       // per control point: H, C, T and h_i · d_i
        attr.height = p.height;
        attr.color = p.color;
        attr.transparency = p.transparency;
        attr.vector = hv;
        float ch[kWrAttributeChannels];
        attributes_to_channels(attr, ch);
        s.attributes_.insert(s.attributes_.end(), ch, ch + kWrAttributeChannels);
        float a = std::fabs(p.height);
        if (length_squared(p.direction) > 0) {
            any_direction = true;
            a *= length(p.direction);
        }
        if (a > s.max_abs_height_) s.max_abs_height_ = a;
    }
    s.mode_ = any_direction ? DisplacementMode::direction : DisplacementMode::normal;
    out = std::move(s);
    return Status::success();
}

Status WrSurface::set_axes(const WrAxis& u, const WrAxis& v) {
    if (u.base_intervals != spans_u_ || v.base_intervals != spans_v_)
        return Status::error(StatusCode::invalid_argument,
                             "IST base intervals (%d, %d) must equal the surface's parameter spans "
                             "(%d, %d) (fujimoto2000 §3.2)",
                             u.base_intervals, v.base_intervals, spans_u_, spans_v_);
    if (u.max_level < 0 || u.max_level > kMaxWrLevel || v.max_level < 0 ||
        v.max_level > kMaxWrLevel)
        return Status::error(StatusCode::invalid_argument,
                             "axis max levels must be in 0..%d (got %d, %d)", kMaxWrLevel,
                             u.max_level, v.max_level);
    if (u.division < 1 || v.division < 1)
        return Status::error(StatusCode::invalid_argument,
                             "IST division numbers must be >= 1 (got %d, %d)", u.division,
                             v.division);
    axis_u_ = u;
    axis_v_ = v;
    return Status::success();
}

namespace {

// u clamped to [0, 1]; NaN -> 0 (the IST formulas turn the parameter into interval indices).
float unit_parameter(float u) { return u >= 0.0f ? (u <= 1.0f ? u : 1.0f) : 0.0f; }

}  // namespace

WrBasisAt WrSurface::basis_u(float u) const {
    return locate_tensor_basis(basis_, degree_, cols_, u);
}

WrBasisAt WrSurface::basis_v(float v) const {
    return locate_tensor_basis(basis_, degree_, rows_, v);
}

BasePoint WrSurface::base_point(float u, float v) const {
    return base_point(basis_u(u), basis_v(v), u, v);
}

BasePoint WrSurface::base_point(const WrBasisAt& bu, const WrBasisAt& bv, float u, float v) const {
    const TensorGrid g{geometry_.data(), cols_, rows_, 4};
    float p[4], pu[4], pv[4];
    evaluate_tensor_located(degree_, g, bu, bv, p, pu, pv);
    BasePoint b;
    b.position = {p[0], p[1], p[2]};
    b.du = {pu[0], pu[1], pu[2]};
    b.dv = {pv[0], pv[1], pv[2]};
    b.delta = clamp(p[3], 1e-6f, 1.0f - 1e-6f);
    Vec3 n = cross(b.du, b.dv);
    if (length_squared(n) < 1e-20f) {
        // A collapsed edge (dP/du or dP/dv = 0): take the normal a little way inside.
        const float eps = 1e-3f;
        float q[4], qu[4], qv[4];
        evaluate_tensor_surface(basis_, degree_, g, u + (u < 0.5f ? eps : -eps),
                                v + (v < 0.5f ? eps : -eps), q, qu, qv);
        n = cross(Vec3{qu[0], qu[1], qu[2]}, Vec3{qv[0], qv[1], qv[2]});
        if (length_squared(n) < 1e-20f) n = {0, 0, 1};
    }
    b.normal = normalize(n);
    return b;
}

WrAttributes WrSurface::attributes(float u, float v) const {
    return attributes(basis_u(u), basis_v(v));
}

WrAttributes WrSurface::attributes(const WrBasisAt& bu, const WrBasisAt& bv) const {
    const TensorGrid g{attributes_.data(), cols_, rows_, kWrAttributeChannels};
    float a[kWrAttributeChannels];
    evaluate_tensor_located(degree_, g, bu, bv, a, nullptr, nullptr);
    return attributes_from_channels(a);
}

float WrSurface::inverse_u(float u, int k) const {
    SHITSUKAN_ASSERT(k >= 0 && k <= axis_u_.max_level);
    const float s = unit_parameter(u) * float(spans_u_);
    return clamp(axis_u_.inverse_at(s, k) / float(spans_u_), 0.0f, 1.0f);
}

float WrSurface::inverse_v(float v, int k) const {
    SHITSUKAN_ASSERT(k >= 0 && k <= axis_v_.max_level);
    const float s = unit_parameter(v) * float(spans_v_);
    return clamp(axis_v_.inverse_at(s, k) / float(spans_v_), 0.0f, 1.0f);
}

WrAttributes WrSurface::wr_attributes(float u, float v, int k) const {
    return attributes(inverse_u(u, k), inverse_v(v, k));
}

Vec3 WrSurface::displace(const BasePoint& b, const WrAttributes& a) const {
    if (mode_ == DisplacementMode::direction) return b.position + a.vector;
    return b.position + b.normal * a.height;
}

Vec3 WrSurface::wr_point(float u, float v, int k) const {
    // fujimoto2000 eq. (15): R(u,v) = P(u,v) + H(F_U^{-1}(u), F_V^{-1}(v)) N(u,v)
    return displace(base_point(u, v), wr_attributes(u, v, k));
}

}  // namespace shitsukan
