// shitsukan/bark/spring_network.hpp — hirota1998's layer of nodes, springs and shear springs,
// and its equilibrium (the quasi-static limit of the paper's spring-mass dynamics).
//
// Manual
//   SpringNetwork net;                             // two nodes, one spring
//   net.dim = 2;                                   // unwrapped cylinder: (u, z) per node
//   net.X = {{0, 0, 0}, {1, 0, 0}};                // reference positions
//   net.k_anchor = {1.0f, 1.0f};                   // shear springs
//   BarkSpring spring;                             // i, j, n, l0, k, growth_rate, eps_c, key
//   spring.i = 0;  spring.j = 1;  spring.n = {1, 0, 0};  spring.l0 = 1;  spring.k = 10;
//   spring.growth_rate = 0.01f;  spring.eps_c = 0.05f;  spring.key = 1;
//   net.springs = {spring};
//   Status s = finalize_network(net);              // CSR adjacency in canonical order
//   float tol = 1e-6f;
//   if (s) s = solve_full(net, tol, 1000);         // equilibrium of the intact network
//   const std::uint32_t seeds[2] = {0, 1};
//   std::vector<std::uint32_t> touched;
//   if (s) s = relax(net, seeds, 2, tol, &touched);  // after a break: only where it matters
//   float E = strain_rate(net, 0);                 // e_s(t) = t·E_s
//   return s;
//
// The model (§3.1): each layer is divided into small volumes, each a node; springs join
// nodes of a layer, shear springs join a node to the one beneath it. In the two-layer model
// the inner layer is moved by the growth ("grow every node in radius and height", §4.3); the
// surface node i sits on its anchor a_i(t), the point of the grown inner layer beneath it,
// through its shear spring k_anchor,i.
//
// Quasi-static and linear (chosen here; docs/papers/hirota1998.md §2): growth is slow next to any
// elastic wave, so the paper's damped dynamics settle into a sequence of equilibria, and with
// strains of a few percent the springs are linear about the reference lattice. With the anchors
// moving linearly in t, a node's position is x_i(t) = a_i(t) + t·W_i, where W (per unit time)
// minimises
//     Phi(W) = sum_s 1/2 k_s (l0_s·g_s + n_s·(W_j - W_i))^2 + sum_i 1/2 k_anchor,i |W_i|^2
// (g_s = the spring's growth strain rate, n_s its reference unit vector i -> j), and spring s
// has strain e_s(t) = t·E_s, E_s = g_s + n_s·(W_j - W_i)/l0_s. Phi is convex with an SPD
// Hessian while every node has k_anchor > 0.
//
// Solver: exact minimisation of Phi over one node at a time (block Gauss-Seidel; every update
// lowers Phi), driven by a FIFO queue of nodes whose neighbours moved by more than the
// tolerance, so a break re-solves only the neighbourhood it disturbs. Only +, -, *, / in
// float: the same bits on every IEEE machine. A node's springs are summed in the canonical
// order of their keys, never in storage order, so renumbering springs changes nothing.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct BarkSpring {
    std::uint32_t i = 0, j = 0;  // nodes; the reference unit direction n points i -> j
    Vec3 n;                      // (n_u, n_z, 0) on the cylinder
    float l0 = 0;                // rest length [cm]
    float k = 0;                 // stiffness k = E_f·S/l0 (connection_area.hpp)
    float growth_rate = 0;       // g_s: growth strain per unit time imposed by the anchors
    float eps_c = 0;             // critical strain kappa_s - 1
    std::uint64_t key = 0;       // canonical key (lattice coordinates): ties and sums use it
    float t_break = -1;          // time of the break; < 0 while intact
    std::uint8_t family = 0;     // 1 axial, 2 circumferential, 0 isotropic
    bool intact() const { return t_break < 0; }
};

