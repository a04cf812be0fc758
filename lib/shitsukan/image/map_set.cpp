// Host side: the map set (map_set.hpp).
#include "shitsukan/image/map_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "shitsukan/core/vec.hpp"
#include "shitsukan/image/exr.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/normal_map.hpp"
#include "shitsukan/image/pfm.hpp"
#include "shitsukan/image/png16.hpp"

namespace shitsukan {
namespace {

std::uint8_t unit_byte(float v) {
    return std::uint8_t(std::lround(std::min(1.0f, std::max(0.0f, v)) * 255.0f));
}

Status check_size(int width, int rows, std::size_t have, const char* what) {
    if (width < 1 || rows < 1 || have != std::size_t(width) * std::size_t(rows))
        return Status::error(StatusCode::invalid_argument,
                             "%s: %zu heights for a %d x %d map", what, have, width, rows);
    return Status::success();
}

// The 8 directions of the horizon search (unit steps along the axes and diagonals).
constexpr int kDirections[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1},
                                   {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};

// Occlusion of texel (x, y) toward direction d: sin of the highest elevation angle.
float horizon_occlusion(const std::vector<float>& h01, int width, int rows, int x, int y, int d,
                        const MapSetOptions& o) {
    const float here = h01[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    const float diagonal = (kDirections[d][0] != 0 && kDirections[d][1] != 0) ? 1.41421356f : 1.0f;
    float best = 0.0f;  // tan of the highest elevation so far
    for (int step = 1; float(step) <= o.ao_radius; step *= 2) {
        int qx = x + kDirections[d][0] * step, qy = y + kDirections[d][1] * step;
        if (o.wrap) {
            qx = ((qx % width) + width) % width;
            qy = ((qy % rows) + rows) % rows;
        } else if (qx < 0 || qy < 0 || qx >= width || qy >= rows) {
            break;
        }
        const float rise = o.strength * (h01[std::size_t(qy) * std::size_t(width) +
                                             std::size_t(qx)] - here);
        best = std::max(best, rise / (float(step) * diagonal));
    }
    return best / std::sqrt(1.0f + best * best);  // sin(atan(best))
}

std::vector<std::uint8_t> gray_bytes(const std::vector<float>& v) {
    std::vector<std::uint8_t> b(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) b[i] = unit_byte(v[i]);
    return b;
}

}  // namespace

Status normalise_heights(const float* height, int width, int rows, std::vector<float>& h01) {
    if (height == nullptr || width < 1 || rows < 1)
        return Status::error(StatusCode::invalid_argument,
                             "normalise_heights: empty height map (%d x %d)", width, rows);
    const std::size_t n = std::size_t(width) * std::size_t(rows);
    float lo = height[0], hi = height[0];
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(height[i]))
            return Status::error(StatusCode::invalid_argument,
                                 "normalise_heights: height at (%zu, %zu) is not finite",
                                 i % std::size_t(width), i / std::size_t(width));
        lo = std::min(lo, height[i]), hi = std::max(hi, height[i]);
    }
    h01.resize(n);
    const float range = hi - lo;
    for (std::size_t i = 0; i < n; ++i)
        h01[i] = range > 0.0f ? std::min(1.0f, (height[i] - lo) / range) : 0.0f;
    return Status::success();
}

Status derive_normal_map(const std::vector<float>& h01, int width, int rows,
                         const MapSetOptions& options, std::vector<Rgb8>& out) {
    SHITSUKAN_TRY(check_size(width, rows, h01.size(), "derive_normal_map"));
    HeightNormalOptions n;
    n.strength = options.strength;
    n.wrap = options.wrap;
    std::vector<Vec3> normals(h01.size());
    SHITSUKAN_TRY(height_map_normals(h01.data(), width, rows, n, normals.data()));
    out.resize(h01.size());
    encode_normal_rgb8(normals.data(), normals.size(), &out[0].r);
    if (options.normal == NormalConvention::directx)
        for (Rgb8& p : out) p.g = std::uint8_t(255 - p.g);  // green = -y: down the image
    return Status::success();
}

