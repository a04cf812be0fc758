// hirota1998 §3.1, Fig. 3: the two-layer cylinder (see cylinder_lattice.hpp).
#include "shitsukan/bark/cylinder_lattice.hpp"

#include <algorithm>

#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {

// The three spring directions of the lattice (unit vectors in (u, z)).
const Vec3 kDirection[3] = {{0.0f, 1.0f, 0.0f},
                            {0.86602540378f, 0.5f, 0.0f},
                            {0.86602540378f, -0.5f, 0.0f}};

// The far end of spring (c, r, dir), or false where the lattice has none (free edges; a
// lattice periodic along the axis wraps row N_H onto row 0 instead).
bool spring_end(int N_R, int N_H, bool periodic_along, int c, int r, int dir, int* c2,
                int* r2) {
    const int p = c & 1;
    if (dir == 0) {
        *c2 = c, *r2 = r + 1;
    } else {
        *c2 = c + 1 == N_R ? 0 : c + 1;
        *r2 = dir == 1 ? r + p : r + p - 1;
    }
    if (periodic_along) *r2 = (*r2 + N_H) % N_H;
    return *r2 >= 0 && *r2 < N_H;
}

}  // namespace

// Critical strain eps_c = (kappa_f - 1)·max(0.05, 1 + sigma·clamp(g, -3, 3)) (chosen here:
// Gaussian, relative spread, clipped so no spring is near-zero strength).
float spring_critical_strain(float kappa, float sigma, std::uint32_t seed, int c, int r, int dir,
                             int generation) {
    const float g = clamp(hash_gaussian(seed, kStreamCylinderSprings, c, r, dir + 4 * generation),
                          -3.0f, 3.0f);
    const float f = 1.0f + sigma * g;
    return (kappa - 1.0f) * (f > 0.05f ? f : 0.05f);
}

Vec3 cylinder_anchor(const BarkCylinder& bark, Vec3 reference, float t) {
    const float et = hoop_strain(bark.params, t), ez = axial_strain(bark.params, t);
    return {reference.x * (1.0f + et), reference.y * (1.0f + ez), 0.0f};
}

Vec3 node_position(const BarkCylinder& bark, std::uint32_t p, float t, const Vec3* W) {
    return cylinder_anchor(bark, bark.net.X[p], t) + W[p] * t;
}

Vec3 corner_position(const BarkCylinder& bark, Vec3 reference, std::uint32_t p, float t,
                     const Vec3* W) {
    return cylinder_anchor(bark, reference, t) + W[p] * t;
}

