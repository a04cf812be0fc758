// Lesson 60: the two-layer bark of hirota1998 §3 in the smallest program that shows it.
// Figure: hirota1998 fig. 5 and Table 3 (paper_figures/hirota1998/fig05_table03_species.cpp).
//
// A trunk is two layers: an inner layer that grows (its radius and height rise linearly with
// time) and the bark surface, a lattice of springs tied to the inner layer by shear springs.
// Growth stretches the surface springs; each breaks once its stretch passes its own critical
// value (Table 2's kappa, spread by sigma), and a broken spring is a crack. Whether the
// cracks run along the trunk or close into blocks comes from the species' Table 2 row alone.
// Camphor and Chinese tallow share every value of subscript 2 (read here as the springs
// around the trunk) and differ in subscript 1 (the springs along it) and in G: camphor's
// axial springs are softer and tougher (E1 107.1e7 against 117.3e7, kappa1 1.040 against 1.033), so few horizontal
// cracks cut its vertical ones and the bark splits into long strips; tallow's vertical
// cracks are cut into blocks.
// docs/papers/hirota1998.md explains the model and every chosen value.
//
// The program grows both species on the library's default trunk (128 x 64 nodes, 5.8 cm
// radius, 21 cm tall), prints Table 3's region sizes beside the paper's, and writes each
// unrolled crack map as an SVG (60_camphor.svg, 60_tallow.svg). Takes a few seconds.
// Run: make examples   (the SVGs appear in build/examples/out/)
#include <cstdio>

#include "shitsukan/bark/bark.hpp"

using namespace shitsukan;

static Status grow(Species species, const char* svg, RegionReport& regions, int& breaks) {
    CylinderParams params;                     // Table 1 + the chosen values (bark_params.hpp)
    params.species = species_preset(species);  // Table 2's row
    BarkCylinder bark;
    SHITSUKAN_TRY(build_cylinder(params, bark));  // the two layers and their springs
    CrackRun run;
    SHITSUKAN_TRY(grow_and_crack(bark, CrackRunOptions{}, run));  // t = 0 .. T, break by break
    breaks = int(run.breaks.size());
    const Vec3* W = bark.net.W.data();  // the surface's displacement at T
    SHITSUKAN_TRY(measure_regions(bark, params.T, W, regions));  // Table 3's measure
    return write_crack_svg(bark, params.T, W, svg);
}

int main() {
    struct Row {
        Species species;
        const char* svg;
        const char* paper;  // Table 3, the paper's simulation (mean width x height, cm)
    };
    const Row rows[] = {{Species::camphor, "60_camphor.svg", "1.58 x 11.6"},
                        {Species::chinese_tallow, "60_tallow.svg", "1.70 x 3.02"}};
    std::printf("species          broken springs  regions  mean width x height (cm)  paper\n");
    for (const Row& row : rows) {
        RegionReport regions;
        int breaks = 0;
        const Status s = grow(row.species, row.svg, regions, breaks);
        if (!s) {
            std::fprintf(stderr, "60_two_layer_bark: %s\n", s.message());
            return 1;
        }
        std::printf("%-16s %14d %8zu  %10.2f x %-13.2f  %s   (%s)\n", species_name(row.species),
                    breaks, regions.regions.size(), double(regions.mean_width),
                    double(regions.mean_height), row.paper, row.svg);
    }
    return 0;
}
