// hirota1998 §4.1, Fig. 7: the four layers' radii over time (see layer_schedule.hpp).
#include "shitsukan/bark/layer_schedule.hpp"

#include <cmath>

namespace shitsukan {

LayerRadii layer_radii(const LayerSchedule& s, float t, bool before_role_change) {
    LayerRadii r;
    const float tau = t / s.T;
    int k = int(std::floor(tau));
    float f = tau - float(k);
    if (before_role_change && f == 0.0f && k > 0) k -= 1, f = 1.0f;
    r.cycle = k;
    r.fraction = f;
    r.inner_boundary = s.R_in0 + s.delta_R * tau;  // the wood grows delta_R per cycle
    r.inner = r.inner_boundary - 0.5f * s.D;
    r.middle2_thickness = s.D * f;                   // new cork: 0 -> D over a cycle
    r.middle2 = r.inner_boundary + 0.5f * r.middle2_thickness;
    r.middle1 = r.inner_boundary + r.middle2_thickness + 0.5f * s.D;
    r.surface = r.inner_boundary + r.middle2_thickness + 1.5f * s.D;
    return r;
}

}  // namespace shitsukan
