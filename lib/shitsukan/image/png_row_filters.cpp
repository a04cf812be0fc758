// PNG rows filtered by stb_image_write's choice, in one pass a row (png_row_filters.hpp).
#include "shitsukan/image/png_row_filters.hpp"

namespace shitsukan {

namespace {

// PNG spec §9.4: the neighbour (left a, up b, up-left c) closest to a + b - c; ties to a, then b.
inline int paeth(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = p > a ? p - a : a - p, pb = p > b ? p - b : b - p, pc = p > c ? p - c : c - p;
    if (pa <= pb && pa <= pc) return a;
    return pb <= pc ? b : c;
}

// Filter type t's byte at x from the byte z, its left a, up b and up-left c (0 outside the
// image), modulo 256.
inline unsigned char filtered(int t, int z, int a, int b, int c) {
    switch (t) {
        case 1: return static_cast<unsigned char>(z - a);
        case 2: return static_cast<unsigned char>(z - b);
        case 3: return static_cast<unsigned char>(z - ((a + b) >> 1));
        case 4: return static_cast<unsigned char>(z - paeth(a, b, c));
        default: return static_cast<unsigned char>(z);
    }
}

// |byte read as signed|.
inline int magnitude(unsigned char v) { return v < 128 ? v : 256 - v; }

}  // namespace

void png_filter_rows_like_stb(const unsigned char* pixels, int stride_bytes, int width,
                              int height, int channels, unsigned char* out) {
    const int row = width * channels;
    for (int y = 0; y < height; ++y) {
        const unsigned char* z = pixels + long(stride_bytes) * y;
        const unsigned char* up = y > 0 ? z - stride_bytes : nullptr;
        // stb's estimate: the sum of |filtered byte| for each type, the least wins.
        int sum[5] = {0, 0, 0, 0, 0};
        for (int i = 0; i < row; ++i) {
            const int a = i >= channels ? z[i - channels] : 0, b = up ? up[i] : 0;
            const int c = up && i >= channels ? up[i - channels] : 0, v = z[i];
            sum[0] += magnitude(static_cast<unsigned char>(v));
            sum[1] += magnitude(static_cast<unsigned char>(v - a));
            sum[2] += magnitude(static_cast<unsigned char>(v - b));
            sum[3] += magnitude(static_cast<unsigned char>(v - ((a + b) >> 1)));
            sum[4] += magnitude(static_cast<unsigned char>(v - paeth(a, b, c)));
        }
        int best = 0;
        for (int t = 1; t < 5; ++t)
            if (sum[t] < sum[best]) best = t;
        unsigned char* o = out + long(row + 1) * y;
        o[0] = static_cast<unsigned char>(best);
        for (int i = 0; i < row; ++i) {
            const int a = i >= channels ? z[i - channels] : 0, b = up ? up[i] : 0;
            const int c = up && i >= channels ? up[i - channels] : 0;
            o[1 + i] = filtered(best, z[i], a, b, c);
        }
    }
}

}  // namespace shitsukan
