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

// Inverse of one step at a point q of u^k: the group holding q and q's place inside it,
// read on u^{k-1} as the point `compressed` = x_i + (2 M_i + 1) · (offset in the group).
struct Origin {
    int destination = 0, source = 0, part = 0;
    double scale = 1.0, before = 0.0, compressed = 0.0;
};

Origin origin_of(const IstOriginal& ist, double q) {
    Origin o;
    o.destination = base_holding(ist, q);
    Arrival list[kMaxArrivals];
    int count = arrivals_in(ist, o.destination, list, kMaxArrivals);
    double total = 0.0;
    for (int a = 0; a < count; ++a) total += list[a].width;
    o.scale = width(ist, o.destination) / total;
    double local = (q - edge(ist, o.destination)) / o.scale;  // unscaled offset in j
    int a = 0;
    double before = 0.0;
    while (a + 1 < count && local >= before + list[a].width) before += list[a++].width;
    o.source = list[a].source;
    o.part = list[a].part;
    o.before = before;
    double in_group = local - before;
    if (in_group < 0.0) in_group = 0.0;
    if (in_group > list[a].width) in_group = list[a].width;
    int m = ist_original_crossing(ist, o.source);
    o.compressed = edge(ist, o.source) + in_group * double(2 * m + 1);
    return o;
}

// The sub-interval of u^level that holds point p: follow p back to its base interval on u^0,
// then divide forward again.
void locate(const IstOriginal& ist, double p, int level, double* start, double* end) {
    Origin chain[kIstMaxIterations];
    for (int l = level; l >= 1; --l) {
        chain[l - 1] = origin_of(ist, p);
        p = chain[l - 1].compressed;
    }
    int b = base_holding(ist, p);
    double a = edge(ist, b), z = edge(ist, b + 1);
    for (int l = 1; l <= level; ++l) {
        const Origin& o = chain[l - 1];
        int n = 2 * ist_original_crossing(ist, o.source) + 1;
        double x_i = edge(ist, o.source);
        double new_a = edge(ist, o.destination) + o.scale * (o.before + (a - x_i) / double(n));
        z = new_a + o.scale * (z - a) / double(n);
        a = new_a;
    }
    *start = a;
    *end = z;
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

double ist_original_forward(const IstOriginal& ist, double u) {
    IstPoint point;
    ist_original_start(ist, u, &point);
    for (int k = 1; k <= ist.iterations; ++k) ist_original_step(ist, &point);
    // the steps' roundings can leave u an ulp above 1 (or below 0): the axis is [0, 1]
    return point.u < 0.0 ? 0.0 : (point.u > 1.0 ? 1.0 : point.u);
}

double ist_original_inverse(const IstOriginal& ist, double q) {
    if (!(q > 0.0)) q = 0.0;
    if (q > 1.0) q = 1.0;
    for (int k = ist.iterations; k >= 1; --k) {
        Origin o = origin_of(ist, q);
        double a = 0.0, z = 0.0;
        locate(ist, o.compressed, k - 1, &a, &z);  // the parent sub-interval on u^{k-1}
        const int n = 2 * ist_original_crossing(ist, o.source) + 1;
        // The part o.part of [a, z), at the same relative place as `compressed` in [a, z).
        double rel = z > a ? (o.compressed - a) / (z - a) : 0.0;  // never 0 / 0
        rel = rel < 0.0 ? 0.0 : (rel > 1.0 ? 1.0 : rel);
        q = a + (z - a) * (double(o.part) + rel) / double(n);
    }
    return q;
}

namespace {
Status check_original_input(const IstOriginal& ist, double u, const double* out) {
    SHITSUKAN_TRY(ist_original_check(ist));
    if (!(u >= 0.0 && u <= 1.0))
        return Status::error(StatusCode::out_of_range,
                             "original IST: u must be in [0, 1] (got %g)", u);
    if (out == nullptr)
        return Status::error(StatusCode::invalid_argument, "original IST: out must not be null");
    return Status::success();
}
}  // namespace

Status ist_original_forward_checked(const IstOriginal& ist, double u, double* out) {
    SHITSUKAN_TRY(check_original_input(ist, u, out));
    *out = ist_original_forward(ist, u);
    return Status::success();
}

Status ist_original_inverse_checked(const IstOriginal& ist, double u, double* out) {
    SHITSUKAN_TRY(check_original_input(ist, u, out));
    *out = ist_original_inverse(ist, u);
    return Status::success();
}

}  // namespace shitsukan
