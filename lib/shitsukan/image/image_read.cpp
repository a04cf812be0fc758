// Host side: image reading through stb_image (image_read.hpp). STB_IMAGE_STATIC keeps every
// stbi_* function private to this file (see image_io.cpp for the same with stb_image_write).
#include "shitsukan/image/image_read.hpp"

#include <cstdint>
#include <cstdio>

#include "shitsukan/core/memory_budget.hpp"

#if !defined(SHITSUKAN_NO_STB) && defined(__has_include)
#if __has_include(<stb/stb_image.h>)
#define SHITSUKAN_USE_STB_IMAGE 1
#endif
#endif

#ifdef SHITSUKAN_USE_STB_IMAGE
#define STB_IMAGE_STATIC
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
// The file's size in bytes, -1 when it cannot be measured (a pipe).
long long file_size(const char* path) {
    std::FILE* f = std::fopen(path, "rb");
    if (!f) return -1;
    long n = -1;
    if (std::fseek(f, 0, SEEK_END) == 0) n = std::ftell(f);
    std::fclose(f);
    return n;
}

// stb_image's PNM header reader (P5, P6) accumulates each number in an int without a bound,
// undefined behaviour past INT_MAX (fuzz_readers: "P5 42 421111...1"). The header is read here
// first, the way stb_image reads it (blanks and '#' comments between the numbers), and a
// number past INT_MAX is refused before stb_image sees it.
bool pnm_header_fits_int(const char* path) {
    std::FILE* f = std::fopen(path, "rb");
    if (!f) return true;  // stb_image reports the missing file
    const int p = std::fgetc(f), t = std::fgetc(f);
    bool fits = true;
    if (p == 'P' && (t == '5' || t == '6')) {
        int c = std::fgetc(f);
        for (int number = 0; number < 3 && fits; ++number) {
            for (;;) {  // blanks, then a comment to the end of its line, again
                while (c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r')
                    c = std::fgetc(f);
                if (c != '#') break;
                while (c != EOF && c != '\n' && c != '\r') c = std::fgetc(f);
            }
            long long value = 0;
            for (; c >= '0' && c <= '9' && fits; c = std::fgetc(f)) {
                value = value * 10 + (c - '0');
                fits = value <= 2147483647LL;
            }
        }
    }
    std::fclose(f);
    return fits;
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
    int w = 0, h = 0, c = 0;
    LoadedImage img;
    if (!pnm_header_fits_int(path))
        return Status::error(StatusCode::invalid_argument,
                             "%s: a PNM header number past %d", path, 2147483647);
    // The decoded buffer (stb's) and our copy must fit the memory budget before decoding:
    // a 100-byte PNG can announce 65535 x 65535 pixels.
    if (stbi_info(path, &w, &h, &c)) {
        const std::uint64_t samples =
            budget_mul(budget_mul(std::uint64_t(w), std::uint64_t(h)), std::uint64_t(c));
        const bool wide = stbi_is_16_bit(path) != 0;
        const std::uint64_t per = wide ? 2 + 2 : 1 + 2;
        // The header's size against the file's: no supported format packs more than
        // kImageMaxExpansion decoded bytes into one byte of file, so a 100-byte file claiming
        // 30000 x 30000 pixels is refused before stb_image allocates for it.
        const long long size = file_size(path);
        const std::uint64_t decoded = budget_mul(samples, wide ? 2 : 1);
        if (size >= 0 && decoded > budget_mul(std::uint64_t(size) + 64, kImageMaxExpansion))
            return Status::error(StatusCode::invalid_argument,
                                 "%s: the header claims %d x %d x %d samples (%llu bytes), more "
                                 "than its %lld bytes can hold (at most %llu decoded bytes a "
                                 "byte)",
                                 path, w, h, c, (unsigned long long)decoded, size,
                                 (unsigned long long)kImageMaxExpansion);
        SHITSUKAN_TRY(check_memory_budget(budget_mul(samples, per), "read_image: the image"));
    }
    if (stbi_is_16_bit(path)) {
        stbi_us* p = stbi_load_16(path, &w, &h, &c, 0);
        if (!p)
            return Status::error(StatusCode::io_error, "cannot read %s: %s", path,
                                 stbi_failure_reason());
        img.samples.assign(p, p + std::size_t(w) * std::size_t(h) * std::size_t(c));
        stbi_image_free(p);
        img.bits = 16;
    } else {
        stbi_uc* p = stbi_load(path, &w, &h, &c, 0);
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
