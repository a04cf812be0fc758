// shitsukan/geom/marching_tetrahedra.cpp — 6 tetrahedra per cube, vertices welded by grid edge.
#include "shitsukan/geom/marching_tetrahedra.hpp"

#include <cmath>
#include <utility>
#include <vector>

namespace shitsukan {

namespace {

// The 6 Kuhn tetrahedra of a cube around its diagonal 0-7; corner c = x + 2y + 4z.
constexpr int kTets[6][4] = {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7},
                             {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}};

// Grid-edge types by the bit difference of their corners (every tetrahedron edge joins a
// corner to one whose bits include it): x, y, xy, z, xz, yz, xyz.
constexpr int kEdgeType[8] = {-1, 0, 1, 2, 3, 4, 5, 6};
constexpr int kEdgeTypes = 7;
constexpr int kPlanarTypes = 3;  // x, y, xy: the edges lying in one z layer

constexpr float kMinT = 1e-4f;  // see the header: no zero-length edges

// Even permutations of (0, 1, 2, 3) that bring a given vertex first / a given pair first.
constexpr int kSingleFirst[4][4] = {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 0, 1, 3}, {3, 0, 2, 1}};
// The same for a pair, indexed by the pair's bit mask.
void pair_first(int mask, int* order) {
    static constexpr int table[16][4] = {{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0},
                                         {0, 1, 2, 3},                              // 3 = {0,1}
                                         {0, 0, 0, 0}, {0, 2, 3, 1},                // 5 = {0,2}
                                         {1, 2, 0, 3},                              // 6 = {1,2}
                                         {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 3, 1, 2},  // 9 = {0,3}
                                         {1, 3, 2, 0},                              // 10 = {1,3}
                                         {0, 0, 0, 0}, {2, 3, 0, 1},                // 12 = {2,3}
                                         {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
    for (int k = 0; k < 4; ++k) order[k] = table[mask][k];
}

int corner_bit(int c, int axis) { return (c >> axis) & 1; }

}  // namespace

Vec3 implicit_gradient(ImplicitFunction f, const void* user, Vec3 p, float step) {
    const float inv = 0.5f / step;
    return Vec3{(f({p.x + step, p.y, p.z}, user) - f({p.x - step, p.y, p.z}, user)) * inv,
                (f({p.x, p.y + step, p.z}, user) - f({p.x, p.y - step, p.z}, user)) * inv,
                (f({p.x, p.y, p.z + step}, user) - f({p.x, p.y, p.z - step}, user)) * inv};
}

namespace {

// The sampling grid: n cells per axis, the last node of an axis exactly on the box face.
struct MarchingGrid {
    Vec3 lo, hi;
    long long n[3] = {1, 1, 1};
    long long NX = 2, NY = 2, NZ = 2;
    double cell[3] = {1, 1, 1};
    double cmin = 1;
    Vec3 node_position(long long i, long long j, long long k) const {
        return Vec3{i == n[0] ? hi.x : float(double(lo.x) + double(i) * cell[0]),
                    j == n[1] ? hi.y : float(double(lo.y) + double(j) * cell[1]),
                    k == n[2] ? hi.z : float(double(lo.z) + double(k) * cell[2])};
    }
};

Status make_marching_grid(const MarchingTetrahedraOptions& options, MarchingGrid* g) {
    const Vec3 lo = options.box_min, hi = options.box_max;
    if (!is_finite(lo) || !is_finite(hi))
        return Status::error(StatusCode::invalid_argument,
                             "marching: box (%g, %g, %g)-(%g, %g, %g) is not finite", double(lo.x),
                             double(lo.y), double(lo.z), double(hi.x), double(hi.y), double(hi.z));
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
        return Status::error(StatusCode::invalid_argument,
                             "marching: box_max (%g, %g, %g) must exceed box_min (%g, %g, %g) "
                             "on every axis",
                             double(hi.x), double(hi.y), double(hi.z), double(lo.x), double(lo.y),
                             double(lo.z));
    const float h = options.spacing;
    if (!is_finite(h) || !(h > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "marching: spacing must be > 0 and finite (got %g)", double(h));
    g->lo = lo, g->hi = hi;
    for (int a = 0; a < 3; ++a) {
        double cells = std::ceil(double(hi[a] - lo[a]) / double(h) - 1e-9);
        g->n[a] = cells < 1.0 ? 1 : (cells > 1e9 ? 1000000000LL : (long long)cells);
    }
    g->NX = g->n[0] + 1, g->NY = g->n[1] + 1, g->NZ = g->n[2] + 1;
    const long long nodes = g->NX * g->NY * g->NZ;  // each factor <= 1e9 + 1
    const long long layer_bytes = g->NX * g->NY * (long long)(2 * sizeof(float) + 10 * sizeof(int));
    if (g->n[0] > (1 << 20) || g->n[1] > (1 << 20) || g->n[2] > (1 << 20) ||
        nodes > kMaxMarchingNodes)
        return Status::error(StatusCode::too_large,
                             "marching: a grid of %lld x %lld x %lld nodes exceeds %lld nodes "
                             "(spacing %g for a box of %g x %g x %g; %lld bytes of layer "
                             "buffers plus the surface)",
                             g->NX, g->NY, g->NZ, kMaxMarchingNodes, double(h), double(hi.x - lo.x),
                             double(hi.y - lo.y), double(hi.z - lo.z), layer_bytes);
    for (int a = 0; a < 3; ++a) g->cell[a] = double(hi[a] - lo[a]) / double(g->n[a]);
    g->cmin = std::fmin(g->cell[0], std::fmin(g->cell[1], g->cell[2]));
    return Status::success();
}

// f on one z layer of nodes; closed box faces are forced outside (and NaN counts as outside).
void sample_layer(ImplicitFunction f, const void* user, const MarchingGrid& g,
                  const MarchingTetrahedraOptions& options, long long k, std::vector<float>& layer,
                  long long* evaluations) {
    const float outside = float(g.cmin);  // any f > 0
    const bool closed_z = (k == 0 && !options.cut_z_min) || (k == g.n[2] && !options.cut_z_max);
    for (long long j = 0; j < g.NY; ++j)
        for (long long i = 0; i < g.NX; ++i) {
            float v = f(g.node_position(i, j, k), user);
            ++*evaluations;
            if (!(v == v)) v = outside;
            const bool face = closed_z || i == 0 || i == g.n[0] || j == 0 || j == g.n[1];
            if (face && v < outside) v = outside;
            layer[std::size_t(i + g.NX * j)] = v;
        }
}

// The 6 Kuhn tetrahedra, each ordered so its orientation is positive (the sign alternates).
void oriented_tetrahedra(int tets[6][4]) {
    for (int t = 0; t < 6; ++t) {
        for (int k = 0; k < 4; ++k) tets[t][k] = kTets[t][k];
        int d[3][3];
        for (int r = 0; r < 3; ++r)
            for (int a = 0; a < 3; ++a)
                d[r][a] = corner_bit(tets[t][r + 1], a) - corner_bit(tets[t][0], a);
        const int det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
                        d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                        d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
        if (det < 0) std::swap(tets[t][2], tets[t][3]);
    }
}

// One cube (i, j, k) of the current layer pair: its surface vertices are welded by grid edge
// (cur: edges starting in layer k, nxt: the planar edges of layer k + 1).
struct CubePolygoniser {
    const MarchingGrid& g;
    const int (&tets)[6][4];
    std::vector<int>& cur;
    std::vector<int>& nxt;
    TriangleMesh& mesh;
    bool overflow = false;
    long long i = 0, j = 0, k = 0;
    float v[8] = {};

    // The vertex on the tetrahedron edge between corners c0 and c1 (created once per edge).
    std::uint32_t edge_vertex(int c0, int c1) {
        if (c0 > c1) std::swap(c0, c1);
        const int type = kEdgeType[c1 - c0];
        const std::size_t node = std::size_t((i + (c0 & 1)) + g.NX * (j + ((c0 >> 1) & 1)));
        int* slot = (c0 & 4) ? &nxt[node * kPlanarTypes + std::size_t(type)]
                             : &cur[node * kEdgeTypes + std::size_t(type)];
        if (*slot >= 0) return std::uint32_t(*slot);
        float t = v[c0] / (v[c0] - v[c1]);  // linear interpolation of f along the edge
        t = t < kMinT ? kMinT : (t > 1.0f - kMinT ? 1.0f - kMinT : t);
        const Vec3 p0 = g.node_position(i + (c0 & 1), j + ((c0 >> 1) & 1), k + ((c0 >> 2) & 1));
        const Vec3 p1 = g.node_position(i + (c1 & 1), j + ((c1 >> 1) & 1), k + ((c1 >> 2) & 1));
        Vec3 p = p0 + (p1 - p0) * t;
        for (int a = 0; a < 3; ++a)  // exact rims on the box planes the edge lies in
            if (p0[a] == p1[a]) p[a] = p0[a];
        if (mesh.positions.size() >= 0x7fffffffu) overflow = true;
        *slot = int(mesh.positions.size());
        mesh.positions.push_back(p);
        return std::uint32_t(*slot);
    }

    // The surface inside one tetrahedron: a triangle (one corner apart) or a quad (two and two).
    void polygonise_tetrahedron(const int (&tet)[4]) {
        int mask = 0, count = 0;
        for (int q = 0; q < 4; ++q)
            if (v[tet[q]] < 0.0f) mask |= 1 << q, ++count;
        if (count == 0 || count == 4) return;
        if (count == 1 || count == 3) {
            int lone = 0;  // the vertex alone on its side
            for (int q = 0; q < 4; ++q)
                if (((mask >> q) & 1) == (count == 1)) lone = q;
            const int* o = kSingleFirst[lone];
            const int a = tet[o[0]], b = tet[o[1]], c = tet[o[2]], d = tet[o[3]];
            const std::uint32_t eb = edge_vertex(a, b), ec = edge_vertex(a, c),
                                ed = edge_vertex(a, d);
            // (a, b, c, d) positive: the triangle (ab, ac, ad) faces away from a.
            if (count == 1)
                mesh.add_triangle(eb, ec, ed);
            else
                mesh.add_triangle(eb, ed, ec);
            return;
        }
        int o[4];
        pair_first(mask, o);
        const int a = tet[o[0]], b = tet[o[1]], c = tet[o[2]], d = tet[o[3]];
        // Inside {a, b}, outside {c, d}: the quad (ac, ad, bd, bc) faces out; split it along
        // its shorter diagonal.
        const std::uint32_t q0 = edge_vertex(a, c), q1 = edge_vertex(a, d), q2 = edge_vertex(b, d),
                            q3 = edge_vertex(b, c);
        const Vec3* P = mesh.positions.data();
        if (length_squared(P[q0] - P[q2]) <= length_squared(P[q1] - P[q3])) {
            mesh.add_triangle(q0, q1, q2);
            mesh.add_triangle(q0, q2, q3);
        } else {
            mesh.add_triangle(q0, q1, q3);
            mesh.add_triangle(q1, q2, q3);
        }
    }
};

}  // namespace

Status marching_tetrahedra(ImplicitFunction f, const void* user,
                           const MarchingTetrahedraOptions& options, TriangleMesh& out,
                           MarchingTetrahedraStats* stats) {
    if (f == nullptr) return Status::error(StatusCode::invalid_argument, "marching: no function");
    MarchingGrid g;
    SHITSUKAN_TRY(make_marching_grid(options, &g));
    int tets[6][4];
    oriented_tetrahedra(tets);

    // Layer by layer (two z layers of samples and of edge vertices in memory).
    long long evaluations = 0;
    TriangleMesh mesh;
    const std::size_t layer_nodes = std::size_t(g.NX * g.NY);
    std::vector<float> fa(layer_nodes), fb(layer_nodes);
    std::vector<int> cur(layer_nodes * kEdgeTypes, -1), nxt(layer_nodes * kPlanarTypes, -1);
    CubePolygoniser cube{g, tets, cur, nxt, mesh};
    sample_layer(f, user, g, options, 0, fa, &evaluations);
    for (long long k = 0; k < g.n[2]; ++k) {
        sample_layer(f, user, g, options, k + 1, fb, &evaluations);
        for (long long j = 0; j < g.n[1]; ++j)
            for (long long i = 0; i < g.n[0]; ++i) {
                int inside = 0;
                for (int c = 0; c < 8; ++c) {
                    const std::size_t node =
                        std::size_t((i + (c & 1)) + g.NX * (j + ((c >> 1) & 1)));
                    cube.v[c] = (c & 4) ? fb[node] : fa[node];
                    inside |= (cube.v[c] < 0.0f) << c;
                }
                if (inside == 0 || inside == 255) continue;
                cube.i = i, cube.j = j, cube.k = k;
                for (const auto& tet : tets) cube.polygonise_tetrahedron(tet);
            }
        if (cube.overflow)
            return Status::error(StatusCode::too_large,
                                 "marching: more than 2^31 surface vertices");
        // Slide the layers: layer k + 1 becomes the current one.
        fa.swap(fb);
        for (std::size_t node = 0; node < layer_nodes; ++node) {
            for (int t = 0; t < kEdgeTypes; ++t) cur[node * kEdgeTypes + std::size_t(t)] = -1;
            for (int t = 0; t < kPlanarTypes; ++t) {
                cur[node * kEdgeTypes + std::size_t(t)] = nxt[node * kPlanarTypes + std::size_t(t)];
                nxt[node * kPlanarTypes + std::size_t(t)] = -1;
            }
        }
    }
    mesh.normals.assign(mesh.positions.size(), Vec3{0, 0, 0});
    mesh.uvs.clear();
    if (options.compute_normals) {
        const float step = float(0.1 * g.cmin);
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            mesh.normals[v] = normalize(implicit_gradient(f, user, mesh.positions[v], step));
            evaluations += 6;
        }
    }
    if (stats) {
        stats->nx = int(g.n[0]);
        stats->ny = int(g.n[1]);
        stats->nz = int(g.n[2]);
        stats->cell = Vec3{float(g.cell[0]), float(g.cell[1]), float(g.cell[2])};
        stats->evaluations = evaluations;
    }
    out = std::move(mesh);
    return Status::success();
}

}  // namespace shitsukan