namespace {

// §3.1, Table 1: node (c, r) at u = c·a_h, z = (r + p/2)·L0 (p = c mod 2).
void place_nodes(BarkCylinder& b) {
    const int N_R = b.params.N_R, N_H = b.params.N_H;
    SpringNetwork& net = b.net;
    net.dim = 2;
    net.X.resize(static_cast<std::size_t>(N_R * N_H));
    for (int c = 0; c < N_R; ++c)
        for (int r = 0; r < N_H; ++r)
            net.X[std::size_t(b.node(c, r))] = {
                float(c) * b.a_h, (float(r) + 0.5f * float(c & 1)) * b.params.species.L0, 0.0f};
}

// The springs in (c, r, dir) order (or reversed): ends, direction, family, growth rate, the
// hashed critical strain, the canonical key.
void make_springs(BarkCylinder& b, bool reverse_springs) {
    const CylinderParams& params = b.params;
    const int N_R = params.N_R, N_H = params.N_H;
    SpringNetwork& net = b.net;
    struct Coord {
        int c, r, dir;
    };
    std::vector<Coord> coords;
    coords.reserve(std::size_t(3 * N_R * N_H));
    for (int c = 0; c < N_R; ++c)
        for (int r = 0; r < N_H; ++r)
            for (int dir = 0; dir < 3; ++dir) {
                int c2, r2;
                if (spring_end(N_R, N_H, b.periodic_along, c, r, dir, &c2, &r2)) coords.push_back({c, r, dir});
            }
    if (reverse_springs) std::reverse(coords.begin(), coords.end());
    b.spring_index.assign(std::size_t(3 * N_R * N_H), -1);
    const float rate_u = params.delta_r / b.R0, rate_z = params.delta_h / b.H0;
    net.springs.resize(coords.size());
    for (std::size_t s = 0; s < coords.size(); ++s) {
        const Coord k = coords[s];
        int c2, r2;
        spring_end(N_R, N_H, b.periodic_along, k.c, k.r, k.dir, &c2, &r2);
        BarkSpring& sp = net.springs[s];
        sp.i = std::uint32_t(b.node(k.c, k.r));
        sp.j = std::uint32_t(b.node(c2, r2));
        sp.n = kDirection[k.dir];
        sp.l0 = params.species.L0;
        // 1 = axial, 2 = circumferential (docs/papers/hirota1998.md §3)
        sp.family = k.dir == 0 ? 1 : 2;
        // §3.1: the anchors pull the spring at g_s = (dr/R0) n_u^2 + (dh/H0) n_z^2.
        sp.growth_rate = rate_u * sp.n.x * sp.n.x + rate_z * sp.n.y * sp.n.y;
        const float kappa = sp.family == 1 ? params.species.kappa1 : params.species.kappa2;
        sp.eps_c = spring_critical_strain(kappa, params.sigma, params.seed, k.c, k.r, k.dir);
        sp.key = cylinder_spring_key(k.c, k.r, k.dir);
        b.spring_index[std::size_t(3 * b.node(k.c, k.r) + k.dir)] = std::int32_t(s);
    }
}

// The lattice's triangles with seam-corrected corners (docs/papers/hirota1998.md §2):
//   T_up(c, r)    = {(c, r), (c, r+1), up-right(c, r)}
//   T_right(c, r) = {(c, r), up-right(c, r), down-right(c, r)}
void make_triangles(BarkCylinder& b) {
    const int N_R = b.params.N_R, N_H = b.params.N_H;
    const bool wrap = b.periodic_along;
    const float height = float(N_H) * b.params.species.L0;
    auto corner = [&](int c, int r, int from_c) {
        const int rw = wrap ? (r + N_H) % N_H : r;
        Vec3 x = b.net.X[std::size_t(b.node(c, rw))];
        if (c < from_c) x.x += b.circumference;  // across the seam
        x.y += height * float((r - rw) / N_H);   // across the axial seam (periodic_along)
        return x;
    };
    auto row = [&](int r) { return wrap ? (r + N_H) % N_H : r; };
    auto triangle = [&](const int (&cr)[3][2], const int (&spring)[3], int c) {
        ConnectionTriangle t;
        for (int k = 0; k < 3; ++k) {
            t.node[k] = std::uint32_t(b.node(cr[k][0], row(cr[k][1])));
            t.spring[k] = std::uint32_t(spring[k]);
            t.corner[k] = corner(cr[k][0], cr[k][1], c);
        }
        b.triangles.push_back(t);
    };
    for (int c = 0; c < N_R; ++c) {
        const int p = c & 1, c1 = c + 1 == N_R ? 0 : c + 1;
        for (int r = 0; r < N_H; ++r) {
            if (wrap || (r + 1 < N_H && r + p < N_H))
                triangle({{c, r}, {c, r + 1}, {c1, r + p}},
                         {b.spring(c, r, 0), b.spring(c, row(r + 1), 2), b.spring(c, r, 1)}, c);
            if (wrap || (r + p < N_H && r + p - 1 >= 0))
                triangle({{c, r}, {c1, r + p}, {c1, r + p - 1}},
                         {b.spring(c, r, 1), b.spring(c1, row(r + p - 1), 0), b.spring(c, r, 2)},
                         c);
        }
    }
    b.spring_triangles.assign(2 * b.net.springs.size(), -1);
    for (std::size_t t = 0; t < b.triangles.size(); ++t)
        for (std::uint32_t s : b.triangles[t].spring) {
            std::int32_t* slot = &b.spring_triangles[2 * s];
            slot[slot[0] < 0 ? 0 : 1] = std::int32_t(t);
        }
}

// §5.1 connection areas -> k = E_f·S/l0 (S = face·D), k_sh = G·A/D.
Status set_constants(BarkCylinder& b) {
    SpringNetwork& net = b.net;
    const int n = net.node_count();
    b.node_area.resize(static_cast<std::size_t>(n));
    b.spring_face.resize(net.springs.size());
    SHITSUKAN_TRY(connection_areas(b.triangles.data(), int(b.triangles.size()), n,
                                   int(net.springs.size()), b.node_area.data(),
                                   b.spring_face.data()));
    const SpeciesParams& sp = b.params.species;
    for (std::size_t s = 0; s < net.springs.size(); ++s) {
        BarkSpring& spring = net.springs[s];
        const float E = spring.family == 1 ? sp.E1 : sp.E2;
        spring.k = spring_constant(E, b.spring_face[s] * b.params.D, spring.l0);
    }
    net.k_anchor.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        net.k_anchor[std::size_t(i)] =
            shear_spring_constant(sp.G, b.node_area[std::size_t(i)], b.params.D);
    for (std::size_t s = 0; s < net.springs.size(); ++s) {
        const BarkSpring& spring = net.springs[s];
        const float a = std::min(net.k_anchor[spring.i], net.k_anchor[spring.j]);
        if (!(double(spring.k) <= kMaxSpringAnchorRatio * double(a)))
            return Status::error(StatusCode::out_of_range,
                                 "bark: a spring's k = %g is %g times the shear spring's k = %g "
                                 "at its node, over %g: float cannot solve the node (raise G or "
                                 "D, lower E1, E2 or raise L0)",
                                 double(spring.k), double(spring.k) / double(a), double(a),
                                 kMaxSpringAnchorRatio);
    }
    return Status::success();
}

}  // namespace

Status build_cylinder(const CylinderParams& params, BarkCylinder& out, bool reverse_springs) {
    return build_cylinder(params, false, out, reverse_springs);
}

Status build_cylinder(const CylinderParams& params, bool periodic_along, BarkCylinder& out,
                      bool reverse_springs) {
    SHITSUKAN_TRY(validate(params));
    if (periodic_along && params.N_H < 3)
        return Status::error(StatusCode::invalid_argument,
                             "bark: a lattice periodic along the axis needs N_H >= 3 (got %d)",
                             params.N_H);
    BarkCylinder& b = out;
    b = BarkCylinder{};
    b.params = params;
    b.periodic_along = periodic_along;
    b.R0 = initial_radius(params);  // Table 1
    b.H0 = initial_height(params);
    b.a_h = column_spacing(params);
    b.circumference = float(params.N_R) * b.a_h;
    place_nodes(b);
    make_springs(b, reverse_springs);
    make_triangles(b);
    SHITSUKAN_TRY(set_constants(b));
    return finalize_network(b.net);
}

}  // namespace shitsukan
