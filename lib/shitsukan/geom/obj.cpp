#include "shitsukan/geom/obj.hpp"

#include <cstdio>
#include <vector>

#include "shitsukan/core/format_number.hpp"
#include "shitsukan/core/output_file.hpp"

namespace shitsukan {

namespace {

// Text into a large buffer, written out in blocks: numbers by core/format_number (the
// shortest decimal that reads back to the same float), no printf per number.
class ObjText {
public:
    explicit ObjText(OutputFile& out) : out_(out), buf_(kBlock + kLine) {}
    void text(const char* s) {
        while (*s) buf_[n_++] = *s++;
    }
    void number(float v) {
        buf_[n_++] = ' ';
        n_ += std::size_t(format_float_round_trip(&buf_[n_], int(kLine), v));
    }
    void index(unsigned i) {
        char digits[10];
        int k = 0;
        do {
            digits[k++] = char('0' + i % 10u);
            i /= 10u;
        } while (i != 0);
        while (k > 0) buf_[n_++] = digits[--k];
    }
    void end_line() {
        buf_[n_++] = '\n';
        if (n_ >= kBlock) flush();
    }
    void flush() {
        out_.write(buf_.data(), n_);
        n_ = 0;
    }

private:
    static constexpr std::size_t kBlock = std::size_t(1) << 16;
    static constexpr std::size_t kLine = 256;  // the longest line: "v" and six numbers
    OutputFile& out_;
    std::vector<char> buf_;
    std::size_t n_ = 0;
};

}  // namespace

Status write_obj(const char* path, const TriangleMesh& mesh) {
    if (!path || !path[0])
        return Status::error(StatusCode::invalid_argument, "write_obj: empty path");
    std::size_t nv = mesh.positions.size();
    for (std::uint32_t i : mesh.indices)
        if (i >= nv)
            return Status::error(StatusCode::invalid_argument,
                                 "write_obj %s: index %u out of range (%zu vertices)", path, i, nv);
    OutputFile file;
    SHITSUKAN_TRY(file.open(path));
    bool has_n = mesh.normals.size() == nv && nv > 0, has_t = mesh.uvs.size() == nv && nv > 0;
    bool has_c = mesh.colors.size() == nv && nv > 0;
    file.print("# shitsukan mesh: %zu vertices, %zu triangles\n", nv, mesh.indices.size() / 3);
    // Every number is the shortest decimal that reads back (strtof) to the same float.
    ObjText out(file);
    for (std::size_t i = 0; i < nv; ++i) {
        const Vec3& p = mesh.positions[i];
        out.text("v");
        out.number(p.x);
        out.number(p.y);
        out.number(p.z);
        if (has_c) {  // the widespread "v x y z r g b" vertex-colour extension
            out.number(mesh.colors[i].x);
            out.number(mesh.colors[i].y);
            out.number(mesh.colors[i].z);
        }
        out.end_line();
    }
    if (has_t)
        for (const Vec2& t : mesh.uvs) {
            out.text("vt");
            out.number(t.x);
            out.number(t.y);
            out.end_line();
        }
    if (has_n)
        for (const Vec3& n : mesh.normals) {
            out.text("vn");
            out.number(n.x);
            out.number(n.y);
            out.number(n.z);
            out.end_line();
        }
    const char* separator = has_t && has_n ? "/" : has_n ? "//" : "/";
    const int repeats = (has_t ? 1 : 0) + (has_n ? 1 : 0);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        out.text("f");
        for (int k = 0; k < 3; ++k) {
            unsigned i = mesh.indices[t + std::size_t(k)] + 1;  // OBJ indices start at 1
            out.text(" ");
            out.index(i);  // v, then v/vt/vn, v/vt or v//vn
            for (int r = 0; r < repeats; ++r) {
                out.text(r == 0 ? separator : "/");
                out.index(i);
            }
        }
        out.end_line();
    }
    out.flush();
    return file.commit();
}

}  // namespace shitsukan
