#include "shitsukan/image/png16.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/core/output_file.hpp"
#include "shitsukan/image/deflate.hpp"

namespace shitsukan {

namespace detail {

namespace {

// CRC-32 with the reflected polynomial 0xEDB88320 (PNG spec. annex D), one table entry
// per byte value.
struct CrcTable {
    std::uint32_t entry[256];
    CrcTable() {
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            entry[n] = c;
        }
    }
};

const CrcTable& crc_table() {
    static const CrcTable table;
    return table;
}

}  // namespace

// `crc` is the running value before the final inversion (start with 0xFFFFFFFF).
std::uint32_t crc32_update(std::uint32_t crc, const std::uint8_t* data, std::size_t size) {
    const CrcTable& t = crc_table();
    for (std::size_t i = 0; i < size; ++i)
        crc = t.entry[(crc ^ data[i]) & 0xFFu] ^ (crc >> 8);
    return crc;
}

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
    return crc32_update(0xFFFFFFFFu, data, size) ^ 0xFFFFFFFFu;
}

// RFC 1950 §8.2: s1 = 1 + sum of bytes, s2 = sum of the s1 values, both modulo 65521 (the
// largest prime below 2^16); the value is s2·65536 + s1. Start with 1. The sums are reduced
// once every 5552 bytes, the most that cannot overflow 32 bits (zlib's NMAX): the same value.
std::uint32_t adler32_update(std::uint32_t adler, const std::uint8_t* data, std::size_t size) {
    std::uint32_t s1 = (adler & 0xFFFFu) % 65521u, s2 = (adler >> 16) % 65521u;
    while (size > 0) {
        const std::size_t n = size < 5552 ? size : 5552;
        for (std::size_t i = 0; i < n; ++i) {
            s1 += data[i];
            s2 += s1;
        }
        s1 %= 65521u;
        s2 %= 65521u;
        data += n;
        size -= n;
    }
    return (s2 << 16) | s1;
}

std::uint32_t adler32(const std::uint8_t* data, std::size_t size) {
    return adler32_update(1u, data, size);
}

}  // namespace detail

namespace {

constexpr std::size_t kStoredBlockMax = 65535;  // RFC 1951: LEN is 16 bits

// Writes one PNG file; the OutputFile remembers the first failure so the calls can be chained.
class PngWriter {
public:
    explicit PngWriter(OutputFile& out) : out_(out) {}
    bool ok() const { return !out_.failed(); }

    void raw(const std::uint8_t* data, std::size_t size) { out_.write(data, size); }
    void begin_chunk(std::uint32_t length, const char type[4]) {
        std::uint8_t head[8];
        put_u32(head, length);
        for (int i = 0; i < 4; ++i) head[4 + i] = std::uint8_t(type[i]);
        raw(head, 8);
        crc_ = detail::crc32_update(0xFFFFFFFFu, head + 4, 4);  // the CRC covers type + data
    }
    void chunk_data(const std::uint8_t* data, std::size_t size) {
        crc_ = detail::crc32_update(crc_, data, size);
        raw(data, size);
    }
    void end_chunk() {
        std::uint8_t c[4];
        put_u32(c, crc_ ^ 0xFFFFFFFFu);
        raw(c, 4);
    }

    static void put_u32(std::uint8_t* p, std::uint32_t v) {  // PNG integers are big-endian
        p[0] = std::uint8_t(v >> 24);
        p[1] = std::uint8_t(v >> 16);
        p[2] = std::uint8_t(v >> 8);
        p[3] = std::uint8_t(v);
    }

private:
    OutputFile& out_;
    std::uint32_t crc_ = 0;
};

// The zlib stream inside IDAT: raw bytes cut into stored deflate blocks, Adler-32 at the end.
class StoredDeflate {
public:
    StoredDeflate(PngWriter& out, std::size_t total) : out_(out), left_(total) {}

    void header() {
        // CMF 0x78: deflate with a 32K window; FLG 0x01: no dictionary, 0x7801 % 31 == 0.
        const std::uint8_t h[2] = {0x78, 0x01};
        out_.chunk_data(h, 2);
    }
    void write(const std::uint8_t* data, std::size_t size) {
        while (size > 0) {
            if (in_block_ == 0) start_block();
            std::size_t n = size < in_block_ ? size : in_block_;
            out_.chunk_data(data, n);
            adler_ = detail::adler32_update(adler_, data, n);
            data += n;
            size -= n;
            in_block_ -= n;
            left_ -= n;
        }
    }
    void finish() {
        std::uint8_t a[4];
        PngWriter::put_u32(a, adler_);
        out_.chunk_data(a, 4);
    }

