// tools/bark_table3_sweep.cpp — hirota1998 Table 3 under the shared chosen values: does any
// setting shared by all three species put the widths in the paper's order (camphor < tallow <
// pine)? Prints one Markdown row per setting: each species' mean width x height over the seeds,
// on table03's trunk and section (128 x 80 nodes, 8 rows left out at each end).
//
//   make build/libshitsukan.a
//   g++ -std=c++17 -O2 -ffp-contract=off -Ilib tools/bark_table3_sweep.cpp build/libshitsukan.a
//       -o build/bark_table3_sweep  &&  build/bark_table3_sweep [seeds]
//   build/bark_table3_sweep views [seeds]   # the max in photograph views 32, 43 and 64
//                                           # columns wide (photograph_views.hpp), as chosen
//   build/bark_table3_sweep set D sigma hoop axial kappa [seeds]
//                                           # one setting: means and the 43-column views' max;
//                                           # tools/bark_table3_grid.sh runs a grid of them
//
// Every setting (the list below; `set` takes one from the command line) changes values for all
// three species at once (no per-species tuning):
// sigma, D, the final hoop and axial strains, a common scale on every kappa - 1, the relaxation
// tolerance. docs/papers/hirota1998.md §4 prints its output.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "shitsukan/bark/bark.hpp"

using namespace shitsukan;

namespace {

// The chosen values (bark_params.hpp's defaults) unless a setting changes them; hoop, axial
// and kappa scale the default final strains and every kappa - 1.
struct Setting {
    const char* name;
    float sigma = CylinderParams{}.sigma, D = CylinderParams{}.D;
    float hoop = 1.0f, axial = 1.0f, kappa = 1.0f, tol = CylinderParams{}.tolerance;
};

struct Cell {
    double w = 0, h = 0, max_w = 0, max_h = 0;
    double view_max_w[3] = {0, 0, 0}, view_max_h[3] = {0, 0, 0};  // kViewColumns' views
    double view_max_h_lo[3] = {1e30, 1e30, 1e30};  // the smallest of the seeds' view max heights
};

const int kViewColumns[3] = {32, 43, 64};

Status species_cell(Species species, const Setting& s, int seeds, Cell* out) {
    for (int k = 0; k < seeds; ++k) {
        CylinderParams p;
        p.species = species_preset(species);
        p.species.kappa1 = 1.0f + s.kappa * (p.species.kappa1 - 1.0f);
        p.species.kappa2 = 1.0f + s.kappa * (p.species.kappa2 - 1.0f);
        const CylinderParams defaults;  // table03's trunk: 80 rows, the default final strains
        p.N_H = 80;
        p.delta_h = s.axial * axial_strain(defaults, defaults.T) * initial_height(p) / p.T;
        p.delta_r = s.hoop * defaults.delta_r;
        p.sigma = s.sigma, p.D = s.D, p.tolerance = s.tol;
        p.seed = k == 0 ? 1998u : std::uint32_t(k);
        BarkCylinder bark;
        SHITSUKAN_TRY(build_cylinder(p, bark));
        CrackRun run;
        SHITSUKAN_TRY(grow_and_crack(bark, CrackRunOptions{}, run));
        RegionOptions section;
        section.end_rows = kSectionEndRows;
        RegionReport r;
        SHITSUKAN_TRY(measure_regions(bark, p.T, bark.net.W.data(), r, section));
        out->w += r.mean_width / seeds, out->h += r.mean_height / seeds;
        out->max_w += r.max_width / seeds, out->max_h += r.max_height / seeds;
        for (int v = 0; v < 3; ++v) {
            PhotographViews views;
            SHITSUKAN_TRY(measure_photograph_views(bark, r, kViewColumns[v], views));
            out->view_max_w[v] += views.max_width / seeds;
            out->view_max_h[v] += views.max_height / seeds;
            if (views.max_height < out->view_max_h_lo[v]) out->view_max_h_lo[v] = views.max_height;
        }
    }
    return Status::success();
}

// The three species under one setting, in Table 3's order; false after printing the error.
bool species_cells(const Setting& s, int seeds, const char* what, Cell c[3]) {
    const Species species[3] = {Species::camphor, Species::chinese_tallow, Species::pine};
    for (int i = 0; i < 3; ++i) {
        const Status st = species_cell(species[i], s, seeds, &c[i]);
        if (!st) {
            std::fprintf(stderr, "bark_table3_sweep: %s: %s\n", what, st.message());
            return false;
        }
    }
    return true;
}

}  // namespace

