// The reconstructed shear-lag estimate of the largest crack spacing (see spacing_estimate.hpp).
#include "shitsukan/bark/spacing_estimate.hpp"

#include <cmath>
#include <limits>

#include "shitsukan/core/detmath.hpp"

namespace shitsukan {

float crack_spacing_estimate(float s, float stiffness_ratio_sqrt, float eps_c, float eps_f) {
    if (!(s > 0.0f) || !(stiffness_ratio_sqrt > 0.0f) || !(eps_c > 0.0f) || !(eps_f > 0.0f))
        return std::numeric_limits<float>::quiet_NaN();
    if (eps_c >= eps_f) return std::numeric_limits<float>::infinity();  // never cracks
    const double lambda = double(shear_lag_length(s, stiffness_ratio_sqrt));
    const double x = 1.0 / (1.0 - double(eps_c) / double(eps_f));  // cosh(L / 2 lambda)
    return float(2.0 * lambda * det_log(x + std::sqrt(x * x - 1.0)));  // arccosh (det_log: same bits everywhere)
}

}  // namespace shitsukan
