// Host side: PFM output and input (pfm.hpp).
#include "shitsukan/image/pfm.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>

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

Status read_pfm(const char* path, PfmImage& out) {
    if (path == nullptr || !path[0])
        return Status::error(StatusCode::invalid_argument, "read_pfm: empty path");
    std::FILE* f = std::fopen(path, "rb");
    if (!f) return Status::error(StatusCode::io_error, "cannot open %s for reading", path);
    char magic[3] = {0, 0, 0};
    int width = 0, height = 0;
    double scale = 0;
    // "PF" or "Pf", blanks, width, height, scale, ONE whitespace byte, then the samples.
    const bool header = std::fscanf(f, "%2s %d %d %lf", magic, &width, &height, &scale) == 4 &&
                        std::fgetc(f) != EOF;
    const int channels = std::strcmp(magic, "PF") == 0 ? 3 : std::strcmp(magic, "Pf") == 0 ? 1 : 0;
    if (!header || channels == 0 || scale == 0.0) {
        std::fclose(f);
        return Status::error(StatusCode::invalid_argument, "%s: not a PFM file (header)", path);
    }
    if (width < 1 || height < 1 || width > 65536 || height > 65536) {
        std::fclose(f);
        return Status::error(StatusCode::too_large, "%s: PFM size %d x %d outside 1..65536",
                             path, width, height);
    }
    {
        const std::uint64_t bytes = budget_mul(
            budget_mul(budget_mul(std::uint64_t(width), std::uint64_t(height)), channels), 4);
        Status budget = check_memory_budget(bytes, "read_pfm: the image");
        if (!budget) {
            std::fclose(f);
            return budget;
        }
    }
    PfmImage img;
    img.width = width, img.height = height, img.channels = channels;
    const std::size_t row = std::size_t(width) * std::size_t(channels);
    img.data.resize(row * std::size_t(height));
    for (int j = height - 1; j >= 0; --j)
        if (std::fread(img.data.data() + std::size_t(j) * row, sizeof(float), row, f) != row) {
            std::fclose(f);
            return Status::error(StatusCode::invalid_argument, "%s: PFM data truncated", path);
        }
    std::fclose(f);
    if ((scale < 0) != little_endian())
        for (float& v : img.data) swap_bytes(&v);
    out = std::move(img);
    return Status::success();
}

}  // namespace shitsukan
