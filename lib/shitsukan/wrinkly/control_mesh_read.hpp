// shitsukan/wrinkly/control_mesh_read.hpp — the WR control mesh (fujimoto2000 §3.1,
// control_mesh.hpp) from a text file, the format `shitsukan wrinkly --mesh` reads.
//
// Manual
//   const char text[] = "# a 2 x 2 patch\n2 2\n0 0 0 0\n1 0 0 0.2\n0 1 0 0\n1 1 0 0 1 0 0\n";
//   WrControlMesh mesh;
//   Status s = read_control_mesh_text(text, sizeof text - 1, "inline", mesh);
//   if (s) s = read_control_mesh("examples/data/ridge.mesh", mesh);  // "file:line: what"
//   return s.code() == StatusCode::io_error ? Status::success() : s;  // (run from anywhere)
//
// Format: '#' starts a comment; blank lines are skipped; the first line is "cols rows"
// (integers, cols·rows <= kControlMeshMaxPoints), then cols·rows points row by row, one a
// line: "x y z h [r g b [delta]]": position x_i, height h_i, colour c_i with every component in
// [0, 1], the ratio value delta_i of eq. (19) in (0, 1). Every number finite as a float.
// Errors (invalid_argument, "name:line: what"): a line that is not such numbers, a colour
// outside [0, 1], delta outside (0, 1), too many or too few points, a NUL byte. A line
// longer than kControlMeshMaxLine or a file longer than kControlMeshMaxBytes -> too_large
// (refused, never split). A missing file -> io_error. Host side.
#pragma once

#include <cstddef>

#include "shitsukan/core/status.hpp"
#include "shitsukan/wrinkly/control_mesh.hpp"

namespace shitsukan {

// chosen here: eight numbers need well under 1 KiB, a mesh of 65536 points is far above the
// papers' 8 x 8 and 12 x 12 meshes.
constexpr std::size_t kControlMeshMaxLine = 1024;
constexpr long kControlMeshMaxPoints = 65536;
constexpr std::size_t kControlMeshMaxBytes = std::size_t(64) << 20;  // 64 MiB

Status read_control_mesh(const char* path, WrControlMesh& out);
// `name` is used in the messages in place of a path.
Status read_control_mesh_text(const char* text, std::size_t length, const char* name,
                              WrControlMesh& out);

}  // namespace shitsukan
