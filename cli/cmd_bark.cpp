// cli/cmd_bark.cpp — `shitsukan bark` (hirota1998 §3: the two-layer cylinder grows and cracks).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"
#include "flags.hpp"
#include "preview.hpp"
#include "shitsukan/bark/bark.hpp"
#include "shitsukan/bark/bark_texture.hpp"
#include "shitsukan/core/scalar.hpp"
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


// Everything `shitsukan bark` is told.
struct BarkArgs {
    CylinderParams p;
    SpeciesParams given = species_preset(Species::camphor);  // Table 2 values given as flags
    int species = 0, size = 1024;
    float px_per_cm = 24.0f;
    MapFlags maps;  // -o: the prefix of every file (map set: docs/TOOL.md)
    std::string preview;
    bool no_csv = false, texture = false;
    BarkTextureOptions tex;
};

void add_bark_flags(FlagSet& f, BarkArgs& a) {
    f.choice("species", &a.species, "camphor|chinese_tallow|pine",
             "Table 2 column: (1) camphor, (2) Chinese tallow, (3) pine");
    f.number("L0", &a.given.L0, 0.001, 100, "Table 2: initial node spacing L0 [cm] (species)");
    f.number("E1", &a.given.E1, 1, 1e15, "Table 2: Young's modulus, axial springs (species)");
    f.number("E2", &a.given.E2, 1, 1e15, "Table 2: Young's modulus, diagonal springs (species)");
    f.number("G", &a.given.G, 1, 1e15, "Table 2: shear modulus of the shear springs (species)");
    f.number("kappa1", &a.given.kappa1, 1.000001, 10,
             "Table 2: mean critical elongation ratio, axial (species)");
    f.number("kappa2", &a.given.kappa2, 1.000001, 10,
             "Table 2: mean critical elongation ratio, diagonal (species)");
    f.integer("N_R", &a.p.N_R, 4, 4096, "Table 1: nodes around (even; chosen 128)");
    f.integer("N_H", &a.p.N_H, 2, 4096,
              "Table 1: nodes along the axis (chosen 64; --texture: a square period, 109)");
    f.number("D", &a.p.D, 0.001, 100, "§5.1: layer thickness D [cm] (chosen 0.55)");
    f.number("sigma", &a.p.sigma, 0, 0.2999, "Table 1: spread of the critical elongation (chosen)");
    f.number("T", &a.p.T, 0.001, 1e6, "Table 1: growth period T [s] (chosen 100)");
    f.number("delta_r", &a.p.delta_r, 0, 10,
             "Table 1: radial growth rate [cm/s] (chosen; --texture: x N_R/128)");
    f.number("delta_h", &a.p.delta_h, 0, 10,
             "Table 1: height growth rate [cm/s] (chosen; --texture: x N_H/64)");
    f.number("tolerance", &a.p.tolerance, 1e-7, 0.1, "relaxation tolerance (chosen 1e-3)");
    f.seed(&a.p.seed, "critical elongations of the springs (chosen 1998)");
    f.number("px-per-cm", &a.px_per_cm, 1, 400, "crack map and SVG scale");
    f.toggle("no-csv", &a.no_csv, "skip the three CSV files");
    f.toggle("texture", &a.texture,
             "a seamless map set instead (lattice periodic along the axis too): <o>_albedo.png,\n"
             "_height16.png, _height.exr (cm), _normal.png, _roughness.png, _ao.png");
    f.integer("size", &a.size, 8, 8192, "--texture: map side in pixels (a power of two)");
    f.number("bevel", &a.tex.bevel, 0.01, 4, "--texture: rounded plate edge, x D (chosen 0.25)");
    f.number("relief", &a.tex.relief, 0, 1, "--texture: spread of plate tops, x D (chosen 0.2)");
    f.number("tone", &a.tex.tone, 0, 1, "--texture: spread of plate tones (chosen 0.24)");
    a.maps.prefix = "bark";
    add_map_flags(f, a.maps);
    f.text("preview", &a.preview, "--texture: also the map set on a lit sphere and plane, one PNG");
}

