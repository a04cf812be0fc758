// shitsukan/wrinkly/ist.hpp — the Iterated Shuffle Transformation family of fujimoto2000 §2,
// everything in one include.
//
// Manual
//   ist_axis.hpp       IstAxis: kind (unit / fully-connected / connected + IstShuffle), N, K,
//                      B base intervals, cyclic or translation ends; the named shuffles
//   ist_formula.hpp    ist_forward / ist_inverse on u in [0, 1]: eqs. (9), (10), (14)
//   ist_digits.hpp     the digit-string form alpha^0 -> alpha^K: eqs. (7), (12), (22)-(28)
//   ist_procedure.hpp  div / in-shf / ex-shf simulated on a real u (the reference)
//   ist_original.hpp   the original IST of §2.1 with a crossing number M_i per base interval
#pragma once
#include "shitsukan/wrinkly/ist_axis.hpp"
#include "shitsukan/wrinkly/ist_digits.hpp"
#include "shitsukan/wrinkly/ist_formula.hpp"
#include "shitsukan/wrinkly/ist_procedure.hpp"
#include "shitsukan/wrinkly/ist_original.hpp"
#include "shitsukan/wrinkly/ist_table.hpp"
