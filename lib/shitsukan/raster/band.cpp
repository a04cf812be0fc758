// small-device: yes (no allocation, no exceptions)
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

#include "shitsukan/raster/rasterizer.hpp"

namespace shitsukan {

FrameBand full_frame_band(const RgbView& color, const FloatView& depth) {
    return make_band(color, depth, 0, color.width, color.height);
}

FrameBand make_band(const RgbView& color, const FloatView& depth, int y0, int frame_width,
                    int frame_height) {
    FrameBand band;
    band.color = color;
    band.depth = depth;
    band.y0 = y0;
    band.frame_width = frame_width;
    band.frame_height = frame_height;
    return band;
}

namespace {

// One row of colour: the first pixel set, then doubled by copying what is already written
// (memcpy of 3, 6, 12, ... bytes: the C library's word copies instead of a store per pixel,
// which was 12 instructions per pixel on a Cortex-M4F).
void fill_color_row(Rgb8* row, int width, Rgb8 value) {
    row[0] = value;
    int done = 1;
    while (done < width) {
        const int n = done < width - done ? done : width - done;
        std::memcpy(row + done, row, std::size_t(n) * sizeof(Rgb8));
        done += n;
    }
}

// One row of depth: +inf, eight pixels a step (a store per pixel was five instructions per
// pixel on a Cortex-M4F, the C library's word copies about three).
void fill_depth_row(float* row, int width) {
    const float inf = std::numeric_limits<float>::infinity();
    float* p = row;
    for (float* const end = row + (width & ~7); p != end; p += 8) {
        p[0] = inf;
        p[1] = inf;
        p[2] = inf;
        p[3] = inf;
        p[4] = inf;
        p[5] = inf;
        p[6] = inf;
        p[7] = inf;
    }
    for (float* const end = row + width; p != end; ++p) *p = inf;
}

}  // namespace

// Depth +inf: any finite fragment depth is nearer than an empty pixel. Row by row (a band's
// rows are its stride apart); the first colour row is copied to the others whole. A stride
// below the width (a view validate_band refuses) makes rows overlap, which memcpy must not
// copy: each row is then filled on its own (the same bytes).
void clear_band(const FrameBand& band, Rgb8 background) {
    if (!band.color.empty()) {
        fill_color_row(band.color.row(0), band.color.width, background);
        const bool disjoint_rows = band.color.stride >= band.color.width;
        for (int y = 1; y < band.color.height; ++y) {
            if (disjoint_rows)
                std::memcpy(band.color.row(y), band.color.row(0),
                            std::size_t(band.color.width) * sizeof(Rgb8));
            else
                fill_color_row(band.color.row(y), band.color.width, background);
        }
    }
    if (!band.depth.empty())
        for (int y = 0; y < band.depth.height; ++y)
            fill_depth_row(band.depth.row(y), band.depth.width);
}

}  // namespace shitsukan

namespace shitsukan {

namespace {
bool finite_matrix(const Mat4& m) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!is_finite(m.m[i][j])) return false;
    return true;
}

// Bit for bit (a -0 entry is not the identity's +0: its inverse could carry signed zeros).
bool is_identity(const Mat4& m) {
    const Mat4 identity = Mat4::identity();
    return std::memcmp(&m, &identity, sizeof m) == 0;
}
}  // namespace

