// shitsukan/bark/branch_shape.cpp — the trunk-with-branch surface and its §5.2 growth.
#include "shitsukan/bark/branch_shape.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>

#include "shitsukan/geom/marching_tetrahedra.hpp"
#include "shitsukan/geom/mesh_topology.hpp"

namespace shitsukan {

namespace {

struct LimbGeometry {
    float a, b;   // f_trunk, f_branch
    Vec3 ga, gb;  // their gradients (unit)
};

// u = branch_axis_direction(s), passed in so the mesher computes its sine and cosine once.
LimbGeometry limbs(const BranchShapeParams& s, Vec3 u, Vec3 p) {
    LimbGeometry g;
    const float r = std::sqrt(p.x * p.x + p.y * p.y);
    g.a = r - s.trunk_radius;
    g.ga = r > 0.0f ? Vec3{p.x / r, p.y / r, 0.0f} : Vec3{1.0f, 0.0f, 0.0f};
    const Vec3 d = p - s.branch_origin;
    float t = dot(d, u);
    if (t < 0.0f) t = 0.0f;  // the half-line ends at the origin (inside the trunk)
    const Vec3 q = d - u * t;
    const float rb = length(q);
    g.b = rb - s.branch_radius;
    g.gb = rb > 0.0f ? q / rb : Vec3{0.0f, 1.0f, 0.0f};
    return g;
}

float blend_weight(float a, float b, float k) {  // h of the polynomial smooth minimum
    float h = 0.5f + 0.5f * (b - a) / k;
    return h < 0.0f ? 0.0f : (h > 1.0f ? 1.0f : h);
}

float smooth_union(const BranchShapeParams& s, const LimbGeometry& g) {
    const float h = blend_weight(g.a, g.b, s.blend);
    return g.b + h * (g.a - g.b) - s.blend * h * (1.0f - h);
}

struct PreparedShape {
    const BranchShapeParams* params;
    Vec3 axis;
};

float shape_function(Vec3 p, const void* user) {
    const PreparedShape& s = *static_cast<const PreparedShape*>(user);
    return smooth_union(*s.params, limbs(*s.params, s.axis, p));
}

}  // namespace

Status validate_branch_shape(const BranchShapeParams& s) {
    const float values[] = {
        s.trunk_radius,    s.height,          s.branch_radius,        s.branch_origin.x,
        s.branch_origin.y, s.branch_origin.z, s.branch_angle_degrees, s.blend};
    for (float v : values)
        if (!is_finite(v))
            return Status::error(StatusCode::invalid_argument,
                                 "branch shape: a parameter is not finite (NaN or inf)");
    if (!(s.trunk_radius > 0.0f) || !(s.branch_radius > 0.0f) || !(s.blend > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "branch shape: radii and blend must be > 0 (R_t %g, R_b %g, k %g)",
                             double(s.trunk_radius), double(s.branch_radius), double(s.blend));
    if (!(s.height > 0.0f) || !(s.branch_origin.z > 0.0f && s.branch_origin.z < s.height))
        return Status::error(StatusCode::invalid_argument,
                             "branch shape: need height > 0 and the branch origin's z in (0, "
                             "height) (height %g, origin z %g)",
                             double(s.height), double(s.branch_origin.z));
    if (!(s.branch_angle_degrees > 0.0f && s.branch_angle_degrees < 80.0f))
        return Status::error(StatusCode::invalid_argument,
                             "branch shape: branch angle must be in (0, 80) degrees from "
                             "vertical so the branch leaves through the top plane (got %g)",
                             double(s.branch_angle_degrees));
    return Status::success();
}

Vec3 branch_axis_direction(const BranchShapeParams& s) {
    const double a = double(s.branch_angle_degrees) * kPiD / 180.0;
    return Vec3{float(det_sin(a)), 0.0f, float(det_cos(a))};
}

float branch_shape_value(const BranchShapeParams& s, Vec3 p) {
    return smooth_union(s, limbs(s, branch_axis_direction(s), p));
}

Vec3 branch_shape_gradient(const BranchShapeParams& s, Vec3 p) {
    const LimbGeometry g = limbs(s, branch_axis_direction(s), p);
    const float h = blend_weight(g.a, g.b, s.blend);
    return g.ga * h + g.gb * (1.0f - h);
}

LimbDistances limb_distances(const BranchShapeParams& s, Vec3 p) {
    const LimbGeometry g = limbs(s, branch_axis_direction(s), p);
    LimbDistances d;
    d.f_trunk = g.a;
    d.f_branch = g.b;
    d.trunk_axis = g.a + s.trunk_radius;
    d.branch_axis = g.b + s.branch_radius;
    return d;
}

void branch_shape_box(const BranchShapeParams& s, float spacing, Vec3* box_min, Vec3* box_max) {
    const Vec3 u = branch_axis_direction(s);
    const float margin = 0.25f * s.blend + 2.0f * spacing;
    // Where the branch axis meets the top plane, and the half-width of its elliptic cut.
    const float t_top = (s.height - s.branch_origin.z) / u.z;
    const float x_top = s.branch_origin.x + u.x * t_top;
    const float half = s.branch_radius / u.z;
    const float rt = s.trunk_radius;
    *box_min = Vec3{std::fmin(-rt, s.branch_origin.x - s.branch_radius) - margin,
                    std::fmin(-rt, s.branch_origin.y - s.branch_radius) - margin, 0.0f};
    *box_max = Vec3{std::fmax(rt, x_top + half) + margin,
                    std::fmax(rt, s.branch_origin.y + s.branch_radius) + margin, s.height};
}

Status make_branch_mesh(const BranchShapeParams& params, float target_edge_length,
                        TriangleMesh& out, BranchMeshStats* stats) {
    SHITSUKAN_TRY(validate_branch_shape(params));
    const float L0 = target_edge_length;
    if (!is_finite(L0) || !(L0 > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "branch mesh: target edge length must be > 0 and finite (got %g)",
                             double(L0));
    if (L0 < 0.05f)
        return Status::error(StatusCode::too_large,
                             "branch mesh: edge length %g cm < 0.05 cm would make more than "
                             "~160,000 nodes (~%.0f bytes)",
                             double(L0), 3700.0 * (0.33 / double(L0)) * (0.33 / double(L0)) * 200);
    if (L0 > 5.0f)
        return Status::error(StatusCode::invalid_argument,
                             "branch mesh: edge length %g cm > 5 cm cannot resolve the limbs",
                             double(L0));
    BranchMeshStats local;
    BranchMeshStats* s = stats ? stats : &local;
    *s = BranchMeshStats{};
    MarchingTetrahedraOptions mt;
    mt.spacing = 0.5f * L0;
    branch_shape_box(params, mt.spacing, &mt.box_min, &mt.box_max);
    mt.cut_z_min = mt.cut_z_max = true;
    mt.compute_normals = false;
    TriangleMesh mesh;
    const PreparedShape prepared{&params, branch_axis_direction(params)};
    SHITSUKAN_TRY(marching_tetrahedra(&shape_function, &prepared, mt, mesh));
    s->marching_vertices = mesh.vertex_count();
    s->marching_triangles = mesh.triangle_count();
    IsotropicRemeshOptions ro;
    ro.target_edge_length = L0;
    ro.surface = &shape_function;
    ro.user = &prepared;
    SHITSUKAN_TRY(isotropic_remesh(ro, mesh, &s->remesh));
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        mesh.normals[v] = branch_shape_normal(params, mesh.positions[v]);
    MeshTopology topo;
    SHITSUKAN_TRY(mesh_topology(mesh, topo));
    s->boundary_loops = topo.boundary_loops;
    s->euler_characteristic = topo.euler_characteristic;
    out = std::move(mesh);
    return Status::success();
}

Status validate_growth(const AnisotropicGrowth& g) {
    if (!is_finite(g.r_h) || !is_finite(g.r_n) || !is_finite(g.duration) || !is_finite(g.centre))
        return Status::error(StatusCode::invalid_argument,
                             "growth: r_h, r_n, T and c must be finite");
    if (!(g.duration > 0.0f))
        return Status::error(StatusCode::invalid_argument, "growth: T must be > 0 (got %g)",
                             double(g.duration));
    if (!(g.r_h > -1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "growth: r_h must be > -1 so the scaling stays positive (got %g)",
                             double(g.r_h));
    return Status::success();
}

float isotropic_scaling(const AnisotropicGrowth& g, float t) {
    return 1.0f + g.r_h * t / g.duration;
}

float normal_offset(const AnisotropicGrowth& g, float t) { return g.r_n * t / g.duration; }

Vec3 anisotropic_growth_anchor(const AnisotropicGrowth& g, Vec3 x, Vec3 n, float t) {
    return g.centre + (x - g.centre) * isotropic_scaling(g, t) + n * normal_offset(g, t);
}

float edge_growth_rate(const AnisotropicGrowth& g, Vec3 xi, Vec3 xj, Vec3 ni, Vec3 nj) {
    const Vec3 e = xj - xi;
    const float l2 = dot(e, e);
    if (!(l2 > 0.0f)) return g.r_h / g.duration;
    // (e/l0)·(n_j - n_i)/l0 = e·(n_j - n_i)/l0².
    return g.r_h / g.duration + (g.r_n / g.duration) * dot(e, nj - ni) / l2;
}

}  // namespace shitsukan
