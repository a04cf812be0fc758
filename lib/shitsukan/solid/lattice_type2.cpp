// Host side: Type II keeps its list in a std::unordered_map.
#include "shitsukan/solid/lattice_type2.hpp"

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/solid/fractal_node.hpp"
#include "shitsukan/solid/turbulence.hpp"

namespace shitsukan {
namespace {
std::uint64_t pack(std::int32_t x, std::int32_t y, std::int32_t z) {
    return std::uint64_t(std::uint32_t(x)) | (std::uint64_t(std::uint32_t(y)) << 21) |
           (std::uint64_t(std::uint32_t(z)) << 42);
}
}  // namespace

Status TypeIILattice::init(const FractalParams& params) {
    SHITSUKAN_TRY(validate_fractal_params(params, kTypeIIMaxDepth));
    params_ = params;
    for (int n = 1; n <= params.R; ++n) amplitude_[n] = level_amplitude(n, params.beta);
    ready_ = true;
    clear();
    return Status::success();
}

void TypeIILattice::clear() {
    list_.clear();
    rng_ = Pcg32(params_.seed, kLatticeStream);
}

// The recursion of eqs. (1)-(4) from one node back to its ancestors.
float TypeIILattice::compute(std::int32_t x, std::int32_t y, std::int32_t z) {
    const int R = params_.R;
    const NodeClass c = classify_node(R, x, y, z);
    if (c.level == 0) {  // an initial corner
        const std::int32_t last = std::int32_t(1) << R;
        return params_.corners[(x == last) + 2 * (y == last) + 4 * (z == last)];
    }
    const std::uint64_t key = pack(x, y, z);
    auto found = list_.find(key);
    if (found != list_.end()) return found->second;

    // Parents first (recursively, in the parent rule's order), then the node's own g: the
    // order a sequential stream sees.
    float parents[6];
    for (int k = 0; k < 2 * c.odd_count; ++k) {
        const ParentStep p = parent_step(c.odd_axes, k);
        const std::int32_t d = p.sign * c.half;
        parents[k] = compute(x + (p.axis == 0 ? d : 0), y + (p.axis == 1 ? d : 0),
                             z + (p.axis == 2 ? d : 0));
    }
    const float g = params_.noise == NoiseSource::hash ? node_gaussian(params_.seed, x, y, z)
                                                       : rng_.gaussian();
    const float value = node_from_parents(c.odd_count, parents, g * amplitude_[c.level]);
    list_.emplace(key, value);
    return value;
}

float TypeIILattice::node_value(std::int32_t x, std::int32_t y, std::int32_t z) {
    SHITSUKAN_REQUIRE_BUILT(ready_, "TypeIILattice::init()", "a TypeIILattice");
    const std::int32_t last = std::int32_t(1) << params_.R;
    SHITSUKAN_ASSERT(x >= 0 && y >= 0 && z >= 0 && x <= last && y <= last && z <= last);
    return compute(x, y, z);
}

Status TypeIILattice::node_value_checked(std::int32_t x, std::int32_t y, std::int32_t z,
                                         float& out) {
    if (!ready_)
        return Status::error(StatusCode::invalid_argument, "Type II lattice: not initialised");
    const std::int32_t last = std::int32_t(1) << params_.R;
    if (x < 0 || y < 0 || z < 0 || x > last || y > last || z > last)
        return Status::error(StatusCode::out_of_range,
                             "Type II lattice: node (%d, %d, %d) is outside [0, %d]^3", int(x),
                             int(y), int(z), int(last));
    SHITSUKAN_TRY(check_list_growth());
    out = compute(x, y, z);
    return Status::success();
}

// A query adds at most 27 nodes a level (the node and its ancestors, R + 1 levels); the hash
// map may also double its bucket array. The list after the query must fit the memory budget
// (core/memory_budget.hpp): with sequential noise it can never be cleared, so a long run
// stops here with the byte count instead of dying of std::bad_alloc.
Status TypeIILattice::check_list_growth() const {
    const std::uint64_t nodes = budget_add(list_.size(), budget_mul(27, params_.R + 1));
    const std::uint64_t bytes = budget_add(budget_mul(nodes, 32), budget_mul(nodes, 2 * 8));
    return check_memory_budget(bytes, "Type II lattice: the list of computed nodes");
}

float TypeIILattice::turbulence(Vec3 p) {
    SHITSUKAN_REQUIRE_BUILT(ready_, "TypeIILattice::init()", "a TypeIILattice");
    const int cells = 1 << params_.R;
    int ix, iy, iz;
    float fx, fy, fz;
    split_lattice_coordinate(p.x, cells, &ix, &fx);
    split_lattice_coordinate(p.y, cells, &iy, &fy);
    split_lattice_coordinate(p.z, cells, &iz, &fz);
    float d[8];
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) d[i + 2 * j + 4 * k] = compute(ix + i, iy + j, iz + k);
    return trilinear_corners(d, fx, fy, fz);
}

std::size_t TypeIILattice::container_bytes() const {
    // One node of std::unordered_map<uint64_t, float>: the next pointer and the pair
    // (libstdc++ keeps no cached hash for std::hash<uint64_t>), then the malloc chunk.
    const std::size_t node = sizeof(void*) + sizeof(std::pair<const std::uint64_t, float>);
    std::size_t chunk = (node + sizeof(std::size_t) + 15) / 16 * 16;
    if (chunk < 32) chunk = 32;
    return list_.bucket_count() * sizeof(void*) + list_.size() * chunk;
}

}  // namespace shitsukan
