// A height map read from a PNG or a PFM (see height_map.hpp).
#include "shitsukan/image/height_map.hpp"

#include <cmath>
#include <string>

#include "shitsukan/image/image_read.hpp"
#include "shitsukan/image/pfm.hpp"

namespace shitsukan {

namespace {

bool has_pfm_extension(const std::string& p) {
    return p.size() > 4 &&
           (p.compare(p.size() - 4, 4, ".pfm") == 0 || p.compare(p.size() - 4, 4, ".PFM") == 0);
}

Status height_map_from_pfm(const std::string& p, std::vector<float>& out, int& width, int& height) {
    PfmImage img;
    SHITSUKAN_TRY(read_pfm(p.c_str(), img));
    std::vector<float> h(std::size_t(img.width) * std::size_t(img.height));
    for (std::size_t i = 0; i < h.size(); ++i) {
        h[i] = img.data[i * std::size_t(img.channels)];
        if (!std::isfinite(h[i]))
            return Status::error(StatusCode::invalid_argument,
                                 "%s: height at pixel (%d, %d) is not finite", p.c_str(),
                                 int(i % std::size_t(img.width)), int(i / std::size_t(img.width)));
    }
    out = std::move(h);
    width = img.width, height = img.height;
    return Status::success();
}

}  // namespace

Status read_height_map(const char* path, std::vector<float>& out, int& width, int& height) {
    if (!path) return Status::error(StatusCode::invalid_argument, "read_height_map: path is null");
    const std::string p = path;
    if (has_pfm_extension(p)) return height_map_from_pfm(p, out, width, height);
    LoadedImage img;
    SHITSUKAN_TRY(read_image(p.c_str(), img));
    std::vector<float> h(std::size_t(img.width) * std::size_t(img.height));
    const float scale = img.bits == 16 ? 1.0f / 65535.0f : 1.0f / 255.0f;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            h[std::size_t(y) * std::size_t(img.width) + std::size_t(x)] = float(img.sample(x, y, 0)) * scale;
    out = std::move(h);
    width = img.width, height = img.height;
    return Status::success();
}

}  // namespace shitsukan
