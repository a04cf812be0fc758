// small-device: yes (Type III lattice: hash-addressed nodes, O(R) state, no allocation)
#include "shitsukan/solid/lattice_type3.hpp"

#include "shitsukan/core/assert.hpp"
#include "shitsukan/solid/fractal_node.hpp"
#include "shitsukan/solid/turbulence.hpp"

namespace shitsukan {
namespace {
inline int grid_index(int a, int b, int c) { return a + 3 * b + 9 * c; }
}  // namespace

Status TypeIIILattice::init(const FractalParams& params) {
    SHITSUKAN_TRY(validate_fractal_params(params, kTypeIIIMaxDepth));
    if (params.noise != NoiseSource::hash)
        return Status::error(StatusCode::not_supported,
                             "Type III lattice: needs NoiseSource::hash (a sequential stream "
                             "depends on the order of queries)");
    R_ = params.R;
    seed_ = params.seed;
    for (int n = 1; n <= R_; ++n) amplitude_[n] = level_amplitude(n, params.beta);
    // Level 0: the initial cube and its eight given corner values.
    cells_[0].x0 = cells_[0].y0 = cells_[0].z0 = 0;
    for (int i = 0; i < 8; ++i) cells_[0].corner[i] = params.corners[i];
    cached_depth_ = 0;
    subdivisions_ = 0;
    return Status::success();
}

// One recursion level on one cell (okada1987 §2.2 steps (1)-(3)): the cell of level n-1 is
// split into 27 nodes on a 3x3x3 grid (h apart); the sub-cell (ox, oy, oz) becomes level n.
void TypeIIILattice::subdivide(int n, std::int32_t ox, std::int32_t oy, std::int32_t oz) {
    const Cell& parent = cells_[n - 1];
    const std::int32_t h = std::int32_t(1) << (R_ - n);
    const float amplitude = amplitude_[n];
    float grid[27];
    auto g = [&](int a, int b, int c) {
        return node_gaussian(seed_, parent.x0 + a * h, parent.y0 + b * h, parent.z0 + c * h) *
               amplitude;
    };
    // The parent's corners sit at the even grid positions.
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                grid[grid_index(2 * i, 2 * j, 2 * k)] = parent.corner[i + 2 * j + 4 * k];
    // Step (1), eq. (1): the 12 edge midpoints (one grid index is 1).
    for (int c = 0; c < 3; ++c)
        for (int b = 0; b < 3; ++b)
            for (int a = 0; a < 3; ++a) {
                int odd = (a == 1) + (b == 1) + (c == 1);
                if (odd != 1) continue;
                float lo, hi;
                if (a == 1) {
                    lo = grid[grid_index(0, b, c)], hi = grid[grid_index(2, b, c)];
                } else if (b == 1) {
                    lo = grid[grid_index(a, 0, c)], hi = grid[grid_index(a, 2, c)];
                } else {
                    lo = grid[grid_index(a, b, 0)], hi = grid[grid_index(a, b, 2)];
                }
                grid[grid_index(a, b, c)] = edge_midpoint(lo, hi, g(a, b, c));
            }
    // Step (2), eq. (3): the 6 face centres from the face's four edge midpoints, in the
    // order (first odd axis -, +, second odd axis -, +).
    for (int c = 0; c < 3; ++c)
        for (int b = 0; b < 3; ++b)
            for (int a = 0; a < 3; ++a) {
                int odd = (a == 1) + (b == 1) + (c == 1);
                if (odd != 2) continue;
                float e[4];
                if (a != 1) {  // odd axes y, z
                    e[0] = grid[grid_index(a, 0, 1)], e[1] = grid[grid_index(a, 2, 1)];
                    e[2] = grid[grid_index(a, 1, 0)], e[3] = grid[grid_index(a, 1, 2)];
                } else if (b != 1) {  // odd axes x, z
                    e[0] = grid[grid_index(0, b, 1)], e[1] = grid[grid_index(2, b, 1)];
                    e[2] = grid[grid_index(1, b, 0)], e[3] = grid[grid_index(1, b, 2)];
                } else {  // odd axes x, y
                    e[0] = grid[grid_index(0, 1, c)], e[1] = grid[grid_index(2, 1, c)];
                    e[2] = grid[grid_index(1, 0, c)], e[3] = grid[grid_index(1, 2, c)];
                }
                grid[grid_index(a, b, c)] = face_centre(e, g(a, b, c));
            }
    // Step (3), eq. (4): the centre from the six face centres x-, x+, y-, y+, z-, z+.
    const float faces[6] = {grid[grid_index(0, 1, 1)], grid[grid_index(2, 1, 1)],
                            grid[grid_index(1, 0, 1)], grid[grid_index(1, 2, 1)],
                            grid[grid_index(1, 1, 0)], grid[grid_index(1, 1, 2)]};
    grid[grid_index(1, 1, 1)] = cube_centre(faces, g(1, 1, 1));

    Cell& child = cells_[n];
    child.x0 = parent.x0 + ox * h;
    child.y0 = parent.y0 + oy * h;
    child.z0 = parent.z0 + oz * h;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                child.corner[i + 2 * j + 4 * k] = grid[grid_index(ox + i, oy + j, oz + k)];
    ++subdivisions_;
}

const float* TypeIIILattice::descend_to_unit_cell(std::int32_t ix, std::int32_t iy,
                                                  std::int32_t iz) {
    for (int n = 1; n <= R_; ++n) {
        const std::int32_t size = std::int32_t(1) << (R_ - n);  // cell edge at level n
        const std::int32_t x0 = ix & ~(size - 1), y0 = iy & ~(size - 1), z0 = iz & ~(size - 1);
        if (n <= cached_depth_ && cells_[n].x0 == x0 && cells_[n].y0 == y0 && cells_[n].z0 == z0)
            continue;  // the ancestry cached from the previous query still holds this point
        const Cell& parent = cells_[n - 1];
        subdivide(n, (x0 - parent.x0) / size, (y0 - parent.y0) / size, (z0 - parent.z0) / size);
        cached_depth_ = n;
    }
    return cells_[R_].corner;
}

float TypeIIILattice::node_value(std::int32_t x, std::int32_t y, std::int32_t z) {
    SHITSUKAN_ASSERT(R_ >= 0);
    const std::int32_t last = std::int32_t(1) << R_;
    SHITSUKAN_ASSERT(x >= 0 && y >= 0 && z >= 0 && x <= last && y <= last && z <= last);
    // The unit cell whose lower corner is the node (the last node uses the last cell).
    const std::int32_t ix = x < last ? x : last - 1, iy = y < last ? y : last - 1,
                       iz = z < last ? z : last - 1;
    if (R_ == 0) return cells_[0].corner[x + 2 * y + 4 * z];
    const float* corner = descend_to_unit_cell(ix, iy, iz);
    return corner[(x - ix) + 2 * (y - iy) + 4 * (z - iz)];
}

Status TypeIIILattice::node_value_checked(std::int32_t x, std::int32_t y, std::int32_t z,
                                          float* out) {
    if (R_ < 0) return Status::error(StatusCode::invalid_argument, "Type III lattice: not initialised");
    const std::int32_t last = std::int32_t(1) << R_;
    if (x < 0 || y < 0 || z < 0 || x > last || y > last || z > last)
        return Status::error(StatusCode::out_of_range,
                             "Type III lattice: node (%d, %d, %d) is outside [0, %d]^3", int(x),
                             int(y), int(z), int(last));
    if (out == nullptr) return Status::error(StatusCode::invalid_argument, "out must not be null");
    *out = node_value(x, y, z);
    return Status::success();
}

float TypeIIILattice::turbulence(Vec3 p) {
    SHITSUKAN_ASSERT(R_ >= 0);
    const int cells = 1 << R_;
    int ix, iy, iz;
    float fx, fy, fz;
    split_lattice_coordinate(p.x, cells, &ix, &fx);
    split_lattice_coordinate(p.y, cells, &iy, &fy);
    split_lattice_coordinate(p.z, cells, &iz, &fz);
    const float* corner = R_ == 0 ? cells_[0].corner : descend_to_unit_cell(ix, iy, iz);
    return trilinear_corners(corner, fx, fy, fz);
}

Status TypeIIILattice::turbulence_checked(Vec3 p, float* out) {
    if (R_ < 0) return Status::error(StatusCode::invalid_argument, "Type III lattice: not initialised");
    if (out == nullptr) return Status::error(StatusCode::invalid_argument, "out must not be null");
    SHITSUKAN_TRY(check_lattice_point(p, R_));
    *out = turbulence(p);
    return Status::success();
}

}  // namespace shitsukan
