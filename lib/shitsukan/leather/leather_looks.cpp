// The named leather looks (leather_looks.hpp).
#include "shitsukan/leather/leather_looks.hpp"

#include <cstring>

namespace shitsukan {
namespace {

const LeatherLook kLooks[] = {
    {"crocodile-belly", 0, Table1Section::convex, 0.1f, 0.1f, 0.25f, 0.015f,
     Vec3{96, 72, 44}, Vec3{214, 190, 146},
     "tokai1994 figs. 4-7: the two-stage belly, d = D, a = 0.25, p = 0.015; fig. 13(a) convex",
     "D 0.1 (10 rows a unit), tan grooves and cream crowns"},
    {"crocodile-back", 1, Table1Section::two_segment, 0.2f, 0.2f, 0.15f, 0.02f,
     Vec3{24, 28, 18}, Vec3{88, 94, 60},
     "tokai1994 fig. 3's square lattice (one Voronoi stage); fig. 15(a) two-segment section",
     "D 0.2 (the back's larger plates), a 0.15 (rows kept straight), p 0.02, dark olive"},
};

}  // namespace

const LeatherLook* find_leather_look(const char* name) {
    if (name == nullptr) return nullptr;
    for (const LeatherLook& look : kLooks)
        if (std::strcmp(look.name, name) == 0) return &look;
    return nullptr;
}

const char* leather_look_names() { return "crocodile-belly|crocodile-back"; }

}  // namespace shitsukan
