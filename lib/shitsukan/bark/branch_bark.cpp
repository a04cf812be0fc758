// hirota1998 §5: the spring network on the branching trunk (see branch_bark.hpp).
#include "shitsukan/bark/branch_bark.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {

std::uint32_t bits(float x) {
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

// The canonical key of the edge between two positions: a hash of their bit patterns, the
// smaller position first (as tokai1994's shared polygon edges).
std::uint64_t edge_key(std::uint32_t seed, Vec3 a, Vec3 b) {
    const bool swap = a.x != b.x ? b.x < a.x : (a.y != b.y ? b.y < a.y : b.z < a.z);
    if (swap) std::swap(a, b);
    std::uint64_t h = hash_start(seed, kStreamBranchSprings);
    for (float v : {a.x, a.y, a.z, b.x, b.y, b.z}) h = hash_add(h, bits(v));
    return h;
}

}  // namespace

Status validate(const BranchBarkParams& p) {
    SHITSUKAN_TRY(validate_branch_shape(p.shape));
    SHITSUKAN_TRY(validate_growth(p.growth));
    auto positive = [](float x) { return is_finite(x) && x > 0.0f; };
    if (!positive(p.edge_length) || !positive(p.E) || !positive(p.G) || !positive(p.D))
        return Status::error(StatusCode::invalid_argument,
                             "branch bark: edge length, E, G and D must be > 0 (got %g, %g, %g, "
                             "%g)",
                             double(p.edge_length), double(p.E), double(p.G), double(p.D));
    if (!(is_finite(p.kappa) && p.kappa > 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "branch bark: kappa must be > 1 (got %g)", double(p.kappa));
    if (!(is_finite(p.sigma) && p.sigma >= 0.0f && p.sigma < 0.3f))
        return Status::error(StatusCode::invalid_argument,
                             "branch bark: sigma must be in [0, 0.3) (got %g)", double(p.sigma));
    if (!(is_finite(p.tolerance) && p.tolerance > 0.0f && p.tolerance <= 0.1f))
        return Status::error(StatusCode::invalid_argument,
                             "branch bark: tolerance must be in (0, 0.1] (got %g)",
                             double(p.tolerance));
    return Status::success();
}

Status mesh_springs(const TriangleMesh& mesh, std::vector<ConnectionTriangle>& triangles,
                    std::vector<std::uint32_t>& edge_nodes) {
    const int nv = mesh.vertex_count(), nt = mesh.triangle_count();
    for (int i = 0; i < nv; ++i)
        if (!is_finite(mesh.positions[std::size_t(i)]))
            return Status::error(StatusCode::invalid_argument,
                                 "mesh_springs: vertex %d is not finite", i);
    // Edges sorted by (smaller, larger) vertex: one spring each.
    std::vector<std::uint64_t> edges;
    edges.reserve(std::size_t(3 * nt));
    for (int t = 0; t < nt; ++t)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = mesh.indices[std::size_t(3 * t + k)];
            std::uint32_t b = mesh.indices[std::size_t(3 * t + (k + 1) % 3)];
            if (a >= std::uint32_t(nv) || b >= std::uint32_t(nv) || a == b)
                return Status::error(StatusCode::invalid_argument,
                                     "mesh_springs: triangle %d has a bad or repeated vertex", t);
            if (b < a) std::swap(a, b);
            edges.push_back(std::uint64_t(a) << 32 | b);
        }
    std::vector<std::uint64_t> sorted = edges;
    std::sort(sorted.begin(), sorted.end());
    // Each edge at most twice (a manifold).
    for (std::size_t i = 2; i < sorted.size(); ++i)
        if (sorted[i] == sorted[i - 2])
            return Status::error(StatusCode::invalid_argument,
                                 "mesh_springs: edge %u-%u is shared by more than two triangles",
                                 unsigned(sorted[i] >> 32), unsigned(sorted[i] & 0xffffffffu));
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    edge_nodes.clear();
    for (std::uint64_t e : sorted) {
        edge_nodes.push_back(std::uint32_t(e >> 32));
        edge_nodes.push_back(std::uint32_t(e & 0xffffffffu));
    }
    triangles.assign(std::size_t(nt), ConnectionTriangle{});
    for (int t = 0; t < nt; ++t) {
        ConnectionTriangle& ct = triangles[std::size_t(t)];
        for (int k = 0; k < 3; ++k) {
            ct.node[k] = mesh.indices[std::size_t(3 * t + k)];
            ct.corner[k] = mesh.positions[ct.node[k]];
            const std::uint64_t e = edges[std::size_t(3 * t + k)];
            ct.spring[k] = std::uint32_t(std::lower_bound(sorted.begin(), sorted.end(), e) -
                                         sorted.begin());
        }
    }
    return Status::success();
}

