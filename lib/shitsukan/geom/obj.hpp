// shitsukan/geom/obj.hpp — Wavefront OBJ export.
//
// Manual
//   Status s = write_obj("pot.obj", mesh);   // v (with "r g b" when the mesh has colours,
//                                            // the common vertex-colour extension), vt, vn, f
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

Status write_obj(const char* path, const TriangleMesh& mesh);

}  // namespace shitsukan
