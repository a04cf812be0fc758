// shitsukan/wrinkly/wr_axis.hpp — the parameter transformation F_U (or F_V) of one surface axis,
// as the wrinkly surface sees it: only the inverse (F^k)^{-1} is ever evaluated (eq. 15, 16).
//
// Manual
//   WrAxis identity = identity_axis(5);            // 5 base intervals, no shuffle
//   float s0 = identity.inverse_at(2.37f, 3);      // = 2.37
//   // WrAxis a = wr_ist.axis();                    // from an IST (wr_ist_axis.hpp):
//   // float s = a.inverse_at(s_k, k);              // (F^k)^{-1}(s_k), k = 0..a.max_level
//
// Coordinates are in base-interval units: s in [0, base_intervals], base interval i =
// [i, i+1). For the IST-Bezier surface there is one base interval (the whole patch, §3.2);
// for the IST-B-spline surface each knot span is one base interval (§3.2, fig. 9/10/16b).
// `division` is the IST's interval division number N (the sampling of §4.2 makes N^k small
// intervals per base interval at step k). k = 0 is always the identity (eq. 16: "F^0 does
// not transform u").
#pragma once

namespace shitsukan {

constexpr int kMaxWrLevel = 12;  // deepest IST step k a surface evaluates

struct WrAxis {
    int base_intervals = 1;
    int division = 1;  // N; 1 = no shuffle (fig. 4a)
    // Deepest step k that `inverse` can evaluate (a WrIstAxis holds F^0 .. F^max_level).
    int max_level = kMaxWrLevel;
    // (F^k)^{-1}(s); nullptr = the identity. `context` is passed back unchanged.
    float (*inverse)(const void* context, float s, int k) = nullptr;
    const void* context = nullptr;

    float inverse_at(float s, int k) const {
        if (k == 0 || inverse == nullptr) return s;
        return inverse(context, s, k);
    }
};

// No transformation: the wrinkly surface reduces to the plain interpolating surface with H
// mapped on it (fig. 14c, 15c: "conventional surface").
inline WrAxis identity_axis(int base_intervals, int division = 1) {
    WrAxis a;
    a.base_intervals = base_intervals;
    a.division = division;
    return a;
}

}  // namespace shitsukan
