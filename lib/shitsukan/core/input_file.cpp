#include "shitsukan/core/input_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

#include "shitsukan/core/memory_budget.hpp"

namespace shitsukan {

namespace {

// The chunk's bytes appended to `bytes`, or why they may not be (a NUL only in a text).
template <class Bytes>
Status append_chunk(const char* path, const char* buf, std::size_t got, std::size_t max_bytes,
                    const char* what, bool text, Bytes& bytes) {
    if (const void* nul = text ? std::memchr(buf, '\0', got) : nullptr) {
        const std::size_t at = std::size_t(static_cast<const char*>(nul) - buf);
        const long line = 1 + long(std::count(bytes.begin(), bytes.end(), '\n') +
                                   std::count(buf, buf + at, '\n'));
        return Status::error(StatusCode::invalid_argument, "%s:%ld: NUL byte in the text", path,
                             line);
    }
    if (bytes.size() + got > max_bytes)
        return Status::error(StatusCode::too_large, "%s: longer than %zu bytes", path, max_bytes);
    SHITSUKAN_TRY(check_memory_budget(bytes.size() + got, what));
    bytes.insert(bytes.end(), buf, buf + got);
    return Status::success();
}

// The file read in 64 KiB chunks, each checked before it is kept.
template <class Bytes>
Status read_whole(const char* path, std::size_t max_bytes, const char* what, bool text,
                  Bytes& out) {
    if (path == nullptr || !path[0])
        return Status::error(StatusCode::invalid_argument, "%s: empty path",
                             text ? "read_text_file" : "read_binary_file");
    std::FILE* f = std::fopen(path, "rb");
    if (!f)
        return Status::error(StatusCode::io_error, "cannot open %s for reading: %s", path,
                             std::strerror(errno));
    Bytes bytes;
    char buf[1 << 16];
    std::size_t got;
    Status s = Status::success();
    while (s && (got = std::fread(buf, 1, sizeof buf, f)) > 0)
        s = append_chunk(path, buf, got, max_bytes, what, text, bytes);
    const int read_errno = std::ferror(f) != 0 ? errno : 0;
    std::fclose(f);
    if (!s) return s;
    if (read_errno != 0)
        return Status::error(StatusCode::io_error, "reading %s failed: %s", path,
                             std::strerror(read_errno));
    out = std::move(bytes);
    return Status::success();
}

}  // namespace

Status read_text_file(const char* path, std::size_t max_bytes, const char* what, std::string& out) {
    return read_whole(path, max_bytes, what, true, out);
}

Status read_binary_file(const char* path, std::size_t max_bytes, const char* what,
                        std::vector<unsigned char>& out) {
    return read_whole(path, max_bytes, what, false, out);
}

}  // namespace shitsukan
