// ports/web/api/api_okada1987.cpp — the C API of the okada1987 panels: the lattice level by
// level (§2, figs. 1-2, eqs. (1)-(5)), D(P) on a slice (eq. (6)), marble (eqs. (8), (9),
// (12)), wood (eqs. (10), (11)), the forward mapping of §3.2 beside okada1989's backward
// one, and the objects of figs. 10a and 13 drawn by the library's rasterizer.
// Each function calls the public library and copies what it returns into the buffers of
// api_common.hpp; the return value is the library's StatusCode (0 = ok).
#include <cmath>
#include <cstdio>
#include <vector>

#include "api_common.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/image/colormap.hpp"
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/render/solid_bake.hpp"
#include "shitsukan/render/solid_mesh.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"
#include "shitsukan/solid/pixel_shift.hpp"
#include "shitsukan/solid/quadtree_lattice.hpp"
#include "shitsukan/solid/turbulence.hpp"

using namespace shitsukan;

namespace {

FractalLattice g_lattice;                      // the lattice every slice and object uses
MarbleStripe g_stripes[kOkada1987StripeCount];  // okada1987's six stripes, editable
bool g_stripes_set = false;

const MarbleStripe* stripes() {
    if (!g_stripes_set) {
        for (int i = 0; i < kOkada1987StripeCount; ++i) g_stripes[i] = kOkada1987Stripes[i];
        g_stripes_set = true;
    }
    return g_stripes;
}

SolidMaterial marble(float k) {
    SolidMaterial m = okada1987_marble(k);
    m.marble.stripes = stripes();
    return m;
}

Status need_lattice() {
    if (g_lattice.empty())
        return Status::error(StatusCode::invalid_argument,
                             "no lattice yet: call sk_okada1987_build (FractalLattice::build) first");
    return Status::success();
}

// Which rule of okada1987 §2.2 set node (x, y, z) at level n (h = 2^(R-n) the new spacing):
// 0 = an older node, 1 = eq. (1) edge midpoint, 2 = eq. (3) face centre, 3 = eq. (4) cube
// centre — the number of coordinates that are odd multiples of h (fractal_lattice.hpp's
// "which axes are odd"). 2D (z = 0): 1 = edge midpoint, 2 = square centre.
int rule_of(int x, int y, int z, int R, int n) {
    const int h = 1 << (R - n);
    if (x % h || y % h || z % h) return -1;  // not defined yet
    return ((x / h) & 1) + ((y / h) & 1) + ((z / h) & 1);
}

const Rgb8 kRuleColor[4] = {{200, 200, 200}, {52, 101, 164}, {245, 121, 0}, {204, 0, 0}};

// Two panels side by side, each size x size: the values (diverging map over [-range, range],
// each node drawn as the square nearest to it, nodes not yet set light grey) and the rule
// that set each node at level n, on the same squares.
template <class Value, class Rule>
void draw_levels(int size, int side, int spacing, float range, Value value, Rule rule, RgbImage& out) {
    out.resize(2 * size + 8, size, Rgb8{255, 255, 255});
    const float cells = float(side - 1);
    for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px) {
            const float u = (float(px) + 0.5f) / float(size), v = 1.0f - (float(py) + 0.5f) / float(size);
            // values: the node of the current spacing nearest to the pixel (fig. 1's squares)
            const int i = int(std::lround(u * cells / float(spacing))) * spacing;
            const int j = int(std::lround(v * cells / float(spacing))) * spacing;
            const float val = value(i, j);
            out.view().at(px, py) = std::isnan(val) ? Rgb8{236, 236, 236}
                                                    : colormap(ColorMap::diverging, 0.5f + 0.5f * val / range);
            // rules: the same node's (each node of the level a square, as fig. 1 draws them)
            const int r = rule(i, j);
            out.view().at(size + 8 + px, py) = r < 0 ? Rgb8{250, 250, 250} : kRuleColor[r];
        }
}

}  // namespace