Status build_branch_bark(const BranchBarkParams& params, BranchBark& out) {
    SHITSUKAN_TRY(validate(params));
    TriangleMesh mesh;
    BranchMeshStats stats;
    SHITSUKAN_TRY(make_branch_mesh(params.shape, params.edge_length, mesh, &stats));
    SHITSUKAN_TRY(build_bark_on_mesh(params, mesh, out));
    out.mesh_stats = stats;
    return Status::success();
}

Status build_bark_on_mesh(const BranchBarkParams& params, const TriangleMesh& mesh,
                          BranchBark& out) {
    SHITSUKAN_TRY(validate(params));
    if (mesh.normals.size() != mesh.positions.size())
        return Status::error(StatusCode::invalid_argument,
                             "build_bark_on_mesh: %zu normals for %zu vertices (one per vertex "
                             "needed: the growth offsets along them)",
                             mesh.normals.size(), mesh.positions.size());
    for (std::size_t i = 0; i < mesh.normals.size(); ++i)
        if (!is_finite(mesh.normals[i]) || std::fabs(length(mesh.normals[i]) - 1.0f) > 1e-3f)
            return Status::error(StatusCode::invalid_argument,
                                 "build_bark_on_mesh: normal %zu is not a unit vector", i);
    BranchBark& b = out;
    b = BranchBark{};
    b.params = params;
    b.mesh = mesh;
    std::vector<std::uint32_t> edge_nodes;
    SHITSUKAN_TRY(mesh_springs(b.mesh, b.triangles, edge_nodes));
    const int n = b.mesh.vertex_count(), m = int(edge_nodes.size() / 2);
    // §5.1, Fig. 9: connection areas -> constants (the cylinder's function).
    b.node_area.resize(std::size_t(n));
    b.spring_face.resize(std::size_t(m));
    SHITSUKAN_TRY(connection_areas(b.triangles.data(), int(b.triangles.size()), n, m,
                                   b.node_area.data(), b.spring_face.data()));
    b.spring_triangles.assign(std::size_t(2 * m), -1);
    for (std::size_t t = 0; t < b.triangles.size(); ++t)
        for (std::uint32_t s : b.triangles[t].spring) {
            std::int32_t* slot = &b.spring_triangles[2 * std::size_t(s)];
            slot[slot[0] < 0 ? 0 : 1] = std::int32_t(t);
        }
    SpringNetwork& net = b.net;
    net.dim = 3;
    net.X = b.mesh.positions;
    net.node_key.resize(std::size_t(n));  // canonical: from the position's bits
    for (int i = 0; i < n; ++i) {
        const Vec3 x = b.mesh.positions[std::size_t(i)];
        std::uint64_t h = hash_start(params.seed, kStreamBranchSprings + 100);
        for (float v : {x.x, x.y, x.z}) h = hash_add(h, bits(v));
        net.node_key[std::size_t(i)] = h;
    }
    net.k_anchor.resize(std::size_t(n));
    for (int i = 0; i < n; ++i)
        net.k_anchor[std::size_t(i)] = shear_spring_constant(params.G, b.node_area[std::size_t(i)],
                                                             params.D);
    net.springs.resize(std::size_t(m));
    for (int s = 0; s < m; ++s) {
        BarkSpring& sp = net.springs[std::size_t(s)];
        sp.i = edge_nodes[std::size_t(2 * s)], sp.j = edge_nodes[std::size_t(2 * s + 1)];
        const Vec3 xi = b.mesh.positions[sp.i], xj = b.mesh.positions[sp.j];
        const Vec3 d = xj - xi;
        sp.l0 = length(d);
        sp.n = d * (1.0f / sp.l0);
        sp.k = spring_constant(params.E, b.spring_face[std::size_t(s)] * params.D, sp.l0);
        // §5.2: the edge's growth strain rate between the two anchors.
        sp.growth_rate = edge_growth_rate(params.growth, xi, xj, b.mesh.normals[sp.i],
                                          b.mesh.normals[sp.j]);
        sp.key = edge_key(params.seed, xi, xj);
        const float g = clamp(gaussian_from_bits(mix64(sp.key)), -3.0f, 3.0f);
        sp.eps_c = (params.kappa - 1.0f) * std::max(0.05f, 1.0f + params.sigma * g);
        sp.family = 0;  // isotropic
    }
    return finalize_network(net);
}

