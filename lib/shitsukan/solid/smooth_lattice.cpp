// Host side: the smoother refinement of the lattice (smooth_lattice.hpp).
#include "shitsukan/solid/smooth_lattice.hpp"

#include <cstddef>
#include <cstdint>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/solid/fractal_node.hpp"
#include "shitsukan/solid/lattice_store.hpp"

namespace shitsukan {
namespace {

struct Grid {
    float* v;
    int side, n;  // side = n + 1
    bool periodic;
    float& at(const int c[3]) const {
        return v[(std::size_t(c[2]) * std::size_t(side) + std::size_t(c[1])) * std::size_t(side) +
                 std::size_t(c[0])];
    }
};

// The mean of the parents of node c (fractal_node.hpp's order and operations).
float parent_mean(const LatticeView& l, const int c[3], const NodeClass& k) {
    float parents[6];
    for (int i = 0; i < 2 * k.odd_count; ++i) {
        const ParentStep p = parent_step(k.odd_axes, i);
        int q[3] = {c[0], c[1], c[2]};
        q[p.axis] += p.sign * k.half;
        parents[i] = l.at(q[0], q[1], q[2]);
    }
    return node_from_parents(k.odd_count, parents, 0.0f);
}

// The value of W at c moved by `offset` along `axis`; false when it leaves a clamped lattice.
bool neighbour(const Grid& g, const int c[3], int axis, int offset, float* out) {
    int q[3] = {c[0], c[1], c[2]};
    q[axis] += offset;
    if (g.periodic) {
        q[axis] = ((q[axis] % g.n) + g.n) % g.n;
    } else if (q[axis] < 0 || q[axis] > g.n) {
        return false;
    }
    *out = g.at(q);
    return true;
}

// The cubic prediction along one odd axis (four points, or three near a face, or two).
float predict_along(const Grid& g, const int c[3], int axis, int h) {
    float a = 0.0f, b = 0.0f, d = 0.0f, e = 0.0f;
    neighbour(g, c, axis, -h, &b);
    neighbour(g, c, axis, h, &d);
    const bool left = neighbour(g, c, axis, -3 * h, &a);
    const bool right = neighbour(g, c, axis, 3 * h, &e);
    if (left && right) return (9.0f * (b + d) - (a + e)) / 16.0f;
    if (left) return (6.0f * b + 3.0f * d - a) / 8.0f;
    if (right) return (6.0f * d + 3.0f * b - e) / 8.0f;
    return 0.5f * (b + d);
}

// Level n, the nodes with `odd_count` odd axes: W = prediction + the source's displacement.
void refine(const Grid& g, const LatticeView& source, int level, int odd_count) {
    const int h = 1 << (source.R - level);
    for (int z = 0; z <= g.n; z += h)
        for (int y = 0; y <= g.n; y += h)
            for (int x = 0; x <= g.n; x += h) {
                const int c[3] = {x, y, z};
                const NodeClass k = classify_node(source.R, x, y, z);
                if (k.level != level || k.odd_count != odd_count) continue;
                const float displacement = source.at(x, y, z) - parent_mean(source, c, k);
                float sum = 0.0f;
                for (int axis = 0; axis < 3; ++axis)
                    if (k.odd_axes & (1 << axis)) sum += predict_along(g, c, axis, h);
                g.at(c) = sum / float(odd_count) + displacement;
            }
}

}  // namespace

Status SmoothLattice::build(const LatticeView& source, LatticeWrap wrap) {
    if (source.values == nullptr || source.R < 0 || source.R > kTypeIMaxDepth ||
        source.side != (1 << source.R) + 1)
        return Status::error(StatusCode::invalid_argument,
                             "SmoothLattice::build: the source lattice is empty or not "
                             "(2^R + 1)^3 (R = %d, side %d)", source.R, source.side);
    SHITSUKAN_TRY(check_memory_budget(lattice_bytes(source.R), "smooth lattice"));
    const int n = 1 << source.R;
    values_.assign(std::size_t(source.side) * std::size_t(source.side) * std::size_t(source.side),
                   0.0f);
    const Grid g{values_.data(), source.side, n, wrap == LatticeWrap::periodic};
    for (int k = 0; k < 8; ++k) {
        const int c[3] = {(k & 1) * n, ((k >> 1) & 1) * n, ((k >> 2) & 1) * n};
        g.at(c) = source.at(c[0], c[1], c[2]);
    }
    for (int level = 1; level <= source.R; ++level)
        for (int odd = 1; odd <= 3; ++odd) refine(g, source, level, odd);
    view_ = LatticeView{values_.data(), source.R, source.side};
    return Status::success();
}

LatticeView SmoothLattice::view() const {
    SHITSUKAN_REQUIRE_BUILT(!values_.empty(), "SmoothLattice::build()", "SmoothLattice::view()");
    return view_;
}

}  // namespace shitsukan
