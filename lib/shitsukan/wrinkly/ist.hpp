// shitsukan/wrinkly/ist.hpp — the Iterated Shuffle Transformation family of fujimoto2000 §2,
// everything in one include.
//
// Manual
//   IstAxis axis;                                   // ist_axis.hpp: kind (unit / fully-
//   Status s = ist_unit_axis(3, 2, axis);           // connected / connected + IstShuffle), N, K,
//                                                   // B base intervals, cyclic or translation ends
//   float v = s ? ist_forward(axis, 0.25f) : 0.0f;  // ist_formula.hpp: eqs. (9), (10), (14)
//   IstDigits a, b;                                 // ist_digits.hpp: alpha^0 -> alpha^K,
//   ist_digits_from_index(axis, 0, 5, &a);          // eqs. (7), (12), (22)-(28)
//   ist_digits_forward(axis, a, &b);
//   double w = ist_procedure_forward(axis, 0.25);   // ist_procedure.hpp: div / in-shf / ex-shf
//                                                   // simulated on a real u (the reference)
//   // ist_original.hpp: the original IST of §2.1 with a crossing number M_i per base interval
//   return s;
#pragma once
#include "shitsukan/wrinkly/ist_axis.hpp"
#include "shitsukan/wrinkly/ist_digits.hpp"
#include "shitsukan/wrinkly/ist_formula.hpp"
#include "shitsukan/wrinkly/ist_procedure.hpp"
#include "shitsukan/wrinkly/ist_original.hpp"
#include "shitsukan/wrinkly/ist_table.hpp"