// The species preset, the Table 2 values given, the texture mode's defaults; 0 or exit code.
int finish_bark_args(FlagSet& f, BarkArgs& a) {
    if (int e = check_map_flags(f, a.maps)) return e;
    const Species sp = Species(a.species);
    a.p.species = species_preset(sp);
    if (f.given("L0")) a.p.species.L0 = a.given.L0;
    if (f.given("E1")) a.p.species.E1 = a.given.E1;
    if (f.given("E2")) a.p.species.E2 = a.given.E2;
    if (f.given("G")) a.p.species.G = a.given.G;
    if (f.given("kappa1")) a.p.species.kappa1 = a.given.kappa1;
    if (f.given("kappa2")) a.p.species.kappa2 = a.given.kappa2;
    if (a.p.N_R % 2 != 0)
        return f.fail("--N_R must be an even integer in [4, 4096] (got %d)", a.p.N_R);
    const char* texture_only[] = {"size",   "bevel",  "relief",    "tone",
                                  "normal", "float",  "strength",  "ao-radius", "preview"};
    for (const char* name : texture_only)
        if (f.given(name) && !a.texture)
            return f.fail("--%s shapes the --texture maps; add --texture", name);
    if (!a.preview.empty())
        if (int e = f.check_output("preview", a.preview, ".png")) return e;
    if (a.texture && (a.size & (a.size - 1)) != 0)
        return f.fail("--size must be a power of two in [8, 8192] (got %d)", a.size);
    if (a.texture && !f.given("N_H")) {
        // chosen here: the grown period as near square as the lattice allows (C : H = 1)
        const float C = float(a.p.N_R) * 0.86602540378f * (1.0f + 0.023f);
        a.p.N_H = std::max(3, int(std::lround(C / (1.0f + 0.036f))));
    }
    if (a.texture && a.p.N_H < 3) return f.fail("--N_H must be >= 3 with --texture (got %d)", a.p.N_H);
    // chosen here: the texture keeps Table 3's calibrated strains (bark_params.hpp) at any
    // lattice size (the growth rates are absolute: the same rates on a taller lattice strain
    // it less)
    if (a.texture && !f.given("delta_r")) a.p.delta_r *= float(a.p.N_R) / 128.0f;
    if (a.texture && !f.given("delta_h")) a.p.delta_h *= float(a.p.N_H) / 64.0f;
    a.tex.width = a.tex.height = a.size;
    a.tex.colors = bark_texture_colors(sp);
    a.tex.seed = a.p.seed;
    Status s = validate(a.p);
    return s ? 0 : f.fail_status(s);
}

// Classic output: the crack map, SVG, CSV, the trunk.
Status write_simulation(const BarkArgs& a, const BarkCylinder& bark) {
    const float T = a.p.T;
    const Vec3* W = bark.net.W.data();
    const std::string& out = a.maps.prefix;
    RgbImage map;
    SHITSUKAN_TRY(draw_cracks(bark, T, W, a.px_per_cm, &map));
    SHITSUKAN_TRY(write_png((out + "_cracks.png").c_str(), map.view()));
    SHITSUKAN_TRY(write_crack_svg(bark, T, W, (out + ".svg").c_str(), a.px_per_cm));
    if (!a.no_csv) SHITSUKAN_TRY(write_bark_csv(bark, T, W, out.c_str()));
    TriangleMesh trunk;
    SHITSUKAN_TRY(make_trunk_mesh(bark, T, W, trunk));
    return write_obj((out + "_trunk.obj").c_str(), trunk);
}

