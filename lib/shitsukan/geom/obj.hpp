// shitsukan/geom/obj.hpp — Wavefront OBJ export.
//
// Manual
//   TriangleMesh mesh;
//   Status s = make_uv_sphere(1.0f, 16, 8, mesh);
//   if (s) s = write_obj("pot.obj", mesh);   // v (with "r g b" when the mesh has colours,
//                                            // the common vertex-colour extension), vt, vn, f
//   return s;
//   #include "shitsukan/geom/mesh_builders.hpp"
//
// Written through core/output_file.hpp: the file appears complete or not at all, and a
// failure names the path and the reason.
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

Status write_obj(const char* path, const TriangleMesh& mesh);

}  // namespace shitsukan
