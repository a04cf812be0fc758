// hirota1998 §4: the four-layer bark over several cycles (see layered_bark.hpp).
#include "shitsukan/bark/layered_bark.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {

constexpr float kNever = std::numeric_limits<float>::infinity();
constexpr float kRegulariser = 1e-6f;  // a debonded surface node keeps this much of k_sh
constexpr float kNeverTension = 1e30f;  // ties break by shear strain, never by tension

int key_column(std::uint64_t key) { return int(key >> 32); }
int key_row(std::uint64_t key) { return int((key >> 2) & 0x3fffffffu); }
int key_dir(std::uint64_t key) { return int(key & 3u); }

}  // namespace

Status validate(const LayeredParams& p) {
    SHITSUKAN_TRY(validate(p.species));
    if (p.N_R < 4 || p.N_R > 1024 || p.N_R % 2 != 0 || p.N_H < 2 || p.N_H > 1024)
        return Status::error(StatusCode::invalid_argument,
                             "layered bark: N_R must be even in [4, 1024] and N_H in [2, 1024] "
                             "(got %d x %d)",
                             p.N_R, p.N_H);
    const LayerSchedule& s = p.schedule;
    auto positive = [](float x) { return is_finite(x) && x > 0.0f; };
    if (!positive(s.R_in0) || !positive(s.D) || !positive(s.T) || !is_finite(s.delta_R) ||
        s.delta_R < 0.0f)
        return Status::error(StatusCode::invalid_argument,
                             "layered bark: R_in0, D, T must be > 0 and delta_R >= 0 (got %g, "
                             "%g, %g, %g)",
                             double(s.R_in0), double(s.D), double(s.T), double(s.delta_R));
    if (!is_finite(p.axial_growth) || p.axial_growth < 0.0f)
        return Status::error(StatusCode::invalid_argument,
                             "layered bark: axial growth must be >= 0 (got %g)",
                             double(p.axial_growth));
    if (!(is_finite(p.sigma) && p.sigma >= 0.0f && p.sigma < 0.3f))
        return Status::error(StatusCode::invalid_argument,
                             "layered bark: sigma must be in [0, 0.3) (got %g)", double(p.sigma));
    const PeelingParams& q = p.peeling;
    if (!positive(q.kappa_h) || !is_finite(q.eta) || q.eta < 0.0f ||
        !(is_finite(q.gamma) && q.gamma >= 0.0f && q.gamma < 1.0f) ||
        !(is_finite(q.A) && q.A >= 1.0f) || q.dt_ref_steps < 1)
        return Status::error(StatusCode::invalid_argument,
                             "layered bark: Table 4 needs kappa_h > 0, eta >= 0, gamma in [0, 1), "
                             "A >= 1 (got %g, %g, %g, %g)",
                             double(q.kappa_h), double(q.eta), double(q.gamma), double(q.A));
    if (p.cycles < 1 || p.cycles > 100 || p.spin_up_cycles < 0 || p.spin_up_cycles >= p.cycles ||
        p.steps_per_cycle < 1 || p.steps_per_cycle > 10000)
        return Status::error(StatusCode::invalid_argument,
                             "layered bark: cycles in [1, 100], spin-up < cycles, steps per cycle "
                             "in [1, 10000] (got %d, %d, %d)",
                             p.cycles, p.spin_up_cycles, p.steps_per_cycle);
    if (!(is_finite(p.tolerance) && p.tolerance > 0.0f && p.tolerance <= 0.1f))
        return Status::error(StatusCode::invalid_argument,
                             "layered bark: tolerance must be in (0, 0.1] (got %g)",
                             double(p.tolerance));
    return Status::success();
}

