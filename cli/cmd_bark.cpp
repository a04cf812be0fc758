// cli/cmd_bark.cpp — `shitsukan bark` (hirota1998 §3: the two-layer cylinder grows and cracks).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"
#include "flags.hpp"
#include "shitsukan/bark/bark.hpp"
#include "shitsukan/core/output_file.hpp"
#include "shitsukan/geom/obj.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/raster_canvas.hpp"
#include "shitsukan/render/bark_crack_map.hpp"

namespace shitsukan::cli {
namespace {

void bark_progress(float fraction, void* user) { static_cast<Progress*>(user)->report(fraction); }

// The unrolled crack map at t (render/bark_crack_map.hpp, as the hirota1998 figures draw it):
// the plates, every crack as Fig. 4's ribbon (width l - l0, at least 1 px so a fresh crack
// shows), wrapped around the seam, in the figures' colours.
Status draw_cracks(const BarkCylinder& bark, float t, const Vec3* W, float px_per_cm,
                   RgbImage* out) {
    int w = 0, h = 0;
    SHITSUKAN_TRY(crack_map_size(bark, t, px_per_cm, w, h));  // checked against the budget
    CrackMapStyle style;
    style.origin = {0.0f, float(h)};
    style.px_per_cm = px_per_cm;
    style.min_width_cm = 1.0f / px_per_cm;
    SHITSUKAN_TRY(out->try_resize(w, h, style.plate));
    RasterCanvas canvas(out->view());
    return draw_crack_map(canvas, bark, t, W, style);
}

}  // namespace

int run_bark(int argc, char** argv) {
    CylinderParams p;
    int species = 0;
    float px_per_cm = 24.0f;
    std::string out = "bark";
    bool csv = true, no_csv = false;
    // Table 2's values are flags too; a species preset fills the ones not given.
    SpeciesParams given = species_preset(Species::camphor);
    FlagSet f("bark",
              "hirota1998 §3 (Tables 1-2): a two-layer cylinder of springs (outer layer on shear\n"
              "springs over a growing inner layer); springs break past their critical elongation,\n"
              "one break at a time (§3.1-3.2), a crack drawn as in Fig. 4. Table 2's three species\n"
              "are presets; every Table 1/2 value is a flag (units cm, s, dyn/cm^2). Writes\n"
              "<o>_cracks.png (unrolled crack map), <o>.svg, <o>_nodes/_springs/_triangles.csv,\n"
              "<o>_trunk.obj (the deformed trunk, uv = the crack map).",
              "shitsukan bark [--species camphor|chinese_tallow|pine] [flags] [-o prefix]");
    f.choice("species", &species, "camphor|chinese_tallow|pine",
             "Table 2 column: (1) camphor, (2) Chinese tallow, (3) pine");
    f.number("L0", &given.L0, 0.001, 100, "Table 2: initial node spacing L0 [cm] (species)");
    f.number("E1", &given.E1, 1, 1e15, "Table 2: Young's modulus, axial springs (species)");
    f.number("E2", &given.E2, 1, 1e15, "Table 2: Young's modulus, diagonal springs (species)");
    f.number("G", &given.G, 1, 1e15, "Table 2: shear modulus of the shear springs (species)");
    f.number("kappa1", &given.kappa1, 1.000001, 10,
             "Table 2: mean critical elongation ratio, axial (species)");
    f.number("kappa2", &given.kappa2, 1.000001, 10,
             "Table 2: mean critical elongation ratio, diagonal (species)");
    f.integer("N_R", &p.N_R, 4, 4096, "Table 1: nodes around (even; chosen 128)");
    f.integer("N_H", &p.N_H, 2, 4096, "Table 1: nodes along the axis (chosen 64)");
    f.number("D", &p.D, 0.001, 100, "§5.1: layer thickness D [cm] (chosen 0.55)");
    f.number("sigma", &p.sigma, 0, 0.2999, "Table 1: spread of the critical elongation (chosen)");
    f.number("T", &p.T, 0.001, 1e6, "Table 1: growth period T [s] (chosen 100)");
    f.number("delta_r", &p.delta_r, 0, 10, "Table 1: radial growth rate [cm/s] (chosen)");
    f.number("delta_h", &p.delta_h, 0, 10, "Table 1: height growth rate [cm/s] (chosen)");
    f.number("tolerance", &p.tolerance, 1e-7, 0.1, "relaxation tolerance (chosen 1e-3)");
    f.seed(&p.seed, "critical elongations of the springs (chosen 1998)");
    f.number("px-per-cm", &px_per_cm, 1, 400, "crack map and SVG scale");
    f.toggle("no-csv", &no_csv, "skip the three CSV files");
    f.text("o", &out, "output prefix");
    // Defaults shown in --help are camphor's; the chosen species replaces those not given.
    const int rc = f.parse(argc, argv);
    if (rc != kParsed) return rc;
    if (int e = f.check_prefix("o", out)) return e;
    csv = !no_csv;
    const Species sp = Species(species);
    p.species = species_preset(sp);
    if (f.given("L0")) p.species.L0 = given.L0;
    if (f.given("E1")) p.species.E1 = given.E1;
    if (f.given("E2")) p.species.E2 = given.E2;
    if (f.given("G")) p.species.G = given.G;
    if (f.given("kappa1")) p.species.kappa1 = given.kappa1;
    if (f.given("kappa2")) p.species.kappa2 = given.kappa2;
    if (p.N_R % 2 != 0) return f.fail("--N_R must be an even integer in [4, 4096] (got %d)", p.N_R);
    Status s = validate(p);
    if (!s) return f.fail_status(s);

    BarkCylinder bark;
    CrackRun run;
    RegionReport rep;
    Progress progress = f.progress("growing and cracking");
    CrackRunOptions opt;
    opt.progress = bark_progress;
    opt.progress_user = &progress;
    s = build_cylinder(p, bark);
    if (s) s = grow_and_crack(bark, opt, run);
    const float T = p.T;
    const Vec3* W = bark.net.W.data();
    if (s) s = measure_regions(bark, T, W, rep);
    if (!s) return f.fail_status(s);
    RgbImage map;
    OutputSet files;  // every file of the run appears, or none (core/output_file.hpp)
    if (!(s = draw_cracks(bark, T, W, px_per_cm, &map))) return f.fail_status(s);
    if (!(s = write_png((out + "_cracks.png").c_str(), map.view()))) return f.fail_status(s);
    if (!(s = write_crack_svg(bark, T, W, (out + ".svg").c_str(), px_per_cm)))
        return f.fail_status(s);
    if (csv && !(s = write_bark_csv(bark, T, W, out.c_str()))) return f.fail_status(s);
    TriangleMesh trunk;
    if (!(s = make_trunk_mesh(bark, T, W, trunk))) return f.fail_status(s);
    if (!(s = write_obj((out + "_trunk.obj").c_str(), trunk))) return f.fail_status(s);
    if (!(s = files.commit())) return f.fail_status(s);
    std::fprintf(stderr,
                 "shitsukan bark: %s, %d breaks, %zu regions of mean %.2f x %.2f cm (width x "
                 "height, Table 3's measure); wrote %s_cracks.png, %s.svg%s, %s_trunk.obj\n",
                 species_name(sp), int(run.breaks.size()), rep.regions.size(),
                 double(rep.mean_width), double(rep.mean_height), out.c_str(), out.c_str(),
                 csv ? ", CSV" : "", out.c_str());
    return 0;
}

}  // namespace shitsukan::cli
