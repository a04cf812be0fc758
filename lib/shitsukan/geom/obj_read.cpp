// Host side: the OBJ reader (obj_read.hpp).
#include "shitsukan/geom/obj_read.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "shitsukan/core/input_file.hpp"
#include "shitsukan/geom/mesh_builders.hpp"

namespace shitsukan {
namespace {

struct Reader {
    const char* name;
    long line = 0;
    std::vector<Vec3> v, vn, colors;
    std::vector<Vec2> vt;
    long colored = 0;
    struct Corner {
        long v, t, n;  // 0-based, -1 = none
    };
    std::vector<Corner> corners;  // every triangle's three corners, in order
    bool any_t = false, any_n = false;

    Status fail(const char* what, const char* token = nullptr) const {
        if (token)
            return Status::error(StatusCode::invalid_argument, "%s:%ld: %s (\"%.40s\")", name,
                                 line, what, token);
        return Status::error(StatusCode::invalid_argument, "%s:%ld: %s", name, line, what);
    }
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Splits on blanks; tokens point into `line` (which is modified).
int split(char* line, char** tokens, int capacity, bool* overflow) {
    int n = 0;
    *overflow = false;
    char* p = line;
    while (*p) {
        while (*p && is_space(*p)) ++p;
        if (!*p) break;
        if (n == capacity) {
            *overflow = true;
            return n;
        }
        tokens[n++] = p;
        while (*p && !is_space(*p)) ++p;
        if (*p) *p++ = '\0';
    }
    return n;
}

bool parse_float(const char* s, float* out) {
    errno = 0;
    char* end = nullptr;
    const double d = std::strtod(s, &end);
    if (end == s || *end != '\0' || !std::isfinite(d) || std::fabs(d) > 3.0e38) return false;
    *out = float(d);
    return true;
}

// An OBJ index (1-based or negative) into a list of `count` elements, 0-based out.
bool parse_index(const char* s, std::size_t len, std::size_t count, long* out) {
    if (len == 0 || len > 12) return false;
    char buf[16];
    std::memcpy(buf, s, len);
    buf[len] = '\0';
    char* end = nullptr;
    errno = 0;
    const long long i = std::strtoll(buf, &end, 10);
    if (end != buf + len || errno != 0 || i == 0) return false;
    const long long resolved = i > 0 ? i - 1 : (long long)count + i;
    if (resolved < 0 || resolved >= (long long)count) return false;
    *out = long(resolved);
    return true;
}

Status parse_corner(Reader& r, const char* tok, Reader::Corner* c) {
    const char* s1 = std::strchr(tok, '/');
    const char* s2 = s1 ? std::strchr(s1 + 1, '/') : nullptr;
    if (s2 && std::strchr(s2 + 1, '/')) return r.fail("face corner is not v, v/t, v//n or v/t/n", tok);
    const std::size_t lv = s1 ? std::size_t(s1 - tok) : std::strlen(tok);
    c->v = c->t = c->n = -1;
    if (!parse_index(tok, lv, r.v.size(), &c->v))
        return r.fail(r.v.empty() ? "face refers to a vertex but none is defined above it"
                                  : "vertex index is not an integer in range (0 is not an "
                                    "index; indices refer to vertices defined above)",
                      tok);
    if (s1) {
        const char* t = s1 + 1;
        const std::size_t lt = s2 ? std::size_t(s2 - t) : std::strlen(t);
        if (lt > 0 && !parse_index(t, lt, r.vt.size(), &c->t))
            return r.fail("texture index (vt) is not an integer in range", tok);
        if (!s2 && lt == 0) return r.fail("face corner 'v/' has no texture index", tok);
        if (s2) {
            const char* n = s2 + 1;
            if (!parse_index(n, std::strlen(n), r.vn.size(), &c->n))
                return r.fail("normal index (vn) is not an integer in range", tok);
        }
    }
    return Status::success();
}

Status parse_line(Reader& r, char* text) {
    constexpr int kMaxTokens = 4096;
    static thread_local char* tokens[kMaxTokens];
    bool overflow = false;
    if (char* hash = std::strchr(text, '#')) *hash = '\0';
    const int n = split(text, tokens, kMaxTokens, &overflow);
    if (overflow) return r.fail("more than 4095 values on one line");
    if (n == 0) return Status::success();
    const char* key = tokens[0];
    auto floats = [&](int first, int count, float* out) -> Status {
        for (int k = 0; k < count; ++k)
            if (!parse_float(tokens[first + k], &out[k]))
                return r.fail("not a finite number", tokens[first + k]);
        return Status::success();
    };
    const std::size_t limit = kObjMaxElements;
    if (std::strcmp(key, "v") == 0) {
        if (n != 4 && n != 5 && n != 7) return r.fail("'v' needs x y z (or x y z r g b)");
        float f[6] = {0, 0, 0, 0, 0, 0};
        SHITSUKAN_TRY(floats(1, 3, f));
        if (n == 7) {
            SHITSUKAN_TRY(floats(4, 3, f + 3));
            ++r.colored;
        } else if (n == 5) {
            float w = 1.0f;
            SHITSUKAN_TRY(floats(4, 1, &w));  // homogeneous w: accepted, must be non-zero
            if (w == 0.0f) return r.fail("'v' with w = 0");
            f[0] /= w, f[1] /= w, f[2] /= w;
        }
        if (r.v.size() >= limit)
            return Status::error(StatusCode::too_large, "%s:%ld: more than %zu vertices", r.name,
                                 r.line, limit);
        r.v.push_back({f[0], f[1], f[2]});
        r.colors.push_back({f[3], f[4], f[5]});
    } else if (std::strcmp(key, "vt") == 0) {
        if (n < 2 || n > 4) return r.fail("'vt' needs u [v [w]]");
        float f[3] = {0, 0, 0};
        SHITSUKAN_TRY(floats(1, n - 1, f));
        if (r.vt.size() >= limit)
            return Status::error(StatusCode::too_large, "%s:%ld: too many vt", r.name, r.line);
        r.vt.push_back({f[0], f[1]});
    } else if (std::strcmp(key, "vn") == 0) {
        if (n != 4) return r.fail("'vn' needs x y z");
        float f[3];
        SHITSUKAN_TRY(floats(1, 3, f));
        if (r.vn.size() >= limit)
            return Status::error(StatusCode::too_large, "%s:%ld: too many vn", r.name, r.line);
        r.vn.push_back({f[0], f[1], f[2]});
    } else if (std::strcmp(key, "f") == 0) {
        if (n < 4) return r.fail("a face needs at least 3 corners");
        Reader::Corner first, prev, c;
        for (int k = 1; k < n; ++k) {
            SHITSUKAN_TRY(parse_corner(r, tokens[k], &c));
            if (k > 1 && ((c.t < 0) != (first.t < 0)))
                return r.fail("some corners of this face have a texture index and some not");
            if (k == 1) first = c;
            if (k >= 3) {
                if (r.corners.size() + 3 > limit)
                    return Status::error(StatusCode::too_large, "%s:%ld: too many faces",
                                         r.name, r.line);
                r.corners.push_back(first);
                r.corners.push_back(prev);
                r.corners.push_back(c);
            }
            prev = c;
        }
        r.any_t = r.any_t || first.t >= 0;
        r.any_n = r.any_n || first.n >= 0;
    }
    // Anything else (o, g, s, usemtl, mtllib, p, l, curves...) is skipped, as OBJ allows.
    return Status::success();
}

// Distinct (v, t, n) corners become vertices.
Status assemble(Reader& r, TriangleMesh* out) {
    if (r.corners.empty())
        return Status::error(StatusCode::degenerate, "%s: no faces (%zu vertices)", r.name,
                             r.v.size());
    TriangleMesh m;
    const bool keep_colors = r.colored > 0 && std::size_t(r.colored) == r.v.size();
    // A per-vertex file (every corner i, i/i, i//i or i/i/i, with as many vt / vn as v, as
    // write_obj writes): the vertices keep the file's numbering, unreferenced ones too.
    bool per_vertex = (!r.any_t || r.vt.size() == r.v.size()) &&
                      (!r.any_n || r.vn.size() == r.v.size());
    for (std::size_t k = 0; per_vertex && k < r.corners.size(); ++k) {
        const Reader::Corner& c = r.corners[k];
        per_vertex = (c.t < 0 || c.t == c.v) && (c.n < 0 || c.n == c.v) &&
                     ((c.t >= 0) == r.any_t) && ((c.n >= 0) == r.any_n);
    }
    if (per_vertex) {
        for (std::size_t i = 0; i < r.v.size(); ++i)
            m.add_vertex(r.v[i], r.any_n ? r.vn[i] : Vec3{0, 0, 0},
                         r.any_t ? r.vt[i] : Vec2{0, 0});
        if (keep_colors) m.colors = r.colors;
        for (const Reader::Corner& c : r.corners) m.indices.push_back(std::uint32_t(c.v));
    }
    std::unordered_map<std::string, std::uint32_t> seen;
    std::string key;
    for (std::size_t k = 0; !per_vertex && k < r.corners.size(); ++k) {
        const Reader::Corner& c = r.corners[k];
        key.assign(reinterpret_cast<const char*>(&c), sizeof c);
        auto it = seen.find(key);
        std::uint32_t index;
        if (it != seen.end()) {
            index = it->second;
        } else {
            index = m.add_vertex(r.v[std::size_t(c.v)],
                                 c.n >= 0 ? r.vn[std::size_t(c.n)] : Vec3{0, 0, 0},
                                 c.t >= 0 ? r.vt[std::size_t(c.t)] : Vec2{0, 0});
            if (keep_colors) m.colors.push_back(r.colors[std::size_t(c.v)]);
            seen.emplace(key, index);
        }
        m.indices.push_back(index);
    }
    if (!r.any_t) m.uvs.clear();
    if (!r.any_n) {
        Status s = compute_vertex_normals(m);
        if (!s)
            return Status::error(s.code(), "%s: computing normals: %s", r.name, s.message());
    }
    *out = std::move(m);
    return Status::success();
}

}  // namespace

Status read_obj_text(const char* text, std::size_t length, const char* name, TriangleMesh& out) {
    if (text == nullptr && length > 0)
        return Status::error(StatusCode::invalid_argument, "read_obj: null text");
    Reader r;
    r.name = name && name[0] ? name : "obj";
    std::string line;
    std::size_t i = 0;
    while (i < length) {
        std::size_t j = i;
        while (j < length && text[j] != '\n') ++j;
        ++r.line;
        if (j - i > kObjMaxLine)
            return Status::error(StatusCode::too_large, "%s:%ld: line longer than %zu bytes",
                                 r.name, r.line, kObjMaxLine);
        line.assign(text + i, j - i);
        if (line.find('\0') != std::string::npos) return r.fail("NUL byte in the text");
        // A trailing backslash continues the line (OBJ): join with the next.
        while (!line.empty() && line.back() == '\\' && j < length) {
            line.pop_back();
            i = j + 1;
            j = i;
            while (j < length && text[j] != '\n') ++j;
            ++r.line;
            line.append(text + i, j - i);
            if (line.size() > kObjMaxLine)
                return Status::error(StatusCode::too_large, "%s:%ld: line longer than %zu bytes",
                                     r.name, r.line, kObjMaxLine);
        }
        SHITSUKAN_TRY(parse_line(r, &line[0]));
        i = j + 1;
    }
    return assemble(r, &out);
}

Status read_obj(const char* path, TriangleMesh& out) {
    if (path == nullptr || !path[0])
        return Status::error(StatusCode::invalid_argument, "read_obj: empty path");
    // The text is held whole: capped at kObjMaxBytes and the memory budget as it grows, and a
    // NUL byte (not text: /dev/zero, a binary file) stops the read at its chunk.
    std::string text;
    SHITSUKAN_TRY(read_text_file(path, kObjMaxBytes, "read_obj: the text", text));
    return read_obj_text(text.data(), text.size(), path, out);
}

}  // namespace shitsukan
