// cli/cmd_leather.cpp — `shitsukan leather` (tokai1994 §3.1 scale pattern, §3.2 relief).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "commands.hpp"
#include "flags.hpp"
#include "shitsukan/core/output_file.hpp"
#include "shitsukan/geom/obj.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/pfm.hpp"
#include "shitsukan/image/png16.hpp"
#include "shitsukan/image/svg_canvas.hpp"
#include "preview.hpp"
#include "shitsukan/leather/leather_looks.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/tileable.hpp"

namespace shitsukan::cli {
namespace {

// "r0,z0,r1,z1,r2,z2,r3,z3;r3,z3,..." -> a chain of cubic segments (tokai1994 eq. (2)).
bool parse_section(const std::string& text, BezierChain* out) {
    BezierChain chain;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t semi = text.find(';', start);
        const std::string seg =
            text.substr(start, semi == std::string::npos ? std::string::npos : semi - start);
        if (chain.count == kMaxChainSegments) return false;
        float v[8];
        std::size_t p = 0;
        for (int k = 0; k < 8; ++k) {
            const std::size_t comma = seg.find(',', p);
            if ((k < 7) == (comma == std::string::npos)) return false;
            const std::string num = seg.substr(p, comma == std::string::npos ? std::string::npos
                                                                             : comma - p);
            double d;
            if (!parse_double(num.c_str(), &d)) return false;
            v[k] = float(d);
            p = comma + 1;
        }
        for (int k = 0; k < 4; ++k) chain.segments[chain.count].p[k] = Vec2{v[2 * k], v[2 * k + 1]};
        ++chain.count;
        if (semi == std::string::npos) break;
        start = semi + 1;
    }
    *out = chain;
    return chain.count > 0;
}

// One part [lo, hi] of the command's progress line.
struct PartProgress {
    Progress whole;
    float lo, hi;
    static void show(float fraction, void* user) {
        const PartProgress* p = static_cast<const PartProgress*>(user);
        p->whole.report(p->lo + (p->hi - p->lo) * fraction);
    }
    Progress part() { return whole.fn ? Progress{show, this} : Progress{}; }
};

// The scale pattern of the chosen layout: the belly (figs. 4-7) or a fig. 3 lattice (one
// Voronoi stage, seeds moved along x and y), plain or tileable (tileable.hpp).
Status make_pattern(const ScaleParams& prm, int layout, bool tileable, ScalePattern* pattern,
                    std::string* note, Progress progress) {
    if (tileable) {
        TileParams tp;
        tp.layout = layout == 0 ? TileLayout::belly
                                : (layout == 1 ? TileLayout::square_lattice
                                               : TileLayout::triangular_lattice);
        tp.scales = prm;
        TileReport rep;
        SHITSUKAN_TRY(generate_tileable_pattern(tp, *pattern, &rep, progress));
        char buf[160];
        std::snprintf(buf, sizeof buf, "; tileable: %s, spacing %.5g x %.5g (%d rows)",
                      "along x and y", double(rep.Dx), double(rep.Dy),
                      rep.rows);
        *note = buf;
        return Status::success();
    }
    if (layout == 0) return generate_scale_pattern(prm, *pattern, nullptr, progress);
    SeedLayout seeds;
    if (layout == 1)
        SHITSUKAN_TRY(square_lattice_seeds(prm.width, prm.height, prm.D, prm.a, prm.seed, seeds));
    else
        SHITSUKAN_TRY(
            triangular_lattice_seeds(prm.width, prm.height, prm.D, prm.a, prm.seed, seeds));
    PlanarSubdivision sub;
    SHITSUKAN_TRY(divide_single_stage(seeds.moved.data(), int(seeds.moved.size()), prm.width,
                                      prm.height, sub));
    return perturb_subdivision(sub, prm.perturbation, prm.seed, prm.width, prm.height, *pattern);
}


struct LeatherRun {
    ScaleParams prm;
    ReliefOptions relief;
    int section = 0, size = 1024, mesh_step = 0, layout = 0;
    bool tileable = false;
    MapFlags maps;
    std::string control, look_text, preview;
    BezierChain chain;
    Vec3 crevice{96, 72, 44}, top{214, 190, 146};  // the belly look's colours (leather_looks)
};

const char* kLeatherAbout =
    "tokai1994 §3.1: the crocodile-belly scale pattern, a two-stage Voronoi division\n"
    "(stage 1 vertical, stage 2 horizontal inside each stage-1 polygon) and the edge\n"
    "perturbation (processing 4); §3.2: each scale's relief from a Bezier cross-section\n"
    "z(r) (eqs. (2)-(4), Table 1). Writes the map set (docs/TOOL.md): <o>_albedo.png (the look's\n"
    "crevice and crown colours mixed by the height), <o>_height16.png, <o>_height.exr,\n"
    "<o>_normal.png (OpenGL, green = +y; --normal directx), <o>_roughness.png, <o>_ao.png, and\n"
    "<o>_pattern.svg; on request <o>_relief.obj. Pattern units: the region is W x H.\n"
    "--layout square|triangular: fig. 3's lattices (one Voronoi stage) instead of the belly.\n"
    "--tileable: the maps repeat with no seam (a periodic Voronoi division on a torus,\n"
    "the same perturbation on both sides of each seam; not in the paper). Every layout\n"
    "tiles along x and y (D is rounded so whole columns and rows fit the tile); the belly's\n"
    "tile edge is a joint like its centre line: the narrow flank scales of one tile meet\n"
    "those of the next (fig. 6's size gradient, mirrored).\n"
    "--strength: unless given, the relief's true scale (heights in pattern units over the\n"
    "pixel size).";

void add_leather_flags(FlagSet& f, LeatherRun& r) {
    f.text("look", &r.look_text, "a named look: crocodile-belly|crocodile-back (flags given "
                                 "beside it win)");
    f.number("W", &r.prm.width, 0.01, 100, "§3.1: width of the pattern region");
    f.number("H", &r.prm.height, 0.01, 100, "§3.1: height of the pattern region");
    f.number("D", &r.prm.D, 0.001, 10, "§3.1 (1): seed spacing D (chosen: 10 rows a unit)");
    f.number("d", &r.prm.d, 0, 10, "§3.1 (1): stage-1 rows' distance d from the centre (fig. 7: D)");
    f.number("a", &r.prm.a, 0, 1, "§3.1 processing 2: random move a of the seeds (fig. 7)");
    f.number("edge-ratio", &r.prm.edge_ratio, 0.051, 1,
             "§3.1 (2): stage-2 spacing at the edges / D (chosen)");
    f.number("p", &r.prm.perturbation.p, 0, 1,
             "§3.1 processing 4: perturbation amplitude p (fig. 7)");
    f.integer("levels", &r.prm.perturbation.levels, 0, kMaxPerturbationLevels,
              "§3.1 processing 4: recursion levels of the perturbation (chosen)");
    f.seed(&r.prm.seed, "seed moves and perturbation (chosen 1)");
    f.choice("section", &r.section, "convex|concave|two_segment",
             "§3.2 Table 1 cross-section: figs. 13(a), 14(a), 15(a)");
    f.choice("layout", &r.layout, "belly|square|triangular",
             "§3.1: figs. 4-7's two-stage belly, or fig. 3's square / triangular lattice");
    f.toggle("tileable", &r.tileable, "seamless tiles along x and y");
    f.text("control", &r.control,
           "your own section: r0,z0,r1,z1,r2,z2,r3,z3[;next segment] (eq. (2) control points)");
    f.number("edge-r", &r.relief.edge_r, 0.01, 10, "§3.2: r at the scale's edge (chosen 1)");
    f.number("height-scale", &r.relief.height_scale, 0.001, 1000, "§3.2: heights times this");
    // 8192 at most: the maps are held whole (make_leather_maps: 20 bytes a pixel, labels,
    // heights and normals), so 16384 x 16384 needs 5.4 GB, over the default memory budget of
    // 4 GiB, and was refused after being offered; 8192 needs 1.3 GB plus 0.6 GB of PNG rows.
    f.integer("size", &r.size, 8, 8192, "map side in pixels (W x H mapped to size x size·H/W)");
    add_map_flags(f, r.maps);
    f.text("preview", &r.preview, "also the map set on a lit sphere and plane, one PNG");
    f.integer("obj-step", &r.mesh_step, 0, 4096,
              "also <o>_relief.obj, one vertex every this many pixels (0 = no OBJ)");
}

// The look's values for every flag not given beside it; then the section.
int settle_leather(const FlagSet& f, LeatherRun& r) {
    if (!r.look_text.empty()) {
        const LeatherLook* look = find_leather_look(r.look_text.c_str());
        if (look == nullptr)
            return f.fail("--look must be one of %s (got \"%s\")", leather_look_names(),
                          r.look_text.c_str());
        if (!f.given("layout")) r.layout = look->layout;
        if (!f.given("section")) r.section = int(look->section);
        if (!f.given("D")) r.prm.D = look->D;
        if (!f.given("d")) r.prm.d = look->d;
        if (!f.given("a")) r.prm.a = look->a;
        if (!f.given("p")) r.prm.perturbation.p = look->p;
        r.crevice = look->crevice, r.top = look->top;
    }
    r.chain = table1_section(Table1Section(r.section));
    if (!r.control.empty()) {
        if (f.given("section")) return f.fail("--control and --section: give one of them");
        if (!parse_section(r.control, &r.chain))
            return f.fail("--control must be 8 numbers r0,z0,...,r3,z3 per segment, segments "
                          "separated by ';', at most %d (got \"%s\")",
                          kMaxChainSegments, r.control.c_str());
        Status s = validate_section(r.chain);
        if (!s) return f.fail("--control: %s", s.message());
    }
    if (int e = check_map_flags(f, r.maps)) return e;
    if (!r.preview.empty())
        if (int e = f.check_output("preview", r.preview, ".png")) return e;
    const Status s = check_scale_params(r.prm);
    return s ? 0 : f.fail_status(s);
}

// The pattern as vector outlines (pattern y up = SVG y down, flipped), 512 px wide.
Status write_pattern_svg(const std::string& path, const ScalePattern& pattern,
                         const ScaleParams& prm) {
    const float px = 512.0f / prm.width;
    SvgCanvas svg_canvas(512, int(prm.height * px + 0.5f), Rgb8{255, 255, 255});
    for (int i = 0; i < pattern.polygon_count(); ++i) {
        int n = 0;
        const Vec2* poly = pattern.polygon(i, &n);
        std::vector<Vec2> pts;
        for (int k = 0; k < n; ++k) pts.push_back({poly[k].x * px, (prm.height - poly[k].y) * px});
        svg_canvas.polygon_outline(pts.data(), n, Rgb8{40, 30, 20}, 1.0f);
    }
    return svg_canvas.save(path);
}

// The map set: heights with the image's rows (top row = largest y), the albedo from them.
int write_leather_maps(const FlagSet& f, const LeatherRun& r, const LeatherMaps& maps,
                       std::vector<std::string>& written) {
    const int w = maps.width, h = maps.height;
    std::vector<float> top(maps.heights.size());
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) top[std::size_t(j) * w + i] = maps.at_height(i, h - 1 - j);
    std::vector<float> h01;
    Status s = normalise_heights(top.data(), w, h, h01);
    if (!s) return f.fail_status(s);
    std::vector<Rgb8> albedo(h01.size());
    for (std::size_t i = 0; i < h01.size(); ++i) {
        const Vec3 c = r.crevice + (r.top - r.crevice) * std::sqrt(h01[i]);
        albedo[i] = Rgb8{std::uint8_t(c.x + 0.5f), std::uint8_t(c.y + 0.5f),
                         std::uint8_t(c.z + 0.5f)};
    }
    MapSetOptions options = map_set_options(r.maps, r.tileable);
    if (!f.given("strength")) {  // the true scale: pattern units of height over the pixel size
        float lo = top[0], hi = top[0];
        for (float v : top) lo = std::min(lo, v), hi = std::max(hi, v);
        options.strength = (hi - lo) * float(w) / r.prm.width;
    }
    const MapSetInput input{albedo.data(), top.data(), w, h};
    if (int e = write_maps(f, r.maps, input, options, &written)) return e;
    if (!r.preview.empty()) {
        if (!(s = write_map_preview(r.preview.c_str(), input, options))) return f.fail_status(s);
        written.push_back(r.preview);
    }
    return 0;
}

}  // namespace

