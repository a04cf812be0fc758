// ports/web/api/api_okada1989.cpp — the C API of the okada1989 panel: lattice Types I, II
// and III (§2-1, §3-2, §3-3) giving the same D(P) at the same points, with the memory each
// holds and the time each takes per point. The backward (pixel-shift) mapping of §4-1 is
// sk_okada1987_mapping (api_okada1987.cpp), drawn beside okada1987's forward reading.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "api_common.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/core/prng.hpp"
#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/solid/lattice_type2.hpp"
#include "shitsukan/solid/lattice_type3.hpp"
#include "shitsukan/solid/turbulence.hpp"

using namespace shitsukan;

namespace {

// The query points: pattern 0 a raster row of n pixels across the lattice at y = z = 2^R/2 +
// 0.3 (coherent, as a renderer asks), pattern 1 n points drawn uniformly from the lattice by
// Pcg32(11, 5) (scattered; the seed of the okada1989 table-types figure).
std::vector<Vec3> query_points(int R, int n, int pattern) {
    const float top = float(std::int64_t(1) << R);
    std::vector<Vec3> pts(static_cast<std::size_t>(n));
    Pcg32 rng(11u, 5u);
    for (int i = 0; i < n; ++i)
        pts[std::size_t(i)] = pattern == 0
                                  ? Vec3{top * (float(i) + 0.5f) / float(n), 0.5f * top + 0.3f, 0.5f * top + 0.3f}
                                  : Vec3{rng.uniform(0.0f, top), rng.uniform(0.0f, top), rng.uniform(0.0f, top)};
    return pts;
}

void append_number(std::string& t, const char* key, double value) {
    char buf[80];
    std::snprintf(buf, sizeof buf, ",\"%s\":%.6g", key, value);
    t += buf;
}

}  // namespace

// D(P) at n points by Type I (FractalLattice: the whole array), Type II (TypeIILattice: the
// ancestors in a list) and Type III (TypeIIILattice: no table; with and without its reuse of
// the ancestry). Floats: 3n values, Type I's n, then II's, then III's (NaN where a type
// refused the depth). Text: each type's Status message, bytes held and milliseconds per point,
// and how many of the n values agree bit for bit between the types that ran.
// Returns the first refusal's code when no type could run, else 0.
SK_API int sk_okada1989_types(int R, float beta, unsigned seed, int n, int pattern) {
    FractalParams p;
    p.R = R;
    p.beta = beta;
    p.seed = seed;
    Status s = validate_fractal_params(p, kTypeIIIMaxDepth);
    if (s && (n < 1 || n > 200000))
        s = Status::error(StatusCode::invalid_argument, "points must be in 1..200000 (got %d)", n);
    if (s && (pattern < 0 || pattern > 1))
        s = Status::error(StatusCode::invalid_argument, "pattern must be 0 (row) or 1 (scattered) (got %d)", pattern);
    if (!s) return skweb::finish(s);
    const std::vector<Vec3> pts = query_points(R, n, pattern);
    std::vector<float>& out = skweb::floats();
    out.assign(3 * std::size_t(n), NAN);
    std::string& t = skweb::text();
    t = "{\"n\":" + std::to_string(n);

    double t0 = skweb::now_ms();
    FractalLattice type1;
    Status s1 = validate_fractal_params(p, kTypeIMaxDepth);
    if (s1) s1 = type1.build(p);
    const double build_ms = skweb::now_ms() - t0;
    if (s1) {
        t0 = skweb::now_ms();
        turbulence_points(type1.view(), pts.data(), pts.size(), out.data());
        append_number(t, "I_ms_per_point", (skweb::now_ms() - t0) / n);
        append_number(t, "I_build_ms", build_ms);
        append_number(t, "I_bytes", double(type1.bytes()));
    }
    t += ",\"I_status\":" + skweb::json_string(s1.message());

    // Type II keeps every node it computes. Chosen here: its run is refused beforehand (with
    // the budget's message) when n points could need more than the budget, counting at most
    // 27 new nodes per level per point and 48 bytes a held node (TypeIILattice's own 32 per
    // node and 16 of buckets): a hung or aborted worker is worse than a skipped column.
    TypeIILattice type2;
    Status s2 = check_memory_budget(budget_mul(budget_mul(std::uint64_t(n), 27u * std::uint64_t(R > 0 ? R : 1)), 48u),
                                    "the Type II list for these points");
    if (s2) s2 = type2.init(p);
    if (s2) {
        t0 = skweb::now_ms();
        for (int i = 0; i < n && s2; ++i) out[std::size_t(n + i)] = type2.turbulence(pts[std::size_t(i)]);
        append_number(t, "II_ms_per_point", (skweb::now_ms() - t0) / n);
        append_number(t, "II_nodes", double(type2.list_size()));
        append_number(t, "II_bytes", double(type2.list_bytes()));
        append_number(t, "II_container_bytes", double(type2.container_bytes()));
    }
    t += ",\"II_status\":" + skweb::json_string(s2.message());

    static TypeIIILattice type3;  // 10.9 KB: kept off the stack
    Status s3 = type3.init(p);
    if (s3) {
        type3.set_reuse(true);
        t0 = skweb::now_ms();
        for (int i = 0; i < n; ++i) out[std::size_t(2 * n + i)] = type3.turbulence(pts[std::size_t(i)]);
        append_number(t, "III_ms_per_point", (skweb::now_ms() - t0) / n);
        append_number(t, "III_subdivisions", double(type3.subdivisions()));
        append_number(t, "III_ancestry_bytes", double(type3.ancestry_bytes()));
        append_number(t, "III_bytes", double(TypeIIILattice::object_bytes()));
        Status again = type3.init(p);  // okada1989's own Type III: every query from the top
        if (again) {
            type3.set_reuse(false);
            t0 = skweb::now_ms();
            float sink = 0.0f;
            for (int i = 0; i < n; ++i) sink += type3.turbulence(pts[std::size_t(i)]);
            append_number(t, "III_noreuse_ms_per_point", (skweb::now_ms() - t0) / n);
            append_number(t, "III_noreuse_subdivisions", double(type3.subdivisions()));
            append_number(t, "III_noreuse_sum", double(sink));
        }
    }
    t += ",\"III_status\":" + skweb::json_string(s3.message());

    int agree = 0;
    for (int i = 0; i < n; ++i) {
        const float a = out[std::size_t(i)], b = out[std::size_t(n + i)], c = out[std::size_t(2 * n + i)];
        const bool ab = !s1 || std::memcmp(&a, &b, sizeof a) == 0;
        const bool bc = std::memcmp(&b, &c, sizeof b) == 0;
        if (ab && bc) ++agree;
    }
    append_number(t, "agree", agree);
    t += "}";
    skweb::set_float_columns(n);
    if (!s1 && !s2 && !s3) return skweb::finish(s1);
    return skweb::finish(Status::success());
}
