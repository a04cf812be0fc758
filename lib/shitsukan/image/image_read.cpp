// Host side: image reading through stb_image (image_read.hpp). STB_IMAGE_STATIC keeps every
// stbi_* function private to this file (see image_io.cpp for the same with stb_image_write).
#include "shitsukan/image/image_read.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "shitsukan/core/input_file.hpp"
#include "shitsukan/core/memory_budget.hpp"

#if !defined(SHITSUKAN_NO_STB) && defined(__has_include)
#if __has_include(<stb/stb_image.h>)
#define SHITSUKAN_USE_STB_IMAGE 1
#endif
#endif

#ifdef SHITSUKAN_USE_STB_IMAGE
#define STB_IMAGE_STATIC
// The formats a height map or a photo comes in; stb_image's GIF, PSD, PIC and HDR readers are left
// out (chosen here: less of a third-party decoder exposed to hostile files; PFM carries floats).
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_ONLY_PNM
#define STB_IMAGE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wpedantic"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
#endif

namespace shitsukan {

#ifdef SHITSUKAN_USE_STB_IMAGE
namespace {
using Bytes = std::vector<unsigned char>;

// stb_image's PNM header reader (P5, P6) accumulates each number in an int without a bound,
// undefined behaviour past INT_MAX (fuzz_readers: "P5 42 421111...1"). The header is read here
// first, the way stb_image reads it (blanks and '#' comments between the numbers), and a
// number past INT_MAX is refused before stb_image sees it.
bool pnm_header_fits_int(const Bytes& file) {
    std::size_t at = 2;
    auto next = [&]() { return at < file.size() ? int(file[at++]) : EOF; };
    if (file.size() < 2 || file[0] != 'P' || (file[1] != '5' && file[1] != '6')) return true;
    int c = next();
    for (int number = 0; number < 3; ++number) {
        for (;;) {  // blanks, then a comment to the end of its line, again
            while (c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r')
                c = next();
            if (c != '#') break;
            while (c != EOF && c != '\n' && c != '\r') c = next();
        }
        long long value = 0;
        for (; c >= '0' && c <= '9'; c = next()) {
            value = value * 10 + (c - '0');
            if (value > 2147483647LL) return false;
        }
    }
    return true;
}

std::uint32_t big_endian_u32(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 |
           std::uint32_t(p[3]);
}

// A PNG's chunks walked before stb_image decodes it: stb_image grows its compressed-data buffer
// to each IDAT chunk's stated length before reading it, so a 60-byte file whose IDAT claims
// 2^30 bytes allocated 1 GiB (fuzz_readers, an out-of-memory). Every chunk must lie inside the
// file, its length at most 2^31 - 1 (the PNG specification's bound), and IEND must come.
// Not a PNG: success, for stb_image to judge.
Status png_chunks_inside(const char* path, const Bytes& file) {
    static const unsigned char signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    if (file.size() < 8 || std::memcmp(file.data(), signature, 8) != 0) return Status::success();
    std::size_t at = 8;
    while (at + 8 <= file.size()) {
        const std::uint32_t length = big_endian_u32(&file[at]);
        char type[5] = {0, 0, 0, 0, 0};
        for (int i = 0; i < 4; ++i) {
            const unsigned char t = file[at + 4 + std::size_t(i)];
            type[i] = (t >= 'A' && t <= 'Z') || (t >= 'a' && t <= 'z') ? char(t) : '?';
        }
        if (length > 0x7fffffffu)
            return Status::error(StatusCode::invalid_argument,
                                 "%s: PNG chunk %s at byte %zu claims %u bytes (at most "
                                 "2^31 - 1)",
                                 path, type, at, length);
        if (std::uint64_t(at) + 12 + length > file.size())
            return Status::error(StatusCode::invalid_argument,
                                 "%s: PNG chunk %s at byte %zu claims %u bytes, past the file's "
                                 "end (%zu bytes): a truncated file",
                                 path, type, at, length, file.size());
        if (std::memcmp(type, "IEND", 4) == 0) return Status::success();
        at += 12 + std::size_t(length);
    }
    return Status::error(StatusCode::invalid_argument,
                         "%s: PNG ends after %zu bytes without its IEND chunk: a truncated file",
                         path, file.size());
}

// A JPEG's marker segments walked before stb_image decodes it: each inside the file, and every
// Huffman table (DHT) of at most 256 codes. stb_image 2.27 sums a table's 16 code counts
// without that bound and writes past its 257-entry size list (fuzz_readers: a 28-byte file,
// counts summing to 1,578). Between the segments after a scan (SOS) the entropy-coded bytes are
// skipped (0xFF there is followed by 0x00 or a restart marker). The end of image (EOI) must
// come. A start of image after fill bytes (0xFF 0xFF 0xD8) is a JPEG to stb_image too (the
// rerun's second finding). Not a JPEG: success, for stb_image to judge.
Status jpeg_segments_inside(const char* path, const Bytes& file) {
    const std::size_t n = file.size();
    std::size_t at = 0;  // SOI: 0xFF, any fill bytes 0xFF, 0xD8 (as stb_image reads a marker)
    while (at < n && file[at] == 0xFF) ++at;
    if (at == 0 || at >= n || file[at] != 0xD8) return Status::success();
    ++at;
    while (at + 1 < n) {
        if (file[at] != 0xFF) {  // entropy-coded data after a scan
            ++at;
            continue;
        }
        const unsigned marker = file[at + 1];
        if (marker == 0xFF) {  // a fill byte
            ++at;
            continue;
        }
        if (marker == 0x00 || (marker >= 0xD0 && marker <= 0xD8) || marker == 0x01) {
            at += 2;  // a stuffed 0xFF, a restart marker, SOI or TEM: no length follows
            continue;
        }
        if (marker == 0xD9) return Status::success();  // EOI
        if (at + 4 > n)
            return Status::error(StatusCode::invalid_argument,
                                 "%s: JPEG ends inside the marker at byte %zu: a truncated file",
                                 path, at);
        const std::size_t length = std::size_t(file[at + 2]) << 8 | file[at + 3];
        const std::size_t end = at + 2 + length;
        if (length < 2 || end > n)
            return Status::error(StatusCode::invalid_argument,
                                 "%s: JPEG segment 0x%02X at byte %zu claims %zu bytes, past the "
                                 "file's end (%zu bytes): a truncated file",
                                 path, marker, at, length, n);
        for (std::size_t table = at + 4; marker == 0xC4 && table < end;) {  // DHT's tables
            std::size_t codes = 0;
            for (std::size_t i = 1; i <= 16 && table + i < end; ++i) codes += file[table + i];
            if (codes > 256 || table + 17 + codes > end)
                return Status::error(StatusCode::invalid_argument,
                                     "%s: JPEG Huffman table at byte %zu holds %zu codes (at most "
                                     "256, within its segment)",
                                     path, table, codes);
            table += 17 + codes;
        }
        at = end;
    }
    return Status::error(StatusCode::invalid_argument,
                         "%s: JPEG ends after %zu bytes without its end-of-image marker: a "
                         "truncated file",
                         path, n);
}
}  // namespace
#endif

bool image_reading_available() {
#ifdef SHITSUKAN_USE_STB_IMAGE
    return true;
#else
    return false;
#endif
}

Status read_image(const char* path, LoadedImage& out) {
    if (path == nullptr || !path[0])
        return Status::error(StatusCode::invalid_argument, "read_image: empty path");
#ifdef SHITSUKAN_USE_STB_IMAGE
    // The file is held whole (within the memory budget) and checked before stb_image decodes
    // it from memory: its headers against its size, a PNG's chunks against its end.
    Bytes file;
    SHITSUKAN_TRY(read_binary_file(path, std::size_t(-1), "read_image: the file", file));
    if (file.size() > std::size_t(2147483647))
        return Status::error(StatusCode::too_large, "%s: %zu bytes, more than stb_image reads",
                             path, file.size());
    const stbi_uc* bytes = file.data();
    const int size = int(file.size());
    if (!pnm_header_fits_int(file))
        return Status::error(StatusCode::invalid_argument,
                             "%s: a PNM header number past %d", path, 2147483647);
    SHITSUKAN_TRY(png_chunks_inside(path, file));
    SHITSUKAN_TRY(jpeg_segments_inside(path, file));
    int w = 0, h = 0, c = 0;
    LoadedImage img;
    const bool wide = stbi_is_16_bit_from_memory(bytes, size) != 0;
    // The decoded buffer (stb's) and our copy must fit the memory budget before decoding:
    // a 100-byte PNG can announce 65535 x 65535 pixels.
    if (stbi_info_from_memory(bytes, size, &w, &h, &c)) {
        const std::uint64_t samples =
            budget_mul(budget_mul(std::uint64_t(w), std::uint64_t(h)), std::uint64_t(c));
        const std::uint64_t per = wide ? 2 + 2 : 1 + 2;
        // The header's size against the file's: no supported format packs more than
        // kImageMaxExpansion decoded bytes into one byte of file, so a 100-byte file claiming
        // 30000 x 30000 pixels is refused before stb_image allocates for it.
        const std::uint64_t decoded = budget_mul(samples, wide ? 2 : 1);
        if (decoded > budget_mul(std::uint64_t(size) + 64, kImageMaxExpansion))
            return Status::error(StatusCode::invalid_argument,
                                 "%s: the header claims %d x %d x %d samples (%llu bytes), more "
                                 "than its %d bytes can hold (at most %llu decoded bytes a "
                                 "byte)",
                                 path, w, h, c, (unsigned long long)decoded, size,
                                 (unsigned long long)kImageMaxExpansion);
        SHITSUKAN_TRY(check_memory_budget(budget_mul(samples, per) + file.size(),
                                          "read_image: the image"));
    }
    if (wide) {
        stbi_us* p = stbi_load_16_from_memory(bytes, size, &w, &h, &c, 0);
        if (!p)
            return Status::error(StatusCode::io_error, "cannot read %s: %s", path,
                                 stbi_failure_reason());
        img.samples.assign(p, p + std::size_t(w) * std::size_t(h) * std::size_t(c));
        stbi_image_free(p);
        img.bits = 16;
    } else {
        stbi_uc* p = stbi_load_from_memory(bytes, size, &w, &h, &c, 0);
        if (!p)
            return Status::error(StatusCode::io_error, "cannot read %s: %s", path,
                                 stbi_failure_reason());
        img.samples.assign(p, p + std::size_t(w) * std::size_t(h) * std::size_t(c));
        stbi_image_free(p);
        img.bits = 8;
    }
    // stb_image's PNM reader accepts a size of 0 (fuzz_readers: "P6 21255 0 255" read as an
    // ok image of no pixels); an image has at least one.
    if (w < 1 || h < 1 || c < 1 || c > 4)
        return Status::error(StatusCode::invalid_argument,
                             "%s: an image of %d x %d pixels and %d channels (each must be >= 1, "
                             "at most 4 channels)",
                             path, w, h, c);
    img.width = w, img.height = h, img.channels = c;
    out = std::move(img);
    return Status::success();
#else
    (void)out;  // nothing read: a build without stb_image (say, the WASM build) leaves it as is
    return Status::error(StatusCode::not_supported,
                         "read_image %s: this build has no stb_image (install libstb-dev)", path);
#endif
}

}  // namespace shitsukan
