// hirota1998 §3.1: the spring layer's equilibrium, node by node (see spring_network.hpp).
#include "shitsukan/bark/spring_network.hpp"

#include <algorithm>
#include <cmath>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {

constexpr std::uint8_t kInQueue = 1;
constexpr std::uint8_t kTouched = 2;

// The minimiser of Phi over W_p with the other nodes fixed:
//   K_p W_p = b_p,  K_p = k_anchor·I + sum_s k_s n n^T,  b_p = sum_s (load_s + k_s n·W_q) n
// with n oriented p -> q (the derivative of 1/2 k (l0 g + n·W_q - n·W_p)^2 w.r.t. W_p).
Vec3 node_minimiser(const SpringNetwork& net, std::uint32_t p) {
    const float ka = net.k_anchor[p];
    const NetworkEntry* e = net.adj.data() + net.adj_begin[p];
    const NetworkEntry* end = net.adj.data() + net.adj_begin[p + 1];
    if (net.dim == 2) {
        float kxx = ka, kxy = 0, kyy = ka, bx = 0, by = 0;
        for (; e != end; ++e) {
            const Vec3 q = net.W[e->q];
            const float f = e->load + e->k * (e->n.x * q.x + e->n.y * q.y);  // spring pull
            const float kx = e->k * e->n.x, ky = e->k * e->n.y;
            kxx += kx * e->n.x, kxy += kx * e->n.y, kyy += ky * e->n.y;
            bx += f * e->n.x, by += f * e->n.y;
        }
        const float det = kxx * kyy - kxy * kxy;  // > 0: k_anchor > 0 makes K_p SPD
        return {(kyy * bx - kxy * by) / det, (kxx * by - kxy * bx) / det, 0.0f};
    }
    float kxx = ka, kxy = 0, kxz = 0, kyy = ka, kyz = 0, kzz = ka, bx = 0, by = 0, bz = 0;
    for (; e != end; ++e) {
        const Vec3 q = net.W[e->q];
        const float f = e->load + e->k * (e->n.x * q.x + e->n.y * q.y + e->n.z * q.z);
        const float kx = e->k * e->n.x, ky = e->k * e->n.y, kz = e->k * e->n.z;
        kxx += kx * e->n.x, kxy += kx * e->n.y, kxz += kx * e->n.z;
        kyy += ky * e->n.y, kyz += ky * e->n.z, kzz += kz * e->n.z;
        bx += f * e->n.x, by += f * e->n.y, bz += f * e->n.z;
    }
    // Cramer's rule on the symmetric 3 x 3 block.
    const float c00 = kyy * kzz - kyz * kyz, c01 = kxz * kyz - kxy * kzz,
                c02 = kxy * kyz - kxz * kyy;
    const float c11 = kxx * kzz - kxz * kxz, c12 = kxy * kxz - kxx * kyz,
                c22 = kxx * kyy - kxy * kxy;
    const float det = kxx * c00 + kxy * c01 + kxz * c02;
    return {(c00 * bx + c01 * by + c02 * bz) / det, (c01 * bx + c11 * by + c12 * bz) / det,
            (c02 * bx + c12 * by + c22 * bz) / det};
}

}  // namespace

