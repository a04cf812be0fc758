// small-device: yes (validation and eq. (2) amplitudes; no allocation)
#include "shitsukan/solid/fractal_params.hpp"

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

float level_amplitude(int n, float beta) {
    // okada1987 eq. (2): L^(n) = e^{-(n-1)·beta}; level 1 has amplitude 1.
    return float(det_exp(-double(n - 1) * double(beta)));
}

Status validate_fractal_params(const FractalParams& params, int max_depth) {
    if (params.R < 0 || params.R > max_depth)
        return Status::error(StatusCode::invalid_argument,
                             "fractal lattice: R must be in [0, %d] (got %d)", max_depth,
                             params.R);
    if (!is_finite(params.beta) || params.beta < 0.0f)
        return Status::error(StatusCode::invalid_argument,
                             "fractal lattice: beta must be finite and >= 0 (got %g)",
                             double(params.beta));
    for (int i = 0; i < 8; ++i)
        if (!is_finite(params.corners[i]))
            return Status::error(StatusCode::invalid_argument,
                                 "fractal lattice: corner value %d is not finite (%g)", i,
                                 double(params.corners[i]));
    if (params.noise != NoiseSource::hash && params.noise != NoiseSource::sequential)
        return Status::error(StatusCode::invalid_argument,
                             "fractal lattice: unknown noise source %d", int(params.noise));
    return Status::success();
}

}  // namespace shitsukan
