// shitsukan/wrinkly/ist_table.hpp — the table of an IST (fujimoto2000 §2, figs. 3, 6): every
// sub-interval number alpha^0 with its image alpha^K, one pair a line, as the paper lists
// them. Used by `shitsukan ist` (cli/cmd_ist.cpp) and examples/20_ist_table.cpp.
//
// Manual
//   #include <cstdio>
//
//   IstAxis axis;
//   Status s = ist_unit_axis(3, 2, axis);    // fig. 3: N = 3, K = 2
//   if (!s) return s;
//   IstTableOptions o;                       // name "unit", first base 0, forward
//   auto print = [](const char* line, void*) { std::puts(line); };
//   s = ist_table(axis, o, print, nullptr);
//   // # fujimoto2000 IST (unit), N = 3, K = 2
//   // # alpha^0 alpha^K
//   // 00 00
//   // 01 10   ...
//
// Lines: comments start with '#' (the IST, then the column heads, then for a connected IST
// its external shuffle "group:offset slot"); then one pair a line in the order of alpha^0 on
// u^0. A unit-IST on one base interval is written with its K digits only (fig. 3); otherwise
// "b.digits" with the base-interval number b + first (fig. 6 numbers from 4). Digits 0-9,
// then a-v for N > 10 (ist_digits_format). The library does not print: each line (without a
// newline) goes to the caller's function.
// Errors: an invalid axis (ist_validate); more than options.max_lines pairs (N^K B) ->
// too_large naming N^K and B. Host side (snprintf).
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/wrinkly/ist_axis.hpp"

namespace shitsukan {

struct IstTableOptions {
    const char* name = nullptr;  // shown in the first comment ("unit", "fully", ...); nullptr:
                                 // the axis' kind
    int first = 0;               // number of the first base interval in the labels
    bool inverse = false;        // alpha^K -> alpha^0 instead
    std::uint64_t max_lines = 1000000;
};

using IstTableLine = void (*)(const char* line, void* user);

Status ist_table(const IstAxis& axis, const IstTableOptions& options, IstTableLine line,
                 void* user);

}  // namespace shitsukan