Status validate_band(const Camera& camera, const FrameBand& band) {
    if (camera.width < 1 || camera.height < 1 || camera.width > kMaxFrameSize ||
        camera.height > kMaxFrameSize)
        return Status::error(StatusCode::invalid_argument,
                             "camera frame is %d x %d pixels; each side must be in [1, %d]",
                             camera.width, camera.height, kMaxFrameSize);
    if (!finite_matrix(camera.view) || !finite_matrix(camera.projection))
        return Status::error(StatusCode::invalid_argument,
                             "camera view or projection matrix has a NaN/inf entry");
    if (band.color.empty() || band.depth.empty())
        return Status::error(StatusCode::invalid_argument,
                             "band is empty (colour %d x %d, depth %d x %d): nothing to draw into",
                             band.color.width, band.color.height, band.depth.width,
                             band.depth.height);
    if (band.color.width != band.depth.width || band.color.height != band.depth.height)
        return Status::error(StatusCode::invalid_argument,
                             "band colour buffer is %d x %d but its depth buffer is %d x %d",
                             band.color.width, band.color.height, band.depth.width,
                             band.depth.height);
    // Rows are pixels + y·stride: a stride below the width would make rows overlap and the
    // last one run past the caller's buffer.
    if (band.color.stride < band.color.width || band.depth.stride < band.depth.width)
        return Status::error(StatusCode::invalid_argument,
                             "band strides must be >= the width %d (colour stride %d, depth "
                             "stride %d)",
                             band.color.width, band.color.stride, band.depth.stride);
    if (band.frame_width != camera.width || band.frame_height != camera.height)
        return Status::error(StatusCode::invalid_argument,
                             "band belongs to a %d x %d frame but the camera's frame is %d x %d",
                             band.frame_width, band.frame_height, camera.width, camera.height);
    if (band.color.width != band.frame_width)
        return Status::error(StatusCode::invalid_argument,
                             "band is %d pixels wide; a band spans the whole frame width %d",
                             band.color.width, band.frame_width);
    // Written as a difference: y0 + height could overflow int for a y0 near INT_MAX.
    if (band.y0 < 0 || band.y0 > band.frame_height ||
        band.color.height > band.frame_height - band.y0)
        return Status::error(StatusCode::invalid_argument,
                             "band rows [%d, %lld) are outside the frame rows [0, %d)", band.y0,
                             static_cast<long long>(band.y0) + band.color.height,
                             band.frame_height);
    return Status::success();
}

Status validate_mesh_arrays(const MeshView& mesh) {
    if (mesh.triangle_count < 0 || mesh.vertex_count < 0)
        return Status::error(StatusCode::invalid_argument,
                             "mesh has %d triangles and %d vertices; counts must be >= 0",
                             mesh.triangle_count, mesh.vertex_count);
    if (mesh.triangle_count == 0) return Status::success();
    if (mesh.indices == nullptr || mesh.positions == nullptr || mesh.vertex_count == 0)
        return Status::error(StatusCode::invalid_argument,
                             "mesh has %d triangles but %s", mesh.triangle_count,
                             mesh.indices == nullptr ? "no index array" : "no vertices");
    return Status::success();
}

Status validate_mesh(const MeshView& mesh) {
    SHITSUKAN_TRY(validate_mesh_arrays(mesh));
    // size_t: 3·triangle_count can exceed INT_MAX (and a 32-bit long).
    const std::size_t n = 3 * std::size_t(mesh.triangle_count);
    // The largest index first, without a branch per index (bin_mesh runs this once per frame,
    // draw_mesh once per band); the first bad index is looked for only when there is one.
    std::uint32_t largest = 0;
    for (const std::uint32_t *index = mesh.indices, *const end = index + n; index != end; ++index)
        largest = *index > largest ? *index : largest;
    if (largest < std::uint32_t(mesh.vertex_count)) return Status::success();
    for (std::size_t i = 0; i < n; ++i)
        if (mesh.indices[i] >= std::uint32_t(mesh.vertex_count))
            return Status::error(StatusCode::invalid_argument,
                                 "triangle %lld corner %d has index %u, out of range for %d "
                                 "vertices",
                                 static_cast<long long>(i / 3), int(i % 3),
                                 unsigned(mesh.indices[i]), mesh.vertex_count);
    return Status::success();
}

Status validate_model(const Mat4& model, Mat4& normal_matrix) {
    // The identity (DrawOptions' default model) is its own inverse transpose: inverse() would
    // give it exactly (cofactors 0 and 1, determinant 1), after about 5,000 instructions of
    // software double on a Cortex-M4F, once per band.
    if (is_identity(model)) {
        normal_matrix = Mat4::identity();
        return Status::success();
    }
    bool ok = finite_matrix(model);
    Mat4 inv = ok ? inverse(model, &ok) : Mat4::identity();
    if (!ok)
        return Status::error(StatusCode::invalid_argument,
                             "model matrix is singular or has a NaN/inf entry");
    normal_matrix = transpose(inv);  // normals transform by the inverse transpose
    return Status::success();
}

}  // namespace shitsukan
