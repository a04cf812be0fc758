// Host side: image reading through stb_image (image_read.hpp). STB_IMAGE_STATIC keeps every
// stbi_* function private to this file (see image_io.cpp for the same with stb_image_write).
#include "shitsukan/image/image_read.hpp"

#include <cstdint>

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
    // The decoded buffer (stb's) and our copy must fit the memory budget before decoding:
    // a 100-byte PNG can announce 65535 x 65535 pixels.
    if (stbi_info(path, &w, &h, &c)) {
        const std::uint64_t samples =
            budget_mul(budget_mul(std::uint64_t(w), std::uint64_t(h)), std::uint64_t(c));
        const std::uint64_t per = stbi_is_16_bit(path) ? 2 + 2 : 1 + 2;
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