Status finalize_network(SpringNetwork& net) {
    const int n = net.node_count();
    if (net.dim != 2 && net.dim != 3)
        return Status::error(StatusCode::invalid_argument, "spring network: dim must be 2 or 3 "
                                                           "(got %d)", net.dim);
    if (int(net.k_anchor.size()) != n)
        return Status::error(StatusCode::invalid_argument,
                             "spring network: %zu anchor stiffnesses for %d nodes",
                             net.k_anchor.size(), n);
    for (int p = 0; p < n; ++p) {
        if (!is_finite(net.X[p]))
            return Status::error(StatusCode::invalid_argument,
                                 "spring network: node %d has a non-finite position", p);
        if (!(is_finite(net.k_anchor[p]) && net.k_anchor[p] > 0.0f))
            return Status::error(StatusCode::invalid_argument,
                                 "spring network: node %d needs a shear spring k > 0 (got %g)",
                                 p, double(net.k_anchor[p]));
    }
    std::vector<std::uint32_t> degree(std::size_t(n) + 1, 0);
    for (std::size_t s = 0; s < net.springs.size(); ++s) {
        const BarkSpring& sp = net.springs[s];
        if (sp.i >= std::uint32_t(n) || sp.j >= std::uint32_t(n) || sp.i == sp.j)
            return Status::error(StatusCode::invalid_argument,
                                 "spring network: spring %zu joins nodes %u and %u (have %d)", s,
                                 sp.i, sp.j, n);
        if (!(is_finite(sp.l0) && sp.l0 > 0.0f && is_finite(sp.k) && sp.k >= 0.0f &&
              is_finite(sp.growth_rate) && is_finite(sp.eps_c) && sp.eps_c > 0.0f &&
              is_finite(sp.n)))
            return Status::error(StatusCode::invalid_argument,
                                 "spring network: spring %zu has l0 %g, k %g, growth %g, eps_c "
                                 "%g (need l0 > 0, k >= 0, eps_c > 0, all finite)",
                                 s, double(sp.l0), double(sp.k), double(sp.growth_rate),
                                 double(sp.eps_c));
        ++degree[sp.i + 1];
        ++degree[sp.j + 1];
    }
    net.adj_begin.assign(std::size_t(n) + 1, 0);
    for (int p = 0; p < n; ++p) net.adj_begin[p + 1] = net.adj_begin[p] + degree[p + 1];
    net.adj.assign(net.adj_begin[n], NetworkEntry{});
    std::vector<std::uint32_t> fill(net.adj_begin.begin(), net.adj_begin.end() - 1);
    for (std::size_t s = 0; s < net.springs.size(); ++s) {
        const BarkSpring& sp = net.springs[s];
        const float k = sp.intact() ? sp.k : 0.0f;
        const float load = k * sp.l0 * sp.growth_rate;
        net.adj[fill[sp.i]++] = NetworkEntry{sp.j, std::uint32_t(s), sp.n, k, load};
        net.adj[fill[sp.j]++] = NetworkEntry{sp.i, std::uint32_t(s), -sp.n, k, load};
    }
    // Canonical order within each node: by spring key, so the float sums do not depend on how
    // the springs were numbered.
    for (int p = 0; p < n; ++p)
        std::sort(net.adj.begin() + net.adj_begin[p], net.adj.begin() + net.adj_begin[p + 1],
                  [&](const NetworkEntry& a, const NetworkEntry& b) {
                      return net.springs[a.s].key < net.springs[b.s].key;
                  });
    if (!net.node_key.empty() && int(net.node_key.size()) != n)
        return Status::error(StatusCode::invalid_argument,
                             "spring network: %zu node keys for %d nodes", net.node_key.size(), n);
    net.sweep_order.resize(static_cast<std::size_t>(n));
    for (int p = 0; p < n; ++p) net.sweep_order[std::size_t(p)] = std::uint32_t(p);
    canonical_order(net, net.sweep_order.data(), n);
    net.W.assign(static_cast<std::size_t>(n), Vec3{});
    net.flags.assign(static_cast<std::size_t>(n), 0);
    net.queue.assign(static_cast<std::size_t>(n), 0);
    net.updates = 0;
    return Status::success();
}

void canonical_order(const SpringNetwork& net, std::uint32_t* nodes, int count) {
    if (net.node_key.empty()) {
        std::sort(nodes, nodes + count);
        return;
    }
    std::sort(nodes, nodes + count, [&](std::uint32_t a, std::uint32_t b) {
        return net.node_key[a] != net.node_key[b] ? net.node_key[a] < net.node_key[b] : a < b;
    });
}

void break_spring(SpringNetwork& net, std::uint32_t s, float t_break) {
    BarkSpring& sp = net.springs[s];
    SHITSUKAN_ASSERT(sp.intact());
    sp.t_break = t_break;
    for (std::uint32_t p : {sp.i, sp.j})
        for (std::uint32_t e = net.adj_begin[p]; e < net.adj_begin[p + 1]; ++e)
            if (net.adj[e].s == s) net.adj[e].k = 0.0f, net.adj[e].load = 0.0f;
}

void restore_spring(SpringNetwork& net, std::uint32_t s) {
    BarkSpring& sp = net.springs[s];
    sp.t_break = -1.0f;
    const float load = sp.k * sp.l0 * sp.growth_rate;
    for (std::uint32_t p : {sp.i, sp.j})
        for (std::uint32_t e = net.adj_begin[p]; e < net.adj_begin[p + 1]; ++e)
            if (net.adj[e].s == s) net.adj[e].k = sp.k, net.adj[e].load = load;
}

void set_growth_rate(SpringNetwork& net, std::uint32_t s, float growth_rate) {
    BarkSpring& sp = net.springs[s];
    sp.growth_rate = growth_rate;
    if (!sp.intact()) return;
    const float load = sp.k * sp.l0 * growth_rate;
    for (std::uint32_t p : {sp.i, sp.j})
        for (std::uint32_t e = net.adj_begin[p]; e < net.adj_begin[p + 1]; ++e)
            if (net.adj[e].s == s) net.adj[e].load = load;
}