// One adjacency entry of node p: its spring to q, the unit vector oriented p -> q.
struct NetworkEntry {
    std::uint32_t q = 0, s = 0;
    Vec3 n;
    float k = 0;     // 0 once the spring is broken
    float load = 0;  // k·l0·g: the spring's pull per unit time on the anchored layout
};

// Solver scratch: a node's stiffness block K_p, kept while k_anchor (the value it was made
// with; NaN = stale) and the node's springs do not change (spring_network.cpp, node_block).
struct NodeBlock {
    float m[7] = {0, 0, 0, 0, 0, 0, 0};
    float k_anchor = std::numeric_limits<float>::quiet_NaN();
};

struct SpringNetwork {
    int dim = 2;                         // 2 (unwrapped cylinder) or 3 (a mesh in space)
    std::vector<Vec3> X;                 // reference positions
    std::vector<float> k_anchor;         // shear spring of each node (> 0)
    std::vector<BarkSpring> springs;
    std::vector<Vec3> W;                 // displacement per unit time relative to the anchor
    // Canonical node keys (optional; empty = the node index). Sweeps and seeds go in this
    // order, so renumbering the nodes of a mesh changes no bit of the result.
    std::vector<std::uint64_t> node_key;
    std::vector<std::uint32_t> sweep_order;  // nodes sorted by key (finalize_network)
    // CSR adjacency built by finalize_network: node p's entries adj[adj_begin[p] ..
    // adj_begin[p + 1]), sorted by spring key.
    std::vector<std::uint32_t> adj_begin;
    std::vector<NetworkEntry> adj;
    // Solver scratch (FIFO queue of nodes, in-queue flags, touched list).
    std::vector<std::uint32_t> queue;
    std::vector<std::uint8_t> flags;
    std::vector<NodeBlock> blocks;
    std::uint64_t updates = 0;           // node updates so far (for the bench and tests)

    int node_count() const { return int(X.size()); }
    int spring_count() const { return int(springs.size()); }
};

// Checks sizes and values, builds the adjacency, sets W = 0.
Status finalize_network(SpringNetwork& net);

// Removes spring s for good (no healing, no contact): it exerts no force from now on.
void break_spring(SpringNetwork& net, std::uint32_t s, float t_break);

// Puts a broken spring back (a layer born anew, §4.1's role change): its force counts again.
void restore_spring(SpringNetwork& net, std::uint32_t s);

// Changes spring s's growth strain (rate) g_s and so its pull k·l0·g_s (stepped drivers whose
// loading is not linear in t).
void set_growth_rate(SpringNetwork& net, std::uint32_t s, float growth_rate);

// Minimises Phi over node p with the others fixed; returns |Delta W_p|^2.
float update_node(SpringNetwork& net, std::uint32_t p);

// Full Gauss-Seidel sweeps in node order until the largest update is below tol (or
// max_sweeps: then a not_supported Status says how far it got).
Status solve_full(SpringNetwork& net, float tol, int max_sweeps);

// Sorts nodes into canonical order (by node_key) in place.
void canonical_order(const SpringNetwork& net, std::uint32_t* nodes, int count);

// Residual-driven relaxation from the seed nodes (taken in the given order): a node that moves by more than tol pushes its
// intact neighbours. Nodes updated are appended to *touched once each (may be null). More
// than max_updates_per_node·N updates returns an error instead of looping forever.
Status relax(SpringNetwork& net, const std::uint32_t* seeds, int seed_count, float tol,
             std::vector<std::uint32_t>* touched, int max_updates_per_node = 200);

// E_s: the strain rate of spring s under the current W (e_s(t) = t·E_s).
inline float strain_rate(const SpringNetwork& net, std::uint32_t s) {
    const BarkSpring& sp = net.springs[s];
    return sp.growth_rate + dot(sp.n, net.W[sp.j] - net.W[sp.i]) / sp.l0;
}

// Phi(W) in double (tests).
double network_energy(const SpringNetwork& net);

// Largest |Delta W_p| a full update of every node would make (tests: the residual).
float max_residual(SpringNetwork& net);

}  // namespace shitsukan
