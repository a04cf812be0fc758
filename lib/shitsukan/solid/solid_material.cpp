// small-device: yes (no allocation, no exceptions)
#include "shitsukan/solid/solid_material.hpp"

#include <cmath>

#include "shitsukan/core/scalar.hpp"
#include "shitsukan/solid/color_lookup.hpp"
#include "shitsukan/solid/turbulence.hpp"

namespace shitsukan {

namespace {
bool finite_colour(Vec3 c) { return is_finite(c.x) && is_finite(c.y) && is_finite(c.z); }
}  // namespace

Status validate_solid_material(const SolidMaterial& m) {
    if (!finite_colour(m.i_min) || !finite_colour(m.i_max))
        return Status::error(StatusCode::invalid_argument,
                             "solid material: I_min and I_max must be finite");
    if (m.pattern == SolidPattern::marble) return validate_marble(m.marble);
    if (m.pattern == SolidPattern::wood) return validate_wood(m.wood);
    return Status::error(StatusCode::invalid_argument, "solid material: unknown pattern %d",
                         int(m.pattern));
}

float solid_density(const SolidMaterial& m, const LatticeView& lattice, Vec3 p) {
    return solid_density_at(m, p, turbulence(lattice, p));  // D(P), eq. (6)
}

float solid_density_at(const SolidMaterial& m, Vec3 p, float d) {
    if (m.pattern == SolidPattern::marble && m.layer_period > 0.0f) {
        // okada1989 eqs. (8), (9): the one layer at the displaced z' = z + k·D(P), repeated
        // every period: the two nearest repeats, at t and t - period from z'.
        const MarbleStripe& one = m.marble.stripes[0];
        const float zp = p.z + m.marble.k * d;
        float t = std::fmod(zp - one.c, m.layer_period);
        if (t < 0.0f) t += m.layer_period;
        const MarbleStripe layer{0.0f, one.w, one.alpha};
        const float g = trapezoid_skirt(t, layer) + trapezoid_skirt(t - m.layer_period, layer);
        return 1.0f - (g < 1.0f ? g : 1.0f);
    }
    if (m.pattern == SolidPattern::marble) return marble_density(p, d, m.marble);
    return wood_unit_range(wood_texture(p, d, m.wood));  // (sin(k2·r') + 1)/2
}

Vec3 solid_density_color(const SolidMaterial& m, float density) {
    return lookup_color(density, m.i_min, m.i_max);  // eq. (12)
}

Vec3 solid_color(const SolidMaterial& m, const LatticeView& lattice, Vec3 p) {
    return solid_density_color(m, solid_density(m, lattice, p));
}

}  // namespace shitsukan
