// Host side: the control-mesh text format (control_mesh_read.hpp).
#include "shitsukan/wrinkly/control_mesh_read.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "shitsukan/core/input_file.hpp"

namespace shitsukan {
namespace {

struct MeshReader {
    const char* name = "mesh";
    long line = 0;
    int cols = 0, rows = 0, filled = 0;
    WrControlMesh mesh;

    Status fail(const char* what) const {
        return Status::error(StatusCode::invalid_argument, "%s:%ld: %s", name, line, what);
    }
};

// The numbers of one line (comment cut off): at most 8, each finite. Returns the count, or -1
// for anything else on the line.
int line_numbers(char* p, double v[8]) {
    if (char* hash = std::strchr(p, '#')) *hash = '\0';
    int n = 0;
    while (true) {
        while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
        if (!*p) return n;
        char* end = nullptr;
        const double d = std::strtod(p, &end);
        // finite as the float it is stored in (fuzz_readers: 1e115 became an infinite position)
        if (end == p || !(std::fabs(d) <= double(FLT_MAX)) || n == 8) return -1;
        v[n++] = d;
        p = end;
    }
}

bool in_unit(double x) { return x >= 0.0 && x <= 1.0; }

Status read_size(MeshReader& r, int n, const double v[8]) {
    if (n != 2 || v[0] < 1 || v[1] < 1 || v[0] * v[1] > double(kControlMeshMaxPoints) ||
        v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]))
        return r.fail("the first line must be \"cols rows\" (integers, at most 65536 points)");
    r.cols = int(v[0]), r.rows = int(v[1]);
    r.mesh = make_control_mesh(r.cols, r.rows);
    return Status::success();
}

Status read_point(MeshReader& r, int n, const double v[8]) {
    if (n != 4 && n != 7 && n != 8)
        return r.fail("a point is \"x y z h [r g b [delta]]\" (4, 7 or 8 finite numbers)");
    if (r.filled == r.cols * r.rows)
        return Status::error(StatusCode::invalid_argument, "%s:%ld: more than %d x %d points",
                             r.name, r.line, r.cols, r.rows);
    if (n >= 7 && !(in_unit(v[4]) && in_unit(v[5]) && in_unit(v[6])))
        return Status::error(StatusCode::invalid_argument,
                             "%s:%ld: the colour (%g, %g, %g) must be in [0, 1] (fujimoto2000 "
                             "§3.1: c_i = (r, g, b))",
                             r.name, r.line, v[4], v[5], v[6]);
    if (n == 8 && !(v[7] > 0.0 && v[7] < 1.0))
        return Status::error(StatusCode::invalid_argument,
                             "%s:%ld: delta must be in (0, 1) (got %g; eq. 17 needs 0 < delta < 1)",
                             r.name, r.line, v[7]);
    WrControlPoint& q = r.mesh.points[std::size_t(r.filled++)];
    q.position = {float(v[0]), float(v[1]), float(v[2])};
    q.height = float(v[3]);
    if (n >= 7) q.color = {float(v[4]), float(v[5]), float(v[6])};
    if (n == 8) q.delta = float(v[7]);
    return Status::success();
}

}  // namespace

Status read_control_mesh_text(const char* text, std::size_t length, const char* name,
                              WrControlMesh& out) {
    if (text == nullptr && length > 0)
        return Status::error(StatusCode::invalid_argument, "read_control_mesh: null text");
    MeshReader r;
    r.name = name && name[0] ? name : "mesh";
    char line[kControlMeshMaxLine + 1];
    for (std::size_t i = 0; i < length;) {
        std::size_t j = i;
        while (j < length && text[j] != '\n') ++j;
        ++r.line;
        if (j - i > kControlMeshMaxLine)
            return Status::error(StatusCode::too_large, "%s:%ld: line longer than %zu bytes",
                                 r.name, r.line, kControlMeshMaxLine);
        std::memcpy(line, text + i, j - i);
        line[j - i] = '\0';
        if (std::strlen(line) != j - i) return r.fail("NUL byte in the text");
        i = j + 1;
        double v[8];
        const int n = line_numbers(line, v);
        if (n == 0) continue;
        if (n < 0 && r.cols == 0)
            return r.fail("the first line must be \"cols rows\" (integers, at most 65536 points)");
        SHITSUKAN_TRY(r.cols == 0 ? read_size(r, n, v) : read_point(r, n, v));
    }
    if (r.cols == 0 || r.filled != r.cols * r.rows)
        return Status::error(StatusCode::invalid_argument, "%s: %d of %d x %d points given",
                             r.name, r.filled, r.cols, r.rows);
    out = std::move(r.mesh);
    return Status::success();
}

Status read_control_mesh(const char* path, WrControlMesh& out) {
    if (path == nullptr || !path[0])
        return Status::error(StatusCode::invalid_argument, "read_control_mesh: empty path");
    std::string text;
    SHITSUKAN_TRY(
        read_text_file(path, kControlMeshMaxBytes, "read_control_mesh: the text", text));
    return read_control_mesh_text(text.data(), text.size(), path, out);
}

}  // namespace shitsukan
