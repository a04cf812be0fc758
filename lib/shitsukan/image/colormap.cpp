// small-device: yes (no allocation, no exceptions)
#include "shitsukan/image/colormap.hpp"

#include <cmath>

namespace shitsukan {

namespace {

// Control colours, evenly spaced in t (chosen here; see the header for how).
constexpr Rgb8 kPerceptual[] = {{37, 14, 67},   {55, 46, 111},  {47, 88, 137}, {32, 131, 133},
                                {49, 173, 110}, {142, 208, 67}, {248, 229, 44}};
constexpr Rgb8 kDiverging[] = {{59, 76, 192}, {242, 242, 242}, {175, 35, 42}};

Rgb8 piecewise_linear(const Rgb8* stops, int count, float t) {
    float x = t * float(count - 1);
    int i = int(x);
    if (i >= count - 1) return stops[count - 1];
    float f = x - float(i);
    auto mix = [f](std::uint8_t a, std::uint8_t b) {
        return std::uint8_t(std::floor(float(a) + (float(b) - float(a)) * f + 0.5f));
    };
    const Rgb8& a = stops[i];
    const Rgb8& b = stops[i + 1];
    return Rgb8{mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

}  // namespace

Rgb8 colormap(ColorMap map, float t) {
    if (std::isnan(t)) return kColorMapNaN;
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    switch (map) {
        case ColorMap::gray: {
            std::uint8_t v = to_byte(t);
            return Rgb8{v, v, v};
        }
        case ColorMap::perceptual:
            return piecewise_linear(kPerceptual, int(sizeof kPerceptual / sizeof(Rgb8)), t);
        case ColorMap::diverging:
            return piecewise_linear(kDiverging, int(sizeof kDiverging / sizeof(Rgb8)), t);
    }
    return kColorMapNaN;
}

const char* colormap_name(ColorMap map) {
    switch (map) {
        case ColorMap::gray: return "gray";
        case ColorMap::perceptual: return "perceptual";
        case ColorMap::diverging: return "diverging";
    }
    return "unknown";
}

}  // namespace shitsukan
