// shitsukan/geom/mesh_topology.cpp — half-edge twins, manifold checks, Euler characteristic.
#include "shitsukan/geom/mesh_topology.hpp"

namespace shitsukan {

namespace {

inline int next_halfedge(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
inline int prev_halfedge(int h) { return h % 3 == 0 ? h + 2 : h - 1; }

}  // namespace

Status halfedge_opposites(const std::uint32_t* indices, int triangles, int vertex_count,
                          std::vector<int>& opposite) {
    if (triangles < 0 || vertex_count < 0 || (triangles > 0 && indices == nullptr))
        return Status::error(StatusCode::invalid_argument,
                             "mesh: %d triangles, %d vertices, indices %s", triangles, vertex_count,
                             indices ? "given" : "missing");
    const int halfedges = 3 * triangles;
    for (int t = 0; t < triangles; ++t) {
        std::uint32_t a = indices[3 * t], b = indices[3 * t + 1], c = indices[3 * t + 2];
        if (a >= std::uint32_t(vertex_count) || b >= std::uint32_t(vertex_count) ||
            c >= std::uint32_t(vertex_count))
            return Status::error(StatusCode::invalid_argument,
                                 "mesh: triangle %d has an index out of range (%u, %u, %u; "
                                 "%d vertices)",
                                 t, a, b, c, vertex_count);
        if (a == b || b == c || c == a)
            return Status::error(StatusCode::degenerate,
                                 "mesh: triangle %d repeats a vertex (%u, %u, %u)", t, a, b, c);
    }
    // Outgoing half-edges of every vertex, compressed rows (index order: deterministic).
    std::vector<int> start(std::size_t(vertex_count) + 1, 0);
    std::vector<int> out(static_cast<std::size_t>(halfedges));
    for (int h = 0; h < halfedges; ++h) ++start[indices[h] + 1];
    for (int v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int h = 0; h < halfedges; ++h) out[std::size_t(fill[indices[h]]++)] = h;

    auto target = [&](int h) { return indices[next_halfedge(h)]; };
    opposite.assign(std::size_t(halfedges), -1);
    std::vector<int>& opp = opposite;
    for (int h = 0; h < halfedges; ++h) {
        const std::uint32_t a = indices[h], b = target(h);
        int twin = -1;
        for (int k = start[b]; k < start[b + 1]; ++k) {
            int g = out[std::size_t(k)];
            if (target(g) != a) continue;
            if (twin >= 0)
                return Status::error(StatusCode::invalid_argument,
                                     "mesh is not manifold: edge (%u, %u) belongs to more than "
                                     "two triangles or to two triangles of opposite orientation",
                                     a, b);
            twin = g;
        }
        for (int k = start[a]; k < start[a + 1]; ++k) {
            int g = out[std::size_t(k)];
            if (g != h && target(g) == b)
                return Status::error(StatusCode::invalid_argument,
                                     "mesh is not manifold: directed edge %u -> %u is used by "
                                     "triangles %d and %d (inconsistent orientation or more "
                                     "than two triangles on the edge)",
                                     a, b, h / 3, g / 3);
        }
        opp[std::size_t(h)] = twin;
    }
    // One fan per vertex: walk around it from its boundary half-edge (or any half-edge) and
    // count the triangles reached; all of its triangles must be reached.
    for (int v = 0; v < vertex_count; ++v) {
        const int count = start[v + 1] - start[v];
        if (count == 0) continue;
        int first = out[std::size_t(start[v])], boundary = 0;
        for (int k = start[v]; k < start[v + 1]; ++k)
            if (opp[std::size_t(out[std::size_t(k)])] < 0) {
                // On the boundary the fan starts at the outgoing half-edge without a twin.
                first = out[std::size_t(k)];
                ++boundary;
            }
        if (boundary > 1)
            return Status::error(StatusCode::invalid_argument,
                                 "mesh is not manifold: vertex %d joins %d separate fans of "
                                 "triangles (a bow-tie vertex)",
                                 v, boundary);
        int reached = 0, h = first;
        do {
            ++reached;
            h = opp[std::size_t(prev_halfedge(h))];
        } while (h >= 0 && h != first && reached <= count);
        if (reached != count)
            return Status::error(StatusCode::invalid_argument,
                                 "mesh is not manifold: the %d triangles around vertex %d form "
                                 "more than one fan (%d reached from one)",
                                 count, v, reached);
    }
    return Status::success();
}

Status mesh_topology(const TriangleMesh& mesh, MeshTopology& out) {
    out = MeshTopology{};
    const int triangles = mesh.triangle_count(), n = mesh.vertex_count();
    out.triangles = triangles;
    if (mesh.indices.size() % 3 != 0)
        return Status::error(StatusCode::invalid_argument,
                             "mesh: %zu indices is not a multiple of 3", mesh.indices.size());
    std::vector<char> used(std::size_t(n), 0);
    for (std::uint32_t i : mesh.indices)
        if (i < std::uint32_t(n)) used[i] = 1;
    for (char u : used) out.vertices += u;
    out.unreferenced = n - out.vertices;
    std::vector<int> opp;
    SHITSUKAN_TRY(halfedge_opposites(mesh.indices.data(), triangles, n, opp));
    int interior_halfedges = 0;
    for (int o : opp) {
        if (o < 0)
            ++out.boundary_edges;
        else
            ++interior_halfedges;
    }
    out.edges = out.boundary_edges + interior_halfedges / 2;
    // Boundary loops: follow boundary half-edges a -> b, then the boundary half-edge leaving b
    // (unique on a manifold: the rotation around b ends there).
    std::vector<char> seen(opp.size(), 0);
    for (std::size_t h0 = 0; h0 < opp.size(); ++h0) {
        if (opp[h0] >= 0 || seen[h0]) continue;
        ++out.boundary_loops;
        int h = int(h0);
        while (!seen[std::size_t(h)]) {
            seen[std::size_t(h)] = 1;
            // Next boundary half-edge: rotate around the end vertex starting at next(h).
            int g = next_halfedge(h);
            while (opp[std::size_t(g)] >= 0) g = next_halfedge(opp[std::size_t(g)]);
            h = g;
        }
    }
    out.euler_characteristic = out.vertices - out.edges + out.triangles;
    out.manifold = true;
    return Status::success();
}

}  // namespace shitsukan