Status grow_branch_bark(BranchBark& bark, const CrackRunOptions& options, CrackRun& out) {
    float g_max = 0.0f;
    for (const BarkSpring& s : bark.net.springs) g_max = std::max(g_max, std::fabs(s.growth_rate));
    const float tol = bark.params.tolerance * bark.params.edge_length * g_max;
    return run_cracking(bark.net, bark.params.growth.duration, tol, options, out);
}

Vec3 branch_node_position(const BranchBark& bark, std::uint32_t i, float t, const Vec3* W) {
    return anisotropic_growth_anchor(bark.params.growth, bark.mesh.positions[i],
                                     bark.mesh.normals[i], t) +
           W[i] * t;
}

namespace {

int limb_zone(const BranchShapeParams& shape, Vec3 x, float depth) {  // 1 trunk, 2 branch
    const LimbDistances d = limb_distances(shape, x);
    return d.f_trunk < d.f_branch - depth ? 1 : (d.f_branch < d.f_trunk - depth ? 2 : 0);
}

// Does the spring run across the junction (f_trunk - f_branch changing by more than its
// length along it) rather than along it?
bool across_junction(const BranchBark& bark, const BarkSpring& sp) {
    const LimbDistances a = limb_distances(bark.params.shape, bark.mesh.positions[sp.i]);
    const LimbDistances b = limb_distances(bark.params.shape, bark.mesh.positions[sp.j]);
    return std::fabs((a.f_trunk - a.f_branch) - (b.f_trunk - b.f_branch)) > sp.l0;
}

int find_network(std::vector<int>& parent, int a) {
    while (parent[std::size_t(a)] != a)
        a = parent[std::size_t(a)] = parent[std::size_t(parent[std::size_t(a)])];
    return a;
}

}  // namespace

std::vector<std::uint8_t> cracked_springs(const BranchBark& bark, float t) {
    const auto& springs = bark.net.springs;
    std::vector<std::uint8_t> strong(springs.size(), 0), cracked(springs.size(), 0);
    for (const ConnectionTriangle& tri : bark.triangles) {
        bool intact = true;
        for (std::uint32_t s : tri.spring) intact = intact && intact_at(springs[s], t);
        if (intact)
            for (std::uint32_t s : tri.spring) strong[s] = 1;
    }
    for (std::size_t s = 0; s < springs.size(); ++s) cracked[s] = !strong[s];
    return cracked;
}

namespace {

// Crack networks: the springs `joined` accepts, united when they share a triangle (a
// union-find forest over the springs: find_network gives each one's network).
template <class Joined>
std::vector<int> join_through_triangles(const BranchBark& bark, Joined joined) {
    std::vector<int> parent(bark.net.springs.size());
    for (std::size_t s = 0; s < parent.size(); ++s) parent[s] = int(s);
    for (const ConnectionTriangle& tri : bark.triangles)
        for (int k = 0; k < 3; ++k)
            for (int j = k + 1; j < 3; ++j) {
                if (!joined(tri.spring[k]) || !joined(tri.spring[j])) continue;
                const int a = find_network(parent, int(tri.spring[k]));
                const int b = find_network(parent, int(tri.spring[j]));
                if (a != b) parent[std::size_t(a)] = b;
            }
    return parent;
}

// Crossing paths: components of the crotch zone's cracked springs (joined through shared
// triangles) that share a triangle with a cracked spring of each limb's zone.
int crotch_crossing_paths(const BranchBark& bark, const std::vector<std::uint8_t>& cracked,
                          const std::vector<int>& zone) {
    const std::size_t m = cracked.size();
    auto in_crotch = [&](std::uint32_t s) { return cracked[s] && zone[s] == 0; };
    std::vector<int> parent = join_through_triangles(bark, in_crotch), touches(m, 0);
    for (const ConnectionTriangle& tri : bark.triangles)  // the limbs' cracks each path meets
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t s = tri.spring[k];
            if (!in_crotch(s)) continue;
            for (std::uint32_t o : tri.spring)
                if (cracked[o] && zone[o] != 0)
                    touches[std::size_t(find_network(parent, int(s)))] |= zone[o];
        }
    int paths = 0;
    for (std::size_t s = 0; s < m; ++s)
        paths += in_crotch(std::uint32_t(s)) && find_network(parent, int(s)) == int(s) &&
                 touches[s] == 3;
    return paths;
}

}  // namespace