Status LayeredBark::build(const LayeredParams& params) {
    SHITSUKAN_TRY(validate(params));
    *this = LayeredBark{};
    params_ = params;
    // One layer's lattice, areas and constants: the two-layer cylinder's builder on the patch.
    CylinderParams cp;
    cp.species = params.species;
    cp.N_R = params.N_R, cp.N_H = params.N_H;
    cp.D = params.schedule.D;
    cp.sigma = params.sigma;
    cp.seed = params.seed;
    SHITSUKAN_TRY(build_cylinder(cp, lattice_));
    n_ = lattice_.net.node_count();
    m_ = lattice_.net.spring_count();

    // Both mechanical layers in one network: slot 0 nodes [0, n), slot 1 [n, 2n); lattice
    // springs of slot 0, of slot 1, then two ties per node (x and y: together an isotropic
    // zero-length shear spring between the surface node and the middle (1) node below).
    net_.dim = 2;
    for (int slot = 0; slot < 2; ++slot)
        for (int p = 0; p < n_; ++p) {
            net_.X.push_back(lattice_.net.X[std::size_t(p)]);
            const float k_sh = lattice_.net.k_anchor[std::size_t(p)];
            net_.k_anchor.push_back(slot == surface_slot_ ? kRegulariser * k_sh : k_sh);
        }
    for (int slot = 0; slot < 2; ++slot)
        for (int s = 0; s < m_; ++s) {
            BarkSpring sp = lattice_.net.springs[std::size_t(s)];
            sp.i += std::uint32_t(slot * n_), sp.j += std::uint32_t(slot * n_);
            sp.key |= std::uint64_t(slot + 1) << 60;
            sp.growth_rate = 0.0f;
            net_.springs.push_back(sp);
        }
    for (int p = 0; p < n_; ++p)
        for (int axis = 0; axis < 2; ++axis) {
            BarkSpring tie;
            tie.i = std::uint32_t(p), tie.j = std::uint32_t(n_ + p);
            tie.n = axis == 0 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
            tie.l0 = 1.0f;
            tie.k = lattice_.net.k_anchor[std::size_t(p)];  // k_sh = G·A/D
            tie.eps_c = kNeverTension;
            tie.family = 3;
            tie.key = (std::uint64_t(3) << 60) | (std::uint64_t(p) << 1) | std::uint64_t(axis);
            net_.springs.push_back(tie);
        }
    SHITSUKAN_TRY(finalize_network(net_));

    // Birth at t = 0: the surface and middle (1) both stress-free.
    const LayerRadii r0 = layer_radii(params.schedule, 0.0f);
    birth_radius_[surface_slot_] = r0.surface;
    birth_radius_[1 - surface_slot_] = r0.middle1;
    birth_scale_[0] = birth_scale_[1] = 1.0f;
    for (int slot = 0; slot < 2; ++slot)
        for (int s = 0; s < m_; ++s) {
            BarkSpring& sp = net_.springs[std::size_t(lattice_spring(slot, s))];
            const float kappa = sp.family == 1 ? params.species.kappa1 : params.species.kappa2;
            sp.eps_c = spring_critical_strain(kappa, params.sigma, params.seed, key_column(sp.key),
                                              key_row(sp.key), key_dir(sp.key), generation_[slot]);
        }
    alive_.assign(std::size_t(n_), 1);
    bonded_.assign(std::size_t(n_), 1);
    dry_.assign(std::size_t(n_), 0);
    source_done_.assign(std::size_t(m_ + n_), 0);
    kappa_h_.resize(std::size_t(n_));
    for (int p = 0; p < n_; ++p) {
        const float g = clamp(hash_gaussian(params.seed, kStreamShearThresholds,
                                            lattice_.column_of(p), lattice_.row_of(p),
                                            generation_[surface_slot_]),
                              -3.0f, 3.0f);
        kappa_h_[std::size_t(p)] = params.peeling.kappa_h * std::max(0.05f, 1.0f + params.sigma * g);
    }
    // Tolerance: tau·L0 times the strain scale of one cycle (0.02).
    tol_ = params.tolerance * params.species.L0 * 0.02f;
    return Status::success();
}

float LayeredBark::axial_scale(float t) const {
    return 1.0f + params_.axial_growth * t / params_.schedule.T;
}

