// hirota1998 §3.1: the spring layer's equilibrium, node by node (see spring_network.hpp).
#include "shitsukan/bark/spring_network.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {

constexpr std::uint8_t kInQueue = 1;
constexpr std::uint8_t kTouched = 2;

// Node p's block K_p = k_anchor·I + sum_s k_s n n^T (2D: kxx, kxy, kyy and det; 3D: the
// cofactors c00 c01 c02 c11 c12 c22 and det), summed over its entries in canonical order. It
// changes only when a spring at p breaks or comes back (break_spring, restore_spring mark it
// stale) or when k_anchor[p] changes (compared on use), so it is kept between updates: the
// same float operations in the same order as summing it afresh every time, done once.
const NodeBlock& node_block(SpringNetwork& net, std::uint32_t p) {
    NodeBlock& b = net.blocks[p];
    const float ka = net.k_anchor[p];
    if (b.k_anchor == ka) return b;  // stale blocks hold NaN, equal to nothing
    const NetworkEntry* e = net.adj.data() + net.adj_begin[p];
    const NetworkEntry* end = net.adj.data() + net.adj_begin[p + 1];
    if (net.dim == 2) {
        float kxx = ka, kxy = 0, kyy = ka;
        for (; e != end; ++e) {
            const float kx = e->k * e->n.x, ky = e->k * e->n.y;
            kxx += kx * e->n.x, kxy += kx * e->n.y, kyy += ky * e->n.y;
        }
        b.m[0] = kxx, b.m[1] = kxy, b.m[2] = kyy;
        b.m[6] = kxx * kyy - kxy * kxy;  // > 0: k_anchor > 0 makes K_p SPD
    } else {
        float kxx = ka, kxy = 0, kxz = 0, kyy = ka, kyz = 0, kzz = ka;
        for (; e != end; ++e) {
            const float kx = e->k * e->n.x, ky = e->k * e->n.y, kz = e->k * e->n.z;
            kxx += kx * e->n.x, kxy += kx * e->n.y, kxz += kx * e->n.z;
            kyy += ky * e->n.y, kyz += ky * e->n.z, kzz += kz * e->n.z;
        }
        // Cramer's rule on the symmetric 3 x 3 block.
        b.m[0] = kyy * kzz - kyz * kyz, b.m[1] = kxz * kyz - kxy * kzz,
        b.m[2] = kxy * kyz - kxz * kyy;
        b.m[3] = kxx * kzz - kxz * kxz, b.m[4] = kxy * kxz - kxx * kyz,
        b.m[5] = kxx * kyy - kxy * kxy;
        b.m[6] = kxx * b.m[0] + kxy * b.m[1] + kxz * b.m[2];
    }
    b.k_anchor = ka;
    return b;
}

void mark_stale(SpringNetwork& net, std::uint32_t p) {
    net.blocks[p].k_anchor = std::numeric_limits<float>::quiet_NaN();
}

// The minimiser of Phi over W_p with the other nodes fixed:
//   K_p W_p = b_p,  K_p = k_anchor·I + sum_s k_s n n^T,  b_p = sum_s (load_s + k_s n·W_q) n
// with n oriented p -> q (the derivative of 1/2 k (l0 g + n·W_q - n·W_p)^2 w.r.t. W_p).
// Every entry is summed, broken ones too (k = load = 0 adds a signed zero, as it always has).
Vec3 node_minimiser(SpringNetwork& net, std::uint32_t p) {
    const NodeBlock& K = node_block(net, p);
    const NetworkEntry* e = net.adj.data() + net.adj_begin[p];
    const NetworkEntry* end = net.adj.data() + net.adj_begin[p + 1];
    const Vec3* W = net.W.data();
    if (net.dim == 2) {
        float bx = 0, by = 0;
        for (; e != end; ++e) {
            const Vec3& q = W[e->q];
            const float f = e->load + e->k * (e->n.x * q.x + e->n.y * q.y);  // spring pull
            bx += f * e->n.x, by += f * e->n.y;
        }
        const float kxx = K.m[0], kxy = K.m[1], kyy = K.m[2], det = K.m[6];
        return {(kyy * bx - kxy * by) / det, (kxx * by - kxy * bx) / det, 0.0f};
    }
    float bx = 0, by = 0, bz = 0;
    for (; e != end; ++e) {
        const Vec3& q = W[e->q];
        const float f = e->load + e->k * (e->n.x * q.x + e->n.y * q.y + e->n.z * q.z);
        bx += f * e->n.x, by += f * e->n.y, bz += f * e->n.z;
    }
    const float c00 = K.m[0], c01 = K.m[1], c02 = K.m[2], c11 = K.m[3], c12 = K.m[4],
                c22 = K.m[5], det = K.m[6];
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
    net.blocks.assign(static_cast<std::size_t>(n), NodeBlock{});
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
    mark_stale(net, sp.i), mark_stale(net, sp.j);
    for (std::uint32_t p : {sp.i, sp.j})
        for (std::uint32_t e = net.adj_begin[p]; e < net.adj_begin[p + 1]; ++e)
            if (net.adj[e].s == s) net.adj[e].k = 0.0f, net.adj[e].load = 0.0f;
}

void restore_spring(SpringNetwork& net, std::uint32_t s) {
    BarkSpring& sp = net.springs[s];
    sp.t_break = -1.0f;
    mark_stale(net, sp.i), mark_stale(net, sp.j);
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

namespace {
// update_node's body, inlined into the solvers' loops.
inline float update_at(SpringNetwork& net, std::uint32_t p) {
    const Vec3 w = node_minimiser(net, p);
    const Vec3 d = w - net.W[p];
    net.W[p] = w;
    ++net.updates;
    return length_squared(d);
}
}  // namespace

float update_node(SpringNetwork& net, std::uint32_t p) { return update_at(net, p); }

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
        for (std::uint32_t p : net.sweep_order) worst = std::max(worst, update_at(net, p));
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
    // FIFO ring of at most n nodes (a node is queued at most once: the in-queue flag). The
    // arrays are held in locals: a store to the byte flags may alias any memory, so reading
    // them through `net` would reload every pointer after each flag write.
    std::uint8_t* const flags = net.flags.data();
    std::uint32_t* const queue = net.queue.data();
    const std::uint32_t* const adj_begin = net.adj_begin.data();
    std::uint32_t head = 0, size = 0;
    auto push = [&](std::uint32_t p) {
        if (flags[p] & kInQueue) return;
        flags[p] |= kInQueue;
        std::uint32_t slot = head + size;
        if (slot >= n) slot -= n;
        queue[slot] = p;
        ++size;
    };
    for (int i = 0; i < seed_count; ++i) push(seeds[i]);
    const std::uint64_t cap = std::uint64_t(max_updates_per_node) * n;
    std::uint64_t done = 0;
    while (size > 0) {
        const std::uint32_t p = queue[head];
        head = head + 1 == n ? 0 : head + 1;
        --size;
        flags[p] &= std::uint8_t(~kInQueue);
        if (touched && !(flags[p] & kTouched)) {
            flags[p] |= kTouched;
            touched->push_back(p);
        }
        if (update_at(net, p) > tol2) {
            const NetworkEntry* const adj = net.adj.data();
            for (std::uint32_t e = adj_begin[p], end = adj_begin[p + 1]; e < end; ++e)
                if (adj[e].k > 0.0f) push(adj[e].q);
        }
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