Status derive_ambient_occlusion(const std::vector<float>& h01, int width, int rows,
                                const MapSetOptions& options, std::vector<float>& out) {
    SHITSUKAN_TRY(check_size(width, rows, h01.size(), "derive_ambient_occlusion"));
    if (!std::isfinite(options.strength) || options.strength < 0.0f ||
        !(options.ao_radius >= 1.0f && options.ao_radius <= 4096.0f))
        return Status::error(StatusCode::invalid_argument,
                             "derive_ambient_occlusion: strength %g must be >= 0 and ao_radius "
                             "%g in [1, 4096] pixels",
                             double(options.strength), double(options.ao_radius));
    out.resize(h01.size());
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < width; ++x) {
            float occluded = 0.0f;
            for (int d = 0; d < 8; ++d)
                occluded += horizon_occlusion(h01, width, rows, x, y, d, options);
            out[std::size_t(y) * std::size_t(width) + std::size_t(x)] = 1.0f - occluded / 8.0f;
        }
    return Status::success();
}

void derive_roughness(const std::vector<float>& h01, const std::vector<float>& ao,
                      const MapSetOptions& options, std::vector<float>& out) {
    out.resize(h01.size());
    for (std::size_t i = 0; i < h01.size(); ++i) {
        const float polish = h01[i] * (i < ao.size() ? ao[i] : 1.0f);
        out[i] = options.roughness_low + (options.roughness_high - options.roughness_low) *
                                             (1.0f - polish);
    }
}

Status write_map_set(const char* prefix, const MapSetInput& input, const MapSetOptions& options,
                     std::vector<std::string>& written) {
    if (prefix == nullptr || !prefix[0])
        return Status::error(StatusCode::invalid_argument, "write_map_set: empty prefix");
    const int w = input.width, h = input.height_rows;
    std::vector<float> h01, ao, rough;
    SHITSUKAN_TRY(normalise_heights(input.height, w, h, h01));
    const std::size_t n = h01.size();
    const std::string p = prefix;
    auto note = [&](const std::string& path) { written.push_back(path); };
    if (input.albedo) {
        RgbView albedo{const_cast<Rgb8*>(input.albedo), w, h, w};
        SHITSUKAN_TRY(write_png((p + "_albedo.png").c_str(), albedo));
        note(p + "_albedo.png");
    }
    Gray16Image h16(w, h);
    for (std::size_t i = 0; i < n; ++i)
        h16.data()[i] = std::uint16_t(std::lround(h01[i] * 65535.0f));
    SHITSUKAN_TRY(write_png16((p + "_height16.png").c_str(), h16.view()));
    note(p + "_height16.png");
    if (options.exr) {
        SHITSUKAN_TRY(write_exr((p + "_height.exr").c_str(), input.height, w, h, 1));
        note(p + "_height.exr");
    }
    if (options.pfm) {
        SHITSUKAN_TRY(write_pfm((p + "_height.pfm").c_str(), input.height, w, h, 1));
        note(p + "_height.pfm");
    }
    std::vector<Rgb8> normal;
    SHITSUKAN_TRY(derive_normal_map(h01, w, h, options, normal));
    SHITSUKAN_TRY(write_png((p + "_normal.png").c_str(), RgbView{normal.data(), w, h, w}));
    note(p + "_normal.png");
    SHITSUKAN_TRY(derive_ambient_occlusion(h01, w, h, options, ao));
    derive_roughness(h01, ao, options, rough);
    std::vector<std::uint8_t> bytes = gray_bytes(rough);
    SHITSUKAN_TRY(write_png((p + "_roughness.png").c_str(), GrayView{bytes.data(), w, h, w}));
    note(p + "_roughness.png");
    bytes = gray_bytes(ao);
    SHITSUKAN_TRY(write_png((p + "_ao.png").c_str(), GrayView{bytes.data(), w, h, w}));
    note(p + "_ao.png");
    return Status::success();
}

}  // namespace shitsukan
