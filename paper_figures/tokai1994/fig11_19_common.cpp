#include "tokai1994/fig11_19_common.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/scale_labels.hpp"
#include "shitsukan/leather/seed_layout.hpp"
#include "shitsukan/raster/bump_mapping.hpp"
#include "shitsukan/render/leather_mesh.hpp"

namespace shitsukan::figures::tokai_relief {

// The materials, lights and gamma are the library's (render/leather_mesh.hpp, chosen there).
Blinn1977Material leather_material() { return tokai1994_leather_material(); }
Blinn1977Material metal_material() { return tokai1994_metal_material(); }
Blinn1977Material suede_material() { return tokai1994_suede_material(); }

void record_shading(FigureContext& ctx) {
    ctx.given("reflection model", "Blinn 1977", "tokai1994 §5, ref. 20");
    ctx.chosen("Blinn 1977 distribution", "D3 (Trowbridge-Reitz), with G and Fresnel F",
               "Blinn's best fit to measured data; the paper does not say which of D1-D3");
    Blinn1977Material l = leather_material(), m = metal_material();
    ctx.chosen("leather",
               fmt("colour (%.2f, %.2f, %.2f), Ka %.2f, Kd %.2f, Ks %.2f, c3 %.2f, n %.1f",
                   double(l.color.x), double(l.color.y), double(l.color.z), double(l.ka),
                   double(l.kd), double(l.ks), double(l.c3), double(l.refractive_index)),
               "paper: 'reflection parameters found by trial and error' (not printed)");
    ctx.chosen("clasp metal",
               fmt("colour (%.2f, %.2f, %.2f), Ka %.2f, Kd %.2f, Ks %.2f, c3 %.2f, n %.1f",
                   double(m.color.x), double(m.color.y), double(m.color.z), double(m.ka),
                   double(m.kd), double(m.ks), double(m.c3), double(m.refractive_index)),
               "brass-like; not printed");
    ctx.given("lights", "2 point lights, Z-buffer, no shadows, no anti-aliasing", "tokai1994 §5");
    ctx.chosen("light placement",
               "key light high at the upper left, fill light (about 1/3) low at the right; flat "
               "textures: placed relative to the window; objects: (-3.5, 4, 3.5), (4.5, 1, 1.5)",
               "positions not printed");
    ctx.chosen("display gamma", "1/2.2", "the model's output is linear");
}

void record_relief(FigureContext& ctx) {
    ctx.chosen("edge_r", "1: r is the relative distance |x - m| / |p - m|",
               "README reading; the section ends before the edge, leaving a groove floor");
    ctx.chosen("height unit", "S = 2·area/perimeter per scale", "flat sections stay flat");
    ctx.chosen("normals", "eq. (4), (n_x, n_y) along p - m", "the paper's rule");
}

Rgb8 to_display(Vec3 c) { return to_display_gamma(c); }

Status crocodile_pattern(FigureContext& ctx, ScalePattern* out) {
    ScaleParams prm;  // the fig. 7 defaults of the scale-pattern module
    ctx.given(
        "pattern",
        fmt("fig. 7: d = 1.0 D, a = %.2f, p = %.3f", double(prm.a), double(prm.perturbation.p)),
        "tokai1994 §3.1 (the parameters used for the rest of the paper)");
    ctx.chosen("pattern D, seed", fmt("D = %.3f, seed %u", double(prm.D), unsigned(prm.seed)),
               "scale-pattern module defaults (the paper prints no D)");
    return generate_scale_pattern(prm, *out);
}

Status snake_pattern(FigureContext& ctx, float width, float height, ScalePattern* out) {
    // fig. 3(b): triangle-lattice seeds with a small displacement a, one Voronoi division,
    // edges perturbed (a, the random seed and p relative to D as the fig. 3 figure uses:
    // a = 0.1, seed 3, p = 0.015 at D = 0.125).
    const float D = 0.065f, a = 0.1f;
    const std::uint32_t seed = 3;
    ctx.given("belt pattern", "fig. 3(b): triangle lattice + Voronoi division", "tokai1994 §5");
    ctx.chosen("belt pattern D, a, seed",
               fmt("D = %.3f, a = %.2f, seed %u", double(D), double(a), unsigned(seed)),
               "about 6 scales across the belt; a and seed as the fig. 3(b) figure");
    SeedLayout seeds;
    SHITSUKAN_TRY(triangular_lattice_seeds(width, height, D, a, seed, seeds));
    PlanarSubdivision sub;
    SHITSUKAN_TRY(
        divide_single_stage(seeds.moved.data(), int(seeds.moved.size()), width, height, sub));
    PerturbationParams prm;
    prm.p = 0.015f * D / 0.125f;  // fig. 3(b)'s perturbation relative to its spacing
    return perturb_subdivision(sub, prm, seed, width, height, *out);
}

Status leather_maps(const ScalePattern& pattern, int w, int h, const BezierChain& section,
                    const ReliefOptions& options, LeatherMaps* out) {
    return make_leather_maps(pattern, w, h, section, options, *out);  // the library's one call
}

void flat_texture_lights(Vec2 lo, Vec2 hi, float key_height, PointLight out[2]) {
    Vec2 size = hi - lo;
    float span = std::fmax(size.x, size.y);
    // Two point lights: a key light high at the upper left, a fill light low at the right
    // (chosen here), at distances proportional to the window so a close-up is lit alike.
    out[0] = {{lo.x - 0.5f * span, hi.y + 0.5f * span, key_height * span}, {1.1f, 1.05f, 1.0f}};
    out[1] = {{hi.x + 0.9f * span, lo.y + 0.1f * span, 0.5f * span}, {0.30f, 0.32f, 0.38f}};
}

void shade_flat_texture(const LeatherMaps& maps, Vec2 lo, Vec2 hi, const RgbView& out,
                        const Blinn1977Material& m, float key_height) {
    Vec2 size = hi - lo;
    float span = std::fmax(size.x, size.y);
    PointLight lights[2];
    flat_texture_lights(lo, hi, key_height, lights);
    for (int j = 0; j < out.height; ++j) {
        Rgb8* row = out.row(j);
        float y = hi.y - (float(j) + 0.5f) / float(out.height) * size.y;
        for (int i = 0; i < out.width; ++i) {
            float x = lo.x + (float(i) + 0.5f) / float(out.width) * size.x;
            Vec3 n = normal_at(maps, {x, y});
            Vec3 p{x, y, height_at(maps, {x, y})};
            Vec3 eye = p + Vec3{0, 0, 10.0f * span};  // seen from straight above
            row[i] = to_display(shade_blinn1977(m, p, n, eye, lights, 2));
        }
    }
}

void scene_lights(PointLight out[2]) { tokai1994_scene_lights(out); }

Rgb8 background_color() { return Rgb8{206, 210, 214}; }

Status compute_texture_tangents(BumpSurface* s) {
    const int n = s->mesh.triangle_count();
    s->dpdx.assign(std::size_t(n), Vec3{});
    s->dpdy.assign(std::size_t(n), Vec3{});
    return mesh_texture_tangents(s->mesh.view(), s->dpdx.data(), s->dpdy.data(), n);
}

Vec3 mirrored_normal(const LeatherMaps& maps, Vec2 t) {
    return mirrored_normal_at(maps, t);  // the library's tiling
}

Rgb8 LeatherShader::operator()(const Fragment& f) const {
    // The library's leather shader (render/leather_mesh.hpp): Blinn 1978 bumps with the
    // mirrored maps, Blinn 1977 light, display gamma.
    const bool bumps = maps != nullptr && surface != nullptr;
    const std::size_t t = std::size_t(f.triangle);
    return shade_leather_fragment(f, camera->eye, front, back, lights, 2, bumps ? maps : nullptr,
                                  bumps ? surface->dpdx[t] : Vec3{},
                                  bumps ? surface->dpdy[t] : Vec3{});
}

void draw_axes(Canvas& c, const PlotFrame& f, Vec2 lo, Vec2 hi, float tick, const char* x_label,
               const char* y_label) {
    const Rgb8 ink{40, 40, 40}, grid{225, 225, 225};
    for (float x = 0.0f; x <= hi.x + 1e-4f; x += tick)
        c.line(f.to_pixel({x, lo.y}), f.to_pixel({x, hi.y}), grid, 1.0f);
    for (float y = 0.0f; y <= hi.y + 1e-4f; y += tick)
        c.line(f.to_pixel({lo.x, y}), f.to_pixel({hi.x, y}), grid, 1.0f);
    c.line(f.to_pixel({lo.x, 0}), f.to_pixel({hi.x, 0}), ink, 1.5f);
    c.line(f.to_pixel({0, lo.y}), f.to_pixel({0, hi.y}), ink, 1.5f);
    for (float x = 0.0f; x <= hi.x + 1e-4f; x += tick) {
        Vec2 p = f.to_pixel({x, 0});
        c.line(p, p + Vec2{0, 5}, ink, 1.0f);
        c.text(p + Vec2{-8, 8}, fmt("%.1f", double(x)), ink, 1);
    }
    for (float y = 0.0f; y <= hi.y + 1e-4f; y += tick) {
        Vec2 p = f.to_pixel({0, y});
        c.line(p, p - Vec2{5, 0}, ink, 1.0f);
        c.text(p + Vec2{-30, -4}, fmt("%.1f", double(y)), ink, 1);
    }
    c.text(f.to_pixel({hi.x, 0}) + Vec2{-6 * float(std::string(x_label).size()), 22}, x_label, ink,
           2);
    c.text(f.to_pixel({0, hi.y}) + Vec2{8, -2}, y_label, ink, 2);
}

}  // namespace shitsukan::figures::tokai_relief
