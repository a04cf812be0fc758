// shitsukan/core/core.hpp — everything in core, for convenience.
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