// §4.1: each layer is pulled by the growth of the layers below it, relative to its birth.
void LayeredBark::set_loads(float t) {
    const LayerRadii r = layer_radii(params_.schedule, t);
    float a[2], b[2];
    for (int slot = 0; slot < 2; ++slot) {
        const float radius = slot == surface_slot_ ? r.surface : r.middle1;
        a[slot] = radius / birth_radius_[slot] - 1.0f;         // hoop growth strain
        b[slot] = axial_scale(t) / birth_scale_[slot] - 1.0f;  // axial growth strain
    }
    for (int s = 0; s < 2 * m_; ++s) {
        BarkSpring& sp = net_.springs[std::size_t(s)];
        const int slot = s / m_;
        sp.growth_rate = a[slot] * sp.n.x * sp.n.x + b[slot] * sp.n.y * sp.n.y;
    }
    for (NetworkEntry& e : net_.adj)
        if (e.s < std::uint32_t(2 * m_) && e.k > 0.0f) {
            const BarkSpring& sp = net_.springs[e.s];
            e.load = e.k * sp.l0 * sp.growth_rate;
        }
}

Status LayeredBark::relax_all() {
    std::vector<std::uint32_t> seeds;
    seeds.reserve(std::size_t(2 * n_));
    for (int q = 0; q < 2 * n_; ++q)
        if (q / n_ != surface_slot_ || alive_[std::size_t(q % n_)]) seeds.push_back(std::uint32_t(q));
    touched_.clear();
    return relax(net_, seeds.data(), int(seeds.size()), tol_, &touched_);
}

float LayeredBark::tension_ratio(int s) const {
    const BarkSpring& sp = net_.springs[std::size_t(s)];
    if (!sp.intact()) return 0.0f;
    const float e = strain_rate(net_, std::uint32_t(s));  // here: the strain itself
    return e > 0.0f ? e / sp.eps_c : 0.0f;
}

// §4.2: the shear strain between the surface node and the middle (1) node below, over D.
float LayeredBark::shear_ratio(int p) const {
    if (!alive_[std::size_t(p)] || !bonded_[std::size_t(p)]) return 0.0f;
    const Vec3 d = net_.W[std::size_t(lattice_node(surface_slot_, p))] -
                   net_.W[std::size_t(lattice_node(1 - surface_slot_, p))];
    return length(d) / params_.schedule.D / kappa_h_[std::size_t(p)];
}

void LayeredBark::debond(int p) {
    if (!bonded_[std::size_t(p)]) return;
    bonded_[std::size_t(p)] = 0;
    for (int axis = 0; axis < 2; ++axis) {
        const std::uint32_t t = std::uint32_t(tie_spring(p, axis));
        if (net_.springs[t].intact()) break_spring(net_, t, 0.0f);
    }
}

void LayeredBark::break_surface_spring(int s, float t) {
    const std::uint32_t ns = std::uint32_t(lattice_spring(surface_slot_, s));
    if (net_.springs[ns].intact()) break_spring(net_, ns, t);
}

// The four-layer bark as break_loop.hpp's model, within one step at time t: items are the
// lattice springs of both layers, then one shear tie per node; an item's value is 1 / (its
// strain over its threshold), due below 1, so the largest ratio goes first. A spring event
// breaks that spring; a tie event debonds every surface node past its threshold together.
struct LayeredBark::Events {
    LayeredBark* bark;
    float t;

