#include "shitsukan/image/image_io.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "shitsukan/core/output_file.hpp"
#include "shitsukan/image/png16.hpp"
#include "shitsukan/image/png_row_filters.hpp"

// With stb_image_write's header (Debian libstb-dev) the PNGs are compressed, in stb's format
// byte for byte: its row filters and its zlib stream, computed by the library's own faster
// steps (png_row_filters.hpp, fixed_huffman_zlib.hpp; the tests compare them with stb's).
// stb itself is compiled privately: STB_IMAGE_WRITE_STATIC makes every stbi_* function and
// global static to this file, so libshitsukan.a exports no stb symbol and links beside a
// program's own stb implementation (CI checks both with `make check-api`). Without the
// header (or with SHITSUKAN_NO_STB) write_png falls back to the library's own encoder
// (png16.cpp): the same pixels in stored, uncompressed deflate blocks, so `make install`
// needs only a compiler.
#if !defined(SHITSUKAN_NO_STB) && defined(__has_include)
#if __has_include(<stb/stb_image_write.h>)
#define SHITSUKAN_USE_STB_IMAGE_WRITE 1
#endif
#endif

#ifdef SHITSUKAN_USE_STB_IMAGE_WRITE
// stb's own zlib calls (detail::zlib_compress) get fixed_huffman_zlib too, through stb's
// documented hook.
#include "shitsukan/image/fixed_huffman_zlib.hpp"
#define STBIW_ZLIB_COMPRESS(data, size, out_size, quality) \
    ::shitsukan::fixed_huffman_zlib(data, size, out_size, quality)
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"  // the static writers we do not call
#endif
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
#endif

namespace shitsukan {

namespace detail {
bool zlib_compress(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>* out) {
#ifdef SHITSUKAN_USE_STB_IMAGE_WRITE
    if (size > 0x7FFF0000u) return false;
    int length = 0;
    unsigned char* z = stbi_zlib_compress(const_cast<unsigned char*>(data), int(size), &length,
                                          stbi_write_png_compression_level);
    if (z == nullptr) return false;
    out->assign(z, z + length);
    STBIW_FREE(z);
    return true;
#else
    (void)data, (void)size, (void)out;
    return false;
#endif
}
}  // namespace detail

namespace {

Status check(const char* path, int width, int height, bool empty) {
    if (path == nullptr || path[0] == '\0')
        return Status::error(StatusCode::invalid_argument, "image path is empty");
    if (empty)
        return Status::error(StatusCode::invalid_argument,
                             "cannot write %s: image is empty (%d x %d)", path, width, height);
    return Status::success();
}

template <class P>
Status write_netpbm(const char* path, const ImageView<P>& image, const char* magic, int channels) {
    SHITSUKAN_TRY(check(path, image.width, image.height, image.empty()));
    OutputFile out;
    SHITSUKAN_TRY(out.open(path));
    out.print("%s\n%d %d\n255\n", magic, image.width, image.height);
    for (int y = 0; !out.failed() && y < image.height; ++y)
        out.write(image.row(y), std::size_t(channels) * std::size_t(image.width));
    return out.commit();
}

}  // namespace

namespace {
#ifdef SHITSUKAN_USE_STB_IMAGE_WRITE
// One PNG chunk: length, type, data, the CRC-32 of type and data.
void write_chunk(OutputFile& out, const char* type, const unsigned char* data, std::size_t size) {
    const unsigned char head[8] = {
        static_cast<unsigned char>(size >> 24), static_cast<unsigned char>(size >> 16),
        static_cast<unsigned char>(size >> 8),  static_cast<unsigned char>(size),
        static_cast<unsigned char>(type[0]),    static_cast<unsigned char>(type[1]),
        static_cast<unsigned char>(type[2]),    static_cast<unsigned char>(type[3])};
    out.write(head, 8);
    if (size > 0) out.write(data, size);
    std::uint32_t crc = detail::crc32_update(0xFFFFFFFFu, head + 4, 4);
    crc = detail::crc32_update(crc, data, size) ^ 0xFFFFFFFFu;
    const unsigned char tail[4] = {
        static_cast<unsigned char>(crc >> 24), static_cast<unsigned char>(crc >> 16),
        static_cast<unsigned char>(crc >> 8), static_cast<unsigned char>(crc)};
    out.write(tail, 4);
}
#endif

Status encode_png8(const char* path, const void* pixels, int width, int height, int channels,
                   int stride_bytes) {
#ifdef SHITSUKAN_USE_STB_IMAGE_WRITE
    // stb_image_write's PNG (stbi_write_png_to_mem) byte for byte, from the library's own
    // faster steps: its row filters (png_row_filters.hpp), its zlib stream at its compression
    // level (fixed_huffman_zlib.hpp), its chunks; written through OutputFile.
    const std::size_t row = std::size_t(width) * std::size_t(channels) + 1;
    const std::size_t size = row * std::size_t(height);
    unsigned char* filtered = size <= 0x7FFF0000u ? static_cast<unsigned char*>(std::malloc(size))
                                                  : nullptr;
    int zlength = 0;
    unsigned char* z = nullptr;
    if (filtered != nullptr) {
        png_filter_rows_like_stb(static_cast<const unsigned char*>(pixels), stride_bytes, width,
                                 height, channels, filtered);
        z = fixed_huffman_zlib(filtered, int(size), &zlength, stbi_write_png_compression_level);
        std::free(filtered);
    }
    if (z == nullptr)
        return Status::error(StatusCode::too_large, "cannot write %s: PNG encoding of %d x %d "
                             "failed (out of memory)", path, width, height);
    OutputFile out;
    Status s = out.open(path);
    if (s) {
        static const unsigned char signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
        static const unsigned char colour_type[5] = {0, 0, 4, 2, 6};  // by channel count
        const unsigned char ihdr[13] = {
            static_cast<unsigned char>(width >> 24),  static_cast<unsigned char>(width >> 16),
            static_cast<unsigned char>(width >> 8),   static_cast<unsigned char>(width),
            static_cast<unsigned char>(height >> 24), static_cast<unsigned char>(height >> 16),
            static_cast<unsigned char>(height >> 8),  static_cast<unsigned char>(height),
            8, colour_type[channels], 0, 0, 0};
        out.write(signature, 8);
        write_chunk(out, "IHDR", ihdr, 13);
        write_chunk(out, "IDAT", z, std::size_t(zlength));
        write_chunk(out, "IEND", nullptr, 0);
        s = out.commit();
    }
    std::free(z);
    return s;
#else
    return detail::write_png8_stored(path, static_cast<const std::uint8_t*>(pixels), width,
                                     height, channels, std::size_t(stride_bytes), false);
#endif
}
}  // namespace

Status write_png(const char* path, const RgbView& image) {
    SHITSUKAN_TRY(check(path, image.width, image.height, image.empty()));
    static_assert(sizeof(Rgb8) == 3, "Rgb8 must be packed");
    return encode_png8(path, image.pixels, image.width, image.height, 3, image.stride * 3);
}

Status write_png(const char* path, const GrayView& image) {
    SHITSUKAN_TRY(check(path, image.width, image.height, image.empty()));
    return encode_png8(path, image.pixels, image.width, image.height, 1, image.stride);
}

bool png_compressed() {
#ifdef SHITSUKAN_USE_STB_IMAGE_WRITE
    return true;
#else
    return false;
#endif
}

Status write_ppm(const char* path, const RgbView& image) {
    return write_netpbm(path, image, "P6", 3);
}
Status write_pgm(const char* path, const GrayView& image) {
    return write_netpbm(path, image, "P5", 1);
}

}  // namespace shitsukan
