// cli/cmd_solid.cpp — `shitsukan marble` and `shitsukan wood` (okada1987 §2.2, §4; okada1989):
// the map set of a slice (cli/flags.hpp's -o convention), or a bake onto an OBJ's uv map.
#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"
#include "flags.hpp"
#include "preview.hpp"
#include "shitsukan/core/output_file.hpp"
#include "shitsukan/geom/mesh_fit.hpp"
#include "shitsukan/geom/obj_read.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/render/solid_bake.hpp"
#include "shitsukan/render/solid_mesh.hpp"
#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"
#include "shitsukan/solid/periodic_lattice.hpp"
#include "shitsukan/solid/smooth_lattice.hpp"
#include "shitsukan/solid/solid_looks.hpp"

namespace shitsukan::cli {
namespace {

// Everything one run is given (flags) and builds (material, lattice).
struct SolidRun {
    bool wood = false;
    int R = kOkada1987R, size = 512, plane = 0, gutter = 16, interpolation = 0, look = -1;
    float beta = kOkada1987Beta, k = kOkada1987MarbleK, layer_period = 0.0f;
    float w = kOkada1989Stripe.w, alpha = kOkada1989Stripe.alpha;
    float k2 = kOkada1987WoodK2, x0 = kOkada1987WoodAxis.x, y0 = kOkada1987WoodAxis.y;
    float at = -1.0f;
    std::uint32_t seed = kOkada1987Seed;
    bool tileable = false;
    MapFlags maps;
    std::string obj, view, preview, stripes_text, i_min_text, i_max_text, look_text;
    SolidMaterial material;
    MarbleStripe layer;
    std::vector<MarbleStripe> own;
};

// "a,b,c" -> exactly `count` numbers; false on anything else.
bool parse_numbers(const std::string& text, float* out, int count) {
    std::size_t p = 0;
    for (int k = 0; k < count; ++k) {
        const std::size_t comma = text.find(',', p);
        if ((k < count - 1) == (comma == std::string::npos)) return false;
        double d;
        if (!parse_double(text.substr(p, comma == std::string::npos ? std::string::npos
                                                                    : comma - p).c_str(), &d))
            return false;
        out[k] = float(d);
        p = comma + 1;
    }
    return true;
}

bool parse_colour(const std::string& text, Vec3* out) {
    float v[3];
    if (!parse_numbers(text, v, 3)) return false;
    for (float c : v)
        if (c < 0.0f || c > 255.0f) return false;
    *out = Vec3{v[0], v[1], v[2]};
    return true;
}

const char* kMarbleAbout =
    "okada1987 §4.1 marble: layers of impurity G(z) (eq. (8): six stripes) displaced along\n"
    "z by k·D(P) (eq. (9)), coloured by eq. (12); with --layer-period (or a --look), okada1989's\n"
    "one layer (eq. (8) there) repeated through the stone. D is the 3D random fractal lattice\n"
    "of okada1987 §2.2 (eqs. (1)-(4)) interpolated by eq. (6). Lengths are lattice units.\n"
    "Writes the map set of a slice: <o>_albedo.png (eq. (12)), <o>_height16.png and\n"
    "<o>_height.exr (the density G', low in the veins), <o>_normal.png, <o>_roughness.png,\n"
    "<o>_ao.png (derived from the height, see docs/TOOL.md); with --obj the uv bake instead.\n"
    "--interpolation smooth (the tool's default, chosen here): the lattice refined with a cubic\n"
    "in place of the mean of the parents, so no crease runs along the lattice's node planes or\n"
    "the tile's seam; eq6: the paper's lattice as it is.";
const char* kWoodAbout =
    "okada1987 §4.2 wood: G = sin(k2·r) about the axis (x0, y0) along z (eq. (10)),\n"
    "each point displaced radially by k·D(P) (eq. (11)), coloured by eq. (12);\n"
    "D is the 3D random fractal lattice of §2.2 (eqs. (1)-(4)) interpolated by eq. (6).\n"
    "Lengths are lattice units. Writes the same map set as marble (height = G', the late wood\n"
    "standing); --interpolation as for marble (smooth: no crease across the long grain).";

void add_solid_flags(FlagSet& f, SolidRun& r) {
    f.integer("R", &r.R, 1, 8, "okada1987 §2.2: recursion depth, a (2^R+1)^3 lattice");
    f.number("beta", &r.beta, 0, 10, "okada1987 eq. (2): level decay L(n) = e^-(n-1)beta (chosen)");
    f.seed(&r.seed, "random numbers g of the lattice (hash noise; chosen 1987)");
    f.text("look", &r.look_text, r.wood ? "a named look: okada1987-wood|oak|walnut|pine (flags "
                                          "given beside it win)"
                                        : "a named look: okada1987|carrara|nero|rosso|verde "
                                          "(flags given beside it win)");
    f.number("k", &r.k, 0, 1000, r.wood ? "okada1987 eq. (11): contribution k of D (§4.4: 1.6)"
                                         : "okada1987 eq. (9): contribution k of D (§4.4: 16)");
    if (r.wood) {
        f.number("k2", &r.k2, 0.001, 100, "okada1987 eq. (10): ring frequency, rings 2pi/k2 apart");
        f.number("x0", &r.x0, -1e4, 1e4, "okada1987 eq. (10): axis x (chosen 6, beside the pith)");
        f.number("y0", &r.y0, -1e4, 1e4, "okada1987 eq. (10): axis y (chosen 14)");
    } else {
        f.number("layer-period", &r.layer_period, 0, 4096,
                 "okada1989 eq. (8): 0 = okada1987's six stripes; > 0 one layer every this");
        f.number("w", &r.w, 0.001, 1000, "okada1989 eq. (8): width of the layer's flat top");
        f.number("alpha", &r.alpha, 0.001, 1000, "okada1989 eq. (8): decay of the layer's skirt");
        f.text("stripes", &r.stripes_text,
               "okada1987 eq. (8): your own layers c,w,alpha;c,w,alpha;... (default: the six "
               "chosen ones)");
    }
    f.text("i-min", &r.i_min_text, "eq. (12): colour I_min r,g,b 0..255 (at G' = 0)");
    f.text("i-max", &r.i_max_text, "eq. (12): colour I_max r,g,b 0..255 (at G' = 1)");
    f.integer("size", &r.size, 8, 16384, "image side in pixels");
    f.choice("plane", &r.plane, "xz|xy|yz", "slice plane (xz: layers/grain, xy: across the axis)");
    f.number("at", &r.at, -1, 4096, "slice position on the third axis (-1 = the middle, 2^(R-1))");
    f.toggle("tileable", &r.tileable,
             "periodic lattice: the slice (the whole period 2^R) tiles with no seam");
    f.choice("interpolation", &r.interpolation, "smooth|eq6",
             "the lattice's refinement: smooth (chosen, no crease) or the paper's eqs. (1)-(4)");
    add_map_flags(f, r.maps);
    f.text("preview", &r.preview, "also the map set on a lit sphere and plane, one PNG");
    f.text("obj", &r.obj, "bake onto this OBJ's uv map (the mesh is fitted into [-1, 1]^3)");
    f.integer("gutter", &r.gutter, 0, 256,
              "with --obj: pixels of dilation around each uv island (no empty texel near one)");
    f.text("view", &r.view, "with --obj: also a shaded picture of the textured mesh");
}

// The look's values for every flag not given beside it.
int apply_look(const FlagSet& f, SolidRun& r) {
    if (r.look_text.empty()) return 0;
    const SolidLook* look = find_solid_look(r.look_text.c_str());
    if (look == nullptr || look->wood != r.wood)
        return f.fail("--look must be one of %s (got \"%s\")", solid_look_names(r.wood),
                      r.look_text.c_str());
    r.material = solid_look_material(*look);
    if (!f.given("k")) r.k = look->k;
    if (!f.given("k2") && r.wood) r.k2 = look->k2;
    if (!r.wood) {
        if (!f.given("layer-period")) r.layer_period = look->layer_period;
        if (!f.given("w")) r.w = look->w;
        if (!f.given("alpha")) r.alpha = look->alpha;
    }
    return 0;
}

int parse_stripes(const FlagSet& f, SolidRun& r) {
    if (r.layer_period > 0.0f || r.tileable)
        return f.fail("--stripes is okada1987's sum of layers; not with --layer-period, --look "
                      "or --tileable (one repeated layer)");
    std::size_t p = 0;
    while (p <= r.stripes_text.size() && r.own.size() < 64) {
        const std::size_t semi = r.stripes_text.find(';', p);
        float v[3];
        if (!parse_numbers(r.stripes_text.substr(p, semi == std::string::npos ? std::string::npos
                                                                             : semi - p),
                           v, 3) ||
            !(v[1] > 0.0f) || !(v[2] > 0.0f))
            return f.fail("--stripes must be c,w,alpha triples separated by ';' (w, alpha > "
                          "0; at most 64) (got \"%s\")", r.stripes_text.c_str());
        r.own.push_back(MarbleStripe{v[0], v[1], v[2]});
        if (semi == std::string::npos) break;
        p = semi + 1;
    }
    r.material.marble.stripes = r.own.data();
    r.material.marble.count = int(r.own.size());
    return 0;
}

// The material of eqs. (8)-(12) from the flags (and the look).
int make_material(const FlagSet& f, SolidRun& r) {
    const bool looked = !r.look_text.empty();
    const Vec3 look_min = r.material.i_min, look_max = r.material.i_max;
    r.material = r.wood ? okada1987_wood(r.k) : okada1987_marble(r.k);
    if (r.wood) {
        r.material.wood.k2 = r.k2, r.material.wood.x0 = r.x0, r.material.wood.y0 = r.y0;
    } else if (r.layer_period > 0.0f || r.tileable) {
        r.material = okada1989_marble(r.k);
        r.layer = kOkada1989Stripe;
        r.layer.w = r.w, r.layer.alpha = r.alpha;
        r.material.marble.stripes = &r.layer;
        r.material.layer_period = r.layer_period > 0.0f ? r.layer_period : kOkada1989LayerPeriod;
        if (r.tileable)
            r.material.layer_period = tileable_layer_period(r.material.layer_period, r.R);
    }
    if (looked) r.material.i_min = look_min, r.material.i_max = look_max;
    if (!r.stripes_text.empty())
        if (int e = parse_stripes(f, r)) return e;
    if (!r.i_min_text.empty() && !parse_colour(r.i_min_text, &r.material.i_min))
        return f.fail("--i-min must be r,g,b with each in [0, 255] (got \"%s\")",
                      r.i_min_text.c_str());
    if (!r.i_max_text.empty() && !parse_colour(r.i_max_text, &r.material.i_max))
        return f.fail("--i-max must be r,g,b with each in [0, 255] (got \"%s\")",
                      r.i_max_text.c_str());
    const Status s = validate_solid_material(r.material);
    return s ? 0 : f.fail_status(s);
}

int check_combinations(const FlagSet& f, const SolidRun& r) {
    if (r.wood && r.tileable)
        return f.fail("--tileable: wood's rings are concentric about the axis and never repeat; "
                      "only marble and D tile");
    if (r.tileable && !r.obj.empty())
        return f.fail("--tileable is for slices; --obj bakes the mesh's own surface");
    if (!r.view.empty() && r.obj.empty()) return f.fail("--view needs --obj");
    if (f.given("gutter") && r.obj.empty()) return f.fail("--gutter needs --obj");
    if (int e = check_map_flags(f, r.maps)) return e;
    if (!r.preview.empty())
        if (int e = f.check_output("preview", r.preview, ".png")) return e;
    if (!r.view.empty())
        if (int e = f.check_output("view", r.view, ".png")) return e;
    return 0;
}

void report(const FlagSet& f, const std::vector<std::string>& written, const char* what) {
    if (f.quiet()) return;
    std::string list;
    for (const std::string& name : written) list += (list.empty() ? "" : ", ") + name;
    std::fprintf(stderr, "shitsukan %s: wrote %s (%s)\n", f.command(), list.c_str(), what);
}

// The albedo and the density G' (as floats) baked onto the uv map in one pass.
int run_bake(FlagSet& f, SolidRun& r, const LatticeView& lattice) {
    TriangleMesh mesh;
    Status s = read_obj(r.obj.c_str(), mesh);
    if (s) s = fit_mesh_to_cube(mesh, 0.92f);
    if (!s) return f.fail_status(s);
    const ObjectToLattice mapping = object_to_lattice_mapping(r.R);
    OutputSet files;  // every file of the run appears, or none (core/output_file.hpp)
    std::vector<std::string> written;
    if (mesh.uvs.empty() && r.view.empty())
        return f.fail("--obj %s has no uv (vt) to bake onto; add --view picture.png to "
                      "render the mesh with the solid texture instead", r.obj.c_str());
    if (!mesh.uvs.empty()) {
        RgbImage texture;
        FloatImage height;  // G' as floats, so the height maps have no 8-bit steps
        s = bake_solid_texture(mesh.view(), lattice, r.material, mapping, r.size, r.size,
                               texture, height, Rgb8{0, 0, 0}, r.gutter,
                               f.progress("baking"));
        if (!s) return f.fail_status(s);
        const MapSetInput input{texture.data(), height.data(), r.size, r.size};
        const MapSetOptions options = map_set_options(r.maps, false);
        if (int e = write_maps(f, r.maps, input, options, &written)) return e;
        if (!r.preview.empty()) {
            if (!(s = write_map_preview(r.preview.c_str(), input, options))) return f.fail_status(s);
            written.push_back(r.preview);
        }
    }
    if (!r.view.empty()) {
        SolidShading shading;
        shading.mapping = mapping;
        const Camera cam = perspective_camera({1.9f, 2.4f, 4.2f}, {0, 0, 0}, {0, 1, 0}, 30.0f,
                                              r.size, r.size);
        RgbImage picture;
        s = render_solid_texture(cam, mesh.view(), lattice, r.material, picture, shading);
        if (s) s = write_png(r.view.c_str(), picture.view());
        if (!s) return f.fail_status(s);
        written.push_back(r.view);
    }
    if (!(s = files.commit())) return f.fail_status(s);
    report(f, written, "baked onto the uv map");
    return 0;
}

int run_slice(FlagSet& f, SolidRun& r, const LatticeView& lattice) {
    SolidSlice slice;
    const float n = float(1 << r.R), middle = r.at >= 0.0f ? r.at : n * 0.5f;
    slice.extent = n;
    slice.wrap = r.tileable;
    if (r.plane == 0) {  // xz: x right, z up, at y
        slice.origin = {0, middle, 0}, slice.u = {1, 0, 0}, slice.v = {0, 0, 1};
    } else if (r.plane == 1) {  // xy: x right, y up, at z
        slice.origin = {0, 0, middle}, slice.u = {1, 0, 0}, slice.v = {0, 1, 0};
    } else {  // yz
        slice.origin = {middle, 0, 0}, slice.u = {0, 1, 0}, slice.v = {0, 0, 1};
    }
    RgbImage image;
    FloatImage density;
    Status s = render_solid_slice(lattice, r.material, slice, r.size, r.size, image, &density,
                                  f.progress("slice"));
    if (!s) return f.fail_status(s);
    OutputSet files;
    std::vector<std::string> written;
    const MapSetInput input{image.data(), density.data(), r.size, r.size};
    const MapSetOptions options = map_set_options(r.maps, r.tileable);
    if (int e = write_maps(f, r.maps, input, options, &written)) return e;
    if (!r.preview.empty()) {
        if (!(s = write_map_preview(r.preview.c_str(), input, options))) return f.fail_status(s);
        written.push_back(r.preview);
    }
    if (!(s = files.commit())) return f.fail_status(s);
    report(f, written, r.tileable ? "tiles seamlessly" : "a slice");
    return 0;
}

}  // namespace

int run_solid(int argc, char** argv, bool wood) {
    SolidRun r;
    r.wood = wood;
    r.plane = wood ? 1 : 0;
    r.k = wood ? kOkada1987WoodK : kOkada1987MarbleK;
    r.maps.prefix = wood ? "wood" : "marble";
    r.maps.strength = wood ? 3.0f : 2.0f;  // chosen: polished stone is nearly flat
    FlagSet f(wood ? "wood" : "marble", wood ? kWoodAbout : kMarbleAbout,
              wood ? "shitsukan wood [flags] [-o prefix] [--obj mesh.obj [--view shaded.png]]"
                   : "shitsukan marble [flags] [-o prefix] [--obj mesh.obj [--view shaded.png]]");
    add_solid_flags(f, r);
    const int rc = f.parse(argc, argv);
    if (rc != kParsed) return rc;
    if (int e = check_combinations(f, r)) return e;
    if (int e = apply_look(f, r)) return e;
    if (int e = make_material(f, r)) return e;

    FractalParams lp = okada1987_lattice_params();
    lp.R = r.R, lp.beta = r.beta, lp.seed = r.seed;
    FractalLattice type1;
    PeriodicLattice periodic;
    SmoothLattice smooth;
    Status s = r.tileable ? periodic.build(lp) : type1.build(lp);
    if (!s) return f.fail_status(s);
    LatticeView lattice = r.tileable ? periodic.view() : type1.view();
    if (r.interpolation == 0) {
        s = smooth.build(lattice, r.tileable ? LatticeWrap::periodic : LatticeWrap::clamp);
        if (!s) return f.fail_status(s);
        lattice = smooth.view();
    }
    return r.obj.empty() ? run_slice(f, r, lattice) : run_bake(f, r, lattice);
}

}  // namespace shitsukan::cli