    float value(std::uint32_t i) const {
        const int m2 = 2 * bark->m_;
        const float ratio =
            int(i) < m2 ? bark->tension_ratio(int(i)) : bark->shear_ratio(int(i) - m2);
        return ratio > 0.0f ? 1.0f / ratio : kNever;
    }
    bool due(float v) const { return v < 1.0f; }  // some ratio > 1
    float apply(std::uint32_t top, float, std::vector<std::uint32_t>& seeds) {
        SpringNetwork& net = bark->net_;
        if (top < std::uint32_t(2 * bark->m_)) {
            const BarkSpring& sp = net.springs[top];
            break_spring(net, top, t);
            seeds = {std::min(sp.i, sp.j), std::max(sp.i, sp.j)};
            return t;
        }
        for (int p = 0; p < bark->n_; ++p)
            if (bark->shear_ratio(p) > 1.0f) {
                bark->debond(p);
                ++bark->step_debonded_;
                seeds.push_back(std::uint32_t(bark->lattice_node(0, p)));
                seeds.push_back(std::uint32_t(bark->lattice_node(1, p)));
            }
        std::sort(seeds.begin(), seeds.end());
        return t;
    }
    // A moved node changes its tie's shear ratio and its lattice springs' tension ratios.
    void affected(const std::vector<std::uint32_t>& touched, AffectedItems& add) const {
        const SpringNetwork& net = bark->net_;
        const std::uint32_t m2 = std::uint32_t(2 * bark->m_), n = std::uint32_t(bark->n_);
        for (std::uint32_t q : touched) {
            add(m2 + q % n);  // its tie
            for (std::uint32_t e = net.adj_begin[q]; e < net.adj_begin[q + 1]; ++e)
                if (net.adj[e].s < m2) add(net.adj[e].s);
        }
    }
};

// Springs past their threshold break one at a time, largest ratio first; shear springs past
// theirs debond together (break_loop.hpp). Growth, drying and peeling since the last call
// changed ratios anywhere: every value is reloaded first (only the changed leaves re-sorted).
Status LayeredBark::break_until_stable(float t) {
    const int items = 2 * m_ + n_;  // lattice springs of both layers, then one tie per node
    Events model{this, t};
    std::vector<std::uint64_t> keys;
    if (loop_.tree().size() != items) {  // the first call: the tree's ties, once per run
        keys.resize(std::size_t(items));
        for (int i = 0; i < items; ++i)
            keys[std::size_t(i)] = i < 2 * m_ ? net_.springs[std::size_t(i)].key
                                              : (std::uint64_t(3) << 60) | (std::uint64_t(i - 2 * m_) << 1);
    }
    loop_.load(items, [keys](std::uint32_t i) { return keys[i]; }, model);
    const Status s = loop_.run(net_, model, tol_, observer_);
    if (!s) return Status::error(s.code(), "layered bark at t = %g: %s", double(t), s.message());
    return s;
}

// §4.2: the drying zone is everything within eta of a crack or of a debonded or peeled place.
void LayeredBark::update_drying_zone() {
    const float eta = params_.peeling.eta;
    const float a_h = lattice_.a_h, L0 = params_.species.L0;
    const float period = float(params_.N_R) * a_h;
    // The window in cells, at most the lattice (a wider one adds no node; eta is any finite
    // value >= 0, and eta / L0 past INT_MAX would be undefined as an int).
    const float cells_c = std::ceil(eta / a_h) + 1.0f, cells_r = std::ceil(eta / L0) + 1.0f;
    const int wc = cells_c < float(params_.N_R) ? int(cells_c) : params_.N_R;
    const int wr = cells_r < float(params_.N_H) ? int(cells_r) : params_.N_H;
    auto spread = [&](Vec3 source, int c0, int r0) {
        for (int dc = -wc; dc <= wc; ++dc)
            for (int dr = -wr; dr <= wr; ++dr) {
                const int c = ((c0 + dc) % params_.N_R + params_.N_R) % params_.N_R;
                const int r = r0 + dr;
                if (r < 0 || r >= params_.N_H) continue;
                const int q = lattice_.node(c, r);
                Vec3 d = lattice_.net.X[std::size_t(q)] - source;
                d.x -= period * std::round(d.x / period);
                if (length(d) <= eta) dry_[std::size_t(q)] = 1;
            }
    };
    for (int s = 0; s < m_; ++s) {
        if (source_done_[std::size_t(s)]) continue;
        const BarkSpring& sp = net_.springs[std::size_t(lattice_spring(surface_slot_, s))];
        if (sp.intact()) continue;
        source_done_[std::size_t(s)] = 1;
        const BarkSpring& ref = lattice_.net.springs[std::size_t(s)];
        const Vec3 mid = lattice_.net.X[ref.i] + ref.n * (0.5f * ref.l0);
        spread(mid, lattice_.column_of(int(ref.i)), lattice_.row_of(int(ref.i)));
    }
    for (int p = 0; p < n_; ++p) {
        if (source_done_[std::size_t(m_ + p)] || (alive_[std::size_t(p)] && bonded_[std::size_t(p)]))
            continue;
        source_done_[std::size_t(m_ + p)] = 1;
        spread(lattice_.net.X[std::size_t(p)], lattice_.column_of(p), lattice_.row_of(p));
    }
}

