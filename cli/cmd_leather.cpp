// cli/cmd_leather.cpp — `shitsukan leather` (tokai1994 §3.1 scale pattern, §3.2 relief).
#include <algorithm>
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

}  // namespace

int run_leather(int argc, char** argv) {
    ScaleParams prm;
    ReliefOptions relief;
    int section = 0, size = 1024, mesh_step = 0;
    std::string out = "leather", control;
    bool pfm = false, tileable = false;
    int layout = 0;
    FlagSet f("leather",
              "tokai1994 §3.1: the crocodile-belly scale pattern, a two-stage Voronoi division\n"
              "(stage 1 vertical, stage 2 horizontal inside each stage-1 polygon) and the edge\n"
              "perturbation (processing 4); §3.2: each scale's relief from a Bezier cross-section\n"
              "z(r) (eqs. (2)-(4), Table 1). Writes <o>_height16.png (16-bit height), <o>_normal.png\n"
              "(RGB normal map, OpenGL convention, green = +y), <o>_pattern.svg, and on request\n"
              "<o>_height.pfm and <o>_relief.obj. Pattern units: the region is W x H.\n"
              "--layout square|triangular: fig. 3's lattices (one Voronoi stage) instead of the belly.\n"
              "--tileable: the maps repeat with no seam (a periodic Voronoi division on a torus,\n"
              "the same perturbation on both sides of each seam; not in the paper). Every layout\n"
              "tiles along x and y (D is rounded so whole columns and rows fit the tile); the belly's\n"
              "tile edge is a joint like its centre line: the narrow flank scales of one tile meet\n"
              "those of the next (fig. 6's size gradient, mirrored).",
              "shitsukan leather [flags] [-o prefix]");
    f.number("W", &prm.width, 0.01, 100, "§3.1: width of the pattern region");
    f.number("H", &prm.height, 0.01, 100, "§3.1: height of the pattern region");
    f.number("D", &prm.D, 0.001, 10, "§3.1 (1): seed spacing D (chosen: 10 rows a unit)");
    f.number("d", &prm.d, 0, 10, "§3.1 (1): stage-1 rows' distance d from the centre (fig. 7: D)");
    f.number("a", &prm.a, 0, 1, "§3.1 processing 2: random move a of the seeds (fig. 7)");
    f.number("edge-ratio", &prm.edge_ratio, 0.051, 1,
             "§3.1 (2): stage-2 spacing at the edges / D (chosen)");
    f.number("p", &prm.perturbation.p, 0, 1, "§3.1 processing 4: perturbation amplitude p (fig. 7)");
    f.integer("levels", &prm.perturbation.levels, 0, kMaxPerturbationLevels,
              "§3.1 processing 4: recursion levels of the perturbation (chosen)");
    f.seed(&prm.seed, "seed moves and perturbation (chosen 1)");
    f.choice("section", &section, "convex|concave|two_segment",
             "§3.2 Table 1 cross-section: figs. 13(a), 14(a), 15(a)");
    f.choice("layout", &layout, "belly|square|triangular",
             "§3.1: figs. 4-7's two-stage belly, or fig. 3's square / triangular lattice");
    f.toggle("tileable", &tileable,
             "seamless tiles along x and y (see above)");
    f.text("control", &control,
           "your own section: r0,z0,r1,z1,r2,z2,r3,z3[;next segment] (eq. (2) control points)");
    f.number("edge-r", &relief.edge_r, 0.01, 10, "§3.2: r at the scale's edge (chosen 1)");
    f.number("height-scale", &relief.height_scale, 0.001, 1000, "§3.2: heights times this");
    // 8192 at most: the maps are held whole (make_leather_maps: 20 bytes a pixel, labels,
    // heights and normals), so 16384 x 16384 needs 5.4 GB, over the default memory budget of
    // 4 GiB, and was refused after being offered; 8192 needs 1.3 GB plus 0.6 GB of PNG rows.
    f.integer("size", &size, 8, 8192, "map side in pixels (W x H mapped to size x size·H/W)");
    f.text("o", &out, "output prefix");
    f.toggle("pfm", &pfm, "also <o>_height.pfm: the heights as floats (pattern units)");
    f.integer("obj-step", &mesh_step, 0, 4096,
              "also <o>_relief.obj, one vertex every this many pixels (0 = no OBJ)");
    const int rc = f.parse(argc, argv);
    if (rc != kParsed) return rc;
    if (int e = f.check_prefix("o", out)) return e;
    BezierChain chain = table1_section(Table1Section(section));
    if (!control.empty()) {
        if (f.given("section")) return f.fail("--control and --section: give one of them");
        if (!parse_section(control, &chain))
            return f.fail("--control must be 8 numbers r0,z0,...,r3,z3 per segment, segments "
                          "separated by ';', at most %d (got \"%s\")",
                          kMaxChainSegments, control.c_str());
        Status s = validate_section(chain);
        if (!s) return f.fail("--control: %s", s.message());
    }
    Status s = check_scale_params(prm);
    if (!s) return f.fail_status(s);

    Progress progress = f.progress("pattern and maps");
    progress.report(0.0f);
    ScalePattern pattern;
    std::string note;
    PartProgress pattern_part{progress, 0.0f, 0.2f};  // chosen: shares of a 2048 run's time
    if (!(s = make_pattern(prm, layout, tileable, &pattern, &note, pattern_part.part())))
        return f.fail_status(s);
    const int w = size, h = std::max(1, int(float(size) * prm.height / prm.width + 0.5f));
    LeatherMaps maps;
    PartProgress maps_part{progress, 0.2f, 0.8f};
    if (!(s = make_leather_maps(pattern, w, h, chain, relief, maps, maps_part.part())))
        return f.fail_status(s);
    Gray16Image height(w, h);
    encode_height16(maps, height.data());
    const std::string height_path = out + "_height16.png", normal_path = out + "_normal.png";
    OutputSet files;  // every file of the run appears, or none (core/output_file.hpp)
    if (!(s = write_png16(height_path.c_str(), height.view()))) return f.fail_status(s);
    std::vector<std::uint8_t> rgb(3 * std::size_t(w) * std::size_t(h));
    encode_normal_rgb(maps, rgb.data());
    RgbImage normal(w, h);
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i)
        normal.data()[i] = Rgb8{rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]};
    if (!(s = write_png(normal_path.c_str(), normal.view()))) return f.fail_status(s);
    progress.report(0.9f);
    // The pattern as vector outlines (pattern y up = SVG y down, flipped), 512 px wide.
    const float px = 512.0f / prm.width;
    SvgCanvas svg_canvas(512, int(prm.height * px + 0.5f), Rgb8{255, 255, 255});
    for (int i = 0; i < pattern.polygon_count(); ++i) {
        int n = 0;
        const Vec2* poly = pattern.polygon(i, &n);
        std::vector<Vec2> pts;
        for (int k = 0; k < n; ++k) pts.push_back({poly[k].x * px, (prm.height - poly[k].y) * px});
        svg_canvas.polygon_outline(pts.data(), n, Rgb8{40, 30, 20}, 1.0f);
    }
    if (!(s = svg_canvas.save(out + "_pattern.svg"))) return f.fail_status(s);
    if (pfm) {
        // rows flipped to the image convention (top row = largest y), like the PNGs
        std::vector<float> top(maps.heights.size());
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                top[std::size_t(j) * w + i] = maps.at_height(i, h - 1 - j);
        if (!(s = write_pfm((out + "_height.pfm").c_str(), top.data(), w, h, 1)))
            return f.fail_status(s);
    }
    if (mesh_step > 0) {
        TriangleMesh mesh;
        if (!(s = make_relief_mesh(maps, mesh_step, 1.0f, mesh))) return f.fail_status(s);
        if (!(s = write_obj((out + "_relief.obj").c_str(), mesh))) return f.fail_status(s);
    }
    if (!(s = files.commit())) return f.fail_status(s);
    progress.report(1.0f);
    std::fprintf(stderr,
                 "shitsukan leather: %d scales; wrote %s, %s, %s_pattern.svg%s%s (%d x %d; height "
                 "unit = %.3g pattern units)%s\n",
                 pattern.polygon_count(), height_path.c_str(), normal_path.c_str(), out.c_str(),
                 pfm ? ", _height.pfm" : "", mesh_step > 0 ? ", _relief.obj" : "", w, h,
                 double(maps.max_height) / 65535.0, note.c_str());
    return 0;
}

}  // namespace shitsukan::cli