// okada1987 §2.1, fig. 1: the 2D quadtree after levels 1..level. Picture: heights | rule of
// each node at this level (older grey, edge midpoints blue, square centres orange).
// Floats: the (2^R + 1)^2 heights (NaN not yet set). Text: side and L^(level).
SK_API int sk_okada1987_quadtree_level(int R, float beta, unsigned seed, int level, int size) {
    QuadtreeParams q;
    q.R = R;
    q.beta = beta;
    q.seed = seed;
    Status s = validate_fractal_levels("quadtree lattice", R, kQuadtreeMaxDepth, beta, q.corners, 4);
    if (s && (level < 0 || level > R))
        s = Status::error(StatusCode::invalid_argument, "level must be in 0..R = %d (got %d)", R, level);
    if (s && (size < 16 || size > 2048))
        s = Status::error(StatusCode::invalid_argument, "size must be in 16..2048 (got %d)", size);
    if (!s) return skweb::finish(s);
    const int side = int(lattice_side(R));
    std::vector<float>& h = skweb::floats();
    h.assign(std::size_t(side) * std::size_t(side), 0.0f);
    int built_side = 0;
    s = build_quadtree_lattice(q, h.data(), h.size() * sizeof(float), built_side, level);
    if (!s) return skweb::finish(s);
    skweb::set_float_columns(side);
    RgbImage img;
    draw_levels(
        size, side, 1 << (R - level), 1.5f, [&](int i, int j) { return h[std::size_t(j) * std::size_t(side) + std::size_t(i)]; },
        [&](int i, int j) { return level == 0 ? 0 : rule_of(i, j, 0, R, level); }, img);
    skweb::set_picture(img);
    char buf[96];
    std::snprintf(buf, sizeof buf, "{\"side\":%d,\"level\":%d,\"amplitude\":%.9g}", side, level,
                  level > 0 ? double(level_amplitude(level, beta)) : 0.0);
    skweb::text() = buf;
    return skweb::finish(Status::success());
}

// okada1987 §2.2, fig. 2: the 3D lattice after levels 1..level, its plane z = z_plane.
// Picture: values | rule (eq. (1) blue, eq. (3) orange, eq. (4) red, older grey). Floats: the
// plane's values. Text: eq. (5)'s amplitude L^(n) for n = 1..R and the nodes each rule added
// at this level in the whole lattice.
SK_API int sk_okada1987_lattice_level(int R, float beta, unsigned seed, int level, int z_plane,
                                      int size) {
    FractalParams p;
    p.R = R;
    p.beta = beta;
    p.seed = seed;
    Status s = validate_fractal_params(p, kTypeIMaxDepth);
    if (s) s = check_memory_budget(lattice_bytes(R), "the Type I lattice of the level view");
    if (s && (level < 0 || level > R))
        s = Status::error(StatusCode::invalid_argument, "level must be in 0..R = %d (got %d)", R, level);
    if (s && (z_plane < 0 || z_plane > (1 << R)))
        s = Status::error(StatusCode::out_of_range, "plane z must be in 0..2^R = %d (got %d)", 1 << R, z_plane);
    if (s && (size < 16 || size > 2048))
        s = Status::error(StatusCode::invalid_argument, "size must be in 16..2048 (got %d)", size);
    if (!s) return skweb::finish(s);
    std::vector<float> values(std::size_t(lattice_bytes(R) / sizeof(float)));
    LatticeView view;
    s = build_fractal_lattice(p, values.data(), values.size() * sizeof(float), view, level);
    if (!s) return skweb::finish(s);
    const int side = view.side;
    std::vector<float>& plane = skweb::floats();
    plane.resize(std::size_t(side) * std::size_t(side));
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) plane[std::size_t(j) * std::size_t(side) + std::size_t(i)] = view.at(i, j, z_plane);
    skweb::set_float_columns(side);
    RgbImage img;
    draw_levels(
        size, side, 1 << (R - level), 1.5f, [&](int i, int j) { return view.at(i, j, z_plane); },
        [&](int i, int j) { return level == 0 ? 0 : rule_of(i, j, z_plane, R, level); }, img);
    skweb::set_picture(img);
    long added[4] = {0, 0, 0, 0};
    if (level > 0)
        for (int z = 0; z < side; ++z)
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x) {
                    const int r = rule_of(x, y, z, R, level);
                    if (r > 0) ++added[r];
                }
    std::string& t = skweb::text();
    char buf[160];
    std::snprintf(buf, sizeof buf, "{\"side\":%d,\"level\":%d,\"edge\":%ld,\"face\":%ld,\"centre\":%ld,\"amplitude\":[",
                  side, level, added[1], added[2], added[3]);
    t = buf;
    for (int n = 1; n <= R; ++n) {
        std::snprintf(buf, sizeof buf, "%s%.9g", n > 1 ? "," : "", double(level_amplitude(n, beta)));
        t += buf;
    }
    t += "]}";
    return skweb::finish(Status::success());
}

