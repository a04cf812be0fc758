// shitsukan/core/core.hpp — everything in core, for convenience.
//
// Manual
//   Pcg32 rng(1987, 0);
//   Vec3 p{rng.uniform(), rng.uniform(), hash_uniform(1987, 1, 2, 3, 4)};
//   float d = clamp(det_sinf(p.x * kPi), 0.0f, 1.0f);
//   Status s = check_memory_budget(1024, "a small request");
//   if (!s) return s;
#pragma once
#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/config.hpp"
#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/gaussian.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/core/scalar.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
