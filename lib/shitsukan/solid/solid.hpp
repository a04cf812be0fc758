// shitsukan/solid/solid.hpp — everything in solid (okada1987 + okada1989), for convenience.
#pragma once
#include "shitsukan/solid/color_lookup.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"
#include "shitsukan/solid/fractal_node.hpp"
#include "shitsukan/solid/fractal_params.hpp"
#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/solid/lattice_type2.hpp"
#include "shitsukan/solid/lattice_type3.hpp"
#include "shitsukan/solid/marble.hpp"
#include "shitsukan/solid/pixel_shift.hpp"
#include "shitsukan/solid/quadtree_lattice.hpp"
#include "shitsukan/solid/turbulence.hpp"
#include "shitsukan/solid/wood.hpp"
