#include "shitsukan/image/image_io.hpp"

#include <cstdint>
#include <cstdio>

#include "shitsukan/core/output_file.hpp"
#include "shitsukan/image/png16.hpp"

// stb_image_write (Debian libstb-dev) compresses the PNGs when its header is there. It is
// compiled privately: STB_IMAGE_WRITE_STATIC makes every stbi_* function and global static
// to this file, so libshitsukan.a exports no stb symbol and links beside a program's own
// stb implementation (CI checks both with `make check-api`). Without the header (or with
// SHITSUKAN_NO_STB) write_png falls back to the library's own encoder (png16.cpp): the same
// pixels in stored, uncompressed deflate blocks, so `make install` needs only a compiler.
#if !defined(SHITSUKAN_NO_STB) && defined(__has_include)
#if __has_include(<stb/stb_image_write.h>)
#define SHITSUKAN_USE_STB_IMAGE_WRITE 1
#endif
#endif

#ifdef SHITSUKAN_USE_STB_IMAGE_WRITE
// stb's zlib stream comes from fixed_huffman_zlib (the same bytes in a fraction of the time),
// handed to stb through its documented hook.
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
Status encode_png8(const char* path, const void* pixels, int width, int height, int channels,
                   int stride_bytes) {
#ifdef SHITSUKAN_USE_STB_IMAGE_WRITE
    // Encoded in memory by stb, written through OutputFile (stb's own file writer checks
    // neither fwrite nor fclose).
    OutputFile out;
    SHITSUKAN_TRY(out.open(path));
    auto to_file = [](void* context, void* data, int size) {
        static_cast<OutputFile*>(context)->write(data, std::size_t(size));
    };
    if (!stbi_write_png_to_func(to_file, &out, width, height, channels, pixels, stride_bytes))
        return Status::error(StatusCode::too_large, "cannot write %s: PNG encoding of %d x %d "
                             "failed (out of memory)", path, width, height);
    return out.commit();
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
