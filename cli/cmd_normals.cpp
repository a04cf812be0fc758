// cli/cmd_normals.cpp — `shitsukan normals`: a normal map from any height map (an image read
// through stb_image, 8- or 16-bit, or a PFM), by image/normal_map.hpp.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "commands.hpp"
#include "flags.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/image_read.hpp"
#include "shitsukan/image/normal_map.hpp"
#include "shitsukan/image/pfm.hpp"

namespace shitsukan::cli {

namespace {

bool ends_with(const std::string& s, const char* tail) {
    const std::size_t n = std::strlen(tail);
    return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

// Heights in [0, 1] (an integer image's first channel over its full range; a PFM as stored,
// its first channel), checked against the memory budget.
Status read_heights(const std::string& path, std::vector<float>* h, int* w, int* rows) {
    if (ends_with(path, ".pfm") || ends_with(path, ".PFM")) {
        PfmImage pfm;
        SHITSUKAN_TRY(read_pfm(path.c_str(), pfm));
        *w = pfm.width, *rows = pfm.height;
        h->resize(std::size_t(pfm.width) * std::size_t(pfm.height));
        for (std::size_t i = 0; i < h->size(); ++i)
            (*h)[i] = pfm.data[i * std::size_t(pfm.channels)];  // top row first already
        return Status::success();
    }
    LoadedImage img;
    SHITSUKAN_TRY(read_image(path.c_str(), img));
    *w = img.width, *rows = img.height;
    const float scale = img.bits == 16 ? 1.0f / 65535.0f : 1.0f / 255.0f;
    h->resize(std::size_t(img.width) * std::size_t(img.height));
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            (*h)[std::size_t(y) * std::size_t(img.width) + std::size_t(x)] =
                float(img.sample(x, y, 0)) * scale;
    return Status::success();
}

}  // namespace

int run_normals(int argc, char** argv) {
    std::string in, out = "normal.png";
    float strength = 8.0f;
    bool wrap = false;
    int convention = 0;  // 0 opengl, 1 directx
    FlagSet f("normals",
              "A tangent-space normal map from any height map: n = (-s dh/dx, -s dh/dy, 1)/|.|\n"
              "with central differences, the height-field normal of Blinn's bump mapping (Blinn\n"
              "1978, cited by tokai1994 §4) that `shitsukan leather` writes, in the same OpenGL\n"
              "encoding (rgb = (n + 1)/2, green = +y = up the image). Heights: the first channel\n"
              "of a PNG/JPEG/... (8- or 16-bit, full range = 1) or a PFM (values as stored).\n"
              "--normal directx stores 255 - green (green = -y), the only channel that differs.",
              "shitsukan normals HEIGHT.png [-o normal.png] [--strength 8] [--wrap] "
              "[--normal opengl|directx]");
    f.text("in", &in, "the height map (or give it as the first argument)");
    f.number("strength", &strength, 0, 1e6,
             "s: the height, in pixels, of a height difference of 1 (the full range)");
    f.toggle("wrap", &wrap, "differences across the borders: a tileable map stays tileable");
    f.choice("normal", &convention, "opengl|directx",
             "normal map convention (directx: green flipped, 255 - g)");
    f.text("o", &out, "output PNG (8-bit RGB)");
    // The height map may come first, as a plain argument.
    if (argc > 0 && argv[0][0] != '-') {
        in = argv[0];
        --argc, ++argv;
    }
    const int rc = f.parse(argc, argv);
    if (rc != kParsed) return rc;
    if (in.empty()) return f.fail("a height map is required (shitsukan normals HEIGHT.png)");
    if (int e = f.check_output("o", out, ".png")) return e;
    std::vector<float> heights;
    int w = 0, rows = 0;
    Status s = read_heights(in, &heights, &w, &rows);
    if (!s) return f.fail_status(s);
    HeightNormalOptions o;
    o.strength = strength;
    o.wrap = wrap;
    std::vector<Vec3> normals(heights.size());
    if (!(s = height_map_normals(heights.data(), w, rows, o, normals.data())))
        return f.fail_status(s);
    RgbImage rgb;
    if (!(s = rgb.try_resize(w, rows))) return f.fail_status(s);
    std::vector<std::uint8_t> bytes(3 * normals.size());
    encode_normal_rgb8(normals.data(), normals.size(), bytes.data());
    for (std::size_t i = 0; i < normals.size(); ++i)
        rgb.data()[i] = Rgb8{bytes[3 * i],
                             convention == 1 ? std::uint8_t(255 - bytes[3 * i + 1]) : bytes[3 * i + 1],
                             bytes[3 * i + 2]};
    if (!(s = write_png(out.c_str(), rgb.view()))) return f.fail_status(s);
    if (!f.quiet())
        std::fprintf(stderr, "shitsukan normals: %s (%d x %d) -> %s, strength %g%s%s\n", in.c_str(),
                     w, rows, out.c_str(), double(strength), wrap ? ", wrapped" : "",
                     convention == 1 ? ", DirectX" : "");
    return 0;
}

}  // namespace shitsukan::cli
