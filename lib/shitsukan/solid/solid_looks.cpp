// Host side: the named looks (solid_looks.hpp).
#include "shitsukan/solid/solid_looks.hpp"

#include <cstring>

#include "shitsukan/solid/okada1987_presets.hpp"

namespace shitsukan {
namespace {

const SolidLook kLooks[] = {
    {"okada1987", false, kOkada1987MarbleK, kOkada1989LayerPeriod, 1.2f, 1.0f, 0.0f,
     kOkada1987Impurity, kOkada1987Limestone, "okada1987 §4.4 k = 16; okada1989 eq. (8) layer",
     "the library's figure colours (okada1987_presets.hpp)"},
    {"carrara", false, 10.0f, 16.0f, 0.4f, 2.5f, 0.0f, Vec3{112, 118, 126}, Vec3{240, 239, 236},
     "eqs. (8), (9), (12)",
     "white stone, thin grey veins: a narrow layer (w 0.4) with a wide soft skirt, k 10"},
    {"nero", false, 16.0f, 16.0f, 0.3f, 4.0f, 0.0f, Vec3{236, 232, 224}, Vec3{22, 22, 26},
     "okada1987 §4.4 k = 16; eqs. (8), (12)",
     "black stone with thin white veins (I_min white: the layer is the vein)"},
    {"rosso", false, 20.0f, 8.0f, 1.5f, 1.2f, 0.0f, Vec3{236, 214, 196}, Vec3{142, 40, 36},
     "eqs. (8), (9), (12)", "red stone, pale veins twice as often (layer every 8), k 20"},
    {"verde", false, 24.0f, 16.0f, 1.0f, 0.8f, 0.0f, Vec3{26, 64, 44}, Vec3{168, 196, 170},
     "eqs. (8), (9), (12)", "green serpentine: strongly folded (k 24), dark veins"},
    {"okada1987-wood", true, kOkada1987WoodK, 0.0f, 0.0f, 0.0f, kOkada1987WoodK2,
     kOkada1987SummerWood, kOkada1987WinterWood, "okada1987 §4.4 k = 1.6, eqs. (10)-(12)",
     "the library's figure colours and k2 1.2"},
    {"oak", true, 2.0f, 0.0f, 0.0f, 0.0f, 1.6f, Vec3{206, 164, 110}, Vec3{122, 82, 44},
     "eqs. (10)-(12)", "light oak, rings 2pi/1.6 = 3.9 units apart, a little more wavy (k 2)"},
    {"walnut", true, 1.2f, 0.0f, 0.0f, 0.0f, 2.4f, Vec3{120, 82, 56}, Vec3{58, 36, 24},
     "eqs. (10)-(12)", "dark walnut, closer rings (k2 2.4), straighter grain (k 1.2)"},
    {"pine", true, 1.6f, 0.0f, 0.0f, 0.0f, 0.9f, Vec3{232, 198, 146}, Vec3{176, 112, 58},
     "okada1987 §4.4 k = 1.6, eqs. (10)-(12)", "pale pine, wide rings (k2 0.9), red late wood"},
};
constexpr int kLookCount = int(sizeof kLooks / sizeof kLooks[0]);

// Each marble's layer (okada1989 eq. (8)): centred at 32 like kOkada1989Stripe, its w and alpha.
MarbleStripe g_stripes[kLookCount];

}  // namespace

int solid_look_count() { return kLookCount; }
const SolidLook& solid_look(int index) { return kLooks[index]; }

const SolidLook* find_solid_look(const char* name) {
    if (name == nullptr) return nullptr;
    for (const SolidLook& look : kLooks)
        if (std::strcmp(look.name, name) == 0) return &look;
    return nullptr;
}

SolidMaterial solid_look_material(const SolidLook& look) {
    SolidMaterial m = look.wood ? okada1987_wood(look.k) : okada1989_marble(look.k);
    if (look.wood) {
        m.wood.k2 = look.k2;
    } else {
        m.layer_period = look.layer_period;
        const int index = int(&look - kLooks);
        if (index >= 0 && index < kLookCount) {
            g_stripes[index] = MarbleStripe{kOkada1989Stripe.c, look.w, look.alpha};
            m.marble.stripes = &g_stripes[index];
        }
    }
    m.i_min = look.i_min;
    m.i_max = look.i_max;
    return m;
}

const char* solid_look_names(bool wood) {
    return wood ? "okada1987-wood|oak|walnut|pine" : "okada1987|carrara|nero|rosso|verde";
}

}  // namespace shitsukan
