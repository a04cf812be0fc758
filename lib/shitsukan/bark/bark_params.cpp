// hirota1998 Tables 1 and 2: presets and validation.
#include "shitsukan/bark/bark_params.hpp"

#include <cmath>

#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

SpeciesParams species_preset(Species species) {
    SpeciesParams s;  // L0 = 0.33 cm and E2 = 117.3e7 for all three (Table 2)
    switch (species) {
    case Species::camphor:
        s.name = "camphor";
        s.E1 = 107.1e7f, s.E2 = 117.3e7f, s.G = 47.7e7f, s.kappa1 = 1.040f, s.kappa2 = 1.015f;
        break;
    case Species::chinese_tallow:
        s.name = "Chinese tallow";
        s.E1 = 117.3e7f, s.E2 = 117.3e7f, s.G = 53.3e7f, s.kappa1 = 1.033f, s.kappa2 = 1.015f;
        break;
    case Species::pine:
        s.name = "pine";
        s.E1 = 117.3e7f, s.E2 = 117.3e7f, s.G = 53.3e7f, s.kappa1 = 1.038f, s.kappa2 = 1.023f;
        break;
    }
    return s;
}

const char* species_name(Species species) { return species_preset(species).name; }

float column_spacing(const CylinderParams& p) { return 0.86602540378f * p.species.L0; }
float initial_height(const CylinderParams& p) { return p.species.L0 * float(p.N_H); }
// R0 = sqrt(3)·L0·N_R / (4 pi): circumference 2 pi R0 = N_R·(sqrt(3)/2)·L0.
float initial_radius(const CylinderParams& p) {
    return float(p.N_R) * column_spacing(p) / kTwoPi;
}
float hoop_strain(const CylinderParams& p, float t) { return p.delta_r * t / initial_radius(p); }
float axial_strain(const CylinderParams& p, float t) { return p.delta_h * t / initial_height(p); }

std::uint64_t cylinder_model_bytes(int N_R, int N_H) {
    if (N_R <= 0 || N_H <= 0) return 0;
    const std::uint64_t nodes = std::uint64_t(N_R) * std::uint64_t(N_H);
    // per node: reference position, displacement, anchor stiffness, area, CSR start, queue,
    // flags (about 64 bytes); per spring (3 per node): the spring record, two CSR entries,
    // the event tree (about 112 bytes); per triangle (2 per node): 40 bytes.
    return nodes * (64 + 3 * 112 + 2 * 40);
}

namespace {

bool positive(float x) { return is_finite(x) && x > 0.0f; }

}  // namespace

Status validate(const SpeciesParams& s) {
    if (!positive(s.L0))
        return Status::error(StatusCode::invalid_argument, "bark: L0 must be > 0 cm (got %g)",
                             double(s.L0));
    if (!positive(s.E1) || !positive(s.E2))
        return Status::error(StatusCode::invalid_argument,
                             "bark: E1 and E2 must be > 0 (got %g, %g)", double(s.E1),
                             double(s.E2));
    if (!positive(s.G))
        return Status::error(StatusCode::invalid_argument, "bark: G must be > 0 (got %g)",
                             double(s.G));
    if (!(is_finite(s.kappa1) && s.kappa1 > 1.0f) || !(is_finite(s.kappa2) && s.kappa2 > 1.0f))
        return Status::error(StatusCode::invalid_argument,
                             "bark: kappa1 and kappa2 are critical elongation ratios and must "
                             "be > 1 (got %g, %g)",
                             double(s.kappa1), double(s.kappa2));
    return Status::success();
}

Status validate(const CylinderParams& p) {
    SHITSUKAN_TRY(validate(p.species));
    if (p.N_R < 4 || p.N_R > 4096 || p.N_R % 2 != 0)
        return Status::error(StatusCode::invalid_argument,
                             "bark: N_R must be even and in [4, 4096] (got %d): alternate "
                             "columns are shifted by L0/2 and must close around the trunk",
                             p.N_R);
    if (p.N_H < 2 || p.N_H > 4096)
        return Status::error(StatusCode::invalid_argument, "bark: N_H must be in [2, 4096] (got %d)",
                             p.N_H);
    const std::uint64_t bytes = cylinder_model_bytes(p.N_R, p.N_H);
    if (bytes > kMaxBarkBytes)
        return Status::error(StatusCode::too_large,
                             "bark: %d x %d nodes need about %llu bytes (limit %llu)", p.N_R,
                             p.N_H, (unsigned long long)bytes, (unsigned long long)kMaxBarkBytes);
    if (!positive(p.D))
        return Status::error(StatusCode::invalid_argument,
                             "bark: layer thickness D must be > 0 cm (got %g)", double(p.D));
    if (!(is_finite(p.sigma) && p.sigma >= 0.0f && p.sigma < 0.3f))
        return Status::error(StatusCode::invalid_argument,
                             "bark: sigma must be in [0, 0.3) (got %g)", double(p.sigma));
    if (!positive(p.T))
        return Status::error(StatusCode::invalid_argument, "bark: T must be > 0 s (got %g)",
                             double(p.T));
    if (!(is_finite(p.delta_r) && p.delta_r >= 0.0f) ||
        !(is_finite(p.delta_h) && p.delta_h >= 0.0f) || (p.delta_r == 0.0f && p.delta_h == 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "bark: growth rates delta_r, delta_h must be finite, >= 0 and not "
                             "both 0 (got %g, %g cm/s)",
                             double(p.delta_r), double(p.delta_h));
    // Below 1e-7 (the float resolution of W relative to L0·g) the relaxation cannot meet it
    // and runs to its cap (fuzz_bark: 9.5e-41 took 21 s on 16 x 8 nodes).
    if (!(is_finite(p.tolerance) && p.tolerance >= 1e-7f && p.tolerance <= 0.1f))
        return Status::error(StatusCode::invalid_argument,
                             "bark: tolerance must be in [1e-7, 0.1] (got %g)",
                             double(p.tolerance));
    if (!is_finite(p.rho) || p.rho < 0.0f)
        return Status::error(StatusCode::invalid_argument, "bark: rho must be >= 0 (got %g)",
                             double(p.rho));
    return Status::success();
}

}  // namespace shitsukan