    // Bytes the stream takes for `total` raw bytes.
    static std::uint64_t stream_size(std::uint64_t total) {
        std::uint64_t blocks = total == 0 ? 1 : (total + kStoredBlockMax - 1) / kStoredBlockMax;
        return 2 + total + 5 * blocks + 4;
    }

private:
    void start_block() {
        std::size_t len = left_ < kStoredBlockMax ? left_ : kStoredBlockMax;
        bool last = len == left_;
        // BFINAL bit, BTYPE = 00 (stored), padding to the byte; LEN, NLEN little-endian.
        std::uint8_t h[5] = {std::uint8_t(last ? 1 : 0), std::uint8_t(len & 0xFF),
                             std::uint8_t(len >> 8), std::uint8_t(~len & 0xFF),
                             std::uint8_t((~len >> 8) & 0xFF)};
        out_.chunk_data(h, 5);
        in_block_ = len;
    }
    PngWriter& out_;
    std::size_t left_;
    std::size_t in_block_ = 0;
    std::uint32_t adler_ = 1;
};

int paeth(int a, int b, int c) {  // PNG spec 9.4: the predictor closest to a + b - c
    const int p = a + b - c, pa = p > a ? p - a : a - p, pb = p > b ? p - b : b - p,
              pc = p > c ? p - c : c - p;
    return (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
}

// The cost of a filtered row: the sum of |residual|, on bytes for 8-bit images (the PNG
// spec's heuristic, 12.8) and on the 16-bit residuals (high and low byte read together, as a
// signed 16-bit value) for 16-bit ones. Measured on the 4096^2 leather height map: 0.6 %
// smaller than the byte sums (which see a carry between the bytes as a large residual).
std::uint64_t row_cost(const std::uint8_t* r, std::size_t n, int bits) {
    std::uint64_t cost = 0;
    if (bits == 16) {
        for (std::size_t i = 0; i + 1 < n; i += 2) {
            const unsigned v = (unsigned(r[i]) << 8) | r[i + 1];
            cost += v < 32768 ? v : 65536 - v;
        }
    } else {
        for (std::size_t i = 0; i < n; ++i) cost += r[i] < 128 ? r[i] : 256 - r[i];
    }
    return cost;
}

// The raw image with each row filtered (PNG spec 9: None, Sub, Up, Average, Paeth on bytes,
// bpp = bytes per pixel) by the filter with the smallest sum of |byte as signed| (the spec's
// suggested heuristic, 12.8): smooth height maps become runs of small differences.
template <class SampleFn>
void filtered_rows(int width, int height, int channels, int bits, SampleFn sample,
                   std::vector<std::uint8_t>* out) {
    const std::size_t bpp = std::size_t(channels) * (bits == 16 ? 2 : 1);
    const std::size_t n = std::size_t(width) * bpp;
    std::vector<std::uint8_t> prev(n, 0), cur(n), trial(n);
    out->resize((n + 1) * std::size_t(height));
    for (int y = 0; y < height; ++y) {
        std::uint8_t* p = cur.data();
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c) {
                const std::uint16_t v = sample(x, y, c);
                if (bits == 16) *p++ = std::uint8_t(v >> 8);
                *p++ = std::uint8_t(v & 0xFF);
            }
        std::uint8_t* dst = out->data() + (n + 1) * std::size_t(y);
        std::uint64_t best = ~std::uint64_t(0);
        for (int type = 0; type < 5; ++type) {
            std::uint64_t cost = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const int a = i >= bpp ? cur[i - bpp] : 0, b = prev[i],
                          c = i >= bpp ? prev[i - bpp] : 0;
                const int pred = type == 0 ? 0
                                 : type == 1 ? a
                                 : type == 2 ? b
                                 : type == 3 ? (a + b) / 2
                                             : paeth(a, b, c);
                trial[i] = std::uint8_t((cur[i] - pred) & 0xFF);
            }
            cost = row_cost(trial.data(), n, bits);
            if (cost < best) {
                best = cost;
                dst[0] = std::uint8_t(type);
                std::copy(trial.begin(), trial.end(), dst + 1);
            }
        }
        prev.swap(cur);
    }
}

// The IDAT of stored deflate blocks, streamed row by row (filter type None).
template <class SampleFn>
void write_stored_idat(PngWriter& png, int width, int height, int channels, int bits,
                       std::uint64_t row_bytes, std::uint64_t raw_bytes, std::uint64_t idat_bytes,
                       SampleFn sample) {
    png.begin_chunk(std::uint32_t(idat_bytes), "IDAT");
    StoredDeflate z(png, std::size_t(raw_bytes));
    z.header();
    std::vector<std::uint8_t> row(static_cast<std::size_t>(row_bytes));
    for (int y = 0; y < height && png.ok(); ++y) {
        row[0] = 0;  // filter type None
        std::uint8_t* p = row.data() + 1;
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c) {
                std::uint16_t v = sample(x, y, c);
                if (bits == 16) *p++ = std::uint8_t(v >> 8);  // big-endian samples
                *p++ = std::uint8_t(v & 0xFF);
            }
        z.write(row.data(), row.size());
    }
    z.finish();
}

