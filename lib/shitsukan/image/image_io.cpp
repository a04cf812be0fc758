#include "shitsukan/image/image_io.hpp"

#include <cstdio>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

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
    std::FILE* f = std::fopen(path, "wb");
    if (!f) return Status::error(StatusCode::io_error, "cannot open %s for writing", path);
    bool ok = std::fprintf(f, "%s\n%d %d\n255\n", magic, image.width, image.height) > 0;
    for (int y = 0; ok && y < image.height; ++y)
        ok = std::fwrite(image.row(y), std::size_t(channels), std::size_t(image.width), f) ==
             std::size_t(image.width);
    ok = (std::fclose(f) == 0) && ok;
    if (!ok) return Status::error(StatusCode::io_error, "writing %s failed", path);
    return Status::success();
}

}  // namespace

Status write_png(const char* path, const RgbView& image) {
    SHITSUKAN_TRY(check(path, image.width, image.height, image.empty()));
    static_assert(sizeof(Rgb8) == 3, "Rgb8 must be packed");
    if (!stbi_write_png(path, image.width, image.height, 3, image.pixels, image.stride * 3))
        return Status::error(StatusCode::io_error, "cannot write PNG %s", path);
    return Status::success();
}

Status write_png(const char* path, const GrayView& image) {
    SHITSUKAN_TRY(check(path, image.width, image.height, image.empty()));
    if (!stbi_write_png(path, image.width, image.height, 1, image.pixels, image.stride))
        return Status::error(StatusCode::io_error, "cannot write PNG %s", path);
    return Status::success();
}

Status write_ppm(const char* path, const RgbView& image) {
    return write_netpbm(path, image, "P6", 3);
}
Status write_pgm(const char* path, const GrayView& image) {
    return write_netpbm(path, image, "P5", 1);
}

}  // namespace shitsukan
