// tokai1994 §3.1 processing 4, the paper's step: midpoint displacement of one edge
// (edge_perturbation.hpp). The tiling kept around it: perturbation_tiling.hpp,
// perturb_subdivision.cpp, perturb_two_stage.cpp.
#include "shitsukan/leather/edge_perturbation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/leather/seed_layout.hpp"

namespace shitsukan {
namespace {

bool lex_less(Vec2d a, Vec2d b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

std::uint64_t bits_of(double v) {
    if (v == 0.0) v = 0.0;
    std::uint64_t b;
    std::memcpy(&b, &v, 8);
    return b;
}

constexpr double kKeyQuanta = 16777216.0;  // 2^24 per period (see PerturbationParams)

bool wrapped_keys(const PerturbationParams& prm) {
    return prm.period_x > 0.0f || prm.period_y > 0.0f;
}

// The period of an axis for the key: its own, or the other axis's when it is not wrapped.
double key_period(const PerturbationParams& prm, int axis) {
    const float own = axis == 0 ? prm.period_x : prm.period_y;
    return double(own > 0.0f ? own : (axis == 0 ? prm.period_y : prm.period_x));
}

// A coordinate in quanta of its period, wrapped when the axis is periodic. The offset 0.37
// keeps lattice-aligned points (halves, quarters of the period) away from rounding ties.
std::int64_t wrapped_quanta(double v, const PerturbationParams& prm, int axis) {
    const double q = std::floor(v / key_period(prm, axis) * kKeyQuanta + 0.37);
    const bool wraps = (axis == 0 ? prm.period_x : prm.period_y) > 0.0f;
    if (!wraps) return std::int64_t(q);
    const double m = q - kKeyQuanta * std::floor(q / kKeyQuanta);
    return std::int64_t(m);
}

std::int64_t direction_quanta(double d, const PerturbationParams& prm, int axis) {
    return std::int64_t(std::floor(d / key_period(prm, axis) * kKeyQuanta + 0.5));
}

}  // namespace

bool edge_ends_in_order(Vec2d a, Vec2d b, const PerturbationParams& prm) {
    if (!wrapped_keys(prm)) return !lex_less(b, a);
    const std::int64_t dx = direction_quanta(b.x - a.x, prm, 0);
    const std::int64_t dy = direction_quanta(b.y - a.y, prm, 1);
    if (dx != 0) return dx > 0;
    if (dy != 0) return dy > 0;
    return !lex_less(b, a);
}

void midpoint_displacement(Vec2d a, Vec2d b, const PerturbationParams& prm, std::uint32_t seed,
                           double* f, const double* level_cap) {
    SHITSUKAN_ASSERT(prm.levels >= 0 && prm.levels <= kMaxPerturbationLevels);
    if (!edge_ends_in_order(a, b, prm)) std::swap(a, b);
    const int n = 1 << prm.levels;
    std::uint64_t h = hash_start(seed, kStreamPerturbation);
    if (wrapped_keys(prm)) {  // tileable: the same key for the edge and its periodic copies
        const Vec2d m = (a + b) * 0.5;
        h = hash_add(h, std::uint64_t(wrapped_quanta(m.x, prm, 0)));
        h = hash_add(h, std::uint64_t(wrapped_quanta(m.y, prm, 1)));
        h = hash_add(h, std::uint64_t(direction_quanta(b.x - a.x, prm, 0)));
        h = hash_add(h, std::uint64_t(direction_quanta(b.y - a.y, prm, 1)));
    } else {
        h = hash_add(h, bits_of(a.x));
        h = hash_add(h, bits_of(a.y));
        h = hash_add(h, bits_of(b.x));
        h = hash_add(h, bits_of(b.y));
    }
    f[0] = 0.0;
    f[n] = 0.0;
    double amplitude = double(prm.p);
    int level = 0;
    for (int step = n; step >= 2; step /= 2, ++level) {
        double amp = level_cap ? std::min(amplitude, level_cap[level]) : amplitude;
        for (int i = 0; i < n; i += step) {
            int mid = i + step / 2;
            double rnd = 2.0 * double(uniform_from_bits(hash_add(h, std::uint64_t(mid)))) - 1.0;
            f[mid] = 0.5 * (f[i] + f[i + step]) + amp * rnd;
        }
        amplitude *= double(prm.decay);
    }
}

}  // namespace shitsukan