// The texture's map set (image/map_set.hpp): the albedo, the heights in cm, the normal and AO
// at the true slope unless --strength is given (the relief's range in pixels), wrapped.
int write_texture(const FlagSet& f, const BarkArgs& a, const BarkTexture& tex,
                  std::vector<std::string>& written) {
    std::vector<Rgb8> albedo(tex.height_cm.size());
    for (std::size_t i = 0; i < albedo.size(); ++i)
        albedo[i] = Rgb8{tex.albedo[3 * i], tex.albedo[3 * i + 1], tex.albedo[3 * i + 2]};
    MapSetOptions options = map_set_options(a.maps, true);
    if (!f.given("strength")) {
        const auto mm = std::minmax_element(tex.height_cm.begin(), tex.height_cm.end());
        options.strength = (*mm.second - *mm.first) / tex.cm_per_pixel;
    }
    const MapSetInput input{albedo.data(), tex.height_cm.data(), tex.width, tex.height};
    if (int e = write_maps(f, a.maps, input, options, &written)) return e;
    if (!a.preview.empty()) {
        const Status s = write_map_preview(a.preview.c_str(), input, options);
        if (!s) return f.fail_status(s);
        written.push_back(a.preview);
    }
    return 0;
}

}  // namespace

int run_bark(int argc, char** argv) {
    BarkArgs a;
    FlagSet f("bark",
              "hirota1998 §3 (Tables 1-2): a two-layer cylinder of springs (outer layer on shear\n"
              "springs over a growing inner layer); springs break past their critical elongation,\n"
              "one break at a time (§3.1-3.2), a crack drawn as in Fig. 4. Table 2's three species\n"
              "are presets; every Table 1/2 value is a flag (units cm, s, dyn/cm^2). Writes\n"
              "<o>_cracks.png (unrolled crack map), <o>.svg, <o>_nodes/_springs/_triangles.csv,\n"
              "<o>_trunk.obj (the deformed trunk, uv = the crack map); with --texture a seamless\n"
              "map set of one period around and along the trunk instead.",
              "shitsukan bark [--species camphor|chinese_tallow|pine] [--texture] [flags] [-o prefix]");
    add_bark_flags(f, a);
    // Defaults shown in --help are camphor's; the chosen species replaces those not given.
    const int rc = f.parse(argc, argv);
    if (rc != kParsed) return rc;
    if (int e = finish_bark_args(f, a)) return e;
    BarkCylinder bark;
    CrackRun run;
    RegionReport rep;
    Progress progress = f.progress("growing and cracking");
    CrackRunOptions opt;
    opt.progress = bark_progress;
    opt.progress_user = &progress;
    Status s = build_cylinder(a.p, a.texture, bark);
    if (s) s = grow_and_crack(bark, opt, run);
    const Vec3* W = bark.net.W.data();
    if (s) s = measure_regions(bark, a.p.T, W, rep);
    if (!s) return f.fail_status(s);
    OutputSet files;  // every file of the run appears, or none (core/output_file.hpp)
    const Species sp = Species(a.species);
    const char* o = a.maps.prefix.c_str();
    if (a.texture) {
        BarkTexture tex;
        if (!(s = make_bark_texture(bark, a.p.T, W, &rep, a.tex, tex))) return f.fail_status(s);
        std::vector<std::string> written;
        if (int e = write_texture(f, a, tex, written)) return e;
        if (!(s = files.commit())) return f.fail_status(s);
        std::string list;
        for (const std::string& name : written) list += (list.empty() ? "" : ", ") + name;
        std::fprintf(stderr,
                     "shitsukan bark: %s texture %d x %d px = %.2f x %.2f cm (around x along), "
                     "%d breaks, %d plates, mean crack width %.3f cm, relief %.3f cm; wrote %s\n",
                     species_name(sp), tex.width, tex.height, double(tex.period_u),
                     double(tex.period_z), int(run.breaks.size()), tex.plates,
                     double(tex.mean_crack_width), double(tex.max_height), list.c_str());
        return 0;
    }
    if (!(s = write_simulation(a, bark)) || !(s = files.commit())) return f.fail_status(s);
    std::fprintf(stderr,
                 "shitsukan bark: %s, %d breaks, %zu regions of mean %.2f x %.2f cm (width x "
                 "height, Table 3's measure); wrote %s_cracks.png, %s.svg%s, %s_trunk.obj\n",
                 species_name(sp), int(run.breaks.size()), rep.regions.size(),
                 double(rep.mean_width), double(rep.mean_height), o, o, a.no_csv ? "" : ", CSV", o);
    return 0;
}

}  // namespace shitsukan::cli