int run_leather(int argc, char** argv) {
    LeatherRun r;
    r.maps.prefix = "leather";
    FlagSet f("leather", kLeatherAbout, "shitsukan leather [flags] [-o prefix]");
    add_leather_flags(f, r);
    const int rc = f.parse(argc, argv);
    if (rc != kParsed) return rc;
    if (int e = settle_leather(f, r)) return e;

    Progress progress = f.progress("pattern and maps");
    progress.report(0.0f);
    ScalePattern pattern;
    std::string note;
    PartProgress pattern_part{progress, 0.0f, 0.2f};  // chosen: shares of a 2048 run's time
    Status s = make_pattern(r.prm, r.layout, r.tileable, &pattern, &note, pattern_part.part());
    if (!s) return f.fail_status(s);
    const int w = r.size, h = std::max(1, int(float(r.size) * r.prm.height / r.prm.width + 0.5f));
    LeatherMaps maps;
    PartProgress maps_part{progress, 0.2f, 0.8f};
    if (!(s = make_leather_maps(pattern, w, h, r.chain, r.relief, maps, maps_part.part())))
        return f.fail_status(s);
    OutputSet files;  // every file of the run appears, or none (core/output_file.hpp)
    std::vector<std::string> written;
    if (int e = write_leather_maps(f, r, maps, written)) return e;
    progress.report(0.9f);
    if (!(s = write_pattern_svg(r.maps.prefix + "_pattern.svg", pattern, r.prm)))
        return f.fail_status(s);
    written.push_back(r.maps.prefix + "_pattern.svg");
    if (r.mesh_step > 0) {
        TriangleMesh mesh;
        if (!(s = make_relief_mesh(maps, r.mesh_step, 1.0f, mesh))) return f.fail_status(s);
        if (!(s = write_obj((r.maps.prefix + "_relief.obj").c_str(), mesh))) return f.fail_status(s);
        written.push_back(r.maps.prefix + "_relief.obj");
    }
    if (!(s = files.commit())) return f.fail_status(s);
    progress.report(1.0f);
    std::string list;
    for (const std::string& name : written) list += (list.empty() ? "" : ", ") + name;
    std::fprintf(stderr, "shitsukan leather: %d scales; wrote %s (%d x %d; height unit = %.3g "
                 "pattern units)%s\n", pattern.polygon_count(), list.c_str(), w, h,
                 double(maps.max_height) / 65535.0, note.c_str());
    return 0;
}

}  // namespace shitsukan::cli