// Builds the lattice the slices and objects use (FractalLattice::build, its own budget).
SK_API int sk_okada1987_build(int R, float beta, unsigned seed) {
    FractalParams p = okada1987_lattice_params();
    p.R = R;
    p.beta = beta;
    p.seed = seed;
    Status s = validate_fractal_params(p, kTypeIMaxDepth);
    if (s) s = g_lattice.build(p);
    if (!s) g_lattice = FractalLattice();
    return skweb::finish(s);
}

// One of marble's stripes (c, w, alpha of eq. (8)); index -1 restores the six presets.
SK_API int sk_okada1987_set_stripe(int index, float c, float w, float alpha) {
    stripes();
    if (index == -1) {
        g_stripes_set = false;
        stripes();
        return skweb::finish(Status::success());
    }
    if (index < 0 || index >= kOkada1987StripeCount)
        return skweb::finish(Status::error(StatusCode::invalid_argument, "stripe index must be in 0..%d (got %d)",
                                           kOkada1987StripeCount - 1, index));
    const MarbleStripe stripe{c, w, alpha};
    Status s = validate_marble_stripe(stripe);
    if (s) g_stripes[index] = stripe;
    return skweb::finish(s);
}

// The current stripes (c, w, alpha) x 6 as floats: okada1987_presets' six until changed.
SK_API int sk_okada1987_get_stripes() {
    std::vector<float>& f = skweb::floats();
    f.clear();
    for (int i = 0; i < kOkada1987StripeCount; ++i) {
        f.push_back(stripes()[i].c);
        f.push_back(stripes()[i].w);
        f.push_back(stripes()[i].alpha);
    }
    skweb::set_float_columns(3);
    return skweb::finish(Status::success());
}

// eq. (8): G(z) of the current stripes at n samples over z in [0, 2^R]. Floats: G.
SK_API int sk_okada1987_marble_profile(int n) {
    if (n < 2 || n > 4096)
        return skweb::finish(Status::error(StatusCode::invalid_argument, "samples must be in 2..4096 (got %d)", n));
    const float top = g_lattice.empty() ? 64.0f : float(g_lattice.view().side - 1);
    std::vector<float>& g = skweb::floats();
    g.resize(std::size_t(n));
    for (int i = 0; i < n; ++i)
        g[std::size_t(i)] = marble_original(top * float(i) / float(n - 1), stripes(), kOkada1987StripeCount);
    skweb::set_float_columns(n);
    return skweb::finish(Status::success());
}

namespace {
SolidSlice vertical_slice(float y) {
    SolidSlice slice;  // x right, z up (okada1987's layers run along z)
    slice.origin = Vec3{0.0f, y, 0.0f};
    slice.extent = float(g_lattice.view().side - 1);
    return slice;
}

int slice_picture(const SolidMaterial& material, const SolidSlice& slice, int size) {
    RgbImage img;
    FloatImage density;
    Status s = render_solid_slice(g_lattice.view(), material, slice, size, size, img, &density,
                                  skweb::progress());
    if (!s) return skweb::finish(s);
    skweb::set_picture(img);
    skweb::floats().assign(density.data(), density.data() + std::size_t(size) * std::size_t(size));
    skweb::set_float_columns(size);
    return skweb::finish(s);
}
}  // namespace