// "over a time dt the critical shear strain decreases by the fraction gamma": exponential in t.
void LayeredBark::apply_drying(float dt) {
    const float dt_ref = params_.schedule.T / float(params_.peeling.dt_ref_steps);
    const float factor = float(det_exp(double(dt / dt_ref) * det_log(1.0 - double(params_.peeling.gamma))));
    for (int p = 0; p < n_; ++p)
        if (dry_[std::size_t(p)] && alive_[std::size_t(p)] && bonded_[std::size_t(p)])
            kappa_h_[std::size_t(p)] *= factor;
}

// §4.2: a region of the surface bounded by cracks falls off when region / bonded area > A.
int LayeredBark::peel_regions(float t) {
    std::vector<std::int32_t> parent(static_cast<std::size_t>(n_));
    for (int p = 0; p < n_; ++p) parent[std::size_t(p)] = p;
    auto find = [&](int a) {
        while (parent[std::size_t(a)] != a) {
            parent[std::size_t(a)] = parent[std::size_t(parent[std::size_t(a)])];
            a = parent[std::size_t(a)];
        }
        return a;
    };
    for (const ConnectionTriangle& tri : lattice_.triangles) {  // strong connectivity
        bool intact = true;
        for (int k = 0; k < 3; ++k)
            intact = intact && alive_[tri.node[k]] &&
                     net_.springs[std::size_t(lattice_spring(surface_slot_, int(tri.spring[k])))].intact();
        if (!intact) continue;
        for (int k = 1; k < 3; ++k) {
            const int a = find(int(tri.node[0])), b = find(int(tri.node[k]));
            if (a != b) parent[std::size_t(std::max(a, b))] = std::min(a, b);
        }
    }
    std::vector<double> area(static_cast<std::size_t>(n_), 0.0), bonded(static_cast<std::size_t>(n_), 0.0);
    for (int p = 0; p < n_; ++p) {
        if (!alive_[std::size_t(p)]) continue;
        const int root = find(p);
        area[std::size_t(root)] += lattice_.node_area[std::size_t(p)];
        if (bonded_[std::size_t(p)]) bonded[std::size_t(root)] += lattice_.node_area[std::size_t(p)];
    }
    const double A = params_.peeling.A;
    std::vector<std::uint8_t> falls(static_cast<std::size_t>(n_), 0);
    int regions = 0;
    for (int p = 0; p < n_; ++p)
        if (alive_[std::size_t(p)] && find(p) == p && area[std::size_t(p)] > 0.0 &&
            (bonded[std::size_t(p)] == 0.0 || area[std::size_t(p)] > A * bonded[std::size_t(p)]))
            falls[std::size_t(p)] = 1, ++regions;
    for (int p = 0; p < n_; ++p) {
        if (!alive_[std::size_t(p)] || !falls[std::size_t(find(p))]) continue;
        alive_[std::size_t(p)] = 0;  // removed: the layer below shows
        debond(p);
        const int q = lattice_node(surface_slot_, p);
        for (std::uint32_t e = net_.adj_begin[std::size_t(q)]; e < net_.adj_begin[std::size_t(q) + 1]; ++e)
            if (net_.adj[e].s < std::uint32_t(2 * m_) && net_.springs[net_.adj[e].s].intact())
                break_spring(net_, net_.adj[e].s, t);
    }
    return regions;
}

