// Host side: zlib / DEFLATE compression with dynamic Huffman codes (deflate.hpp).
#include "shitsukan/image/deflate.hpp"

#include <algorithm>
#include <queue>

#include "shitsukan/image/png16.hpp"  // detail::adler32

namespace shitsukan {
namespace {

using detail::kDistBase;  // RFC 1951 §3.2.5, deflate.hpp
using detail::kDistExtra;
using detail::kLenBase;
using detail::kLenExtra;
// Order of the code-length code lengths in the block header (§3.2.7).
const int kClOrder[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

struct Symbol {
    std::uint16_t lit_or_len;  // a byte (dist == 0) or a match length 3..258
    std::uint16_t dist;        // 0 for a literal, else 1..32768
};

class BitWriter {
public:
    explicit BitWriter(std::vector<std::uint8_t>* out) : out_(out) {}
    void put(std::uint32_t bits, int count) {  // LSB first
        acc_ |= std::uint64_t(bits) << fill_;
        fill_ += count;
        while (fill_ >= 8) {
            out_->push_back(std::uint8_t(acc_ & 0xFF));
            acc_ >>= 8;
            fill_ -= 8;
        }
    }
    // A Huffman code is sent most significant bit first (§3.1.1).
    void put_code(std::uint32_t code, int length) {
        std::uint32_t r = 0;
        for (int i = 0; i < length; ++i) r |= ((code >> i) & 1u) << (length - 1 - i);
        put(r, length);
    }
    void flush() {
        if (fill_ > 0) out_->push_back(std::uint8_t(acc_ & 0xFF));
        acc_ = 0;
        fill_ = 0;
    }

private:
    std::vector<std::uint8_t>* out_;
    std::uint64_t acc_ = 0;
    int fill_ = 0;
};

// Huffman code lengths for freq (0 = unused), none longer than limit; at least two symbols
// get a code (a decoder may refuse a one-code tree).
void code_lengths(std::vector<std::uint32_t> freq, int limit, std::vector<int>* lengths) {
    const int n = int(freq.size());
    int used = 0;
    for (std::uint32_t f : freq) used += f > 0;
    for (int i = 0; used < 2 && i < n; ++i)
        if (freq[std::size_t(i)] == 0) freq[std::size_t(i)] = 1, ++used;
    lengths->assign(std::size_t(n), 0);
    while (true) {
        // Build the tree: leaves 0..n-1, internal nodes after; parent links give depths.
        using Item = std::pair<std::uint64_t, int>;
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
        std::vector<int> parent(std::size_t(2 * n), -1);
        for (int i = 0; i < n; ++i)
            if (freq[std::size_t(i)] > 0) heap.push({freq[std::size_t(i)], i});
        int next = n;
        while (heap.size() > 1) {
            const Item a = heap.top();
            heap.pop();
            const Item b = heap.top();
            heap.pop();
            parent[std::size_t(a.second)] = next;
            parent[std::size_t(b.second)] = next;
            heap.push({a.first + b.first, next++});
        }
        int longest = 0;
        for (int i = 0; i < n; ++i) {
            if (freq[std::size_t(i)] == 0) {
                (*lengths)[std::size_t(i)] = 0;
                continue;
            }
            int depth = 0;
            for (int p = parent[std::size_t(i)]; p >= 0; p = parent[std::size_t(p)]) ++depth;
            (*lengths)[std::size_t(i)] = depth;
            longest = std::max(longest, depth);
        }
        if (longest <= limit) return;
        for (std::uint32_t& f : freq)
            if (f > 0) f = (f >> 1) | 1u;  // flatten and retry
    }
}

// Canonical codes from lengths (§3.2.2).
void canonical_codes(const std::vector<int>& lengths, std::vector<std::uint32_t>* codes) {
    int bl_count[16] = {0};
    for (int l : lengths) ++bl_count[l];
    bl_count[0] = 0;
    std::uint32_t next_code[16] = {0}, code = 0;
    for (int bits = 1; bits <= 15; ++bits) {
        code = (code + std::uint32_t(bl_count[bits - 1])) << 1;
        next_code[bits] = code;
    }
    codes->assign(lengths.size(), 0);
    for (std::size_t i = 0; i < lengths.size(); ++i)
        if (lengths[i] > 0) (*codes)[i] = next_code[lengths[i]]++;
}

int length_code(int len) {  // index into kLenBase
    int c = 28;
    while (kLenBase[c] > len) --c;
    return c;
}
int distance_code(int dist) {
    int c = 29;
    while (kDistBase[c] > dist) --c;
    return c;
}

void write_block(BitWriter& bw, const Symbol* sym, std::size_t count, bool last) {
    std::vector<std::uint32_t> lit_freq(286, 0), dist_freq(30, 0);
    for (std::size_t i = 0; i < count; ++i) {
        if (sym[i].dist == 0) {
            ++lit_freq[sym[i].lit_or_len];
        } else {
            ++lit_freq[std::size_t(257 + length_code(sym[i].lit_or_len))];
            ++dist_freq[std::size_t(distance_code(sym[i].dist))];
        }
    }
    lit_freq[256] = 1;  // end of block
    std::vector<int> lit_len, dist_len;
    code_lengths(lit_freq, 15, &lit_len);
    code_lengths(dist_freq, 15, &dist_len);
    int hlit = 286, hdist = 30;
    while (hlit > 257 && lit_len[std::size_t(hlit - 1)] == 0) --hlit;
    while (hdist > 1 && dist_len[std::size_t(hdist - 1)] == 0) --hdist;
    // The code lengths of both alphabets, run-length coded (§3.2.7): 16 repeats the previous
    // length 3-6 times, 17 writes 3-10 zeros, 18 writes 11-138 zeros.
    std::vector<int> all(lit_len.begin(), lit_len.begin() + hlit);
    all.insert(all.end(), dist_len.begin(), dist_len.begin() + hdist);
    struct Rle {
        int symbol, extra;
    };
    std::vector<Rle> rle;
    for (std::size_t i = 0; i < all.size();) {
        std::size_t run = 1;
        while (i + run < all.size() && all[i + run] == all[i]) ++run;
        if (all[i] == 0 && run >= 3) {
            const int r = int(std::min<std::size_t>(run, 138));
            rle.push_back(r >= 11 ? Rle{18, r - 11} : Rle{17, r - 3});
            i += std::size_t(r);
        } else if (all[i] != 0 && run >= 4) {
            rle.push_back({all[i], 0});
            const int r = int(std::min<std::size_t>(run - 1, 6));
            rle.push_back({16, r - 3});
            i += std::size_t(r) + 1;
        } else {
            rle.push_back({all[i], 0});
            ++i;
        }
    }
    std::vector<std::uint32_t> cl_freq(19, 0);
    for (const Rle& r : rle) ++cl_freq[std::size_t(r.symbol)];
    std::vector<int> cl_len;
    code_lengths(cl_freq, 7, &cl_len);
    int hclen = 19;
    while (hclen > 4 && cl_len[std::size_t(kClOrder[hclen - 1])] == 0) --hclen;
    std::vector<std::uint32_t> lit_code, dist_code, cl_code;
    canonical_codes(lit_len, &lit_code);
    canonical_codes(dist_len, &dist_code);
    canonical_codes(cl_len, &cl_code);

    bw.put(last ? 1u : 0u, 1);
    bw.put(2u, 2);  // dynamic Huffman codes
    bw.put(std::uint32_t(hlit - 257), 5);
    bw.put(std::uint32_t(hdist - 1), 5);
    bw.put(std::uint32_t(hclen - 4), 4);
    for (int i = 0; i < hclen; ++i) bw.put(std::uint32_t(cl_len[std::size_t(kClOrder[i])]), 3);
    for (const Rle& r : rle) {
        bw.put_code(cl_code[std::size_t(r.symbol)], cl_len[std::size_t(r.symbol)]);
        if (r.symbol == 16) bw.put(std::uint32_t(r.extra), 2);
        if (r.symbol == 17) bw.put(std::uint32_t(r.extra), 3);
        if (r.symbol == 18) bw.put(std::uint32_t(r.extra), 7);
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (sym[i].dist == 0) {
            bw.put_code(lit_code[sym[i].lit_or_len], lit_len[sym[i].lit_or_len]);
            continue;
        }
        const int lc = length_code(sym[i].lit_or_len), dc = distance_code(sym[i].dist);
        bw.put_code(lit_code[std::size_t(257 + lc)], lit_len[std::size_t(257 + lc)]);
        if (kLenExtra[lc]) bw.put(std::uint32_t(sym[i].lit_or_len - kLenBase[lc]), kLenExtra[lc]);
        bw.put_code(dist_code[std::size_t(dc)], dist_len[std::size_t(dc)]);
        if (kDistExtra[dc]) bw.put(std::uint32_t(sym[i].dist - kDistBase[dc]), kDistExtra[dc]);
    }
    bw.put_code(lit_code[256], lit_len[256]);
}

}  // namespace

Status zlib_deflate(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>& out) {
    if (data == nullptr && size > 0)
        return Status::error(StatusCode::invalid_argument, "zlib_deflate: null data");
    if (size > 0x7FFFFFFFu)
        return Status::error(StatusCode::too_large, "zlib_deflate: %zu bytes, more than 2^31",
                             size);
    constexpr std::size_t kWindow = 32768, kHashBits = 15, kBlock = 65536;
    std::vector<std::int64_t> head(std::size_t(1) << kHashBits, -1), prev(kWindow, -1);
    auto hash3 = [&](std::size_t i) {
        const std::uint32_t v = std::uint32_t(data[i]) | (std::uint32_t(data[i + 1]) << 8) |
                                (std::uint32_t(data[i + 2]) << 16);
        return std::size_t((v * 2654435761u) >> (32 - kHashBits));
    };
    auto insert = [&](std::size_t i) {
        if (i + 2 >= size) return;
        const std::size_t h = hash3(i);
        prev[i % kWindow] = head[h];
        head[h] = std::int64_t(i);
    };
    out.clear();
    out.push_back(0x78);  // CM 8 (deflate), CINFO 7 (32 KiB window)
    out.push_back(0x9C);  // FLEVEL 2, FCHECK: 0x789C % 31 == 0
    BitWriter bw(&out);
    std::vector<Symbol> block;
    block.reserve(kBlock);
    // The longest match at i (0 if none of 3 or more), from at most kDeflateChain candidates.
    auto longest_match = [&](std::size_t i, int* dist) {
        int best_len = 0;
        if (i + 2 >= size) return 0;
        const std::size_t max_len = std::min<std::size_t>(258, size - i);
        std::int64_t cand = head[hash3(i)];
        for (int tries = 0; cand >= 0 && tries < kDeflateChain; ++tries) {
            const std::size_t c = std::size_t(cand);
            if (i - c > kWindow - 1 || c >= i) break;
            if (data[c + std::size_t(best_len)] == data[i + std::size_t(best_len)]) {
                std::size_t len = 0;
                while (len < max_len && data[c + len] == data[i + len]) ++len;
                if (int(len) > best_len) {
                    best_len = int(len);
                    *dist = int(i - c);
                    if (len == max_len) break;
                }
            }
            const std::int64_t p = prev[c % kWindow];
            if (p >= cand) break;  // the slot was overwritten by a newer position
            cand = p;
        }
        return best_len >= 3 ? best_len : 0;
    };
    auto emit = [&](Symbol s) {
        block.push_back(s);
        if (block.size() == kBlock) {
            write_block(bw, block.data(), block.size(), false);
            block.clear();
        }
    };
    // Lazy matching (RFC 1951 §4, as zlib does it): a match found at i is kept back for one
    // position; if i + 1 starts a longer one, i goes out as a literal instead.
    std::size_t i = 0;
    int dist = 0;
    int len = longest_match(i, &dist);
    while (i < size) {
        if (len == 0) {
            emit({data[i], 0});
            insert(i);
            ++i;
            len = longest_match(i, &dist);
            continue;
        }
        insert(i);
        int next_dist = 0;
        const int next_len = len < kDeflateLazy ? longest_match(i + 1, &next_dist) : 0;
        if (next_len > len) {
            emit({data[i], 0});
            ++i;
            len = next_len;
            dist = next_dist;
            continue;
        }
        emit({std::uint16_t(len), std::uint16_t(dist)});
        for (int k = 1; k < len; ++k) insert(i + std::size_t(k));
        i += std::size_t(len);
        len = longest_match(i, &dist);
    }
    // the last block (possibly empty: an end-of-block symbol alone) carries BFINAL
    write_block(bw, block.data(), block.size(), true);
    bw.flush();
    const std::uint32_t adler = detail::adler32(data, size);
    for (int k = 3; k >= 0; --k) out.push_back(std::uint8_t(adler >> (8 * k)));
    return Status::success();
}

}  // namespace shitsukan
