// Tests for lib/shitsukan/solid/solid_looks and lib/shitsukan/leather/leather_looks: every look
// makes a valid material (its layer, its colours), the names listed are the table's, an
// unknown name is null; the marbles' layer is their own (w, alpha), kept apart per look.
#include <doctest/doctest.h>

#include <string>

#include "shitsukan/leather/leather_looks.hpp"
#include "shitsukan/solid/solid_looks.hpp"

using namespace shitsukan;

TEST_CASE("solid looks: every look is a valid material with its own values") {
    std::string marbles, woods;
    for (int i = 0; i < solid_look_count(); ++i) {
        const SolidLook& look = solid_look(i);
        std::string& list = look.wood ? woods : marbles;
        list += (list.empty() ? "" : "|") + std::string(look.name);
        const SolidMaterial m = solid_look_material(look);
        CHECK_MESSAGE(validate_solid_material(m), look.name);
        CHECK(m.i_min.x == look.i_min.x);
        CHECK(m.i_max.z == look.i_max.z);
        CHECK(find_solid_look(look.name) == &look);
        CHECK(std::string(look.given).size() > 0);
        CHECK(std::string(look.chosen).size() > 0);
        if (look.wood) {
            CHECK(m.pattern == SolidPattern::wood);
            CHECK(m.wood.k2 == look.k2);
        } else {
            CHECK(m.layer_period == look.layer_period);
            REQUIRE(m.marble.stripes != nullptr);
            CHECK(m.marble.stripes[0].w == look.w);
            CHECK(m.marble.stripes[0].alpha == look.alpha);
        }
    }
    CHECK(marbles == solid_look_names(false));
    CHECK(woods == solid_look_names(true));
    // two marbles' layers do not share storage
    const SolidMaterial a = solid_look_material(*find_solid_look("carrara"));
    const SolidMaterial b = solid_look_material(*find_solid_look("rosso"));
    CHECK(a.marble.stripes != b.marble.stripes);
    CHECK(a.marble.stripes[0].w != b.marble.stripes[0].w);
    CHECK(find_solid_look("granite") == nullptr);
    CHECK(find_solid_look(nullptr) == nullptr);
}

TEST_CASE("leather looks: the crocodile's belly and back, valid sections and parameters") {
    for (const char* name : {"crocodile-belly", "crocodile-back"}) {
        const LeatherLook* look = find_leather_look(name);
        REQUIRE(look != nullptr);
        CHECK(std::string(leather_look_names()).find(name) != std::string::npos);
        CHECK(validate_section(table1_section(look->section)));
        CHECK((look->layout >= 0 && look->layout <= 2));
        CHECK(look->D > 0.0f);
        CHECK((look->a >= 0.0f && look->a <= 1.0f));
    }
    CHECK(find_leather_look("crocodile-belly")->layout == 0);  // figs. 4-7's two-stage belly
    CHECK(find_leather_look("lizard") == nullptr);
}
