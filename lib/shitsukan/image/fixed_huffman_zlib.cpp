// Host side: stb_image_write's zlib stream, the same bytes, faster (fixed_huffman_zlib.hpp).
#include "shitsukan/image/fixed_huffman_zlib.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "shitsukan/image/deflate.hpp"  // detail::kLenBase ... (RFC 1951 tables)
#include "shitsukan/image/png16.hpp"    // detail::adler32

namespace shitsukan {
namespace {

constexpr int kBuckets = 16384;  // stb's stbiw__ZHASH
constexpr int kMaxMatch = 258;   // RFC 1951 §3.2.5
constexpr int kWindow = 32768;

using detail::kDistBase;  // RFC 1951 §3.2.5, deflate.hpp
using detail::kDistExtra;
using detail::kLenBase;
using detail::kLenExtra;

// Bits as they go into the stream (LSB first): a Huffman code already bit-reversed, its extra
// bits above it.
struct Code {
    std::uint32_t bits = 0;
    int length = 0;
};

std::uint32_t reversed(std::uint32_t code, int length) {
    std::uint32_t r = 0;
    for (int i = 0; i < length; ++i) r = (r << 1) | ((code >> i) & 1u);
    return r;
}

// §3.2.6's fixed codes: literal/length symbols 0..287, the codes of every match length
// (3..258), every distance's code number (1..32767) and the 30 distance codes.
struct Tables {
    Code literal[288];
    Code length[kMaxMatch + 1];
    std::uint8_t distance_code[kWindow];
    Code distance[30];  // the 5-bit code, reversed; length with the extra bits
    Tables() {
        for (int j = 0; j < 30; ++j)
            distance[j] = {reversed(std::uint32_t(j), 5), 5 + kDistExtra[j]};
        for (int n = 0; n < 288; ++n) {
            if (n <= 143)
                literal[n] = {reversed(0x30u + std::uint32_t(n), 8), 8};
            else if (n <= 255)
                literal[n] = {reversed(0x190u + std::uint32_t(n - 144), 9), 9};
            else if (n <= 279)
                literal[n] = {reversed(std::uint32_t(n - 256), 7), 7};
            else
                literal[n] = {reversed(0xC0u + std::uint32_t(n - 280), 8), 8};
        }
        for (int len = 3, j = 0; len <= kMaxMatch; ++len) {
            while (j < 28 && len >= kLenBase[j + 1]) ++j;
            const Code c = literal[257 + j];
            length[len] = {c.bits | (std::uint32_t(len - kLenBase[j]) << c.length),
                           c.length + kLenExtra[j]};
        }
        for (int d = 1, j = 0; d < kWindow; ++d) {
            while (j < 29 && d >= kDistBase[j + 1]) ++j;
            distance_code[d] = std::uint8_t(j);
        }
    }
};

const Tables& tables() {
    static const Tables t;
    return t;
}

// Up to 31 bits at a time into the stream, written out 32 bits at a time.
struct BitSink {
    unsigned char* p;
    std::uint64_t acc = 0;
    int fill = 0;
    void put(std::uint32_t bits, int length) {
        acc |= std::uint64_t(bits) << fill;
        fill += length;
        if (fill >= 32) {
            for (int k = 0; k < 4; ++k) *p++ = static_cast<unsigned char>(acc >> (8 * k));
            acc >>= 32;
            fill -= 32;
        }
    }
    void finish() {  // zero bits up to the byte boundary
        for (; fill > 0; fill -= 8, acc >>= 8) *p++ = static_cast<unsigned char>(acc);
        fill = 0;
    }
};

// How many leading bytes a and b share, at most limit (<= 258): eight at a time, the first
// differing byte of eight found from the lowest set bit of their XOR where the compiler says
// the machine is little-endian (else byte by byte).
inline int match_length(const unsigned char* a, const unsigned char* b, int limit) {
    int k = 0;
    for (; k + 8 <= limit; k += 8) {
        std::uint64_t x, y;
        std::memcpy(&x, a + k, 8);
        std::memcpy(&y, b + k, 8);
        if (x != y) {
#if defined(__GNUC__) && defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
            return k + __builtin_ctzll(x ^ y) / 8;
#else
            break;
#endif
        }
    }
    while (k < limit && a[k] == b[k]) ++k;
    return k;
}

// stb's hash of the three bytes at p, to a bucket.
inline int bucket_of(const unsigned char* p) {
    std::uint32_t h =
        std::uint32_t(p[0]) + (std::uint32_t(p[1]) << 8) + (std::uint32_t(p[2]) << 16);
    h ^= h << 3;
    h += h >> 5;
    h ^= h << 4;
    h += h >> 17;
    h ^= h << 25;
    h += h >> 6;
    return int(h & (kBuckets - 1));
}

// The buckets: positions in insertion order, at most 2 x quality each.
struct Buckets {
    int* positions;  // kBuckets x capacity
    int* count;      // kBuckets
    int quality, capacity;
    const int* list(int h) const { return positions + std::size_t(h) * std::size_t(capacity); }
    void insert(int h, int position) {  // stb: when full, keep the newer half
        int* l = positions + std::size_t(h) * std::size_t(capacity);
        int& n = count[h];
        if (n == capacity) {
            std::memmove(l, l + quality, sizeof(int) * std::size_t(quality));
            n = quality;
        }
        l[n++] = position;
    }
};

// The longest match for position i among its bucket's positions within the window (ties: the
// newest), or -1 when none has 3 bytes; *best its length. A candidate must share the first
// *best bytes to tie or win, so the byte at *best - 1 rules most out before a full compare.
int longest_match(const unsigned char* data, int size, const Buckets& b, int h, int i, int* best) {
    const unsigned char* cur = data + i;
    const int limit = size - i < kMaxMatch ? size - i : kMaxMatch;
    const int* l = b.list(h);
    int found = -1, length = 3;
    for (int j = 0, n = b.count[h]; j < n; ++j) {
        const int pos = l[j];
        if (pos <= i - kWindow || data[pos + length - 1] != cur[length - 1]) continue;
        const int d = match_length(data + pos, cur, limit);
        if (d >= length) length = d, found = pos;
    }
    *best = length;
    return found;
}

// stb's lazy test: does a match at i + 1 (window one byte shorter) beat length best?
bool longer_match_next(const unsigned char* data, int size, const Buckets& b, int i, int best) {
    const unsigned char* next = data + i + 1;
    const int limit = size - i - 1 < kMaxMatch ? size - i - 1 : kMaxMatch;
    if (limit <= best) return false;
    const int h = bucket_of(next);
    const int* l = b.list(h);
    for (int j = 0, n = b.count[h]; j < n; ++j) {
        const int pos = l[j];
        if (pos <= i - (kWindow - 1) || data[pos + best] != next[best]) continue;
        if (match_length(data + pos, next, best + 1) == best + 1) return true;
    }
    return false;
}

// The fixed-Huffman block of data into sink (stb's match choices); false: out of memory.
bool compress_block(const unsigned char* data, int size, int quality, BitSink& sink) {
    const Tables& t = tables();
    Buckets b;
    b.quality = quality;
    b.capacity = 2 * quality;
    b.positions = static_cast<int*>(
        std::malloc(sizeof(int) * std::size_t(kBuckets) * std::size_t(b.capacity)));
    b.count = static_cast<int*>(std::calloc(kBuckets, sizeof(int)));
    const bool ok = b.positions && b.count;
    int i = 0;
    while (ok && i < size - 3) {
        const int h = bucket_of(data + i);
        int best = 3;
        int from = longest_match(data, size, b, h, i, &best);
        b.insert(h, i);
        if (from >= 0 && longer_match_next(data, size, b, i, best)) from = -1;
        if (from >= 0) {
            const int d = i - from;
            const Code len = t.length[best];
            sink.put(len.bits, len.length);
            const int j = t.distance_code[d];
            sink.put(t.distance[j].bits | (std::uint32_t(d - kDistBase[j]) << 5),
                     t.distance[j].length);
            i += best;
        } else {
            sink.put(t.literal[data[i]].bits, t.literal[data[i]].length);
            ++i;
        }
    }
    for (; ok && i < size; ++i) sink.put(t.literal[data[i]].bits, t.literal[data[i]].length);
    sink.put(t.literal[256].bits, t.literal[256].length);  // end of block
    sink.finish();
    std::free(b.positions);
    std::free(b.count);
    return ok;
}

}  // namespace

unsigned char* fixed_huffman_zlib(const unsigned char* data, int size, int* out_size, int quality) {
    if (size < 0 || (size > 0 && data == nullptr) || out_size == nullptr) return nullptr;
    if (quality < 5) quality = 5;
    // At most 9 bits a byte in the block (a literal; a match costs less per byte), and stb's
    // limit for falling back to stored blocks.
    const std::size_t n = std::size_t(size);
    const std::size_t stored_limit = n + 2 + ((n + 32766) / 32767) * 5;
    const std::size_t block_bound = 2 + (9 * n + 3 + 7 + 7) / 8 + 8;
    unsigned char* out = static_cast<unsigned char*>(
        std::malloc((block_bound > stored_limit ? block_bound : stored_limit) + 4));
    if (out == nullptr) return nullptr;
    out[0] = 0x78, out[1] = 0x5e;  // deflate, 32 KiB window; FLEVEL 1
    BitSink sink{out + 2};
    sink.put(1u | (1u << 1), 3);  // BFINAL = 1, BTYPE = 1 (fixed Huffman)
    if (!compress_block(data, size, quality, sink)) {
        std::free(out);
        return nullptr;
    }
    std::size_t length = std::size_t(sink.p - out);
    if (length > stored_limit) {  // stored blocks of at most 32767 bytes instead
        length = 2;
        for (std::size_t j = 0; j < n;) {
            const std::size_t block = n - j > 32767 ? 32767 : n - j;
            out[length++] = n - j == block ? 1 : 0;
            out[length++] = static_cast<unsigned char>(block);
            out[length++] = static_cast<unsigned char>(block >> 8);
            out[length++] = static_cast<unsigned char>(~block);
            out[length++] = static_cast<unsigned char>(~block >> 8);
            std::memcpy(out + length, data + j, block);
            length += block;
            j += block;
        }
    }
    const std::uint32_t adler = detail::adler32(data, n);
    for (int k = 3; k >= 0; --k) out[length++] = static_cast<unsigned char>(adler >> (8 * k));
    *out_size = int(length);
    return out;
}

}  // namespace shitsukan
