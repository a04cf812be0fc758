// shitsukan/wrinkly/ist_axis.hpp — which Iterated Shuffle Transformation acts on one axis
// (fujimoto2000 §2.2): unit-IST, connected-IST with an external shuffle, fully-connected IST.
//
// Manual
//   IstAxis axis;
//   Status s = ist_fully_connected_axis(5, 3, 5, IstEnds::cyclic, axis);   // N, K, B, ends
//   if (!s) { std::puts(s.message()); return s; }
//   float v = ist_forward(axis, 0.37f);             // ist_formula.hpp: u^0 -> u^K
//   float w = ist_inverse(axis, v);                 // u^K -> u^0 (w == 0.37 up to rounding)
//   #include "shitsukan/wrinkly/ist_formula.hpp"
//
//   The axis u in [0, 1] is cut into B equal "base intervals" (ベース区間) numbered
//   0 .. B-1 from the left; the paper's figures number them from 4 (fig 6) or 0 (fig 9):
//   add your own offset when labelling. Inside each base interval K iterations of
//     1) div     every sub-interval is divided into N equal parts,
//     2) in-shf  parts at the same position in their parent are grouped (group g = the
//                g-th part of every parent, in parent order) and group g is placed g-th,
//     3) ex-shf  (connected kinds only) group g leaves for base interval b + offset[g]
//                and takes slot slot[g] there (IstShuffle),
//   build a 1:1 map of u^0 onto u^K.
//
// Kinds
//   IstKind::unit             N >= 1, no external shuffle (N-進-単位-IST, eq. 2, 7, 10).
//                             With B > 1 every base interval is an independent unit-IST.
//   IstKind::fully_connected  N odd, N = 2M + 1; the table of fig 6a / fig 8 (eqs. 12, 26):
//                             group g -> base b + g - M, slot N - 1 - g.
//   IstKind::connected        N odd, any external shuffle table given as data.
// Ends
//   IstEnds::cyclic       closed axis (巡回軸): base B-1 and base 0 are neighbours.
//   IstEnds::translation  open axis (並進軸, fig 9): a move past an end is not performed;
//                         the table must then be an exchange (see ist_shuffle_is_exchange)
//                         so that the skipped pairs still leave a bijection.
// Ranges: 1 <= N <= kIstMaxN, 0 <= K <= kIstMaxIterations and N^K <= kIstMaxSubIntervals
// (the sub-interval index of one base interval is a 64-bit integer), 1 <= B <= kIstMaxBase.
// Build an IstAxis with the ist_*_axis functions (they validate and return a Status); the
// fields are public so a reader can see them, and ist_validate() rechecks a hand-made one.
#pragma once

#include <cstdint>

#include "shitsukan/core/status.hpp"

namespace shitsukan {

constexpr int kIstMaxN = 32;                   // largest interval division number N
constexpr int kIstMaxIterations = 40;          // largest K (digit arrays are this long)
constexpr std::uint64_t kIstMaxSubIntervals = std::uint64_t(1) << 53;  // N^K limit: exact
                                               // in a double, so eq. (9) can be evaluated
constexpr int kIstMaxBase = 1 << 20;           // largest number of base intervals B

enum class IstKind : std::uint8_t { unit, fully_connected, connected };
enum class IstEnds : std::uint8_t { cyclic, translation };

// External shuffle (外部交差) of the connected IST, §2.2.2(1): after the internal shuffle,
// group g of base interval b moves to base interval b + offset[g] and becomes the slot[g]-th
// group there. slot[] must be a permutation of 0..n-1 (each slot filled once).
struct IstShuffle {
    int n = 0;
    std::int8_t offset[kIstMaxN] = {};
    std::uint8_t slot[kIstMaxN] = {};
};

struct IstAxis {
    IstKind kind = IstKind::unit;
    int n = 1;               // N: interval division number (区間分割数)
    int iterations = 0;      // K: number of iterations
    int base_intervals = 1;  // B
    IstEnds ends = IstEnds::cyclic;
    IstShuffle shuffle;      // used by the connected kinds (filled for fully_connected too)
};

// Constructors (validate, fill out only on success).
Status ist_unit_axis(int n, int iterations, IstAxis& out);  // B = 1, cyclic
Status ist_unit_axis(int n, int iterations, int base_intervals, IstAxis& out);
Status ist_fully_connected_axis(int n, int iterations, int base_intervals, IstEnds ends,
                                IstAxis& out);
Status ist_connected_axis(const IstShuffle& shuffle, int iterations, int base_intervals,
                          IstEnds ends, IstAxis& out);
Status ist_validate(const IstAxis& axis);

// The same axis with another K (the superposed surface of §4 needs F^k for k = 0..K).
// The new K must keep N^K within the limits (checked).
Status ist_with_iterations(const IstAxis& axis, int iterations, IstAxis& out);

// N^K, the number of sub-intervals in one base interval (valid axis assumed).
std::uint64_t ist_sub_interval_count(const IstAxis& axis);

// External shuffles.
// fully-connected (fig 6a, fig 8; eq. 26): offset g - M, slot N - 1 - g. N odd.
Status ist_shuffle_fully_connected(int n, IstShuffle& out);
// no external shuffle (fig 7b): offset 0, slot g. N odd.
Status ist_shuffle_none(int n, IstShuffle& out);
// fig 6b (N = 5), inferred from the number differences of §2.2.2(2) (see ist_axis.cpp):
// groups 1, 2, 3 stay; group 0 and group 4 are exchanged with the neighbours:
// group 0 -> left neighbour, slot 4; group 4 -> right neighbour, slot 0.
IstShuffle ist_shuffle_fig6b();
// Any table: offsets[g], slots[g] for g = 0..n-1 (n odd). Checks that slots is a permutation.
Status ist_shuffle_from_table(int n, const int* offsets, const int* slots, IstShuffle& out);
// By name: "fully", "none", "fig6b" (N must be 5), "fig7a", "fig7c" (N = 5; chosen here,
// see ist_axis.cpp). Unknown names give invalid_argument listing the known ones.
Status ist_shuffle_named(const char* name, int n, IstShuffle& out);
// True when every move is paired with the reverse move (group g -> (d, s) and group s ->
// (-d, g)): the external shuffle is then an exchange between base intervals, as the paper
// describes it (交換), and the skipped moves at the ends of a translation axis keep a
// bijection.
bool ist_shuffle_is_exchange(const IstShuffle& shuffle);

}  // namespace shitsukan
