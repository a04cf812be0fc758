#include "shitsukan/geom/obj.hpp"

#include <cstdio>

namespace shitsukan {

Status write_obj(const char* path, const TriangleMesh& mesh) {
    if (!path || !path[0])
        return Status::error(StatusCode::invalid_argument, "write_obj: empty path");
    std::size_t nv = mesh.positions.size();
    for (std::uint32_t i : mesh.indices)
        if (i >= nv)
            return Status::error(StatusCode::invalid_argument,
                                 "write_obj %s: index %u out of range (%zu vertices)", path, i, nv);
    std::FILE* f = std::fopen(path, "wb");
    if (!f) return Status::error(StatusCode::io_error, "cannot open %s for writing", path);
    bool has_n = mesh.normals.size() == nv && nv > 0, has_t = mesh.uvs.size() == nv && nv > 0;
    bool has_c = mesh.colors.size() == nv && nv > 0;
    // %.9g: enough digits for every float to read back to the same bits.
    std::fprintf(f, "# shitsukan mesh: %zu vertices, %zu triangles\n", nv, mesh.indices.size() / 3);
    for (std::size_t i = 0; i < nv; ++i) {
        const Vec3& p = mesh.positions[i];
        if (has_c)  // the widespread "v x y z r g b" vertex-colour extension
            std::fprintf(f, "v %.9g %.9g %.9g %.4g %.4g %.4g\n", double(p.x), double(p.y),
                         double(p.z), double(mesh.colors[i].x), double(mesh.colors[i].y),
                         double(mesh.colors[i].z));
        else
            std::fprintf(f, "v %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
    }
    if (has_t)
        for (const Vec2& t : mesh.uvs) std::fprintf(f, "vt %.9g %.9g\n", double(t.x), double(t.y));
    if (has_n)
        for (const Vec3& n : mesh.normals)
            std::fprintf(f, "vn %.6g %.6g %.6g\n", double(n.x), double(n.y), double(n.z));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::fprintf(f, "f");
        for (int k = 0; k < 3; ++k) {
            unsigned i = mesh.indices[t + std::size_t(k)] + 1;  // OBJ indices start at 1
            if (has_t && has_n)
                std::fprintf(f, " %u/%u/%u", i, i, i);
            else if (has_t)
                std::fprintf(f, " %u/%u", i, i);
            else if (has_n)
                std::fprintf(f, " %u//%u", i, i);
            else
                std::fprintf(f, " %u", i);
        }
        std::fprintf(f, "\n");
    }
    bool ok = !std::ferror(f);
    ok = (std::fclose(f) == 0) && ok;
    if (!ok) return Status::error(StatusCode::io_error, "writing %s failed", path);
    return Status::success();
}

}  // namespace shitsukan