// Encode rows of `channels` samples of `bits` (8 or 16) bits; sample(x, y, c) gives each value.
template <class SampleFn>
Status encode_png(const char* path, int width, int height, int channels, int bits, bool empty,
                  SampleFn sample) {
    if (path == nullptr || path[0] == '\0')
        return Status::error(StatusCode::invalid_argument, "PNG path is empty");
    if (empty)
        return Status::error(StatusCode::invalid_argument,
                             "cannot write %s: image is empty (%d x %d)", path, width, height);
    const std::uint64_t bytes_per_sample = bits == 16 ? 2 : 1;
    const std::uint64_t row_bytes =
        1 + std::uint64_t(width) * std::uint64_t(channels) * bytes_per_sample;
    const std::uint64_t raw_bytes = row_bytes * std::uint64_t(height);
    const std::uint64_t idat_bytes = StoredDeflate::stream_size(raw_bytes);
    if (idat_bytes > 0x7FFFFFFFull)
        return Status::error(StatusCode::too_large,
                             "cannot write %s: %d x %d x %d samples need %llu bytes, more than "
                             "one PNG chunk holds (2147483647)",
                             path, width, height, channels, (unsigned long long)idat_bytes);
    // 16-bit images: every row filtered (filtered_rows), then deflated (deflate.hpp); noise
    // does not shrink, so the stored blocks are kept when they are smaller.
    std::vector<std::uint8_t> compressed;
    bool use_compressed = false;
    // The filtered rows and the compressed stream are held in memory (about twice the raw
    // size): over the memory budget (core/memory_budget.hpp) the image is streamed row by row
    // in stored blocks instead, which needs one row.
    const bool fits = check_memory_budget(budget_mul(raw_bytes, 2), "write_png16").ok();
    if (bits == 16 && raw_bytes < 0x7FFF0000ull && fits) {
        std::vector<std::uint8_t> filtered;
        filtered_rows(width, height, channels, bits, sample, &filtered);
        use_compressed = zlib_deflate(filtered.data(), filtered.size(), compressed).ok() &&
                         compressed.size() < idat_bytes;
    }
    OutputFile out;
    SHITSUKAN_TRY(out.open(path));
    PngWriter png(out);
    const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    png.raw(signature, 8);

    std::uint8_t ihdr[13];
    PngWriter::put_u32(ihdr, std::uint32_t(width));
    PngWriter::put_u32(ihdr + 4, std::uint32_t(height));
    ihdr[8] = std::uint8_t(bits);                  // bit depth
    ihdr[9] = std::uint8_t(channels == 1 ? 0 : 2);  // colour type: gray or RGB
    ihdr[10] = 0;                                  // compression: deflate
    ihdr[11] = 0;                                  // filter method 0 (per-row filter byte)
    ihdr[12] = 0;                                  // no interlace
    png.begin_chunk(13, "IHDR");
    png.chunk_data(ihdr, 13);
    png.end_chunk();

    if (use_compressed) {
        png.begin_chunk(std::uint32_t(compressed.size()), "IDAT");
        png.chunk_data(compressed.data(), compressed.size());
    } else {
        write_stored_idat(png, width, height, channels, bits, row_bytes, raw_bytes, idat_bytes,
                          sample);
    }
    png.end_chunk();

    png.begin_chunk(0, "IEND");
    png.end_chunk();

    return out.commit();
}


}  // namespace

Status write_png16(const char* path, const Gray16View& image) {
    return encode_png(path, image.width, image.height, 1, 16, image.empty(),
                        [&](int x, int y, int) { return image.row(y)[x]; });
}

Status write_png16(const char* path, const Rgb16View& image) {
    return encode_png(path, image.width, image.height, 3, 16, image.empty(),
                        [&](int x, int y, int c) {
                            const Rgb16& p = image.row(y)[x];
                            return c == 0 ? p.r : (c == 1 ? p.g : p.b);
                        });
}

namespace detail {
Status write_png8_stored(const char* path, const std::uint8_t* pixels, int width, int height,
                         int channels, std::size_t row_stride_bytes, bool empty) {
    return encode_png(path, width, height, channels, 8, empty, [&](int x, int y, int c) {
        return std::uint16_t(pixels[std::size_t(y) * row_stride_bytes +
                                    std::size_t(x) * std::size_t(channels) + std::size_t(c)]);
    });
}
}  // namespace detail

}  // namespace shitsukan
