// cli/cmd_ist.cpp — `shitsukan ist` (fujimoto2000 §2: the Iterated Shuffle Transformation as
// a table alpha^0 -> alpha^K).
#include <cstdio>

#include "commands.hpp"
#include "flags.hpp"
#include "shitsukan/wrinkly/ist.hpp"

namespace shitsukan::cli {

int run_ist(int argc, char** argv) {
    int N = 3, K = 2, kind = 0, bases = 5, ends = 0, first = 0;
    bool inverse = false;
    const char* kinds[] = {"unit", "fully", "none", "fig6b", "fig7a", "fig7c"};
    FlagSet f("ist",
              "fujimoto2000 §2: an interval is cut into N sub-intervals, shuffled, and the cut and\n"
              "shuffle iterated K times (§2.1 unit-IST, eqs. (5)-(7): the digits of alpha are\n"
              "reversed); connected ISTs (§2.3, figs. 6-7) also move sub-intervals between B base\n"
              "intervals. Prints one pair a line, \"alpha^0 alpha^K\" (K digits; connected: b.digits).",
              "shitsukan ist [--N 3] [--K 2] [--kind unit|fully|none|fig6b|fig7a|fig7c] [flags]");
    f.integer("N", &N, 1, kIstMaxN, "§2.1: interval division number N");
    f.integer("K", &K, 0, kIstMaxIterations, "§2.1: number of iterations K");
    f.choice("kind", &kind, "unit|fully|none|fig6b|fig7a|fig7c",
             "§2.1 unit-IST, §2.3 fully-connected, or a named external shuffle (figs. 6-7)");
    f.integer("bases", &bases, 1, 4096, "§2.3: base intervals B of a connected IST");
    f.choice("ends", &ends, "cyclic|translation", "§2.3: how the end intervals connect");
    f.integer("first", &first, 0, 1000000, "number of the first base interval in the labels");
    f.toggle("inverse", &inverse, "print alpha^K -> alpha^0");
    const int rc = f.parse(argc, argv);
    if (rc != kParsed) return rc;
    const IstEnds e = ends == 0 ? IstEnds::cyclic : IstEnds::translation;
    IstAxis axis;
    Status s;
    if (kind == 0) {
        s = ist_unit_axis(N, K, axis);
    } else if (kind == 1) {
        s = ist_fully_connected_axis(N, K, bases, e, axis);
    } else {
        IstShuffle shuffle;
        s = ist_shuffle_named(kinds[kind], N, shuffle);
        if (s) s = ist_connected_axis(shuffle, K, bases, e, axis);
    }
    if (!s) return f.fail_status(s);
    IstTableOptions o;
    o.name = kinds[kind];
    o.first = first;
    o.inverse = inverse;
    s = ist_table(axis, o, [](const char* line, void*) { std::puts(line); }, nullptr);
    if (s.code() == StatusCode::too_large)
        return f.fail("--N, --K, --bases: %s", s.message());
    if (!s) return f.fail_status(s);
    return 0;
}

}  // namespace shitsukan::cli