// The max in photograph views of three widths, at the chosen values.
int print_views(int seeds) {
    Cell c[3];
    if (!species_cells(Setting{"as chosen"}, seeds, "views", c)) return 1;
    std::printf("| view (%d seeds) | camphor max | Chinese tallow max | pine max |\n"
                "|---|---|---|---|\n",
                seeds);
    std::printf("| whole section | %.2f x %.2f | %.2f x %.2f | %.2f x %.2f |\n", c[0].max_w,
                c[0].max_h, c[1].max_w, c[1].max_h, c[2].max_w, c[2].max_h);
    for (int v = 0; v < 3; ++v)
        std::printf("| %d columns | %.2f x %.2f | %.2f x %.2f | %.2f x %.2f |\n", kViewColumns[v],
                    c[0].view_max_w[v], c[0].view_max_h[v], c[1].view_max_w[v],
                    c[1].view_max_h[v], c[2].view_max_w[v], c[2].view_max_h[v]);
    return 0;
}

// A positive finite number from argv, or false with a message.
bool positive_arg(const char* text, const char* name, double* out) {
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end == text || *end != '\0' || !(v > 0) || !std::isfinite(v)) {
        std::fprintf(stderr, "bark_table3_sweep: set: %s must be a positive number (got '%s')\n",
                     name, text);
        return false;
    }
    *out = v;
    return true;
}

// One setting given on the command line (a grid is a loop over it): each species' means and
// its max in 43-column views, to four decimals, and the smallest of the seeds' camphor view
// max heights (table03 asks every seed's to span the section: '(>20)').
int print_setting(int argc, char** argv) {
    const char* names[6] = {"D", "sigma", "hoop", "axial", "kappa", "seeds"};
    double v[6] = {0, 0, 0, 0, 0, 3};
    if (argc < 7 || argc > 8) {
        std::fprintf(stderr, "bark_table3_sweep: set D sigma hoop axial kappa [seeds]\n");
        return 2;
    }
    for (int i = 0; i + 2 < argc; ++i)
        if (!positive_arg(argv[i + 2], names[i], &v[i])) return 2;
    if (v[5] != std::floor(v[5]) || v[5] > 100) {
        std::fprintf(stderr, "bark_table3_sweep: set: seeds must be a whole number in [1, 100]\n");
        return 2;
    }
    Setting s{"set"};
    s.D = float(v[0]), s.sigma = float(v[1]), s.hoop = float(v[2]), s.axial = float(v[3]);
    s.kappa = float(v[4]);
    const int seeds = int(v[5]);
    Cell c[3];
    if (!species_cells(s, seeds, "set", c)) return 1;
    std::printf("| D %.3f sigma %.4f hoop x%.3f axial x%.3f kappa-1 x%.3f | %.4f x %.4f | "
                "%.4f x %.4f | %.4f x %.4f | %.4f | %.4f x %.4f | %.4f x %.4f | %.4f x %.4f | "
                "%.4f |\n",
                s.D, s.sigma, s.hoop, s.axial, s.kappa, c[0].w, c[0].h, c[1].w, c[1].h, c[2].w,
                c[2].h, c[1].w / c[0].w, c[0].view_max_w[1], c[0].view_max_h[1],
                c[1].view_max_w[1], c[1].view_max_h[1], c[2].view_max_w[1], c[2].view_max_h[1],
                c[0].view_max_h_lo[1]);
    return 0;
}

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "views") == 0)
        return print_views(argc > 2 ? std::atoi(argv[2]) : 5);
    if (argc > 1 && std::strcmp(argv[1], "set") == 0) return print_setting(argc, argv);
    const int seeds = argc > 1 ? std::atoi(argv[1]) : 3;
    Setting list[] = {{"as chosen"},      {"sigma 0.0125"},   {"sigma 0.025"},
                      {"D 0.45"},         {"D 0.70"},         {"hoop strain x0.85"},
                      {"hoop strain x1.15"}, {"axial strain x0.95"}, {"axial strain x1.05"},
                      {"kappa - 1 x0.9"}, {"kappa - 1 x1.1"}, {"tolerance 1e-4"}};
    list[1].sigma = 0.0125f, list[2].sigma = 0.025f, list[3].D = 0.45f, list[4].D = 0.70f;
    list[5].hoop = 0.85f, list[6].hoop = 1.15f, list[7].axial = 0.95f, list[8].axial = 1.05f;
    list[9].kappa = 0.9f, list[10].kappa = 1.1f, list[11].tol = 1e-4f;
    std::printf("| shared setting (%d seeds) | camphor | Chinese tallow | pine | tallow / camphor "
                "width | paper's width order |\n|---|---|---|---|---|---|\n",
                seeds);
    for (const Setting& s : list) {
        Cell c[3];
        if (!species_cells(s, seeds, s.name, c)) return 1;
        std::printf("| %s | %.2f x %.2f | %.2f x %.2f | %.2f x %.2f | %.2f | %s |\n", s.name,
                    c[0].w, c[0].h, c[1].w, c[1].h, c[2].w, c[2].h, c[1].w / c[0].w,
                    c[0].w < c[1].w && c[1].w < c[2].w ? "yes" : "no");
        std::fflush(stdout);
    }
    return 0;
}
