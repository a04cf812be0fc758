// small-device: yes (validation and eq. (2) amplitudes; no allocation)
#include "shitsukan/solid/fractal_params.hpp"

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

float level_amplitude(int n, float beta) {
    // okada1987 eq. (2): L^(n) = e^{-(n-1)·beta}; level 1 has amplitude 1.
    return float(det_exp(-double(n - 1) * double(beta)));
}

Status validate_fractal_levels(const char* what, int R, int max_depth, float beta,
                               const float* corners, int corner_count) {
    if (R < 0 || R > max_depth)
        return Status::error(StatusCode::invalid_argument, "%s: R must be in [0, %d] (got %d)",
                             what, max_depth, R);
    if (!is_finite(beta) || beta < 0.0f)
        return Status::error(StatusCode::invalid_argument,
                             "%s: beta must be finite and >= 0 (got %g)", what, double(beta));
    for (int i = 0; i < corner_count; ++i)
        if (!(corners[i] >= -kMaxFractalCorner && corners[i] <= kMaxFractalCorner))  // NaN too
            return Status::error(StatusCode::invalid_argument,
                                 "%s: corner value %d must be finite and within +-%g (got %g)",
                                 what, i, double(kMaxFractalCorner), double(corners[i]));
    return Status::success();
}

Status validate_fractal_params(const FractalParams& params, int max_depth) {
    SHITSUKAN_TRY(validate_fractal_levels("fractal lattice", params.R, max_depth, params.beta,
                                          params.corners, 8));
    if (params.noise != NoiseSource::hash && params.noise != NoiseSource::sequential)
        return Status::error(StatusCode::invalid_argument,
                             "fractal lattice: unknown noise source %d", int(params.noise));
    return Status::success();
}

}  // namespace shitsukan
