// shitsukan/wrinkly/ist_digits.hpp — the IST on sub-interval numbers (digit strings):
// fujimoto2000 §2.3 and appendix A, eqs. (4)-(8), (11)-(13), (21)-(35).
//
// Manual
//   IstAxis axis;
//   Status s = ist_unit_axis(5, 3, 3, axis);        // N = 5, K = 3, B = 3 (ist_axis.hpp)
//   if (!s) return s;
//   IstDigits a;                                    // alpha^0 = alpha_0 . alpha_1 .. alpha_K
//   ist_digits_from_index(axis, /*base*/ 2, /*index*/ 38, &a);   // 38 = 123 in base 5
//   IstDigits b;
//   ist_digits_forward(axis, a, &b);                // alpha^K (unit-IST: 2.321)
//   ist_digits_inverse(axis, b, &a);                // back to alpha^0
//
// A sub-interval of u^k is named by its base-interval number alpha_0 (0 .. B-1) and K base-N
// digits alpha_1 .. alpha_K, alpha_1 the MOST significant (the first division). digit[i] holds
// alpha_i, i = 1..K (digit[0] is unused so the indices read like the paper).
//
// The transformation is K iterations of (appendix A.1, A.2)
//   internal shuffle, eq. (22)/(25): alpha_k moves to the front:
//       a_1 .. a_K -> a_k a_1 .. a_{k-1} a_{k+1} .. a_K
//   external shuffle, eq. (26) for the fully-connected table, generalised to any table:
//       g = alpha_1;  alpha_0 <- alpha_0 + offset[g];  alpha_1 <- slot[g]
//       (a cyclic axis wraps alpha_0 modulo B; a translation axis skips a move past an end)
// and collapses to the scale reverse formulas (スケール反転式)
//   unit-IST, eq. (7):            alpha^K_i = alpha^0_{K-i+1}
//   fully-connected, eq. (12):    alpha^K_0 = alpha^0_0 + sum_j (alpha^0_j - M),
//                                 alpha^K_i = N - 1 - alpha^0_{K-i+1}
// Both are involutions (eqs. 8, 13). ist_digits_forward uses the formula where the paper has
// one (unit; fully-connected on a cyclic axis) and the step algorithm otherwise (general
// connected IST, and any connected IST on a translation axis, where moves are skipped at the
// ends: §2.3.2 footnote). The axis must be valid (ist_validate); the *_checked variants
// validate axis and digits and return a Status.
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"
#include "shitsukan/wrinkly/ist_axis.hpp"

namespace shitsukan {

struct IstDigits {
    int base = 0;   // alpha_0: base-interval number, 0 .. B-1
    int count = 0;  // K: number of digits
    std::uint8_t digit[kIstMaxIterations + 1] = {};  // digit[i] = alpha_i, i = 1..count
};

// index = alpha_1 N^{K-1} + ... + alpha_K, in [0, N^K): the left-to-right order on u^* (u^0).
void ist_digits_from_index(const IstAxis& axis, int base, std::uint64_t index, IstDigits* out);
std::uint64_t ist_digits_index(const IstAxis& axis, const IstDigits& alpha);

// One iteration, in the paper's three steps (div only appends a digit, so it has no code on
// a fixed K-digit string: the k-th digit is the one created by the k-th division).
void ist_internal_shuffle(const IstAxis& axis, int k, IstDigits* alpha);          // eq. (22)/(25)
void ist_internal_shuffle_inverse(const IstAxis& axis, int k, IstDigits* alpha);
void ist_external_shuffle(const IstAxis& axis, IstDigits* alpha);   // eq. (26) generalised
void ist_external_shuffle_inverse(const IstAxis& axis, IstDigits* alpha);

// alpha^0 -> alpha^K by applying the iterations k = 1..K one by one (eqs. 23, 28).
void ist_digits_forward_by_steps(const IstAxis& axis, const IstDigits& in, IstDigits* out);
void ist_digits_inverse_by_steps(const IstAxis& axis, const IstDigits& in, IstDigits* out);

// The scale reverse formulas themselves (no axis ends: alpha_0 is not wrapped).
void ist_scale_reverse_unit(const IstDigits& in, IstDigits* out);               // eq. (7)
void ist_scale_reverse_fully_connected(int n, const IstDigits& in, IstDigits* out);  // eq. (12)

// alpha^0 -> alpha^K and back, formula where there is one (see above).
void ist_digits_forward(const IstAxis& axis, const IstDigits& in, IstDigits* out);
void ist_digits_inverse(const IstAxis& axis, const IstDigits& in, IstDigits* out);

// Validating versions for user input (ist_table, tools).
Status ist_digits_check(const IstAxis& axis, const IstDigits& alpha);
Status ist_digits_forward_checked(const IstAxis& axis, const IstDigits& in, IstDigits& out);
Status ist_digits_inverse_checked(const IstAxis& axis, const IstDigits& in, IstDigits& out);

// "b.a1a2..aK" (digits 0-9 then a-v for N > 10) into buf of size bytes, base_label added to
// alpha_0 (the paper's figures start at 4 or 6). Returns buf; truncates safely, and prints
// '?' for a digit outside 0..31 (an unchecked string never reads past the digit table).
const char* ist_digits_format(const IstDigits& alpha, int base_label, char* buf, int size);

}  // namespace shitsukan