// eq. (6): D(P) on the plane y (x right, z up), size x size pixels (pixel centres, as
// render_solid_slice). Picture: diverging map over [-range, range]. Floats: D.
SK_API int sk_okada1987_turbulence_slice(float y, int size, float range) {
    Status s = need_lattice();
    if (s && (size < 1 || size > 4096))
        s = Status::error(StatusCode::invalid_argument, "size must be in 1..4096 (got %d)", size);
    if (s && !(range > 0.0f))
        s = Status::error(StatusCode::invalid_argument, "range must be > 0 (got %g)", double(range));
    const float top = s ? float(g_lattice.view().side - 1) : 0.0f;
    if (s) s = check_lattice_point(Vec3{0.0f, y, 0.0f}, g_lattice.params().R);
    if (!s) return skweb::finish(s);
    const float step = top / float(size);
    std::vector<float>& d = skweb::floats();
    d.resize(std::size_t(size) * std::size_t(size));
    RgbImage img(size, size);
    for (int j = 0; j < size; ++j) {
        const float z = (float(size - 1 - j) + 0.5f) * step;
        float* row = d.data() + std::size_t(j) * std::size_t(size);
        turbulence_row(g_lattice.view(), Vec3{0.5f * step, y, z}, step, size, row);
        for (int i = 0; i < size; ++i) img.view().at(i, j) = colormap(ColorMap::diverging, 0.5f + 0.5f * row[i] / range);
    }
    skweb::set_float_columns(size);
    skweb::set_picture(img);
    return skweb::finish(s);
}

// okada1987 §4.1: the marble texture on the plane y (x right, z up): eq. (9)'s shift k·D(P)
// along z, eq. (8)'s stripes, eq. (12)'s colours. Floats: the density G'.
SK_API int sk_okada1987_marble_slice(float k, float y, int size) {
    Status s = need_lattice();
    if (!s) return skweb::finish(s);
    return slice_picture(marble(k), vertical_slice(y), size);
}

// okada1987 §4.2: the wood texture on the plane z (x right, y up): rings about the axis
// (x0, y0) every 2·pi/k2, shifted radially by k·D(P) (eq. (11)).
SK_API int sk_okada1987_wood_slice(float k, float k2, float x0, float y0, float z, int size) {
    Status s = need_lattice();
    if (!s) return skweb::finish(s);
    SolidMaterial m = okada1987_wood(k);
    m.wood.k2 = k2;
    m.wood.x0 = x0;
    m.wood.y0 = y0;
    SolidSlice slice;
    slice.origin = Vec3{0.0f, 0.0f, z};
    slice.u = Vec3{1, 0, 0};
    slice.v = Vec3{0, 1, 0};
    slice.extent = float(g_lattice.view().side - 1);
    return slice_picture(m, slice, size);
}

