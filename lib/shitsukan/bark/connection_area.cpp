// hirota1998 §5.1, Fig. 9: connection areas per node (shear springs) and per spring.
#include "shitsukan/bark/connection_area.hpp"

#include <cmath>

namespace shitsukan {

Status connection_areas(const ConnectionTriangle* triangles, int triangle_count, int node_count,
                        int spring_count, float* area, float* face) {
    if (triangle_count < 0 || node_count < 0 || spring_count < 0 ||
        (triangle_count > 0 && triangles == nullptr) || (node_count > 0 && area == nullptr) ||
        (spring_count > 0 && face == nullptr))
        return Status::error(StatusCode::invalid_argument,
                             "connection_areas: negative count or missing array (%d triangles, "
                             "%d nodes, %d springs)",
                             triangle_count, node_count, spring_count);
    for (int i = 0; i < node_count; ++i) area[i] = 0.0f;
    for (int s = 0; s < spring_count; ++s) face[s] = 0.0f;
    for (int t = 0; t < triangle_count; ++t) {
        const ConnectionTriangle& tri = triangles[t];
        for (int k = 0; k < 3; ++k) {
            if (tri.node[k] >= std::uint32_t(node_count) ||
                tri.spring[k] >= std::uint32_t(spring_count))
                return Status::error(StatusCode::invalid_argument,
                                     "connection_areas: triangle %d refers to node %u or spring "
                                     "%u (have %d nodes, %d springs)",
                                     t, tri.node[k], tri.spring[k], node_count, spring_count);
            if (!is_finite(tri.corner[k]))
                return Status::error(StatusCode::invalid_argument,
                                     "connection_areas: triangle %d has a non-finite corner", t);
        }
        const Vec3 a = tri.corner[0], b = tri.corner[1], c = tri.corner[2];
        const float tri_area = 0.5f * length(cross(b - a, c - a));
        if (!(tri_area > 0.0f))
            return Status::error(StatusCode::degenerate,
                                 "connection_areas: triangle %d (nodes %u, %u, %u) has no area",
                                 t, tri.node[0], tri.node[1], tri.node[2]);
        const Vec3 centroid = (a + b + c) * (1.0f / 3.0f);  // C of Fig. 9
        for (int k = 0; k < 3; ++k) {
            // Fig. 9(b): corner-P-C-P' is a third of the triangle.
            area[tri.node[k]] += tri_area * (1.0f / 3.0f);
            // Fig. 9(a): the segment P-C of the spring's shared boundary C1-P-C2.
            const Vec3 midpoint = (tri.corner[k] + tri.corner[(k + 1) % 3]) * 0.5f;  // P
            face[tri.spring[k]] += length(centroid - midpoint);
        }
    }
    return Status::success();
}

}  // namespace shitsukan
