#include "shitsukan/geom/planar_subdivision.hpp"

#include <cstdint>
#include <cstring>
#include <unordered_map>

#include "shitsukan/core/memory_budget.hpp"

namespace shitsukan {
namespace {

struct PointKey {
    std::uint64_t x, y;
    bool operator==(const PointKey& o) const { return x == o.x && y == o.y; }
};
struct PointKeyHash {
    std::size_t operator()(const PointKey& k) const {
        std::uint64_t h = k.x * 0x9e3779b97f4a7c15ULL ^ (k.y + 0x632be59bd9b4e019ULL + (k.x << 6));
        return std::size_t(h ^ (h >> 29));
    }
};

PointKey key_of(Vec2d p) {
    if (p.x == 0.0) p.x = 0.0;  // -0 and +0 are the same point
    if (p.y == 0.0) p.y = 0.0;
    PointKey k;
    std::memcpy(&k.x, &p.x, 8);
    std::memcpy(&k.y, &p.y, 8);
    return k;
}

}  // namespace

Status build_planar_subdivision(const Vec2d* vertices, const int* offsets, int polygon_count,
                                PlanarSubdivision& out) {
    if (offsets == nullptr || polygon_count < 0)
        return Status::error(StatusCode::invalid_argument,
                             "build_planar_subdivision: bad arguments");
    if (polygon_count > 0 && vertices == nullptr)
        return Status::error(StatusCode::invalid_argument,
                             "build_planar_subdivision: vertices is null");
    if (polygon_count > 0 && offsets[polygon_count] < offsets[0])
        return Status::error(StatusCode::invalid_argument,
                             "build_planar_subdivision: offsets[%d] = %d is below offsets[0] = %d",
                             polygon_count, offsets[polygon_count], offsets[0]);
    const std::uint64_t vertex_refs =
        polygon_count > 0 ? std::uint64_t(std::int64_t(offsets[polygon_count]) - offsets[0]) : 0;
    SHITSUKAN_TRY(check_memory_budget(budget_mul(vertex_refs, kPlanarSubdivisionBytesPerVertex),
                                      "build_planar_subdivision: the vertex and edge tables"));
    out.vertices.clear();
    out.edges.clear();
    out.face_offsets.assign(1, 0);
    out.face_edges.clear();
    std::unordered_map<PointKey, int, PointKeyHash> vertex_id;
    std::unordered_map<std::uint64_t, int> edge_id;  // (min vertex, max vertex) -> edge
    for (int f = 0; f < polygon_count; ++f) {
        int begin = offsets[f], end = offsets[f + 1];
        if (end - begin < 3)
            return Status::error(StatusCode::invalid_argument,
                                 "build_planar_subdivision: polygon %d has %d vertices (need 3)", f,
                                 end - begin);
        int first = -1, prev = -1;
        for (int i = begin; i <= end; ++i) {
            int id;
            if (i < end) {
                if (!is_finite(vertices[i]))
                    return Status::error(
                        StatusCode::invalid_argument,
                        "build_planar_subdivision: polygon %d vertex %d is not finite", f,
                        i - begin);
                auto ins = vertex_id.emplace(key_of(vertices[i]), int(out.vertices.size()));
                if (ins.second) out.vertices.push_back(vertices[i]);
                id = ins.first->second;
            } else {
                id = first;
            }
            if (first < 0) first = id;
            if (prev >= 0) {
                if (prev == id)
                    return Status::error(StatusCode::invalid_argument,
                                         "build_planar_subdivision: polygon %d repeats a vertex",
                                         f);
                int lo = prev < id ? prev : id, hi = prev < id ? id : prev;
                std::uint64_t key = (std::uint64_t(std::uint32_t(lo)) << 32) | std::uint32_t(hi);
                auto ins = edge_id.emplace(key, int(out.edges.size()));
                if (ins.second) {
                    out.edges.push_back({prev, id, f, -1});
                    out.face_edges.push_back(ins.first->second);
                } else {
                    PlanarSubdivision::Edge& e = out.edges[std::size_t(ins.first->second)];
                    if (e.v0 == prev || e.right >= 0)
                        return Status::error(
                            StatusCode::invalid_argument,
                            "build_planar_subdivision: polygons %d and %d overlap along an edge",
                            e.left, f);
                    e.right = f;
                    out.face_edges.push_back(~ins.first->second);
                }
            }
            prev = id;
        }
        out.face_offsets.push_back(int(out.face_edges.size()));
    }
    return Status::success();
}

bool outer_edges_on_box(const PlanarSubdivision& sub, Vec2d lo, Vec2d hi) {
    for (const auto& e : sub.edges) {
        if (e.right >= 0) continue;
        Vec2d a = sub.vertices[std::size_t(e.v0)], b = sub.vertices[std::size_t(e.v1)];
        bool on = (a.x == lo.x && b.x == lo.x) || (a.x == hi.x && b.x == hi.x) ||
                  (a.y == lo.y && b.y == lo.y) || (a.y == hi.y && b.y == hi.y);
        if (!on) return false;
    }
    return true;
}

}  // namespace shitsukan
