#include "shitsukan/geom/mesh_fit.hpp"

#include <cmath>

#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

Status fit_mesh_to_cube(TriangleMesh& mesh, float extent) {
    if (!(extent > 0.0f) || !is_finite(extent))
        return Status::error(StatusCode::invalid_argument,
                             "fit_mesh_to_cube: extent must be > 0 and finite (got %g)",
                             double(extent));
    if (mesh.positions.empty())
        return Status::error(StatusCode::degenerate, "fit_mesh_to_cube: the mesh is empty");
    // The bounding box.
    Vec3 lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
    for (const Vec3& p : mesh.positions) {
        if (!is_finite(p.x) || !is_finite(p.y) || !is_finite(p.z))
            return Status::error(StatusCode::invalid_argument,
                                 "fit_mesh_to_cube: a position is not finite");
        lo = vmin(lo, p), hi = vmax(hi, p);
    }
    // One uniform scale: the longest side becomes 2·extent; the centre goes to the origin.
    const Vec3 size = hi - lo, mid = (lo + hi) * 0.5f;
    const float longest = std::fmax(size.x, std::fmax(size.y, size.z));
    if (!(longest > 0.0f))
        return Status::error(StatusCode::degenerate,
                             "fit_mesh_to_cube: the mesh's bounding box has no extent");
    const float s = 2.0f * extent / longest;
    for (Vec3& p : mesh.positions) p = (p - mid) * s;
    return Status::success();
}

}  // namespace shitsukan