// okada1987 §3.2 read forwards beside okada1989 §4-1's backward (pixel shift) mapping, on
// the marble of the plane y. backward (forward = 0): pixel P shows G(P') with
// P' = pixel_shift(P, k, D(P), (0, 0, 1)) — render_solid_slice. forward (forward = 1): the
// value G(P) of pixel P "is observed at" P' (§3.2's wording), so it is written to the pixel
// holding P'; pixels nothing lands on stay black (holes), later writes win. Floats: per pixel
// how many values landed there (forward) or 1 (backward).
SK_API int sk_okada1987_mapping(float k, float y, int size, int forward) {
    Status s = need_lattice();
    if (!s) return skweb::finish(s);
    if (!forward) {
        const int code = slice_picture(marble(k), vertical_slice(y), size);
        if (code == 0) skweb::floats().assign(std::size_t(size) * std::size_t(size), 1.0f);
        return code;
    }
    if (size < 1 || size > 4096)
        return skweb::finish(Status::error(StatusCode::invalid_argument, "size must be in 1..4096 (got %d)", size));
    const SolidMaterial original = marble(0.0f);  // G(P) itself (no shift)
    s = validate_solid_material(marble(k));
    if (!s) return skweb::finish(s);
    const float top = float(g_lattice.view().side - 1), step = top / float(size);
    RgbImage img(size, size, Rgb8{0, 0, 0});
    std::vector<float>& hits = skweb::floats();
    hits.assign(std::size_t(size) * std::size_t(size), 0.0f);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const Vec3 p{(float(i) + 0.5f) * step, y, (float(size - 1 - j) + 0.5f) * step};
            const Vec3 q = pixel_shift(p, k, turbulence(g_lattice.view(), p), Vec3{0, 0, 1});
            const float jt = float(size) - q.z / step;  // the row holding P'
            if (!(jt >= 0.0f && jt < float(size))) continue;
            const int jq = int(jt);
            const Vec3 c = solid_density_color(original, solid_density_at(original, p, 0.0f));
            img.view().at(i, jq) = Rgb8{std::uint8_t(std::lround(c.x)), std::uint8_t(std::lround(c.y)),
                                     std::uint8_t(std::lround(c.z))};
            hits[std::size_t(jq) * std::size_t(size) + std::size_t(i)] += 1.0f;
        }
    skweb::set_picture(img);
    skweb::set_float_columns(size);
    return skweb::finish(s);
}

// Figs. 10a (scene 0: the cube) and 13 (scene 1: the sphere with an octant cut away), marble
// (material 0) or wood (1), turned by yaw and pitch (radians; the object turns, its texture
// with it), drawn by render_solid_texture (the scanline rasterizer) at size x size.
SK_API int sk_okada1987_object(int scene, int material, float k, float yaw, float pitch, int size) {
    Status s = need_lattice();
    if (s && (scene < 0 || scene > 1))
        s = Status::error(StatusCode::invalid_argument, "scene must be 0 (cube) or 1 (cut sphere) (got %d)", scene);
    if (s && (material < 0 || material > 1))
        s = Status::error(StatusCode::invalid_argument, "material must be 0 (marble) or 1 (wood) (got %d)", material);
    if (!s) return skweb::finish(s);
    static TriangleMesh meshes[2];
    TriangleMesh& mesh = meshes[scene];
    if (mesh.positions.empty()) {
        s = scene == 0 ? make_box({-0.9f, -0.9f, -0.9f}, {0.9f, 0.9f, 0.9f}, mesh)
                       : make_sphere_without_octant(0.9f, 40, mesh);
        if (!s) return skweb::finish(s);
    }
    // The figures' eyes (paper_figures/okada1987/okada_common.cpp: cube (3.6, 3.0, 4.6), cut
    // sphere (2.7, 2.3, 3.1)), 30 degrees.
    const Vec3 eye = scene == 0 ? Vec3{3.6f, 3.0f, 4.6f} : Vec3{2.7f, 2.3f, 3.1f};
    Camera cam;
    s = make_perspective_camera(eye, Vec3{0, 0, 0}, Vec3{0, 1, 0}, 30.0f, size, size, 0.05f, 100.0f, cam);
    if (!s) return skweb::finish(s);
    DrawOptions opt;
    opt.model = Mat4::rotate_x(pitch) * Mat4::rotate_y(yaw);
    const SolidMaterial m = material == 0 ? marble(k) : okada1987_wood(k);
    RgbImage img;
    s = render_solid_texture(cam, mesh.view(), g_lattice.view(), m, img, SolidShading{},
                             Rgb8{24, 26, 32}, opt);
    if (!s) return skweb::finish(s);
    skweb::set_picture(img);
    skweb::floats().clear();
    return skweb::finish(s);
}
