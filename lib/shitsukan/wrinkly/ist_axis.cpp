// small-device: yes (no allocation, no exceptions)
// fujimoto2000 §2.2: the description of one IST axis and its external shuffles.
#include "shitsukan/wrinkly/ist_axis.hpp"

#include <cstring>

#include "shitsukan/core/assert.hpp"

namespace shitsukan {

namespace {

Status check_n_k(int n, int iterations) {
    if (n < 1 || n > kIstMaxN)
        return Status::error(StatusCode::invalid_argument,
                             "IST: interval division number N must be in [1, %d] (got %d)",
                             kIstMaxN, n);
    if (iterations < 0 || iterations > kIstMaxIterations)
        return Status::error(StatusCode::invalid_argument,
                             "IST: iterations K must be in [0, %d] (got %d)", kIstMaxIterations,
                             iterations);
    std::uint64_t count = 1;
    for (int k = 0; k < iterations; ++k) {
        count *= std::uint64_t(n);
        if (count > kIstMaxSubIntervals) {
            int k_max = 0;
            for (std::uint64_t c = 1; c * std::uint64_t(n) <= kIstMaxSubIntervals;
                 c *= std::uint64_t(n))
                ++k_max;
            return Status::error(StatusCode::too_large,
                                 "IST: N^K = %d^%d sub-intervals exceed the 64-bit index limit "
                                 "2^53; for N = %d use K <= %d",
                                 n, iterations, n, k_max);
        }
    }
    return Status::success();
}

Status check_base(int base_intervals) {
    if (base_intervals < 1 || base_intervals > kIstMaxBase)
        return Status::error(StatusCode::invalid_argument,
                             "IST: number of base intervals B must be in [1, %d] (got %d)",
                             kIstMaxBase, base_intervals);
    return Status::success();
}

Status check_odd(int n) {
    if (n % 2 == 0)
        return Status::error(StatusCode::invalid_argument,
                             "IST: a connected IST needs an odd N = 2M + 1 so that groups can be "
                             "dealt symmetrically to both sides (§2.2.2; got N = %d)",
                             n);
    return Status::success();
}

Status check_shuffle(const IstShuffle& shuffle, IstEnds ends) {
    int n = shuffle.n;
    if (n < 1 || n > kIstMaxN)
        return Status::error(StatusCode::invalid_argument,
                             "IST: external shuffle has n = %d groups, must be in [1, %d]", n,
                             kIstMaxN);
    SHITSUKAN_TRY(check_odd(n));
    bool seen[kIstMaxN] = {};
    for (int g = 0; g < n; ++g) {
        int s = shuffle.slot[g];
        if (s >= n)
            return Status::error(StatusCode::invalid_argument,
                                 "IST: external shuffle: group %d goes to slot %d, slots are "
                                 "0..%d",
                                 g, s, n - 1);
        if (seen[s])
            return Status::error(StatusCode::invalid_argument,
                                 "IST: external shuffle is not a bijection: slot %d is filled "
                                 "twice (second time by group %d)",
                                 s, g);
        seen[s] = true;
    }
    if (ends == IstEnds::translation && !ist_shuffle_is_exchange(shuffle)) {
        for (int g = 0; g < n; ++g) {
            int s = shuffle.slot[g];
            if (shuffle.offset[s] != -shuffle.offset[g] || shuffle.slot[s] != g)
                return Status::error(
                    StatusCode::invalid_argument,
                    "IST: a translation axis needs an exchange table (fig 9: moves past an end "
                    "are skipped in pairs): group %d -> (offset %d, slot %d) but group %d -> "
                    "(offset %d, slot %d), expected (%d, %d)",
                    g, shuffle.offset[g], s, s, shuffle.offset[s], shuffle.slot[s],
                    -shuffle.offset[g], g);
        }
    }
    return Status::success();
}

}  // namespace

bool ist_shuffle_is_exchange(const IstShuffle& shuffle) {
    for (int g = 0; g < shuffle.n; ++g) {
        int s = shuffle.slot[g];
        if (s >= shuffle.n) return false;
        if (shuffle.offset[s] != -shuffle.offset[g] || shuffle.slot[s] != g) return false;
    }
    return true;
}

Status ist_validate(const IstAxis& axis) {
    SHITSUKAN_TRY(check_n_k(axis.n, axis.iterations));
    SHITSUKAN_TRY(check_base(axis.base_intervals));
    if (axis.ends != IstEnds::cyclic && axis.ends != IstEnds::translation)
        return Status::error(StatusCode::invalid_argument, "IST: unknown axis ends value %d",
                             int(axis.ends));
    switch (axis.kind) {
        case IstKind::unit: return Status::success();
        case IstKind::fully_connected:
        case IstKind::connected:
            SHITSUKAN_TRY(check_odd(axis.n));
            if (axis.shuffle.n != axis.n)
                return Status::error(StatusCode::invalid_argument,
                                     "IST: external shuffle has %d groups but N = %d",
                                     axis.shuffle.n, axis.n);
            if (axis.kind == IstKind::fully_connected) {
                int m = (axis.n - 1) / 2;
                for (int g = 0; g < axis.n; ++g)
                    if (axis.shuffle.offset[g] != g - m || axis.shuffle.slot[g] != axis.n - 1 - g)
                        return Status::error(StatusCode::invalid_argument,
                                             "IST: fully-connected axis carries a table that is "
                                             "not eq. (26) at group %d",
                                             g);
            }
            return check_shuffle(axis.shuffle, axis.ends);
    }
    return Status::error(StatusCode::invalid_argument, "IST: unknown kind %d", int(axis.kind));
}

Status ist_unit_axis(int n, int iterations, int base_intervals, IstAxis& out) {
    IstAxis axis;
    axis.kind = IstKind::unit;
    axis.n = n;
    axis.iterations = iterations;
    axis.base_intervals = base_intervals;
    axis.ends = IstEnds::cyclic;
    SHITSUKAN_TRY(ist_validate(axis));
    out = axis;
    return Status::success();
}

Status ist_unit_axis(int n, int iterations, IstAxis& out) {
    return ist_unit_axis(n, iterations, 1, out);
}

Status ist_fully_connected_axis(int n, int iterations, int base_intervals, IstEnds ends,
                                IstAxis& out) {
    SHITSUKAN_TRY(check_n_k(n, iterations));
    IstAxis axis;
    axis.kind = IstKind::fully_connected;
    axis.n = n;
    axis.iterations = iterations;
    axis.base_intervals = base_intervals;
    axis.ends = ends;
    SHITSUKAN_TRY(ist_shuffle_fully_connected(n, axis.shuffle));
    SHITSUKAN_TRY(ist_validate(axis));
    out = axis;
    return Status::success();
}

Status ist_connected_axis(const IstShuffle& shuffle, int iterations, int base_intervals,
                          IstEnds ends, IstAxis& out) {
    IstAxis axis;
    axis.kind = IstKind::connected;
    axis.n = shuffle.n;
    axis.iterations = iterations;
    axis.base_intervals = base_intervals;
    axis.ends = ends;
    axis.shuffle = shuffle;
    SHITSUKAN_TRY(check_shuffle(shuffle, ends));
    SHITSUKAN_TRY(ist_validate(axis));
    out = axis;
    return Status::success();
}

Status ist_with_iterations(const IstAxis& axis, int iterations, IstAxis& out) {
    IstAxis copy = axis;
    copy.iterations = iterations;
    SHITSUKAN_TRY(ist_validate(copy));
    out = copy;
    return Status::success();
}

std::uint64_t ist_sub_interval_count(const IstAxis& axis) {
    std::uint64_t count = 1;
    for (int k = 0; k < axis.iterations; ++k) count *= std::uint64_t(axis.n);
    return count;
}

// fujimoto2000 eq. (26): alpha_0 <- alpha_0 + alpha_1 - M, alpha_1 <- N - 1 - alpha_1.
Status ist_shuffle_fully_connected(int n, IstShuffle& out) {
    SHITSUKAN_TRY(check_n_k(n, 0));
    SHITSUKAN_TRY(check_odd(n));
    IstShuffle s;
    s.n = n;
    int m = (n - 1) / 2;
    for (int g = 0; g < n; ++g) {
        s.offset[g] = std::int8_t(g - m);
        s.slot[g] = std::uint8_t(n - 1 - g);
    }
    out = s;
    return Status::success();
}

Status ist_shuffle_none(int n, IstShuffle& out) {
    SHITSUKAN_TRY(check_n_k(n, 0));
    SHITSUKAN_TRY(check_odd(n));
    IstShuffle s;
    s.n = n;
    for (int g = 0; g < n; ++g) {
        s.offset[g] = 0;
        s.slot[g] = std::uint8_t(g);
    }
    out = s;
    return Status::success();
}

// Fig 6b's table is not printed; §2.2.2(2) gives the number differences on u^3 between
// neighbouring ranges: 0.200 0.100 0.100 0.200 (single sub-intervals), 0.420 0.010 0.010
// 0.420 (ranges of 5), 0.442 0.001 0.001 0.442 (ranges of 25), fractions in base 5.
// For any table, the sub-interval found at position b.beta_1..beta_K of u^K carries the
// number (b - sum_i d(p(beta_i))) . p(beta_K) .. p(beta_1), with p = slot^-1 (the group
// that lands in slot t) and d = offset (ist_digits.hpp). So between positions t and t + 1
// at level l the difference is  a_t + c_t / 5^l  with  a_t = d(p(t)) - d(p(t+1)),
// c_t = p(t+1) - p(t). Levels 2 and 3 give for t = 0: c(1/25 - 1/125) = 22/25 - 122/125,
// c = -3, a = 1; for t = 1: c = 1, a = 0; t = 2 as t = 1, t = 3 as t = 0 (level 1 agrees:
// 1 - 3/5 = 0.2_5, 1/5 = 0.1_5). With p(t) in 0..4 the only solution is p = (4, 1, 2, 3, 0),
// and d(p(t)) = e, e-1, e-1, e-1, e-2. The differences fix d only up to a common shift
// (a shift of the whole axis); an exchange (the paper's 交換), or equally "groups 1-3 stay
// home", gives e = 1: offsets (-1, 0, 0, 0, +1), slots (4, 1, 2, 3, 0).
IstShuffle ist_shuffle_fig6b() {
    IstShuffle s;
    s.n = 5;
    const int offsets[5] = {-1, 0, 0, 0, 1};
    const int slots[5] = {4, 1, 2, 3, 0};
    for (int g = 0; g < 5; ++g) {
        s.offset[g] = std::int8_t(offsets[g]);
        s.slot[g] = std::uint8_t(slots[g]);
    }
    return s;
}

Status ist_shuffle_from_table(int n, const int* offsets, const int* slots, IstShuffle& out) {
    SHITSUKAN_ASSERT(offsets != nullptr && slots != nullptr);
    SHITSUKAN_TRY(check_n_k(n, 0));
    SHITSUKAN_TRY(check_odd(n));
    IstShuffle s;
    s.n = n;
    for (int g = 0; g < n; ++g) {
        if (offsets[g] < -127 || offsets[g] > 127)
            return Status::error(StatusCode::invalid_argument,
                                 "IST: external shuffle offset of group %d is %d, must be in "
                                 "[-127, 127]",
                                 g, offsets[g]);
        if (slots[g] < 0 || slots[g] >= n)
            return Status::error(StatusCode::invalid_argument,
                                 "IST: external shuffle: group %d goes to slot %d, slots are "
                                 "0..%d",
                                 g, slots[g], n - 1);
        s.offset[g] = std::int8_t(offsets[g]);
        s.slot[g] = std::uint8_t(slots[g]);
    }
    SHITSUKAN_TRY(check_shuffle(s, IstEnds::cyclic));
    out = s;
    return Status::success();
}

// Fig 7 shows "various external shuffles" for N = 5 without tables; only (b), no shuffle,
// is described. Chosen here for (a) and (c), both exchanges so they also work on a
// translation axis:
//   fig7a: only the nearest neighbours are reached: offsets (-1,-1,0,1,1), slots reversed.
//   fig7c: crossed pairs: 0 <-> left slot 3, 1 <-> right slot 4, 2 stays:
//          offsets (-1,1,0,1,-1), slots (3,4,2,0,1).
Status ist_shuffle_named(const char* name, int n, IstShuffle& out) {
    if (name == nullptr) name = "";
    if (std::strcmp(name, "fully") == 0) return ist_shuffle_fully_connected(n, out);
    if (std::strcmp(name, "none") == 0) return ist_shuffle_none(n, out);
    bool is_fig6b = std::strcmp(name, "fig6b") == 0;
    bool is_fig7a = std::strcmp(name, "fig7a") == 0;
    bool is_fig7c = std::strcmp(name, "fig7c") == 0;
    if (!is_fig6b && !is_fig7a && !is_fig7c)
        return Status::error(StatusCode::invalid_argument,
                             "IST: unknown external shuffle '%s' (known: fully, none, fig6b, "
                             "fig7a, fig7c)",
                             name);
    if (n != 5)
        return Status::error(StatusCode::invalid_argument,
                             "IST: shuffle '%s' is defined for N = 5 only (got N = %d)", name, n);
    if (is_fig6b) {
        out = ist_shuffle_fig6b();
        return Status::success();
    }
    const int a_offsets[5] = {-1, -1, 0, 1, 1}, a_slots[5] = {4, 3, 2, 1, 0};
    const int c_offsets[5] = {-1, 1, 0, 1, -1}, c_slots[5] = {3, 4, 2, 0, 1};
    return is_fig7a ? ist_shuffle_from_table(5, a_offsets, a_slots, out)
                    : ist_shuffle_from_table(5, c_offsets, c_slots, out);
}

}  // namespace shitsukan
