// shitsukan/solid/lattice_type2.hpp — okada1989 §3-2 Type II: evaluate single lattice nodes
// on demand, keeping the nodes already computed (the queried nodes' ancestors) in a list.
// Host side (std::unordered_map).
//
// Manual
//   FractalParams p;                 // R = 6
//   TypeIILattice lattice;
//   Status s = lattice.init(p);      // hash or sequential noise
//   if (!s) return s;
//   float v = lattice.node_value(10, 20, 30);
//   float d = lattice.turbulence(Vec3{10.5f, 20.25f, 30.0f});   // eq. (6), clamped
//   std::size_t held = lattice.list_size();   // nodes held so far; list_bytes() their payload
//
// A node's value needs its parents (eqs. (1)-(4)), theirs, and so on up to the corners:
// at most 27 nodes a level. Each computed node is kept so that it keeps its random number
// g: with NoiseSource::sequential, g is drawn from Pcg32(seed) when the node is first
// computed, so the values depend on the order of the queries and the list can never be
// cleared (okada1989: memory O(2^{3R}) with a small coefficient). With NoiseSource::hash
// the list is only a cache and the values equal Types I and III bit for bit.
// Deviation: the paper searches the list exhaustively ("総当たり"); this list is a hash map
// (O(1) lookup), otherwise checking all 65^3 nodes would take O(n^2) time.
// R: 0..20 (node coordinates are packed into 21 bits each).
#pragma once

#include <cstdint>
#include <unordered_map>

#include "shitsukan/core/prng.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"
#include "shitsukan/solid/fractal_params.hpp"

namespace shitsukan {

constexpr int kTypeIIMaxDepth = 20;

class TypeIILattice {
public:
    Status init(const FractalParams& params);
    void clear();  // forget every node (sequential noise then restarts its stream)

    int depth() const { return params_.R; }
    float node_value(std::int32_t x, std::int32_t y, std::int32_t z);  // asserts the range
    // Also refuses (too_large) when the list after this query could outgrow the memory
    // budget (core/memory_budget.hpp; 32 bytes a node and 16 of buckets counted).
    Status node_value_checked(std::int32_t x, std::int32_t y, std::int32_t z, float& out);
    float turbulence(Vec3 p);

    std::size_t list_size() const { return list_.size(); }
    // Payload of the list: per node its packed coordinates (8 bytes) and value (4 bytes).
    std::size_t list_bytes() const {
        return list_.size() * (sizeof(std::uint64_t) + sizeof(float));
    }
    // What the list really occupies, container overhead included: the hash map's bucket array
    // plus one heap node per entry (next pointer, key, value), each allocation rounded as a
    // glibc-style malloc does (8-byte header, 16-byte granularity, 32 bytes at least): 32
    // bytes a node on a 64-bit libstdc++, 2.7x the payload, plus 8 bytes a bucket.
    std::size_t container_bytes() const;

private:
    Status check_list_growth() const;
    float compute(std::int32_t x, std::int32_t y, std::int32_t z);

    FractalParams params_;
    bool ready_ = false;
    float amplitude_[kTypeIIMaxDepth + 1] = {};
    Pcg32 rng_;
    std::unordered_map<std::uint64_t, float> list_;
};

}  // namespace shitsukan