// §4.1: at every cycle the surface falls off, middle (1) becomes the surface, middle (2)
// becomes a new middle (1).
void LayeredBark::role_change(float t) {
    const int old_surface = surface_slot_;
    surface_slot_ = 1 - surface_slot_;
    // The new surface (old middle (1)): bonded everywhere (its bond to middle (2) never broke),
    // fresh critical shear strains, a drying zone seeded from its existing cracks.
    for (int p = 0; p < n_; ++p) {
        net_.k_anchor[std::size_t(lattice_node(surface_slot_, p))] =
            kRegulariser * lattice_.net.k_anchor[std::size_t(p)];
        for (int axis = 0; axis < 2; ++axis) restore_spring(net_, std::uint32_t(tie_spring(p, axis)));
        alive_[std::size_t(p)] = 1, bonded_[std::size_t(p)] = 1, dry_[std::size_t(p)] = 0;
        const float g = clamp(hash_gaussian(params_.seed, kStreamShearThresholds,
                                            lattice_.column_of(p), lattice_.row_of(p),
                                            generation_[surface_slot_]),
                              -3.0f, 3.0f);
        kappa_h_[std::size_t(p)] =
            params_.peeling.kappa_h * std::max(0.05f, 1.0f + params_.sigma * g);
    }
    std::fill(source_done_.begin(), source_done_.end(), std::uint8_t(0));
    reset_middle1(old_surface, t);
    update_drying_zone();
}

// A new middle (1) in `slot`: stress-free now, every spring intact with fresh thresholds.
void LayeredBark::reset_middle1(int slot, float t) {
    generation_[slot] = std::max(generation_[0], generation_[1]) + 1;
    const LayerRadii r = layer_radii(params_.schedule, t);
    birth_radius_[slot] = r.middle1;
    birth_scale_[slot] = axial_scale(t);
    for (int s = 0; s < m_; ++s) {
        const std::uint32_t ns = std::uint32_t(lattice_spring(slot, s));
        BarkSpring& sp = net_.springs[ns];
        const float kappa = sp.family == 1 ? params_.species.kappa1 : params_.species.kappa2;
        sp.eps_c = spring_critical_strain(kappa, params_.sigma, params_.seed, key_column(sp.key),
                                          key_row(sp.key), key_dir(sp.key), generation_[slot]);
        sp.growth_rate = 0.0f;
        restore_spring(net_, ns);
    }
    for (int p = 0; p < n_; ++p) {
        const int q = lattice_node(slot, p);
        net_.W[std::size_t(q)] = Vec3{};
        net_.k_anchor[std::size_t(q)] = lattice_.net.k_anchor[std::size_t(p)];
    }
}

Status LayeredBark::step(float t, float dt) {
    step_peeled_ = 0, step_debonded_ = 0;
    set_loads(t);
    SHITSUKAN_TRY(relax_all());
    SHITSUKAN_TRY(break_until_stable(t));
    update_drying_zone();
    apply_drying(dt);
    step_peeled_ = peel_regions(t);
    if (step_peeled_ > 0) {
        SHITSUKAN_TRY(relax_all());
        SHITSUKAN_TRY(break_until_stable(t));
        update_drying_zone();
    }
    return Status::success();
}

void LayeredBark::keep_record(float t, int peeled, int debonded, bool role_change_now) {
    LayeredStep r;
    r.t = t;
    double total = 0, alive = 0, bonded = 0;
    for (int p = 0; p < n_; ++p) {
        const double a = lattice_.node_area[std::size_t(p)];
        total += a;
        if (alive_[std::size_t(p)]) alive += a;
        if (alive_[std::size_t(p)] && bonded_[std::size_t(p)]) bonded += a;
    }
    r.alive_fraction = float(alive / total);
    r.bonded_fraction = float(bonded / total);
    for (int s = 0; s < m_; ++s) {
        r.surface_broken += !net_.springs[std::size_t(lattice_spring(surface_slot_, s))].intact();
        r.middle1_broken += !net_.springs[std::size_t(lattice_spring(1 - surface_slot_, s))].intact();
    }
    r.peeled_regions = peeled;
    r.debonded = debonded;
    r.role_change = role_change_now;
    record_.push_back(r);
}

