// small-device: yes (no allocation, no exceptions)
#include "shitsukan/solid/okada1987_presets.hpp"

namespace shitsukan {

// Chosen here (see the header): uneven layers of impurity, sharp and soft skirts.
const MarbleStripe kOkada1987Stripes[kOkada1987StripeCount] = {
    {8.0f, 1.2f, 0.9f},  {17.0f, 2.5f, 0.6f}, {26.0f, 0.8f, 1.5f},
    {35.0f, 3.5f, 0.5f}, {46.0f, 1.5f, 0.8f}, {55.0f, 2.0f, 0.7f}};
const MarbleStripe kOkada1989Stripe{32.0f, 1.2f, 1.0f};

FractalParams okada1987_lattice_params() {
    FractalParams p;
    p.R = kOkada1987R;
    p.beta = kOkada1987Beta;
    p.seed = kOkada1987Seed;
    p.noise = NoiseSource::hash;
    return p;
}

SolidMaterial okada1987_marble(float k) {
    SolidMaterial m;
    m.pattern = SolidPattern::marble;
    m.marble = MarbleParams{kOkada1987Stripes, kOkada1987StripeCount, k};
    m.i_min = kOkada1987Impurity;
    m.i_max = kOkada1987Limestone;
    return m;
}

SolidMaterial okada1989_marble(float k) {
    SolidMaterial m = okada1987_marble(k);
    m.marble = MarbleParams{&kOkada1989Stripe, 1, k};
    m.layer_period = kOkada1989LayerPeriod;
    return m;
}

SolidMaterial okada1987_wood(float k) {
    SolidMaterial m;
    m.pattern = SolidPattern::wood;
    m.wood.x0 = kOkada1987WoodAxis.x;
    m.wood.y0 = kOkada1987WoodAxis.y;
    m.wood.k2 = kOkada1987WoodK2;
    m.wood.k = k;
    m.i_min = kOkada1987SummerWood;
    m.i_max = kOkada1987WinterWood;
    return m;
}

}  // namespace shitsukan
