// Host side: the OpenEXR writer (exr.hpp).
#include "shitsukan/image/exr.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "shitsukan/core/output_file.hpp"
#include "shitsukan/image/deflate.hpp"

namespace shitsukan {
namespace {

// Little-endian byte strings, whatever the host's order.
void put_u32(std::vector<std::uint8_t>& b, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) b.push_back(std::uint8_t(v >> (8 * k)));
}
void put_u64(std::vector<std::uint8_t>& b, std::uint64_t v) {
    for (int k = 0; k < 8; ++k) b.push_back(std::uint8_t(v >> (8 * k)));
}
void put_f32(std::vector<std::uint8_t>& b, float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    put_u32(b, u);
}
void put_text(std::vector<std::uint8_t>& b, const char* s) {
    b.insert(b.end(), s, s + std::strlen(s) + 1);  // with its NUL
}

// One header attribute: name, type, byte size, value.
void put_attribute(std::vector<std::uint8_t>& b, const char* name, const char* type,
                   const std::vector<std::uint8_t>& value) {
    put_text(b, name);
    put_text(b, type);
    put_u32(b, std::uint32_t(value.size()));
    b.insert(b.end(), value.begin(), value.end());
}

// The channel names in the file's (alphabetical) order, and for each its index in the
// caller's interleaved samples.
int channel_order(int channels, const char* names[4], int source[4]) {
    if (channels == 1) {
        names[0] = "Y", source[0] = 0;
        return 1;
    }
    static const char* const kRgba[4] = {"A", "B", "G", "R"};
    static const int kRgbaSource[4] = {3, 2, 1, 0};
    const int first = channels == 4 ? 0 : 1;  // RGB: no "A"
    for (int k = first; k < 4; ++k) names[k - first] = kRgba[k], source[k - first] = kRgbaSource[k];
    return channels;
}

std::vector<std::uint8_t> exr_header(int width, int height, int channels,
                                     ExrCompression compression) {
    std::vector<std::uint8_t> b = {0x76, 0x2f, 0x31, 0x01};  // magic
    put_u32(b, 2);                                            // version 2, single-part scan lines
    const char* names[4];
    int source[4];
    std::vector<std::uint8_t> v;
    for (int c = 0; c < channel_order(channels, names, source); ++c) {
        put_text(v, names[c]);
        put_u32(v, 2);                    // pixel type FLOAT
        v.insert(v.end(), {0, 0, 0, 0});  // pLinear, reserved
        put_u32(v, 1), put_u32(v, 1);     // x and y sampling
    }
    v.push_back(0);
    put_attribute(b, "channels", "chlist", v);
    put_attribute(b, "compression", "compression",
                  {std::uint8_t(compression == ExrCompression::zip ? 3 : 0)});
    v.clear();
    put_u32(v, 0), put_u32(v, 0), put_u32(v, std::uint32_t(width - 1)),
        put_u32(v, std::uint32_t(height - 1));
    put_attribute(b, "dataWindow", "box2i", v);
    put_attribute(b, "displayWindow", "box2i", v);
    put_attribute(b, "lineOrder", "lineOrder", {0});  // INCREASING_Y
    v.clear();
    put_f32(v, 1.0f);
    put_attribute(b, "pixelAspectRatio", "float", v);
    put_attribute(b, "screenWindowWidth", "float", v);
    v.clear();
    put_f32(v, 0.0f), put_f32(v, 0.0f);
    put_attribute(b, "screenWindowCenter", "v2f", v);
    b.push_back(0);  // end of the header
    return b;
}

// The raw bytes of lines [y0, y1): per line, channel by channel in file order.
void raw_lines(const float* samples, int width, int channels, int y0, int y1,
               std::vector<std::uint8_t>& out) {
    const char* names[4];
    int source[4];
    const int n = channel_order(channels, names, source);
    out.clear();
    for (int y = y0; y < y1; ++y)
        for (int c = 0; c < n; ++c)
            for (int x = 0; x < width; ++x)
                put_f32(out, samples[(std::size_t(y) * std::size_t(width) + std::size_t(x)) *
                                         std::size_t(channels) +
                                     std::size_t(source[c])]);
}

// ZIP_COMPRESSION's preprocessing: even bytes then odd bytes, then each byte as its
// difference from the previous one plus 128 (modulo 256).
void zip_predictor(const std::vector<std::uint8_t>& raw, std::vector<std::uint8_t>& out) {
    const std::size_t n = raw.size();
    out.resize(n);
    std::size_t half = (n + 1) / 2;
    for (std::size_t i = 0; i < n; ++i) out[(i % 2 == 0) ? i / 2 : half + i / 2] = raw[i];
    std::uint8_t previous = out.empty() ? 0 : out[0];
    for (std::size_t i = 1; i < n; ++i) {
        const std::uint8_t here = out[i];
        out[i] = std::uint8_t(int(here) - int(previous) + 128);
        previous = here;
    }
}

}  // namespace

Status write_exr(const char* path, const float* samples, int width, int height, int channels,
                 const ExrOptions& options) {
    if (path == nullptr || !path[0])
        return Status::error(StatusCode::invalid_argument, "write_exr: empty path");
    if (samples == nullptr || width < 1 || height < 1 || width > 65536 || height > 65536)
        return Status::error(StatusCode::invalid_argument,
                             "write_exr %s: the image must be 1..65536 a side (got %d x %d)",
                             path, width, height);
    if (channels != 1 && channels != 3 && channels != 4)
        return Status::error(StatusCode::invalid_argument,
                             "write_exr %s: channels must be 1, 3 or 4 (got %d)", path, channels);
    const bool zip = options.compression == ExrCompression::zip;
    const int lines = zip ? 16 : 1;  // per chunk, fixed by the compression
    const int chunks = (height + lines - 1) / lines;
    std::vector<std::uint8_t> head = exr_header(width, height, channels, options.compression);
    std::vector<std::vector<std::uint8_t>> data;
    data.resize(std::size_t(chunks));
    std::vector<std::uint8_t> raw, predicted;
    for (int c = 0; c < chunks; ++c) {
        raw_lines(samples, width, channels, c * lines, std::min(height, (c + 1) * lines), raw);
        std::vector<std::uint8_t>& chunk = data[std::size_t(c)];
        if (zip) {
            zip_predictor(raw, predicted);
            SHITSUKAN_TRY(zlib_deflate(predicted.data(), predicted.size(), chunk));
        }
        if (!zip || chunk.size() >= raw.size()) chunk = raw;  // stored raw
    }
    std::uint64_t offset = head.size() + 8 * std::uint64_t(chunks);
    for (int c = 0; c < chunks; ++c) {
        put_u64(head, offset);
        offset += 8 + data[std::size_t(c)].size();
    }
    OutputFile out;
    SHITSUKAN_TRY(out.open(path));
    out.write(head.data(), head.size());
    for (int c = 0; c < chunks && !out.failed(); ++c) {
        std::vector<std::uint8_t> prefix;
        put_u32(prefix, std::uint32_t(c * lines));
        put_u32(prefix, std::uint32_t(data[std::size_t(c)].size()));
        out.write(prefix.data(), prefix.size());
        out.write(data[std::size_t(c)].data(), data[std::size_t(c)].size());
    }
    return out.commit();
}

}  // namespace shitsukan
