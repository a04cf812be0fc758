// cli/cmd_solid.cpp — `shitsukan marble` and `shitsukan wood` (okada1987 §2.2, §4; okada1989).
#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"
#include "flags.hpp"
#include "shitsukan/core/output_file.hpp"
#include "shitsukan/geom/mesh_fit.hpp"
#include "shitsukan/geom/obj_read.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/pfm.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/render/solid_bake.hpp"
#include "shitsukan/render/solid_mesh.hpp"
#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"
#include "shitsukan/solid/periodic_lattice.hpp"

namespace shitsukan::cli {
namespace {

// "a,b,c" -> up to `max` numbers; false on anything else.
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

}  // namespace

int run_solid(int argc, char** argv, bool wood) {
    const FractalParams defaults = okada1987_lattice_params();
    int R = defaults.R, size = 512, plane = wood ? 1 : 0;
    float beta = defaults.beta;
    std::uint32_t seed = defaults.seed;
    float k = wood ? kOkada1987WoodK : kOkada1987MarbleK;
    float layer_period = 0.0f, w = kOkada1989Stripe.w, alpha = kOkada1989Stripe.alpha;
    float k2 = kOkada1987WoodK2, x0 = kOkada1987WoodAxis.x, y0 = kOkada1987WoodAxis.y;
    float at = -1.0f;
    bool tileable = false;
    std::string out = wood ? "wood.png" : "marble.png", obj, view, pfm, stripes_text;
    std::string i_min_text, i_max_text;

    FlagSet f(wood ? "wood" : "marble",
              wood ? "okada1987 §4.2 wood: G = sin(k2·r) about the axis (x0, y0) along z (eq. (10)),\n"
                     "each point displaced radially by k·D(P) (eq. (11)), coloured by eq. (12);\n"
                     "D is the 3D random fractal lattice of §2.2 (eqs. (1)-(4)) interpolated by eq. (6).\n"
                     "Lengths are lattice units (the lattice spans [0, 2^R]^3)."
                   : "okada1987 §4.1 marble: layers of impurity G(z) (eq. (8): six stripes) displaced along\n"
                     "z by k·D(P) (eq. (9)), coloured by eq. (12); with --layer-period, okada1989's one\n"
                     "layer (eq. (8) there) repeated through the stone. D is the 3D random fractal lattice\n"
                     "of okada1987 §2.2 (eqs. (1)-(4)) interpolated by eq. (6). Lengths are lattice units.",
              wood ? "shitsukan wood [flags] [-o wood.png] [--obj mesh.obj [--view shaded.png]]"
                   : "shitsukan marble [flags] [-o marble.png] [--obj mesh.obj [--view shaded.png]]");
    f.integer("R", &R, 1, 8, "okada1987 §2.2: recursion depth, a (2^R+1)^3 lattice");
    f.number("beta", &beta, 0, 10, "okada1987 eq. (2): level decay L(n) = e^-(n-1)beta (chosen)");
    f.seed(&seed, "random numbers g of the lattice (hash noise; chosen 1987)");
    f.number("k", &k, 0, 1000, wood ? "okada1987 eq. (11): contribution k of D (§4.4: 1.6)"
                                     : "okada1987 eq. (9): contribution k of D (§4.4: 16)");
    if (wood) {
        f.number("k2", &k2, 0.001, 100, "okada1987 eq. (10): ring frequency, rings 2pi/k2 apart");
        f.number("x0", &x0, -1e4, 1e4, "okada1987 eq. (10): axis x (chosen 6, beside the pith)");
        f.number("y0", &y0, -1e4, 1e4, "okada1987 eq. (10): axis y (chosen 14)");
    } else {
        f.number("layer-period", &layer_period, 0, 4096,
                 "okada1989 eq. (8): 0 = okada1987's six stripes; > 0 one layer every this");
        f.number("w", &w, 0.001, 1000, "okada1989 eq. (8): width of the layer's flat top");
        f.number("alpha", &alpha, 0.001, 1000, "okada1989 eq. (8): decay of the layer's skirt");
        f.text("stripes", &stripes_text,
               "okada1987 eq. (8): your own layers c,w,alpha;c,w,alpha;... (default: the six "
               "chosen ones)");
    }
    f.text("i-min", &i_min_text, wood ? "eq. (12): colour I_min r,g,b 0..255 (summer wood, chosen)"
                                      : "eq. (12): colour I_min r,g,b 0..255 (impurity, chosen)");
    f.text("i-max", &i_max_text, wood ? "eq. (12): colour I_max r,g,b 0..255 (winter wood, chosen)"
                                      : "eq. (12): colour I_max r,g,b 0..255 (limestone, chosen)");
    f.integer("size", &size, 8, 16384, "image side in pixels");
    f.choice("plane", &plane, "xz|xy|yz", "slice plane (xz: layers/grain, xy: across the axis)");
    f.number("at", &at, -1, 4096, "slice position on the third axis (-1 = the middle, 2^(R-1))");
    f.toggle("tileable", &tileable,
             "periodic lattice: the slice (the whole period 2^R) tiles with no seam");
    f.text("o", &out, "output PNG (slice, or the baked uv texture with --obj)");
    f.text("pfm", &pfm, "also the density G' of the slice as a float PFM");
    f.text("obj", &obj, "bake onto this OBJ's uv map (the mesh is fitted into [-1, 1]^3)");
    f.text("view", &view, "with --obj: also a shaded picture of the textured mesh");
    const int rc = f.parse(argc, argv);
    if (rc != kParsed) return rc;
    if (wood && tileable)
        return f.fail("--tileable: wood's rings are concentric about the axis and never repeat; "
                      "only marble and D tile");
    if (tileable && !obj.empty())
        return f.fail("--tileable is for slices; --obj bakes the mesh's own surface");
    if (!view.empty() && obj.empty()) return f.fail("--view needs --obj");
    if (!pfm.empty() && !obj.empty()) return f.fail("--pfm is for slices (not with --obj)");
    if (int e = f.check_output("o", out, ".png")) return e;
    if (!pfm.empty())
        if (int e = f.check_output("pfm", pfm, ".pfm")) return e;
    if (!view.empty())
        if (int e = f.check_output("view", view, ".png")) return e;

    FractalParams lp = defaults;
    lp.R = R, lp.beta = beta, lp.seed = seed;
    SolidMaterial material = wood ? okada1987_wood(k) : okada1987_marble(k);
    MarbleStripe layer{0.0f, w, alpha};
    if (wood) {
        material.wood.k2 = k2;
        material.wood.x0 = x0;
        material.wood.y0 = y0;
    } else if (layer_period > 0.0f || tileable) {
        material = okada1989_marble(k);
        layer = kOkada1989Stripe;
        layer.w = w, layer.alpha = alpha;
        material.marble.stripes = &layer;
        material.layer_period = layer_period > 0.0f ? layer_period : kOkada1989LayerPeriod;
        if (tileable) material.layer_period = tileable_layer_period(material.layer_period, R);
    }
    std::vector<MarbleStripe> own;
    if (!stripes_text.empty()) {
        if (layer_period > 0.0f || tileable)
            return f.fail("--stripes is okada1987's sum of layers; not with --layer-period or "
                          "--tileable (one repeated layer)");
        std::size_t p = 0;
        while (p <= stripes_text.size() && own.size() < 64) {
            const std::size_t semi = stripes_text.find(';', p);
            float v[3];
            if (!parse_numbers(stripes_text.substr(p, semi == std::string::npos ? std::string::npos
                                                                               : semi - p),
                               v, 3) ||
                !(v[1] > 0.0f) || !(v[2] > 0.0f))
                return f.fail("--stripes must be c,w,alpha triples separated by ';' (w, alpha > "
                              "0; at most 64) (got \"%s\")", stripes_text.c_str());
            own.push_back(MarbleStripe{v[0], v[1], v[2]});
            if (semi == std::string::npos) break;
            p = semi + 1;
        }
        material.marble.stripes = own.data();
        material.marble.count = int(own.size());
    }
    if (!i_min_text.empty() && !parse_colour(i_min_text, &material.i_min))
        return f.fail("--i-min must be r,g,b with each in [0, 255] (got \"%s\")",
                      i_min_text.c_str());
    if (!i_max_text.empty() && !parse_colour(i_max_text, &material.i_max))
        return f.fail("--i-max must be r,g,b with each in [0, 255] (got \"%s\")",
                      i_max_text.c_str());
    Status s = validate_solid_material(material);
    if (!s) return f.fail_status(s);

    FractalLattice type1;
    PeriodicLattice periodic;
    s = tileable ? periodic.build(lp) : type1.build(lp);
    if (!s) return f.fail_status(s);
    const LatticeView lattice = tileable ? periodic.view() : type1.view();
    const float n = float(1 << R);
    OutputSet files;  // every file of the run appears, or none (core/output_file.hpp)

    if (!obj.empty()) {
        TriangleMesh mesh;
        if (!(s = read_obj(obj.c_str(), mesh))) return f.fail_status(s);
        if (!(s = fit_mesh_to_cube(mesh, 0.92f))) return f.fail_status(s);
        const ObjectToLattice mapping = object_to_lattice_mapping(R);
        if (!mesh.uvs.empty()) {
            RgbImage texture;
            s = bake_solid_texture(mesh.view(), lattice, material, mapping, size, size, texture,
                                   Rgb8{0, 0, 0}, 4, f.progress("baking onto the uv map"));
            if (s) s = write_png(out.c_str(), texture.view());
            if (!s) return f.fail_status(s);
        } else if (view.empty()) {
            return f.fail("--obj %s has no uv (vt) to bake onto; add --view picture.png to "
                          "render the mesh with the solid texture instead", obj.c_str());
        }
        if (!view.empty()) {
            SolidShading shading;
            shading.mapping = mapping;
            const Camera cam = perspective_camera({1.9f, 2.4f, 4.2f}, {0, 0, 0}, {0, 1, 0}, 30.0f,
                                                  size, size);
            RgbImage picture;
            s = render_solid_texture(cam, mesh.view(), lattice, material, picture, shading);
            if (s) s = write_png(view.c_str(), picture.view());
            if (!s) return f.fail_status(s);
        }
        if (!(s = files.commit())) return f.fail_status(s);
        if (!mesh.uvs.empty())
            std::fprintf(stderr, "shitsukan %s: wrote %s (%d x %d uv texture of %s)\n",
                         f.command(), out.c_str(), size, size, obj.c_str());
        if (!view.empty())
            std::fprintf(stderr, "shitsukan %s: wrote %s (%d triangles)\n", f.command(),
                         view.c_str(), mesh.triangle_count());
        return 0;
    }

    SolidSlice slice;
    const float middle = at >= 0.0f ? at : n * 0.5f;
    slice.extent = n;
    slice.wrap = tileable;
    if (plane == 0) {  // xz: x right, z up, at y
        slice.origin = {0, middle, 0}, slice.u = {1, 0, 0}, slice.v = {0, 0, 1};
    } else if (plane == 1) {  // xy: x right, y up, at z
        slice.origin = {0, 0, middle}, slice.u = {1, 0, 0}, slice.v = {0, 1, 0};
    } else {  // yz
        slice.origin = {middle, 0, 0}, slice.u = {0, 1, 0}, slice.v = {0, 0, 1};
    }
    RgbImage image;
    FloatImage density;
    s = render_solid_slice(lattice, material, slice, size, size, image,
                           pfm.empty() ? nullptr : &density, f.progress("slice"));
    if (s) s = write_png(out.c_str(), image.view());
    if (s && !pfm.empty()) s = write_pfm(pfm.c_str(), density.data(), size, size, 1);
    if (s) s = files.commit();
    if (!s) return f.fail_status(s);
    std::fprintf(stderr, "shitsukan %s: wrote %s%s%s (%d x %d%s)\n", f.command(), out.c_str(),
                 pfm.empty() ? "" : " and ", pfm.c_str(), size, size,
                 tileable ? ", tiles seamlessly" : "");
    return 0;
}

}  // namespace shitsukan::cli
