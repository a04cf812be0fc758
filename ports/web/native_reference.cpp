// ports/web/native_reference.cpp — the page's self-test, run natively: the same C API calls
// (api/shitsukan_web.h) in the same order, each output hashed with FNV-1a 64.
//
//   build/web/native_reference            prints "selftest: <case> <output> <hash>" lines
//   build/web/native_reference --js FILE  also writes FILE: window.SK_SELFTEST = {cases: [...]}
//
// The case list lives here alone: the page (page/app.js, URL hash #selftest) loads the file
// written by --js and makes each call by name with the same arguments, hashes what it got
// (the picture as read back from its canvas, the floats' bytes, the text, the Status
// message) and compares. `make test-web` runs both and greps the page's PASS / FAIL.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "api/shitsukan_web.h"

namespace {

std::uint64_t fnv1a64(const void* data, std::size_t n) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

using Args = std::vector<double>;
using Call = std::function<int(const Args&)>;

// Each exported function by name, arguments converted as the page's WASM call converts
// JavaScript numbers (int32 for int/unsigned, float32 for float).
const std::map<std::string, Call>& functions() {
    static const std::map<std::string, Call> f = {
        {"sk_init", [](const Args&) { return sk_init(); }},
        {"sk_okada1987_quadtree_level",
         [](const Args& a) { return sk_okada1987_quadtree_level(int(a[0]), float(a[1]), unsigned(a[2]), int(a[3]), int(a[4])); }},
        {"sk_okada1987_lattice_level",
         [](const Args& a) {
             return sk_okada1987_lattice_level(int(a[0]), float(a[1]), unsigned(a[2]), int(a[3]), int(a[4]), int(a[5]));
         }},
        {"sk_okada1987_build", [](const Args& a) { return sk_okada1987_build(int(a[0]), float(a[1]), unsigned(a[2])); }},
        {"sk_okada1987_set_stripe",
         [](const Args& a) { return sk_okada1987_set_stripe(int(a[0]), float(a[1]), float(a[2]), float(a[3])); }},
        {"sk_okada1987_get_stripes", [](const Args&) { return sk_okada1987_get_stripes(); }},
        {"sk_okada1987_marble_profile", [](const Args& a) { return sk_okada1987_marble_profile(int(a[0])); }},
        {"sk_okada1987_turbulence_slice",
         [](const Args& a) { return sk_okada1987_turbulence_slice(float(a[0]), int(a[1]), float(a[2])); }},
        {"sk_okada1987_marble_slice",
         [](const Args& a) { return sk_okada1987_marble_slice(float(a[0]), float(a[1]), int(a[2])); }},
        {"sk_okada1987_wood_slice",
         [](const Args& a) {
             return sk_okada1987_wood_slice(float(a[0]), float(a[1]), float(a[2]), float(a[3]), float(a[4]), int(a[5]));
         }},
        {"sk_okada1987_mapping",
         [](const Args& a) { return sk_okada1987_mapping(float(a[0]), float(a[1]), int(a[2]), int(a[3])); }},
        {"sk_okada1987_object",
         [](const Args& a) {
             return sk_okada1987_object(int(a[0]), int(a[1]), float(a[2]), float(a[3]), float(a[4]), int(a[5]));
         }},
        {"sk_okada1989_types",
         [](const Args& a) { return sk_okada1989_types(int(a[0]), float(a[1]), unsigned(a[2]), int(a[3]), int(a[4])); }},
        {"sk_tokai1994_pattern",
         [](const Args& a) { return sk_tokai1994_pattern(float(a[0]), float(a[1]), float(a[2]), float(a[3]), unsigned(a[4])); }},
        {"sk_tokai1994_step", [](const Args& a) { return sk_tokai1994_step(int(a[0]), int(a[1])); }},
        {"sk_tokai1994_section_load", [](const Args& a) { return sk_tokai1994_section_load(int(a[0])); }},
        {"sk_tokai1994_section_points", [](const Args&) { return sk_tokai1994_section_points(); }},
        {"sk_tokai1994_section_move",
         [](const Args& a) { return sk_tokai1994_section_move(int(a[0]), int(a[1]), float(a[2]), float(a[3])); }},
        {"sk_tokai1994_section_curve", [](const Args& a) { return sk_tokai1994_section_curve(int(a[0])); }},
        {"sk_tokai1994_scale_relief",
         [](const Args& a) {
             return sk_tokai1994_scale_relief(int(a[0]), float(a[1]), float(a[2]), float(a[3]), float(a[4]));
         }},
        {"sk_tokai1994_maps", [](const Args& a) { return sk_tokai1994_maps(int(a[0])); }},
        {"sk_tokai1994_patch", [](const Args& a) { return sk_tokai1994_patch(float(a[0]), float(a[1]), int(a[2])); }},
        {"sk_fujimoto2000_axis",
         [](const Args& a) { return sk_fujimoto2000_axis(int(a[0]), int(a[1]), int(a[2]), int(a[3]), int(a[4])); }},
        {"sk_fujimoto2000_diagram",
         [](const Args& a) { return sk_fujimoto2000_diagram(int(a[0]), a[1], int(a[2]), int(a[3]), int(a[4])); }},
        {"sk_fujimoto2000_follow", [](const Args& a) { return sk_fujimoto2000_follow(a[0]); }},
        {"sk_fujimoto2000_table", [](const Args& a) { return sk_fujimoto2000_table(int(a[0]), int(a[1])); }},
        {"sk_hirota1998_species", [](const Args& a) { return sk_hirota1998_species(int(a[0])); }},
        {"sk_hirota1998_run",
         [](const Args& a) {
             return sk_hirota1998_run(int(a[0]), float(a[1]), float(a[2]), float(a[3]), int(a[4]), int(a[5]));
         }},
        {"sk_hirota1998_frame", [](const Args& a) { return sk_hirota1998_frame(int(a[0]), float(a[1])); }},
        {"sk_fujimoto2000_wr",
         [](const Args& a) {
             return sk_fujimoto2000_wr(int(a[0]), int(a[1]), float(a[2]), int(a[3]), unsigned(a[4]), float(a[5]),
                                       float(a[6]), float(a[7]), int(a[8]));
         }},
        {"sk_fujimoto2000_ratio", [](const Args& a) { return sk_fujimoto2000_ratio(int(a[0])); }},
        {"sk_hirota1998_layers_run",
         [](const Args& a) { return sk_hirota1998_layers_run(int(a[0]), int(a[1]), int(a[2]), float(a[3])); }},
        {"sk_hirota1998_layers_frame",
         [](const Args& a) { return sk_hirota1998_layers_frame(int(a[0]), float(a[1])); }},
        {"sk_hirota1998_layers_events", [](const Args&) { return sk_hirota1998_layers_events(); }},
        {"sk_hirota1998_layers_event",
         [](const Args& a) { return sk_hirota1998_layers_event(int(a[0]), float(a[1])); }},
        {"sk_hirota1998_branch_run",
         [](const Args& a) {
             return sk_hirota1998_branch_run(float(a[0]), float(a[1]), float(a[2]), float(a[3]), float(a[4]));
         }},
        {"sk_hirota1998_branch_view",
         [](const Args& a) {
             return sk_hirota1998_branch_view(int(a[0]), int(a[1]), float(a[2]), float(a[3]), int(a[4]));
         }},
        {"sk_fujimoto2000_terrain",
         [](const Args& a) {
             return sk_fujimoto2000_terrain(int(a[0]), float(a[1]), int(a[2]), float(a[3]), float(a[4]), unsigned(a[5]),
                                            float(a[6]), float(a[7]), int(a[8]));
         }},
    };
    return f;
}

struct Case {
    const char* name;
    const char* fn;
    Args args;
    const char* outputs;  // which to hash: picture floats text status (space separated)
};

// The self-test's cases for init, okada1987 and okada1989, in order.
void add_okada_cases(std::vector<Case>& c) {
    const Case cases[] = {
            {"init", "sk_init", {}, "status"},
            {"okada1987 fig. 1 quadtree, level 3", "sk_okada1987_quadtree_level", {6, 0.9, 1987, 3, 256}, "picture floats text"},
            {"okada1987 fig. 1 quadtree, level 6", "sk_okada1987_quadtree_level", {6, 0.9, 1987, 6, 256}, "picture floats"},
            {"okada1987 fig. 2 lattice, level 2", "sk_okada1987_lattice_level", {6, 0.9, 1987, 2, 32, 256}, "picture floats text"},
            {"okada1987 fig. 2 lattice, level 6", "sk_okada1987_lattice_level", {6, 0.9, 1987, 6, 32, 256}, "picture floats text"},
            {"okada1987 lattice R = 11 refused", "sk_okada1987_lattice_level", {11, 0.9, 1987, 1, 0, 256}, "status"},
            {"okada1987 build R = 10 refused", "sk_okada1987_build", {10, 0.9, 1987}, "status"},
            {"okada1987 build 65^3", "sk_okada1987_build", {6, 0.9, 1987}, "status"},
            {"okada1987 eq. (6) D(P), y = 32", "sk_okada1987_turbulence_slice", {32, 256, 2.5}, "picture floats"},
            {"okada1987 marble k = 0", "sk_okada1987_marble_slice", {0, 32, 512}, "picture floats"},
            {"okada1987 marble k = 8", "sk_okada1987_marble_slice", {8, 32, 512}, "picture floats"},
            {"okada1987 marble k = 16", "sk_okada1987_marble_slice", {16, 32, 512}, "picture floats"},
            {"okada1987 marble k = 32", "sk_okada1987_marble_slice", {32, 32, 512}, "picture floats"},
            {"okada1987 eq. (8) profile", "sk_okada1987_marble_profile", {256}, "floats"},
            {"okada1987 the six stripes", "sk_okada1987_get_stripes", {}, "floats"},
            {"okada1987 stripe 2 moved", "sk_okada1987_set_stripe", {2, 30, 2, 1}, "status"},
            {"okada1987 marble k = 16, stripe 2 moved", "sk_okada1987_marble_slice", {16, 32, 256}, "picture"},
            {"okada1987 stripe refused (w = 0)", "sk_okada1987_set_stripe", {1, 20, 0, 1}, "status"},
            {"okada1987 stripes reset", "sk_okada1987_set_stripe", {-1, 0, 0, 0}, "status"},
            {"okada1987 wood k = 1.6", "sk_okada1987_wood_slice", {1.6, 1.2, 6, 14, 32, 256}, "picture floats"},
            {"okada1987 §3.2 forward k = 16", "sk_okada1987_mapping", {16, 32, 256, 1}, "picture floats"},
            {"okada1989 §4-1 backward k = 16", "sk_okada1987_mapping", {16, 32, 256, 0}, "picture"},
            {"okada1987 fig. 10a cube, marble", "sk_okada1987_object", {0, 0, 16, 0.0, 0.0, 256}, "picture"},
            {"okada1987 fig. 10a cube turned", "sk_okada1987_object", {0, 0, 16, 0.7, -0.3, 256}, "picture"},
            {"okada1987 fig. 13 cut sphere, wood", "sk_okada1987_object", {1, 1, 1.6, 0.4, 0.2, 256}, "picture"},
            {"okada1989 Types I/II/III, a row", "sk_okada1989_types", {6, 0.9, 1987, 2048, 0}, "floats"},
            {"okada1989 Types I/II/III, scattered", "sk_okada1989_types", {6, 0.9, 1987, 2048, 1}, "floats"},
            {"okada1989 Types II/III at R = 16", "sk_okada1989_types", {16, 0.9, 1987, 512, 1}, "floats"},
    };
    c.insert(c.end(), std::begin(cases), std::end(cases));
}

// The self-test's cases for tokai1994, in order.
void add_tokai1994_cases(std::vector<Case>& c) {
    const Case cases[] = {
            {"tokai1994 pattern D = 0 refused", "sk_tokai1994_pattern", {0, 1, 0.25, 0.015, 1}, "status"},
            {"tokai1994 fig. 7 pattern", "sk_tokai1994_pattern", {0.1, 1, 0.25, 0.015, 1}, "text"},
            {"tokai1994 fig. 4 stage-1 seeds", "sk_tokai1994_step", {0, 384}, "picture"},
            {"tokai1994 fig. 5 stage 1", "sk_tokai1994_step", {1, 384}, "picture"},
            {"tokai1994 fig. 6 stage 2", "sk_tokai1994_step", {2, 384}, "picture"},
            {"tokai1994 fig. 7 final", "sk_tokai1994_step", {3, 384}, "picture"},
            {"tokai1994 fig. 10 perturbation", "sk_tokai1994_step", {4, 384}, "picture"},
            {"tokai1994 Table 1 convex section", "sk_tokai1994_section_load", {0}, "status"},
            {"tokai1994 convex z(r)", "sk_tokai1994_section_curve", {128}, "floats"},
            {"tokai1994 fig. 12 one scale", "sk_tokai1994_scale_relief", {160, 1, 0.3, 0.5, 0.8}, "picture floats text"},
            {"tokai1994 fig. 7 maps 256", "sk_tokai1994_maps", {256}, "picture floats"},
            {"tokai1994 fig. 18 patch", "sk_tokai1994_patch", {0.6, 0.7, 256}, "picture"},
            {"tokai1994 section point moved", "sk_tokai1994_section_move", {0, 1, 0.3, 0.9}, "status"},
            {"tokai1994 section moved, points", "sk_tokai1994_section_points", {}, "floats"},
            {"tokai1994 section move refused", "sk_tokai1994_section_move", {0, 1, 2.5, 0.9}, "status"},
            {"tokai1994 Table 1 two-segment section", "sk_tokai1994_section_load", {2}, "status"},
            {"tokai1994 two-segment relief", "sk_tokai1994_scale_relief", {128, 1, -0.4, 0.2, 0.9}, "picture"},
    };
    c.insert(c.end(), std::begin(cases), std::end(cases));
}

// The self-test's cases for fujimoto2000, in order.
void add_fujimoto2000_cases(std::vector<Case>& c) {
    const Case cases[] = {
            {"fujimoto2000 IST N = 4 refused (fully)", "sk_fujimoto2000_axis", {1, 4, 2, 5, 0}, "status"},
            {"fujimoto2000 fig. 3 unit N = 5, K = 3", "sk_fujimoto2000_axis", {0, 5, 3, 1, 0}, "text"},
            {"fujimoto2000 fig. 3 diagram", "sk_fujimoto2000_diagram", {0, 0.37, 0, 0, 1000}, "picture"},
            {"fujimoto2000 fig. 3 u = 0.37 followed", "sk_fujimoto2000_follow", {0.37}, "floats text"},
            {"fujimoto2000 fig. 3 table (eq. 7)", "sk_fujimoto2000_table", {0, 1000}, "text"},
            {"fujimoto2000 fig. 6a fully N = 5, K = 3", "sk_fujimoto2000_axis", {1, 5, 3, 13, 0}, "text"},
            {"fujimoto2000 fig. 6a diagram", "sk_fujimoto2000_diagram", {1, 0.5, 0, 5, 1200}, "picture"},
            {"fujimoto2000 fig. 6a u = 0.5 followed", "sk_fujimoto2000_follow", {0.5}, "floats text"},
            {"fujimoto2000 fig. 6a table too large", "sk_fujimoto2000_table", {0, 100}, "status"},
            {"fujimoto2000 fig. 6b connected", "sk_fujimoto2000_axis", {2, 5, 3, 13, 0}, "text"},
            {"fujimoto2000 fig. 6b diagram", "sk_fujimoto2000_diagram", {0, 0.5, 0, 5, 1200}, "picture"},
            {"fujimoto2000 fig. 9 translation N = 3", "sk_fujimoto2000_axis", {1, 3, 3, 5, 1}, "text"},
            {"fujimoto2000 fig. 9 diagram", "sk_fujimoto2000_diagram", {1, 0.05, 0, 0, 1000}, "picture"},
            {"fujimoto2000 fig. 9 u = 0.05 followed", "sk_fujimoto2000_follow", {0.05}, "floats text"},
            {"fujimoto2000 fig. 9 table (eq. 12)", "sk_fujimoto2000_table", {0, 1000}, "text"},
            {"fujimoto2000 diagram too large", "sk_fujimoto2000_axis", {0, 7, 6, 1, 0}, "status"},
            {"fujimoto2000 diagram refused", "sk_fujimoto2000_diagram", {0, 0.5, 0, 0, 1000}, "status"},
            {"fujimoto2000 fig. 14 conventional Bezier", "sk_fujimoto2000_wr", {0, 0, 0.35, 2, 14, 0.5, 0, 0, 256}, "picture"},
            {"fujimoto2000 fig. 14 WR eq. (15), K = 3", "sk_fujimoto2000_wr", {0, 1, 0.35, 3, 14, 0.5, 0, 0, 256}, "picture"},
            {"fujimoto2000 fig. 17 superposed delta 0.35, without the jitter", "sk_fujimoto2000_wr", {0, 2, 0.35, 3, 14, 0, 0.5, 0.2, 256}, "picture"},
            {"fujimoto2000 fig. 17 superposed delta 0.35, with §5's jitter 0.5", "sk_fujimoto2000_wr", {0, 2, 0.35, 3, 14, 0.5, 0.5, 0.2, 256}, "picture"},
            {"fujimoto2000 fig. 17 superposed delta 0.65, without the jitter", "sk_fujimoto2000_wr", {0, 2, 0.65, 3, 14, 0, 0.5, 0.2, 256}, "picture"},
            {"fujimoto2000 fig. 18 B-spline WR, K = 2", "sk_fujimoto2000_wr", {1, 1, 0.5, 2, 18, 0.12, 0, 0, 256}, "picture"},
            {"fujimoto2000 WR delta = 1 refused", "sk_fujimoto2000_wr", {1, 2, 1, 2, 18, 0.12, 0, 0, 256}, "status"},
            {"fujimoto2000 WR jitter refused", "sk_fujimoto2000_wr", {1, 2, 0.5, 2, 18, 1000, 0, 0, 256}, "status"},
            {"fujimoto2000 fig. 21c conventional terrain", "sk_fujimoto2000_terrain", {0, 0.55, 3, 0.12, 0.035, 21, 0, 0, 256}, "picture"},
            {"fujimoto2000 fig. 21f superposed, jitter", "sk_fujimoto2000_terrain", {2, 0.55, 3, 0.12, 0.035, 21, 0, 0, 256}, "picture"},
            {"fujimoto2000 fig. 21f jitter seed 22", "sk_fujimoto2000_terrain", {2, 0.55, 3, 0.12, 0.035, 22, 0, 0, 256}, "picture"},
            {"fujimoto2000 fig. 21f no jitter, turned", "sk_fujimoto2000_terrain", {2, 0.55, 3, 0, 0, 21, 0.6, 0.2, 256}, "picture"},
            {"fujimoto2000 fig. 21d WR terrain", "sk_fujimoto2000_terrain", {1, 0.55, 2, 0.12, 0.035, 21, 0, 0, 256}, "picture"},
            {"fujimoto2000 terrain jitter refused", "sk_fujimoto2000_terrain", {2, 0.55, 2, 1000, 0.035, 21, 0, 0, 256}, "status"},
    };
    c.insert(c.end(), std::begin(cases), std::end(cases));
}

// The self-test's cases for hirota1998, in order.
void add_hirota1998_cases(std::vector<Case>& c) {
    const Case cases[] = {
            {"hirota1998 frame before a run refused", "sk_hirota1998_frame", {0, 40}, "status"},
            {"hirota1998 Table 2 camphor", "sk_hirota1998_species", {0}, "text"},
            {"hirota1998 sigma refused", "sk_hirota1998_run", {0, 0.5, 1.04, 1.015, 32, 24}, "status"},
            {"hirota1998 camphor run: events, hash", "sk_hirota1998_run", {0, 0.0175, 1.04, 1.015, 32, 24}, "floats text"},
            {"hirota1998 camphor at event 0", "sk_hirota1998_frame", {0, 40}, "picture text"},
            {"hirota1998 camphor after 300 events", "sk_hirota1998_frame", {300, 40}, "picture text"},
            {"hirota1998 camphor all 1068 events", "sk_hirota1998_frame", {1068, 40}, "picture text"},
            {"hirota1998 event past the run refused", "sk_hirota1998_frame", {1069, 40}, "status"},
            {"hirota1998 Table 2 Chinese tallow", "sk_hirota1998_species", {1}, "text"},
            {"hirota1998 tallow run: events, hash", "sk_hirota1998_run", {1, 0.0175, 1.033, 1.015, 32, 24}, "floats text"},
            {"hirota1998 tallow after 300 events", "sk_hirota1998_frame", {300, 40}, "picture"},
            {"hirota1998 tallow all 1135 events", "sk_hirota1998_frame", {1135, 40}, "picture text"},
            {"hirota1998 Table 2 pine", "sk_hirota1998_species", {2}, "text"},
            {"hirota1998 pine run: events, hash", "sk_hirota1998_run", {2, 0.0175, 1.038, 1.023, 32, 24}, "floats text"},
            {"hirota1998 pine all 912 events", "sk_hirota1998_frame", {912, 40}, "picture text"},
            {"hirota1998 layers frame before a run refused", "sk_hirota1998_layers_frame", {0, 16}, "status"},
            {"hirota1998 figs. 6-8 four layers 24 x 16, 4 cycles", "sk_hirota1998_layers_run", {24, 16, 4, 0.08}, "floats text"},
            {"hirota1998 four layers, step 25", "sk_hirota1998_layers_frame", {24, 16}, "picture text"},
            {"hirota1998 four layers, before role change 1", "sk_hirota1998_layers_frame", {49, 16}, "picture text"},
            {"hirota1998 four layers, after role change 1", "sk_hirota1998_layers_frame", {50, 16}, "picture text"},
            {"hirota1998 four layers, cycle 3 mid", "sk_hirota1998_layers_frame", {127, 16}, "picture text"},
            {"hirota1998 four layers, the end", "sk_hirota1998_layers_frame", {202, 16}, "picture text"},
            {"hirota1998 four layers: every loop event, in order", "sk_hirota1998_layers_events", {}, "floats"},
            {"hirota1998 four layers at event 0", "sk_hirota1998_layers_event", {0, 16}, "picture text"},
            {"hirota1998 four layers at event 100", "sk_hirota1998_layers_event", {100, 16}, "picture text"},
            {"hirota1998 four layers at event 400", "sk_hirota1998_layers_event", {400, 16}, "picture text"},
            {"hirota1998 four layers frame past the end refused", "sk_hirota1998_layers_frame", {203, 16}, "status"},
            {"hirota1998 branch view before a run refused", "sk_hirota1998_branch_view", {20, 0, 0, 0, 256}, "status"},
            {"hirota1998 fig. 11 branch run (L0 0.6)", "sk_hirota1998_branch_run", {0.6, 0.01, 0.05, 1.015, 0.0175}, "floats text"},
            {"hirota1998 fig. 11 branch at T, front", "sk_hirota1998_branch_view", {20, 0, 0, 0, 256}, "picture text"},
            {"hirota1998 fig. 11 branch at T, above", "sk_hirota1998_branch_view", {20, 1, 0, 0, 256}, "picture text"},
            {"hirota1998 fig. 11 branch at T/2, turned", "sk_hirota1998_branch_view", {10, 0, 0.8, 0.3, 256}, "picture text"},
            {"hirota1998 branch frame past T refused", "sk_hirota1998_branch_view", {21, 0, 0, 0, 256}, "status"},
    };
    c.insert(c.end(), std::begin(cases), std::end(cases));
}

// The self-test, in order (the API keeps state: the lattice, the stripes).
const std::vector<Case>& cases() {
    static const std::vector<Case> c = [] {
        std::vector<Case> all;
        add_okada_cases(all);
        add_tokai1994_cases(all);
        add_fujimoto2000_cases(all);
        add_hirota1998_cases(all);
        return all;
    }();
    return c;
}

std::string hex(std::uint64_t h) {
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

std::string json_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    const char* js_path = nullptr;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--js") == 0 && i + 1 < argc)
            js_path = argv[++i];
        else {
            std::fprintf(stderr, "usage: native_reference [--js FILE]\n");
            return 2;
        }
    }
    std::string js = "window.SK_SELFTEST = {\"version\": \"" + std::string(sk_version()) + "\", \"cases\": [\n";
    int failures = 0;
    for (std::size_t ci = 0; ci < cases().size(); ++ci) {
        const Case& c = cases()[ci];
        auto fn = functions().find(c.fn);
        if (fn == functions().end()) {
            std::fprintf(stderr, "native_reference: no function %s\n", c.fn);
            return 1;
        }
        sk_clear_outputs();
        const int code = fn->second(c.args);
        std::string args, hashes;
        for (std::size_t i = 0; i < c.args.size(); ++i) {
            char buf[40];
            std::snprintf(buf, sizeof buf, "%s%.17g", i ? ", " : "", c.args[i]);
            args += buf;
        }
        std::string outs = c.outputs;
        std::size_t pos = 0;
        while (pos < outs.size()) {
            std::size_t end = outs.find(' ', pos);
            if (end == std::string::npos) end = outs.size();
            const std::string o = outs.substr(pos, end - pos);
            pos = end + 1;
            std::uint64_t h = 0;
            if (o == "picture")
                h = fnv1a64(sk_picture_data(), std::size_t(sk_picture_width()) * std::size_t(sk_picture_height()) * 4u);
            else if (o == "floats")
                h = fnv1a64(sk_floats_data(), std::size_t(sk_floats_count()) * sizeof(float));
            else if (o == "text")
                h = fnv1a64(sk_text(), std::strlen(sk_text()));
            else if (o == "status")
                h = fnv1a64(sk_status_message(), std::strlen(sk_status_message()));
            else {
                std::fprintf(stderr, "native_reference: unknown output %s\n", o.c_str());
                return 1;
            }
            if (o == "picture" && sk_picture_width() == 0) ++failures;
            if (o == "text") std::printf("selftest-text: %s: %s\n", c.name, sk_text());
            std::printf("selftest: %-45s %-8s %s\n", c.name, o.c_str(), hex(h).c_str());
            hashes += std::string(hashes.empty() ? "" : ", ") + "\"" + o + "\": \"" + hex(h) + "\"";
        }
        if (code != 0) std::printf("selftest: %-45s status   %s: %s\n", c.name, sk_status_code_name(), sk_status_message());
        js += std::string("  {\"name\": \"") + json_escape(c.name) + "\", \"fn\": \"" + c.fn + "\", \"args\": [" + args +
              "], \"code\": " + std::to_string(code) + ", \"hashes\": {" + hashes + "}}" +
              (ci + 1 < cases().size() ? ",\n" : "\n");
    }
    js += "]};\n";
    if (js_path) {
        std::FILE* f = std::fopen(js_path, "wb");
        if (!f || std::fwrite(js.data(), 1, js.size(), f) != js.size() || std::fclose(f) != 0) {
            std::fprintf(stderr, "native_reference: cannot write %s\n", js_path);
            return 1;
        }
    }
    if (failures) std::fprintf(stderr, "native_reference: %d pictures came back empty\n", failures);
    return failures ? 1 : 0;
}
