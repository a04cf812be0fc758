// The unrolled crack map (see bark_crack_map.hpp).
#include "shitsukan/render/bark_crack_map.hpp"

#include <climits>
#include <cstdio>
#include <cmath>
#include <vector>

#include "shitsukan/bark/crack_drawing.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/image/raster_canvas.hpp"

namespace shitsukan {
namespace {

Rgb8 shade(Rgb8 c, float f) {
    auto ch = [f](std::uint8_t v) {
        const float x = float(v) * f;
        return std::uint8_t(x > 255.0f ? 255.0f : x);
    };
    return {ch(c.r), ch(c.g), ch(c.b)};
}

// A shape reaching past the circumference C is drawn again one period to the left, so the map
// tiles around the trunk. (A shape reaching below u = 0 is not copied to the right edge: the
// hirota1998 figures never did, and their bytes are kept; a copy there would change fig05.)
bool beyond_seam(const Vec3* points, int n, float C) {
    for (int k = 0; k < n; ++k)
        if (points[k].x > C) return true;
    return false;
}

}  // namespace

Status draw_crack_map(Canvas& canvas, const BarkCylinder& bark, float t, const Vec3* W,
                      const CrackMapStyle& style) {
    const float C = bark.circumference * (1.0f + hoop_strain(bark.params, t));
    auto to_px = [&](Vec3 p, float shift) {
        return Vec2{style.origin.x + (p.x + shift) * style.px_per_cm,
                    style.origin.y - p.y * style.px_per_cm};
    };
    auto* raster = dynamic_cast<RasterCanvas*>(&canvas);
    if (style.draw_plates) {
        const bool antialias = raster && raster->antialias();
        if (raster) raster->set_antialias(false);  // plates tile exactly; cracks are smoothed
        for (const ConnectionTriangle& tri : bark.triangles) {
            Vec3 x[3];
            for (int k = 0; k < 3; ++k) x[k] = corner_position(bark, tri.corner[k], tri.node[k], t, W);
            Rgb8 colour = style.plate;
            if (style.regions) {
                const std::int32_t label = style.regions->label[tri.node[0]];
                const float f = label < 0 ? 0.8f
                                          : 0.88f + 0.24f * hash_uniform(7, 5, label);  // chosen here
                colour = shade(style.plate, f);
            }
            const bool beyond = beyond_seam(x, 3, C);
            for (float shift : {0.0f, -C}) {
                if (shift != 0.0f && !beyond) continue;
                const Vec2 pts[3] = {to_px(x[0], shift), to_px(x[1], shift), to_px(x[2], shift)};
                canvas.fill_polygon(pts, 3, colour);
            }
        }
        if (raster) raster->set_antialias(antialias);
    }
    std::vector<CrackRibbon> cracks;
    SHITSUKAN_TRY(crack_ribbons(bark, t, W, cracks, style.include_weak));
    for (const CrackRibbon& r : cracks) {
        // A weak axial spring is a one-node-wide sliver between two vertical cracks, not a
        // crack across it: drawn as part of the sliver (chosen here).
        if (r.weak && bark.net.springs[r.spring].family == 1) continue;
        Vec3 quads[2][4];
        ribbon_quads(r, quads, style.min_width_cm);
        const bool beyond = beyond_seam(&quads[0][0], 8, C);
        for (float shift : {0.0f, -C}) {
            if (shift != 0.0f && !beyond) continue;
            for (auto& q : quads) {
                const Vec2 pts[4] = {to_px(q[0], shift), to_px(q[1], shift), to_px(q[2], shift),
                                     to_px(q[3], shift)};
                canvas.fill_polygon(pts, 4, style.crack);
            }
        }
    }
    return Status::success();
}

Status crack_map_size(const BarkCylinder& bark, float t, float px_per_cm, int& width,
                      int& height) {
    if (!(px_per_cm > 0.0f) || !std::isfinite(px_per_cm))
        return Status::error(StatusCode::invalid_argument,
                             "crack_map_size: px_per_cm must be finite and > 0 (got %g)",
                             double(px_per_cm));
    // In double: a float product past 3.4e38 would be inf, and int(ceil(x)) past INT_MAX is
    // undefined.
    const double C = double(bark.circumference) * (1.0 + double(hoop_strain(bark.params, t)));
    const double H =
        double(initial_height(bark.params)) * (1.0 + double(axial_strain(bark.params, t)));
    const double w = std::ceil(C * double(px_per_cm)), h = std::ceil(H * double(px_per_cm));
    if (!std::isfinite(w) || !std::isfinite(h) || w > double(INT_MAX) || h > double(INT_MAX))
        return Status::error(StatusCode::out_of_range,
                             "crack map: the grown trunk (%g x %g cm at t = %g s) is %g x %g "
                             "pixels at %g px/cm, past the largest image side %d",
                             C, H, double(t), w, h, double(px_per_cm), INT_MAX);
    const int wi = w > 8.0 ? int(w) : 8, hi = h > 8.0 ? int(h) : 8;
    char what[96];
    std::snprintf(what, sizeof what, "crack map of %d x %d pixels (the trunk grown to t = %g s)",
                  wi, hi, double(t));
    SHITSUKAN_TRY(check_memory_budget(
        budget_mul(budget_mul(std::uint64_t(wi), std::uint64_t(hi)), 3), what));
    width = wi;
    height = hi;
    return Status::success();
}

}  // namespace shitsukan