Status crotch_crack_stats(const BranchBark& bark, float t, float depth, CrotchCrackStats& out) {
    if (!(is_finite(t) && t >= 0.0f) || !(is_finite(depth) && depth >= 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "crotch_crack_stats: t and depth must be >= 0 (got %g, %g)",
                             double(t), double(depth));
    out = CrotchCrackStats{};
    const auto& springs = bark.net.springs;
    const auto& x = bark.mesh.positions;
    double area[3] = {0, 0, 0}, broken[3] = {0, 0, 0}, growth[3] = {0, 0, 0}, edges[3] = {0, 0, 0};
    double crotch_growth[2] = {0, 0}, crotch_edges[2] = {0, 0};  // across, along the junction
    for (std::size_t i = 0; i < x.size(); ++i)
        area[limb_zone(bark.params.shape, x[i], depth)] += bark.node_area[i];
    const std::vector<std::uint8_t> cracked = cracked_springs(bark, t);
    std::vector<int> zone(springs.size());
    for (std::size_t s = 0; s < springs.size(); ++s) {
        zone[s] = limb_zone(bark.params.shape, (x[springs[s].i] + x[springs[s].j]) * 0.5f, depth);
        if (!intact_at(springs[s], t)) broken[zone[s]] += 1;
        const double g = double(springs[s].growth_rate) * bark.params.growth.duration;
        growth[zone[s]] += g, edges[zone[s]] += 1;
        if (zone[s] == 0) {
            const int k = across_junction(bark, springs[s]) ? 0 : 1;
            crotch_growth[k] += g, crotch_edges[k] += 1;
        }
    }
    std::vector<int> parent =
        join_through_triangles(bark, [&](std::uint32_t s) { return cracked[s] != 0; });
    std::vector<int> mask(springs.size(), 0), count(springs.size(), 0);
    for (std::size_t s = 0; s < springs.size(); ++s) {
        if (!cracked[s]) continue;
        const int root = find_network(parent, int(s));
        out.networks += root == int(s);
        mask[std::size_t(root)] |= zone[s] == 1 ? 1 : (zone[s] == 2 ? 2 : 0);
        ++count[std::size_t(root)];
    }
    for (std::size_t r = 0; r < springs.size(); ++r)
        if (mask[r] == 3)
            ++out.crossing, out.largest_crossing = std::max(out.largest_crossing, count[r]);
    out.crossing_paths = crotch_crossing_paths(bark, cracked, zone);
    auto density = [&](int z) { return area[z] > 0 ? broken[z] / area[z] : 0.0; };
    auto mean_growth = [&](int z) { return edges[z] > 0 ? growth[z] / edges[z] : 0.0; };
    out.density_trunk = density(1), out.density_crotch = density(0), out.density_branch = density(2);
    out.growth_trunk = mean_growth(1), out.growth_crotch = mean_growth(0);
    out.growth_branch = mean_growth(2);
    if (crotch_edges[0] > 0) out.growth_crotch_across = crotch_growth[0] / crotch_edges[0];
    if (crotch_edges[1] > 0) out.growth_crotch_along = crotch_growth[1] / crotch_edges[1];
    return Status::success();
}

}  // namespace shitsukan
