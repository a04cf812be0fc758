// Lesson 20 (ist_table): print every sub-interval number alpha^0 and its image alpha^K under an IST
// (fujimoto2000 §2.3): watch the scale reversal of eq. (7) and eq. (12).
// Figures: paper_figures/fujimoto2000/fig03_04_unit_ist.cpp,
//   paper_figures/fujimoto2000/fig06_09_connected_ist.cpp,
//   paper_figures/fujimoto2000/fig11_12_scale_reverse.cpp.
//
//   20_ist_table                         N = 3, K = 2, unit-IST (the default table)
//   20_ist_table N K [kind] [options]
//     kind     unit | fully | none | fig6b | fig7a | fig7c | table:d0:s0,d1:s1,...
//              (table: group g goes to base interval + d_g, slot s_g; N entries)
//     options  --bases B        number of base intervals of a connected IST (default 5)
//              --ends cyclic|translation   (default cyclic)
//              --first F        number of the first base interval in the labels (default 0;
//                               the paper's fig 6 starts at 4)
//              --inverse        print alpha^K -> alpha^0 instead
//
// Output: comment lines start with '#'; then one pair a line, "alpha^0 alpha^K", in the order
// of alpha^0 on u^0. Unit-IST numbers are K digits (digits 0-9, then a-v for N > 10);
// connected ones "b.digits" with the base-interval number b.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "shitsukan/wrinkly/ist.hpp"

using namespace shitsukan;

namespace {

int usage(const char* message) {
    std::fprintf(stderr,
                 "ist_table: %s\nusage: ist_table [N K [unit|fully|none|fig6b|fig7a|fig7c|"
                 "table:d0:s0,d1:s1,...] [--bases B] [--ends cyclic|translation] [--first F] "
                 "[--inverse]]\n",
                 message);
    return 2;
}

bool parse_int(const char* text, int* out) {
    char* end = nullptr;
    long v = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || v < -1000000000L || v > 1000000000L) return false;
    *out = int(v);
    return true;
}

// "table:-1:4,0:1,0:2,0:3,1:0"
Status parse_table(const char* text, int n, IstShuffle* out) {
    int offsets[kIstMaxN], slots[kIstMaxN];
    int count = 0;
    std::string rest(text);
    std::size_t pos = 0;
    while (pos <= rest.size()) {
        std::size_t comma = rest.find(',', pos);
        std::string item = rest.substr(pos, comma == std::string::npos ? std::string::npos
                                                                        : comma - pos);
        std::size_t colon = item.rfind(':');
        if (colon == std::string::npos || colon == 0 || count >= kIstMaxN ||
            !parse_int(item.substr(0, colon).c_str(), &offsets[count]) ||
            !parse_int(item.substr(colon + 1).c_str(), &slots[count]))
            return Status::error(StatusCode::invalid_argument,
                                 "shuffle table entry '%s' is not offset:slot", item.c_str());
        ++count;
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    if (count != n)
        return Status::error(StatusCode::invalid_argument,
                             "shuffle table has %d entries, N = %d needs one per group", count, n);
    return ist_shuffle_from_table(n, offsets, slots, *out);
}

}  // namespace

int main(int argc, char** argv) {
    int n = 3, k = 2, bases = 5, first = 0;
    const char* kind = "unit";
    IstEnds ends = IstEnds::cyclic;
    bool inverse = false;
    int positional = 0;
    for (int i = 1; i < argc; ++i) {
        const char* a = argv[i];
        if (std::strcmp(a, "--bases") == 0 && i + 1 < argc) {
            if (!parse_int(argv[++i], &bases)) return usage("--bases needs an integer");
        } else if (std::strcmp(a, "--first") == 0 && i + 1 < argc) {
            if (!parse_int(argv[++i], &first)) return usage("--first needs an integer");
        } else if (std::strcmp(a, "--ends") == 0 && i + 1 < argc) {
            const char* e = argv[++i];
            if (std::strcmp(e, "cyclic") == 0) ends = IstEnds::cyclic;
            else if (std::strcmp(e, "translation") == 0) ends = IstEnds::translation;
            else return usage("--ends is cyclic or translation");
        } else if (std::strcmp(a, "--inverse") == 0) {
            inverse = true;
        } else if (a[0] == '-' && a[1] == '-') {
            return usage("unknown option");
        } else if (positional == 0) {
            if (!parse_int(a, &n)) return usage("N must be an integer");
            ++positional;
        } else if (positional == 1) {
            if (!parse_int(a, &k)) return usage("K must be an integer");
            ++positional;
        } else if (positional == 2) {
            kind = a;
            ++positional;
        } else {
            return usage("too many arguments");
        }
    }

    IstAxis axis;
    Status s;
    if (std::strcmp(kind, "unit") == 0) {
        s = ist_unit_axis(n, k, axis);
    } else if (std::strcmp(kind, "fully") == 0) {
        s = ist_fully_connected_axis(n, k, bases, ends, axis);
    } else {
        IstShuffle shuffle;
        if (std::strncmp(kind, "table:", 6) == 0) {
            s = (n >= 1 && n <= kIstMaxN) ? parse_table(kind + 6, n, &shuffle)
                                          : ist_unit_axis(n, k, axis);   // reports the bad N
        } else {
            s = ist_shuffle_named(kind, n, shuffle);
        }
        if (s) s = ist_connected_axis(shuffle, k, bases, ends, axis);
    }
    IstTableOptions o;  // wrinkly/ist_table.hpp: the same table as `shitsukan ist`
    o.name = kind;
    o.first = first;
    o.inverse = inverse;
    if (s) s = ist_table(axis, o, [](const char* line, void*) { std::puts(line); }, nullptr);
    if (!s) {
        std::fprintf(stderr, "ist_table: %s\n", s.message());
        return 1;
    }
    return 0;
}