float update_node(SpringNetwork& net, std::uint32_t p) {
    const Vec3 w = node_minimiser(net, p);
    const Vec3 d = w - net.W[p];
    net.W[p] = w;
    ++net.updates;
    return length_squared(d);
}

float max_residual(SpringNetwork& net) {
    float worst = 0.0f;
    for (int p = 0; p < net.node_count(); ++p)
        worst = std::max(worst, length(node_minimiser(net, std::uint32_t(p)) - net.W[p]));
    return worst;
}

Status solve_full(SpringNetwork& net, float tol, int max_sweeps) {
    const float tol2 = tol * tol;
    float worst = 0.0f;
    for (int sweep = 0; sweep < max_sweeps; ++sweep) {
        worst = 0.0f;
        for (std::uint32_t p : net.sweep_order) worst = std::max(worst, update_node(net, p));
        if (worst <= tol2) return Status::success();
    }
    return Status::error(StatusCode::not_supported,
                         "spring network: no equilibrium after %d sweeps (last update %g, "
                         "tolerance %g)",
                         max_sweeps, std::sqrt(double(worst)), double(tol));
}

Status relax(SpringNetwork& net, const std::uint32_t* seeds, int seed_count, float tol,
             std::vector<std::uint32_t>* touched, int max_updates_per_node) {
    const std::uint32_t n = std::uint32_t(net.node_count());
    if (n == 0) return Status::success();
    const float tol2 = tol * tol;
    // FIFO ring of at most n nodes (a node is queued at most once: the in-queue flag).
    std::uint32_t head = 0, size = 0;
    auto push = [&](std::uint32_t p) {
        if (net.flags[p] & kInQueue) return;
        net.flags[p] |= kInQueue;
        std::uint32_t slot = head + size;
        if (slot >= n) slot -= n;
        net.queue[slot] = p;
        ++size;
    };
    for (int i = 0; i < seed_count; ++i) push(seeds[i]);
    const std::uint64_t cap = std::uint64_t(max_updates_per_node) * n;
    std::uint64_t done = 0;
    while (size > 0) {
        const std::uint32_t p = net.queue[head];
        head = head + 1 == n ? 0 : head + 1;
        --size;
        net.flags[p] &= std::uint8_t(~kInQueue);
        if (touched && !(net.flags[p] & kTouched)) {
            net.flags[p] |= kTouched;
            touched->push_back(p);
        }
        if (update_node(net, p) > tol2)
            for (std::uint32_t e = net.adj_begin[p]; e < net.adj_begin[p + 1]; ++e)
                if (net.adj[e].k > 0.0f) push(net.adj[e].q);
        if (++done > cap) {
            while (size > 0) {  // leave the flags clean
                net.flags[net.queue[head]] &= std::uint8_t(~kInQueue);
                head = head + 1 == n ? 0 : head + 1;
                --size;
            }
            if (touched)
                for (std::uint32_t t : *touched) net.flags[t] &= std::uint8_t(~kTouched);
            return Status::error(StatusCode::not_supported,
                                 "spring network: relaxation did not settle within %llu node "
                                 "updates (tolerance %g)",
                                 (unsigned long long)cap, double(tol));
        }
    }
    if (touched)
        for (std::uint32_t p : *touched) net.flags[p] &= std::uint8_t(~kTouched);
    return Status::success();
}

float strain_rate(const SpringNetwork& net, std::uint32_t s) {
    const BarkSpring& sp = net.springs[s];
    return sp.growth_rate + dot(sp.n, net.W[sp.j] - net.W[sp.i]) / sp.l0;
}

double network_energy(const SpringNetwork& net) {
    double phi = 0.0;
    for (const BarkSpring& sp : net.springs) {
        if (!sp.intact()) continue;
        const Vec3 d = net.W[sp.j] - net.W[sp.i];
        const double stretch = double(sp.l0) * double(sp.growth_rate) +
                               double(sp.n.x) * d.x + double(sp.n.y) * d.y + double(sp.n.z) * d.z;
        phi += 0.5 * double(sp.k) * stretch * stretch;
    }
    for (int p = 0; p < net.node_count(); ++p)
        phi += 0.5 * double(net.k_anchor[p]) * double(length_squared(net.W[p]));
    return phi;
}

}  // namespace shitsukan
