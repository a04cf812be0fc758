// hirota1998 §3: event-driven growth and cracking (see crack_events.hpp).
#include "shitsukan/bark/crack_events.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shitsukan/bark/break_loop.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {

constexpr float kNever = std::numeric_limits<float>::infinity();

// t_s = eps_c / E_s for an intact spring in tension, never otherwise.
float break_time(const SpringNetwork& net, std::uint32_t s) {
    const BarkSpring& sp = net.springs[s];
    if (!sp.intact()) return kNever;
    const float E = strain_rate(net, s);
    return E > 0.0f ? sp.eps_c / E : kNever;
}

void record_snapshot(const SpringNetwork& net, float t, int breaks, CrackRun* out) {
    CrackSnapshot snap;
    snap.t = t;
    snap.break_count = breaks;
    snap.W = net.W;
    out->snapshots.push_back(std::move(snap));
}

}  // namespace

namespace {
// The solver works in float: growth rates or moduli far beyond the bark's (fuzz_bark: delta_h =
// 3.7e19 cm/s) overflow the displacement field; that is refused, not returned as a result.
Status check_field(const std::vector<Vec3>& W, float t) {
    for (std::size_t p = 0; p < W.size(); ++p)
        if (!is_finite(W[p]))
            return Status::error(StatusCode::out_of_range,
                                 "run_cracking: the displacement of node %zu at t = %g overflowed "
                                 "a float (growth rates or moduli too large)",
                                 p, double(t));
    return Status::success();
}
}  // namespace

namespace {
// The two-layer cylinder as break_loop.hpp's model: items are the springs, a spring's value its
// break time t_s; an event breaks it at max(t, t_s) (a cascade when t_s < t), after taking the
// snapshots that come before it.
struct CylinderEvents {
    SpringNetwork* net;
    float T;
    const CrackRunOptions* options;
    CrackRun* out;
    float t = 0.0f, last_progress = 0.0f;
    int next_snapshot = 0;

    float value(std::uint32_t s) const { return break_time(*net, s); }
    bool due(float ts) const { return ts <= T; }
    float apply(std::uint32_t s, float ts, std::vector<std::uint32_t>& seeds) {
        if (ts < t) ++out->cascade_breaks;  // already past its threshold: breaks now
        t = std::max(t, ts);
        while (next_snapshot < options->snapshot_count &&
               options->snapshot_times[next_snapshot] < t)
            record_snapshot(*net, options->snapshot_times[next_snapshot++],
                            int(out->breaks.size()), out);
        break_spring(*net, s, t);
        out->breaks.push_back({s, t});
        const BarkSpring& sp = net->springs[s];
        seeds = {sp.i, sp.j};
        canonical_order(*net, seeds.data(), 2);
        if (options->progress && t - last_progress >= 0.05f * T) {
            last_progress = t;
            options->progress(t / T, options->progress_user);
        }
        return t;
    }
    // A moved node changes the break times of its intact springs.
    void affected(const std::vector<std::uint32_t>& touched, AffectedItems& add) const {
        for (std::uint32_t p : touched)
            for (std::uint32_t e = net->adj_begin[p]; e < net->adj_begin[p + 1]; ++e)
                if (net->adj[e].k > 0.0f) add(net->adj[e].s);
    }
};
}  // namespace

Status run_cracking(SpringNetwork& net, float T, float tol, const CrackRunOptions& options,
                    CrackRun& out) {
    if (!(is_finite(T) && T > 0.0f) || !(is_finite(tol) && tol > 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "run_cracking: T and the tolerance must be > 0 (got %g, %g)",
                             double(T), double(tol));
    if (options.snapshot_count < 0 || (options.snapshot_count > 0 && !options.snapshot_times))
        return Status::error(StatusCode::invalid_argument,
                             "run_cracking: %d snapshot times but no array",
                             options.snapshot_count);
    for (int i = 0; i < options.snapshot_count; ++i) {
        const float ts = options.snapshot_times[i];
        if (!(is_finite(ts) && ts > 0.0f && ts <= T) ||
            (i > 0 && !(ts > options.snapshot_times[i - 1])))
            return Status::error(StatusCode::invalid_argument,
                                 "run_cracking: snapshot times must ascend in (0, T = %g] "
                                 "(time %d is %g)",
                                 double(T), i, double(ts));
    }
    out = CrackRun{};
    out.tolerance = tol;
    const std::uint64_t updates0 = net.updates;

    // The intact network's equilibrium at unit growth (free edges make W != 0 from the start).
    SHITSUKAN_TRY(solve_full(net, tol, 100000));

    CylinderEvents model{&net, T, &options, &out};
    BreakLoop loop;
    loop.load(net.spring_count(), [&net](std::uint32_t s) { return net.springs[s].key; }, model);
    SHITSUKAN_TRY(loop.run(net, model, tol, options.observer));
    int next_snapshot = model.next_snapshot;
    while (next_snapshot < options.snapshot_count)
        record_snapshot(net, options.snapshot_times[next_snapshot++], int(out.breaks.size()),
                        &out);
    if (options.progress) options.progress(1.0f, options.progress_user);
    out.node_updates = net.updates - updates0;
    SHITSUKAN_TRY(check_field(net.W, T));
    for (const CrackSnapshot& snap : out.snapshots) SHITSUKAN_TRY(check_field(snap.W, snap.t));
    return Status::success();
}

Status grow_and_crack(BarkCylinder& bark, const CrackRunOptions& options, CrackRun& out) {
    float g_max = 0.0f;
    for (const BarkSpring& s : bark.net.springs) g_max = std::max(g_max, std::fabs(s.growth_rate));
    // Relaxation tolerance (docs/papers/hirota1998.md §2, "Relaxation tolerance"): tau·L0·max g_s,
    // in cm per unit time of W.
    const float tol = bark.params.tolerance * bark.params.species.L0 * g_max;
    return run_cracking(bark.net, bark.params.T, tol, options, out);
}

std::uint64_t break_sequence_hash(const SpringNetwork& net, const CrackRun& run, int count) {
    std::uint64_t h = hash_start(0x68697230u, 1998);  // "hir0"
    const int n = std::min(count, int(run.breaks.size()));
    for (int i = 0; i < n; ++i) h = hash_add(h, net.springs[run.breaks[i].spring].key);
    return hash_add(h, std::uint64_t(n));
}

}  // namespace shitsukan
