// small-device: yes (no allocation, no exceptions)
// fujimoto2000 §2.1: the original IST with a crossing number M_i per base interval.
#include "shitsukan/wrinkly/ist_original.hpp"

#include <algorithm>
#include <cmath>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/detmath.hpp"

namespace shitsukan {

namespace {

double edge(const IstOriginal& ist, int i) {
    return ist.edges != nullptr ? ist.edges[i] : double(i) / double(ist.base_intervals);
}

double width(const IstOriginal& ist, int i) { return edge(ist, i + 1) - edge(ist, i); }

int base_holding(const IstOriginal& ist, double u) {
    int b = 0;
    if (ist.edges == nullptr) {
        b = int(std::floor(u * double(ist.base_intervals)));
    } else {
        while (b + 1 < ist.base_intervals && u >= ist.edges[b + 1]) ++b;
    }
    return b < 0 ? 0 : (b >= ist.base_intervals ? ist.base_intervals - 1 : b);
}

int largest_crossing(const IstOriginal& ist) {
    if (ist.crossing == nullptr) return ist.crossing_all;
    int m = 0;
    for (int i = 0; i < ist.base_intervals; ++i) m = ist.crossing[i] > m ? ist.crossing[i] : m;
    return m;
}

// Base interval at offset d from i, or -1 past an end of a translation axis.
int neighbour(const IstOriginal& ist, int i, int d) {
    int j = i + d;
    if (ist.ends == IstEnds::translation) return (j < 0 || j >= ist.base_intervals) ? -1 : j;
    j %= ist.base_intervals;
    return j < 0 ? j + ist.base_intervals : j;
}

// One group of parts arriving in base interval j: from `source`, the parts numbered `part`
// of its sub-intervals; `key` orders the groups left to right (source - j, or for a part
// that stayed home at a translation end, the offset it could not travel).
struct Arrival {
    int source = 0;
    int part = 0;
    int key = 0;
    double width = 0.0;  // before scaling: w_source / (2 M_source + 1)
};

// The groups that fill base interval j on u^k, in order; returns their count.
int arrivals_in(const IstOriginal& ist, int j, Arrival* out, int capacity) {
    const int m_max = largest_crossing(ist);
    int count = 0;
    for (int key = -m_max; key <= m_max; ++key) {
        // A real arrival: source j + key dealt its part with offset -key.
        int source = neighbour(ist, j, key);
        if (source >= 0) {
            int m = ist_original_crossing(ist, source);
            if (m >= (key < 0 ? -key : key)) {
                SHITSUKAN_ASSERT(count < capacity);
                out[count].source = source;
                out[count].part = -key + m;
                out[count].key = key;
                out[count].width = width(ist, source) / double(2 * m + 1);
                ++count;
            }
        } else {
            // No source there (translation end): j's own part with offset `key` stays home.
            int m = ist_original_crossing(ist, j);
            if (m >= (key < 0 ? -key : key)) {
                SHITSUKAN_ASSERT(count < capacity);
                out[count].source = j;
                out[count].part = key + m;
                out[count].key = key;
                out[count].width = width(ist, j) / double(2 * m + 1);
                ++count;
            }
        }
    }
    return count;
}

constexpr int kMaxArrivals = 2 * kIstMaxCrossing + 1;

// Where group (source, part) lies in base j: the scale of j's groups and the unscaled width
// before it.
void place_of(const IstOriginal& ist, int j, int source, int part, double* scale,
              double* before) {
    Arrival list[kMaxArrivals];
    int count = arrivals_in(ist, j, list, kMaxArrivals);
    double total = 0.0, sum = 0.0;
    bool found = false;
    for (int a = 0; a < count; ++a) {
        if (list[a].source == source && list[a].part == part && !found) {
            *before = sum;
            found = true;
        }
        sum += list[a].width;
    }
    total = sum;
    SHITSUKAN_ASSERT(found);
    *scale = width(ist, j) / total;
}

}  // namespace

int ist_original_crossing(const IstOriginal& ist, int base) {
    return ist.crossing != nullptr ? ist.crossing[base] : ist.crossing_all;
}

Status ist_original_check(const IstOriginal& ist) {
    if (ist.base_intervals < 1 || ist.base_intervals > kIstMaxBase)
        return Status::error(StatusCode::invalid_argument,
                             "original IST: number of base intervals B must be in [1, %d] "
                             "(got %d)",
                             kIstMaxBase, ist.base_intervals);
    if (ist.iterations < 0 || ist.iterations > kIstMaxIterations)
        return Status::error(StatusCode::invalid_argument,
                             "original IST: iterations K must be in [0, %d] (got %d)",
                             kIstMaxIterations, ist.iterations);
    if (ist.ends != IstEnds::cyclic && ist.ends != IstEnds::translation)
        return Status::error(StatusCode::invalid_argument, "original IST: unknown ends value %d",
                             int(ist.ends));
    for (int i = 0; i < ist.base_intervals; ++i) {
        int m = ist_original_crossing(ist, i);
        if (m < 0 || m > kIstMaxCrossing)
            return Status::error(StatusCode::invalid_argument,
                                 "original IST: crossing number M_%d must be in [0, %d] (got %d)",
                                 i, kIstMaxCrossing, m);
    }
    if (ist.edges != nullptr) {
        if (!(ist.edges[0] == 0.0) || !(ist.edges[ist.base_intervals] == 1.0))
            return Status::error(StatusCode::invalid_argument,
                                 "original IST: base-interval edges must run from 0 to 1 "
                                 "(got %g .. %g)",
                                 ist.edges[0], ist.edges[ist.base_intervals]);
        for (int i = 0; i < ist.base_intervals; ++i)
            if (!(ist.edges[i + 1] > ist.edges[i]))
                return Status::error(StatusCode::invalid_argument,
                                     "original IST: edges must increase: x_%d = %g, x_%d = %g",
                                     i, ist.edges[i], i + 1, ist.edges[i + 1]);
    }
    // The resolution the header promises: the finest sub-interval, (base width) / prod
    // (2 M + 1) over K steps, must stay above 2^-45 (beyond, widths round to 0 and the inverse
    // divided 0 by 0: NaN, then int(NaN)). Bounded with the largest M and the narrowest base.
    {
        int widest = 0;
        for (int i = 0; i < ist.base_intervals; ++i)
            widest = std::max(widest, 2 * ist_original_crossing(ist, i) + 1);
        double narrowest = 1.0 / ist.base_intervals;
        if (ist.edges != nullptr)
            for (int i = 0; i < ist.base_intervals; ++i)
                narrowest = std::min(narrowest, ist.edges[i + 1] - ist.edges[i]);
        const double finest = narrowest / det_pow(double(widest), double(ist.iterations));
        if (!(finest >= std::ldexp(1.0, -45)))
            return Status::error(StatusCode::out_of_range,
                                 "original IST: K = %d steps of up to %d parts leave "
                                 "sub-intervals %g wide, below the 2^-45 that doubles resolve",
                                 ist.iterations, widest, finest);
        // The same on u^K: with unequal M_i or widths the groups dealt into a base are scaled
        // to fill it, and a group can shrink more than 1 / (2M + 1) a step (found by
        // fuzz_ist: skewed edges and M up to 12 mapped different u onto one double, and the
        // inverse returned a point 0.99 away). Each step keeps at least the smallest share
        // of a group in its base.
        double share = 1.0;
        for (int j = 0; j < ist.base_intervals; ++j) {
            Arrival list[kMaxArrivals];
            const int count = arrivals_in(ist, j, list, kMaxArrivals);
            double total = 0.0;
            for (int a = 0; a < count; ++a) total += list[a].width;
            for (int a = 0; a < count; ++a) share = std::min(share, list[a].width / total);
        }
        const double finest_k = narrowest * det_pow(share, double(ist.iterations));
        if (!(finest_k >= std::ldexp(1.0, -45)))
            return Status::error(StatusCode::out_of_range,
                                 "original IST: K = %d steps leave sub-intervals of u^K %g "
                                 "wide (a group keeps down to %g of its base a step), below "
                                 "the 2^-45 that doubles resolve",
                                 ist.iterations, finest_k, share);
    }
    return Status::success();
}

void ist_original_start(const IstOriginal& ist, double u, IstPoint* point) {
    SHITSUKAN_ASSERT(point != nullptr);
    if (!(u > 0.0)) u = 0.0;
    if (u > 1.0) u = 1.0;
    point->base = base_holding(ist, u);
    point->start = edge(ist, point->base);
    point->end = edge(ist, point->base + 1);
    point->u = u;
    point->step = 0;
}

void ist_original_step(const IstOriginal& ist, IstPoint* point, int* part) {
    SHITSUKAN_ASSERT(point != nullptr);
    const int i = point->base;
    const int m = ist_original_crossing(ist, i);
    const int n = 2 * m + 1;
    // 1) divide the sub-interval into 2 M_i + 1 parts; g = the part holding u.
    const double h = (point->end - point->start) / double(n);
    int g = int(std::floor((point->u - point->start) / h));
    g = g < 0 ? 0 : (g >= n ? n - 1 : g);
    const double inside = point->u - (point->start + double(g) * h);
    // 2) deal part g to base interval i + g - M_i (stays home past a translation end).
    int j = neighbour(ist, i, g - m);
    if (j < 0) j = i;
    double scale = 1.0, before = 0.0;
    place_of(ist, j, i, g, &scale, &before);
    const double x_i = edge(ist, i);
    const double new_start = edge(ist, j) + scale * (before + (point->start - x_i) / double(n));
    point->start = new_start;
    point->end = new_start + scale * h;
    point->u = new_start + scale * inside;
    point->base = j;
    point->step += 1;
    if (part != nullptr) *part = g;
}

// ---- forward / inverse on sub-interval identities ----
// Following a point step by step (ist_original_step) lets rounding move it into the
// neighbouring part: inverse(forward(u)) then missed u by up to the whole axis on about a
// quarter of the sub-interval left ends, and forward() returned values just above 1. Here a
// point is first given its sub-interval's identity, the transformation acts on identities,
// and coordinates are computed from identities by one fixed formula per axis:
//   u^0: base b and the parts g_1..g_K, a mixed-radix fraction I / D of the base (exact
//        integers), left end x_b + w_b I / D;
//   u^K: base j and the arrivals a_K..a_1 (which group of the base at each level), left end
//        from the groups' widths (place_of's layout).
// Locating a coordinate picks the last sub-interval whose computed left end is <= it, so a
// left end is found exactly; the offset inside is kept as a fraction t of the width, and a
// result is held inside [left end, next left end).
namespace {

constexpr int kMaxLevels = kIstMaxIterations + 1;

// The base whose computed left edge is the last one <= u.
int base_of(const IstOriginal& ist, double u) {
    int b = base_holding(ist, u);
    while (b > 0 && edge(ist, b) > u) --b;
    while (b + 1 < ist.base_intervals && edge(ist, b + 1) <= u) ++b;
    return b;
}

double left_on_u0(const IstOriginal& ist, int b, std::uint64_t index, std::uint64_t count) {
    return edge(ist, b) + width(ist, b) * (double(index) / double(count));
}

int arrival_index(const IstOriginal& ist, int j, int source, int part) {
    Arrival list[kMaxArrivals];
    const int count = arrivals_in(ist, j, list, kMaxArrivals);
    for (int a = 0; a < count; ++a)
        if (list[a].source == source && list[a].part == part) return a;
    SHITSUKAN_ASSERT(false);
    return 0;
}

// A sub-interval of u^K: base[K] = j, arrival[l] (l = 1..K) the group of base[l] it lies in;
// base[l - 1] is that group's source. Fills base[], part[] and the left end and width.
struct UpK {
    int base[kMaxLevels];
    int arrival[kMaxLevels];
    int part[kMaxLevels];
};

void measure_upk(const IstOriginal& ist, int k, UpK* s, double* left, double* w) {
    double before[kMaxLevels], group[kMaxLevels], total[kMaxLevels];
    for (int l = k; l >= 1; --l) {
        Arrival list[kMaxArrivals];
        const int count = arrivals_in(ist, s->base[l], list, kMaxArrivals);
        SHITSUKAN_ASSERT(s->arrival[l] < count);
        double sum = 0.0;
        for (int a = 0; a < count; ++a) {
            if (a == s->arrival[l]) before[l] = sum;
            sum += list[a].width;
        }
        total[l] = sum;
        group[l] = list[s->arrival[l]].width;
        s->base[l - 1] = list[s->arrival[l]].source;
        s->part[l] = list[s->arrival[l]].part;
    }
    double frac = 0.0, share = 1.0;  // of base[l]: left end, width
    for (int l = 1; l <= k; ++l) {
        frac = (before[l] + frac * group[l]) / total[l];
        share = share * group[l] / total[l];
    }
    const int j = s->base[k];
    *left = edge(ist, j) + width(ist, j) * frac;
    *w = width(ist, j) * share;
}

// The left end of the sub-interval after s on u^K (1 after the last one).
double next_left_upk(const IstOriginal& ist, int k, const UpK& s) {
    UpK n = s;
    for (int l = 1; l <= k; ++l) {
        Arrival list[kMaxArrivals];
        if (n.arrival[l] + 1 < arrivals_in(ist, n.base[l], list, kMaxArrivals)) {
            ++n.arrival[l];
            for (int i = 1; i < l; ++i) n.arrival[i] = 0;
            double left, w;
            measure_upk(ist, k, &n, &left, &w);
            return left;
        }
    }
    return edge(ist, s.base[k] + 1);
}

// Keeps v inside [a, z) (or [a, z] when the point is the axis' end u = 1).
double hold_inside(double v, double a, double z, bool closed) {
    if (!closed && v >= z) v = z > a ? std::nextafter(z, a) : a;
    if (closed && v > z) v = z;
    return v < a ? a : v;
}

}  // namespace

double ist_original_forward(const IstOriginal& ist, double u) {
    if (!(u > 0.0)) u = 0.0;
    if (u > 1.0) u = 1.0;
    const int k = ist.iterations;
    if (k == 0) return u;
    // Locate u on u^0: base b and parts g_1..g_K, each the last one whose left end is <= u.
    const int b = base_of(ist, u);
    UpK s;
    std::uint64_t index = 0, count = 1;
    int source = b;
    for (int l = 1; l <= k; ++l) {
        const int m = ist_original_crossing(ist, source), n = 2 * m + 1;
        const double guess =
            ((u - edge(ist, b)) / width(ist, b) * double(count) - double(index)) * double(n);
        int g = guess > 0.0 ? (guess < double(n) ? int(guess) : n - 1) : 0;
        while (g > 0 && left_on_u0(ist, b, index * n + std::uint64_t(g), count * n) > u) --g;
        while (g + 1 < n && left_on_u0(ist, b, index * n + std::uint64_t(g + 1), count * n) <= u)
            ++g;
        index = index * std::uint64_t(n) + std::uint64_t(g);
        count *= std::uint64_t(n);
        // §2.1(1) 2): part g goes to base interval source + g - M (stays home past an end).
        int j = neighbour(ist, source, g - m);
        if (j < 0) j = source;
        s.arrival[l] = arrival_index(ist, j, source, g);
        source = j;
    }
    s.base[k] = source;
    const double a0 = left_on_u0(ist, b, index, count);
    double t = (u - a0) / (width(ist, b) / double(count));
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    double left, w;
    measure_upk(ist, k, &s, &left, &w);
    const double v = t > 0.0 ? left + t * w : left;  // a left end goes to a left end, exactly
    const double v_in = hold_inside(v, left, next_left_upk(ist, k, s), u >= 1.0);
    return v_in > 1.0 ? 1.0 : v_in;
}

double ist_original_inverse(const IstOriginal& ist, double q) {
    if (!(q > 0.0)) q = 0.0;
    if (q > 1.0) q = 1.0;
    const int k = ist.iterations;
    if (k == 0) return q;
    // Locate q on u^K: from the outermost group inwards, the last group whose first
    // sub-interval starts at or before q. With the groups below level l all first ones
    // (before = 0), the fraction of base[l] is before(a) / total and the levels above map it
    // by the same affine steps as measure_upk, bit for bit: O(K (2M + 1)) per level.
    UpK s;
    const int j = base_of(ist, q);
    s.base[k] = j;
    for (int l = 1; l <= k; ++l) s.arrival[l] = 0;
    double before_at[kMaxLevels], group_at[kMaxLevels], total_at[kMaxLevels];
    for (int l = k; l >= 1; --l) {
        Arrival list[kMaxArrivals];
        const int count = arrivals_in(ist, s.base[l], list, kMaxArrivals);
        double total = 0.0;
        for (int a = 0; a < count; ++a) total += list[a].width;
        double sum = 0.0;
        int chosen = 0;
        double chosen_before = 0.0;
        for (int a = 0; a < count; ++a) {
            double f = sum / total;  // (before + 0 * group) / total, as measure_upk
            for (int m = l + 1; m <= k; ++m) f = (before_at[m] + f * group_at[m]) / total_at[m];
            if (a > 0 && edge(ist, j) + width(ist, j) * f > q) break;
            chosen = a;
            chosen_before = sum;
            sum += list[a].width;
        }
        s.arrival[l] = chosen;
        before_at[l] = chosen_before;
        group_at[l] = list[chosen].width;
        total_at[l] = total;
        s.base[l - 1] = list[chosen].source;
    }
    double left, w;
    measure_upk(ist, k, &s, &left, &w);
    double t = (q - left) / w;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    // Back on u^0: base[0] and the parts, most significant first.
    const int b = s.base[0];
    std::uint64_t index = 0, count = 1;
    for (int l = 1; l <= k; ++l) {
        const std::uint64_t n = std::uint64_t(2 * ist_original_crossing(ist, s.base[l - 1]) + 1);
        index = index * n + std::uint64_t(s.part[l]);
        count *= n;
    }
    const double a0 = left_on_u0(ist, b, index, count);
    const double z0 =
        index + 1 < count ? left_on_u0(ist, b, index + 1, count) : edge(ist, b + 1);
    const double u = t > 0.0 ? a0 + t * (width(ist, b) / double(count)) : a0;
    const double u_in = hold_inside(u, a0, z0, q >= 1.0);
    return u_in > 1.0 ? 1.0 : u_in;
}

namespace {
Status check_original_input(const IstOriginal& ist, double u) {
    SHITSUKAN_TRY(ist_original_check(ist));
    if (!(u >= 0.0 && u <= 1.0))
        return Status::error(StatusCode::out_of_range,
                             "original IST: u must be in [0, 1] (got %g)", u);
    return Status::success();
}
}  // namespace

Status ist_original_forward_checked(const IstOriginal& ist, double u, double& out) {
    SHITSUKAN_TRY(check_original_input(ist, u));
    out = ist_original_forward(ist, u);
    return Status::success();
}

Status ist_original_inverse_checked(const IstOriginal& ist, double u, double& out) {
    SHITSUKAN_TRY(check_original_input(ist, u));
    out = ist_original_inverse(ist, u);
    return Status::success();
}

}  // namespace shitsukan
