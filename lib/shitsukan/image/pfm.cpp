// Host side: PFM output and input (pfm.hpp).
#include "shitsukan/image/pfm.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <vector>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/core/output_file.hpp"

namespace shitsukan {
namespace {

bool little_endian() {
    const std::uint16_t one = 1;
    unsigned char b;
    std::memcpy(&b, &one, 1);
    return b == 1;
}

void swap_bytes(float* f) {
    unsigned char b[4];
    std::memcpy(b, f, 4);
    const unsigned char r[4] = {b[3], b[2], b[1], b[0]};
    std::memcpy(f, r, 4);
}

}  // namespace

Status write_pfm(const char* path, const float* samples, int width, int height, int channels) {
    if (path == nullptr || !path[0])
        return Status::error(StatusCode::invalid_argument, "write_pfm: empty path");
    if (samples == nullptr || width < 1 || height < 1)
        return Status::error(StatusCode::invalid_argument, "write_pfm %s: empty image (%d x %d)",
                             path, width, height);
    if (channels != 1 && channels != 3)
        return Status::error(StatusCode::invalid_argument,
                             "write_pfm %s: channels must be 1 or 3 (got %d)", path, channels);
    OutputFile out;
    SHITSUKAN_TRY(out.open(path));
    out.print("%s\n%d %d\n%s\n", channels == 3 ? "PF" : "Pf", width, height,
              little_endian() ? "-1.0" : "1.0");
    const std::size_t row = std::size_t(width) * std::size_t(channels);
    for (int j = height - 1; j >= 0 && !out.failed(); --j)
        out.write(samples + std::size_t(j) * row, sizeof(float) * row);
    return out.commit();
}

namespace {

struct PfmHeader {
    int channels = 0, width = 0, height = 0;
    double scale = 0.0;
};

bool blank(int c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// The first byte after the blanks starting at c.
int skip_blanks(std::FILE* f, int c) {
    while (blank(c)) c = std::fgetc(f);
    return c;
}

// A decimal size of at most 6 digits, starting with byte c (a bounded parse: fscanf's %d on
// more digits than an int holds is undefined). Sets *next to the byte after it.
bool parse_size(std::FILE* f, int c, int* value, int* next) {
    long v = 0;
    int digits = 0;
    for (; c >= '0' && c <= '9'; c = std::fgetc(f)) {
        if (++digits > 6) return false;  // > 999999, past the 65536 limit anyway
        v = v * 10 + (c - '0');
    }
    *value = int(v);
    *next = c;
    return digits > 0;
}

// "PF" or "Pf", blanks, width, height, scale, ONE whitespace byte, then the samples.
bool read_header(std::FILE* f, PfmHeader* h) {
    char magic[2];
    if (std::fread(magic, 1, 2, f) != 2 || magic[0] != 'P') return false;
    h->channels = magic[1] == 'F' ? 3 : magic[1] == 'f' ? 1 : 0;
    if (h->channels == 0) return false;
    int c = std::fgetc(f);
    if (!blank(c)) return false;
    c = skip_blanks(f, c);
    if (!parse_size(f, c, &h->width, &c) || !blank(c)) return false;
    c = skip_blanks(f, c);
    if (!parse_size(f, c, &h->height, &c) || !blank(c)) return false;
    c = skip_blanks(f, c);
    char text[32];
    int n = 0;
    for (; c != EOF && !blank(c); c = std::fgetc(f)) {
        if (n + 1 >= int(sizeof text)) return false;
        text[n++] = char(c);
    }
    text[n] = 0;
    char* end = nullptr;
    h->scale = std::strtod(text, &end);
    // the one whitespace byte after the scale was read by the loop above
    return n > 0 && end == text + n && c != EOF && std::isfinite(h->scale) && h->scale != 0.0;
}

// Bytes left in f after the current position, or -1 when f cannot seek (a pipe).
long long bytes_left(std::FILE* f) {
    const long here = std::ftell(f);
    if (here < 0 || std::fseek(f, 0, SEEK_END) != 0) return -1;
    const long size = std::ftell(f);
    if (size < 0 || std::fseek(f, here, SEEK_SET) != 0) return -1;
    return (long long)size - (long long)here;
}

Status read_samples(std::FILE* f, const char* path, const PfmHeader& h, PfmImage* img) {
    const std::uint64_t count = std::uint64_t(h.width) * std::uint64_t(h.height) *
                                std::uint64_t(h.channels);
    // The header's size against the file's before anything is allocated: a 36-byte file
    // claiming 30000 x 30000 is refused here, not after zeroing 3.6 GB.
    const long long left = bytes_left(f);
    if (left >= 0 && std::uint64_t(left) < count * 4)
        return Status::error(StatusCode::invalid_argument,
                             "%s: PFM data truncated: the header's %d x %d x %d floats need "
                             "%llu bytes, the file holds %lld",
                             path, h.width, h.height, h.channels,
                             (unsigned long long)(count * 4), left);
    SHITSUKAN_TRY(check_memory_budget(count * 4, "read_pfm: the image"));
    img->width = h.width, img->height = h.height, img->channels = h.channels;
    const std::size_t row = std::size_t(h.width) * std::size_t(h.channels);
    // Row by row as the data arrives (a pipe's size is not known in advance): the buffer never
    // runs ahead of the bytes read by more than one row. The file holds the bottom row first.
    if (left >= 0) img->data.reserve(std::size_t(count));
    for (int j = 0; j < h.height; ++j) {
        img->data.resize(img->data.size() + row);
        if (std::fread(img->data.data() + std::size_t(j) * row, sizeof(float), row, f) != row)
            return Status::error(StatusCode::invalid_argument, "%s: PFM data truncated", path);
    }
    for (int j = 0; j < h.height / 2; ++j)  // top row first
        std::swap_ranges(img->data.begin() + std::ptrdiff_t(std::size_t(j) * row),
                         img->data.begin() + std::ptrdiff_t(std::size_t(j + 1) * row),
                         img->data.begin() + std::ptrdiff_t(std::size_t(h.height - 1 - j) * row));
    return Status::success();
}

}  // namespace

Status read_pfm(const char* path, PfmImage& out) {
    if (path == nullptr || !path[0])
        return Status::error(StatusCode::invalid_argument, "read_pfm: empty path");
    std::FILE* f = std::fopen(path, "rb");
    if (!f) return Status::error(StatusCode::io_error, "cannot open %s for reading", path);
    PfmHeader h;
    Status s = Status::success();
    if (!read_header(f, &h))
        s = Status::error(StatusCode::invalid_argument, "%s: not a PFM file (header)", path);
    else if (h.width < 1 || h.height < 1 || h.width > 65536 || h.height > 65536)
        s = Status::error(StatusCode::too_large, "%s: PFM size %d x %d outside 1..65536", path,
                          h.width, h.height);
    PfmImage img;
    if (s) s = read_samples(f, path, h, &img);
    std::fclose(f);
    if (!s) return s;
    if ((h.scale < 0) != little_endian())
        for (float& v : img.data) swap_bytes(&v);
    out = std::move(img);
    return Status::success();
}

}  // namespace shitsukan
