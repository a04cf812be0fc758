// shitsukan/geom/obj_read.hpp — Wavefront OBJ input: positions, uv, normals, faces (a
// teacher's own mesh for the solid textures and the bake).
//
// Manual
//   const char text[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
//   TriangleMesh mesh;
//   Status s = read_obj_text(text, sizeof text - 1, "inline", mesh);  // from memory
//   if (s) s = write_obj("teapot.obj", mesh);                          // (obj.hpp)
//   if (s) s = read_obj("teapot.obj", mesh);     // error: "teapot.obj:12: ..." (line number)
//   return s;
//   #include "shitsukan/geom/obj.hpp"
//
// Read: "v x y z" (and "v x y z r g b", the vertex-colour extension write_obj writes; kept
// when every vertex has one), "vt u v [w]", "vn x y z", "f a b c ..." with corners v, v/t,
// v//n or v/t/n, indices from 1 or negative (relative to the end, -1 = the last so far).
// Polygons are split into a fan (a b c, a c d, ...). Each distinct (v, vt, vn) corner becomes
// one vertex of the TriangleMesh (its attributes are per vertex). Ignored: comments and the
// grouping/material/smoothing statements (o g s usemtl mtllib), points and lines (p l),
// and any other statement (curves, ...), which readers are told to skip. Without vn in the
// file the normals are computed (area-weighted, compute_vertex_normals); without vt the
// mesh has no uv (uvs empty). A face's corners must either all have vt or all not.
// Errors (invalid_argument, "path:line: what"): a number that is not one or not finite, a
// wrong count of numbers, an index 0 or out of range (an index refers to the elements defined
// ABOVE it), a face with fewer than 3 corners, a corner that is not v, v/t, v//n or v/t/n.
// A file without faces -> degenerate. A line longer than kObjMaxLine, more than
// kObjMaxElements elements, a file longer than kObjMaxBytes (read_obj holds the text whole;
// it stops reading there, and at the memory budget) -> too_large. A NUL byte (a binary file,
// /dev/zero: refused at the first 64 KiB read) -> invalid_argument. A missing file ->
// io_error. No input crashes the reader (tests/data/obj_malformed, and the sanitizer run).
// Host side (std::vector, std::unordered_map).
#pragma once

#include <cstddef>

#include "shitsukan/core/status.hpp"
#include "shitsukan/geom/mesh.hpp"

namespace shitsukan {

constexpr std::size_t kObjMaxLine = 1u << 16;      // 64 KiB per line
constexpr std::size_t kObjMaxElements = 1u << 26;  // 67 M vertices / corners
// chosen here: 1 GiB of text, about 30 M lines of "v x y z": far above any mesh the figures,
// the tool or a teacher's model need, and a fixed stop for an endless stream (a pipe).
constexpr std::size_t kObjMaxBytes = std::size_t(1) << 30;

Status read_obj(const char* path, TriangleMesh& out);
// `name` is used in the messages in place of a path.
Status read_obj_text(const char* text, std::size_t length, const char* name, TriangleMesh& out);

}  // namespace shitsukan