void LayeredBark::keep_frame(float t, bool before) {
    LayerFrame f;
    f.t = t;
    f.before_role_change = before;
    f.generation_surface = generation_[surface_slot_];
    f.generation_middle1 = generation_[1 - surface_slot_];
    f.surface_alive = alive_;
    f.surface_bonded = bonded_;
    f.surface_broken.resize(std::size_t(m_));
    f.middle1_broken.resize(std::size_t(m_));
    for (int s = 0; s < m_; ++s) {
        f.surface_broken[std::size_t(s)] =
            !net_.springs[std::size_t(lattice_spring(surface_slot_, s))].intact();
        f.middle1_broken[std::size_t(s)] =
            !net_.springs[std::size_t(lattice_spring(1 - surface_slot_, s))].intact();
    }
    const LayerRadii r = layer_radii(params_.schedule, t, before);
    for (int slot : {surface_slot_, 1 - surface_slot_}) {
        const float radius = slot == surface_slot_ ? r.surface : r.middle1;
        const float hoop = radius / birth_radius_[slot], axial = axial_scale(t) / birth_scale_[slot];
        std::vector<Vec3>& out = slot == surface_slot_ ? f.surface_position : f.middle1_position;
        (slot == surface_slot_ ? f.surface_period : f.middle1_period) =
            float(params_.N_R) * lattice_.a_h * hoop;
        out.resize(std::size_t(n_));
        for (int p = 0; p < n_; ++p) {
            const Vec3 x = lattice_.net.X[std::size_t(p)];
            out[std::size_t(p)] = Vec3{x.x * hoop, x.y * axial, 0.0f} +
                                  net_.W[std::size_t(lattice_node(slot, p))];
        }
    }
    frames_.push_back(std::move(f));
}

Status LayeredBark::run(const FrameRequest* frames, int frame_count, void (*progress)(float, void*),
                        void* user) {
    if (n_ == 0) return Status::error(StatusCode::invalid_argument, "layered bark: build() first");
    if (frame_count < 0 || (frame_count > 0 && !frames))
        return Status::error(StatusCode::invalid_argument, "layered bark: %d frames, no array",
                             frame_count);
    const float T = params_.schedule.T;
    const int steps = params_.steps_per_cycle;
    const float dt = T / float(steps);
    int next = 0;
    auto take = [&](float t, bool at_role_change, bool before) {
        while (next < frame_count && std::fabs(frames[next].t - t) <= 0.5f * dt &&
               (!at_role_change || frames[next].before_role_change == before)) {
            keep_frame(t, frames[next].before_role_change);
            ++next;
        }
    };
    keep_record(0.0f, 0, 0, false);
    for (int k = 0; k < params_.cycles; ++k)
        for (int i = 1; i <= steps; ++i) {
            const float t = T * float(k * steps + i) / float(steps);
            SHITSUKAN_TRY(step(t, dt));
            const bool change = i == steps && k + 1 < params_.cycles;
            take(t, change, true);
            keep_record(t, step_peeled_, step_debonded_, false);
            if (change) {
                role_change(t);
                keep_record(t, 0, 0, true);
                take(t, true, false);
            }
            if (progress) progress(float(k * steps + i) / float(params_.cycles * steps), user);
        }
    if (next < frame_count)
        return Status::error(StatusCode::invalid_argument,
                             "layered bark: frame %d at t = %g was not reached (run ends at %g)",
                             next, double(frames[next].t), double(T * float(params_.cycles)));
    return Status::success();
}

int LayeredBark::regions_peeled_in_cycle(int cycle) const {
    const float T = params_.schedule.T;
    int n = 0;
    for (const LayeredStep& s : record_)
        if (!s.role_change && s.t > T * float(cycle) && s.t <= T * float(cycle + 1))
            n += s.peeled_regions;
    return n;
}

}  // namespace shitsukan
