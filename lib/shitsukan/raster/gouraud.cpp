#include "shitsukan/raster/gouraud.hpp"

#include <utility>
#include <vector>

namespace shitsukan {

Status apply_gouraud(TriangleMesh& mesh, const Mat4& model, const Material& material,
                     Vec3 base_color, Vec3 eye, const Light* lights, int light_count) {
    if (mesh.normals.size() != mesh.positions.size())
        return Status::error(StatusCode::invalid_argument,
                             "apply_gouraud: %zu normals for %zu vertices (compute normals first)",
                             mesh.normals.size(), mesh.positions.size());
    std::vector<Vec3> colors(mesh.positions.size());
    MeshView view = mesh.view();
    SHITSUKAN_TRY(light_vertices(view, model, material, base_color, eye, lights, light_count,
                                 colors.data(), int(colors.size())));
    mesh.colors = std::move(colors);
    return Status::success();
}

}  // namespace shitsukan
