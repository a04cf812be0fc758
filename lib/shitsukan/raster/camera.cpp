// small-device: yes (no allocation, no exceptions)
#include "shitsukan/raster/camera.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>

namespace shitsukan {

// World -> eye: the eye at the origin looking down -z, y up (right-handed, as OpenGL's
// gluLookAt). Rows are the eye's side, up and back axes expressed in world coordinates.
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
    Vec3 f = normalize(target - eye);  // forward
    Vec3 s = normalize(cross(f, up));  // side (right)
    Vec3 u = cross(s, f);              // true up, orthogonal to f and s
    Mat4 r = Mat4::identity();
    r.m[0][0] = s.x;  r.m[0][1] = s.y;  r.m[0][2] = s.z;  r.m[0][3] = -dot(s, eye);
    r.m[1][0] = u.x;  r.m[1][1] = u.y;  r.m[1][2] = u.z;  r.m[1][3] = -dot(u, eye);
    r.m[2][0] = -f.x; r.m[2][1] = -f.y; r.m[2][2] = -f.z; r.m[2][3] = dot(f, eye);
    return r;
}

// Eye -> clip (OpenGL's gluPerspective): x_ndc = x_clip / w, w = -z_eye; z_ndc = -1 on the
// near plane and +1 on the far plane.
Camera perspective_camera(Vec3 eye, Vec3 target, Vec3 up, float fov_y_degrees, int width,
                          int height, float near_plane, float far_plane) {
    Camera c;
    c.view = look_at(eye, target, up);
    c.eye = eye;
    c.width = width;
    c.height = height;
    c.orthographic = false;
    float aspect = height > 0 ? float(width) / float(height) : 1.0f;
    float f = 1.0f / det_tan(fov_y_degrees * (kPi / 180.0f) * 0.5f);  // cot(fov / 2)
    Mat4 p;  // all zero
    p.m[0][0] = f / aspect;
    p.m[1][1] = f;
    p.m[2][2] = (far_plane + near_plane) / (near_plane - far_plane);
    p.m[2][3] = 2.0f * far_plane * near_plane / (near_plane - far_plane);
    p.m[3][2] = -1.0f;  // w_clip = -z_eye: the perspective divide
    c.projection = p;
    return c;
}

// Eye -> clip for a parallel projection (glOrtho, symmetric): w stays 1.
Camera orthographic_camera(Vec3 eye, Vec3 target, Vec3 up, float half_height, int width,
                           int height, float near_plane, float far_plane) {
    Camera c;
    c.view = look_at(eye, target, up);
    c.eye = eye;
    c.width = width;
    c.height = height;
    c.orthographic = true;
    float aspect = height > 0 ? float(width) / float(height) : 1.0f;
    float half_width = half_height * aspect;
    Mat4 p = Mat4::identity();
    p.m[0][0] = 1.0f / half_width;
    p.m[1][1] = 1.0f / half_height;
    p.m[2][2] = -2.0f / (far_plane - near_plane);
    p.m[2][3] = -(far_plane + near_plane) / (far_plane - near_plane);
    c.projection = p;
    return c;
}

namespace {

constexpr StatusCode kBad = StatusCode::invalid_argument;

bool finite_matrix(const Mat4& m) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!is_finite(m.m[i][j])) return false;
    return true;
}

bool row_is(const Mat4& m, int row, float a, float b, float c, float d) {
    return m.m[row][0] == a && m.m[row][1] == b && m.m[row][2] == c && m.m[row][3] == d;
}

Vec3 row3(const Mat4& m, int row) { return {m.m[row][0], m.m[row][1], m.m[row][2]}; }

// The inputs both builders share: frame, eye, target, up, near and far.
Status check_view_inputs(const char* who, Vec3 eye, Vec3 target, Vec3 up, int width,
                         int height, float near_plane, float far_plane) {
    if (width < 1 || height < 1)
        return Status::error(kBad, "%s: frame is %d x %d pixels; each side must be >= 1", who,
                             width, height);
    if (!is_finite(eye) || !is_finite(target) || !is_finite(up))
        return Status::error(kBad, "%s: eye, target and up must be finite (NaN/inf given)", who);
    Vec3 d = target - eye;
    if (!is_finite(d) || !(length_squared(d) > 0.0f))
        return Status::error(kBad, "%s: eye and target coincide at (%g, %g, %g): no view "
                             "direction", who, double(eye.x), double(eye.y), double(eye.z));
    // sin of the angle between up and the view direction (chosen here: >= 1e-3, 0.06 degrees;
    // below it the side axis cross(f, up) loses too many bits).
    float up_length = length(up);
    float sine = up_length > 0.0f ? length(cross(normalize(d), up / up_length)) : 0.0f;
    if (!(sine >= 1e-3f))
        return Status::error(kBad, "%s: up (%g, %g, %g) is zero or parallel to the view "
                             "direction (%g, %g, %g)", who, double(up.x), double(up.y),
                             double(up.z), double(d.x), double(d.y), double(d.z));
    if (!(near_plane > 0.0f) || !is_finite(near_plane))
        return Status::error(kBad, "%s: near plane %g must be > 0 and finite", who,
                             double(near_plane));
    if (!(far_plane > near_plane) || !is_finite(far_plane))
        return Status::error(kBad, "%s: far plane %g must be finite and beyond the near "
                             "plane %g", who, double(far_plane), double(near_plane));
    return Status::success();
}

}  // namespace

Status make_perspective_camera(Vec3 eye, Vec3 target, Vec3 up, float fov_y_degrees, int width,
                               int height, float near_plane, float far_plane, Camera& out) {
    const char* who = "make_perspective_camera";
    SHITSUKAN_TRY(
        check_view_inputs(who, eye, target, up, width, height, near_plane, far_plane));
    if (!(fov_y_degrees > 0.0f && fov_y_degrees < 180.0f))
        return Status::error(kBad, "%s: fov_y_degrees %g must be in (0, 180)", who,
                             double(fov_y_degrees));
    Camera c = perspective_camera(eye, target, up, fov_y_degrees, width, height, near_plane,
                                  far_plane);
    SHITSUKAN_TRY(validate_camera(c));  // e.g. a near/far ratio float cannot hold
    out = c;
    return Status::success();
}

Status make_orthographic_camera(Vec3 eye, Vec3 target, Vec3 up, float half_height, int width,
                                int height, float near_plane, float far_plane, Camera& out) {
    const char* who = "make_orthographic_camera";
    SHITSUKAN_TRY(
        check_view_inputs(who, eye, target, up, width, height, near_plane, far_plane));
    if (!(half_height > 0.0f) || !is_finite(half_height))
        return Status::error(kBad, "%s: half_height %g must be > 0 and finite", who,
                             double(half_height));
    Camera c = orthographic_camera(eye, target, up, half_height, width, height, near_plane,
                                   far_plane);
    SHITSUKAN_TRY(validate_camera(c));
    out = c;
    return Status::success();
}

Status validate_camera(const Camera& camera) {
    if (camera.width < 1 || camera.height < 1)
        return Status::error(kBad, "camera frame is %d x %d pixels; each side must be >= 1",
                             camera.width, camera.height);
    if (!finite_matrix(camera.view) || !finite_matrix(camera.projection) ||
        !is_finite(camera.eye))
        return Status::error(kBad, "camera view, projection or eye has a NaN/inf entry");
    // The view: a rotation (rows orthonormal, determinant +1) and a translation.
    const Mat4& v = camera.view;
    if (!row_is(v, 3, 0, 0, 0, 1))
        return Status::error(kBad, "camera view matrix's last row is (%g, %g, %g, %g), not "
                             "(0, 0, 0, 1)", double(v.m[3][0]), double(v.m[3][1]),
                             double(v.m[3][2]), double(v.m[3][3]));
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            float d = dot(row3(v, i), row3(v, j));
            float expected = i == j ? 1.0f : 0.0f;
            if (!(std::fabs(d - expected) <= kCameraTolerance))
                return Status::error(kBad, "camera view matrix is not a rotation: rows %d and "
                                     "%d give %g, not %g (eye == target, or up parallel to "
                                     "the view direction?)", i, j, double(d), double(expected));
        }
    float det = dot(row3(v, 0), cross(row3(v, 1), row3(v, 2)));
    if (!(det > 0.0f))
        return Status::error(kBad, "camera view matrix is mirrored (determinant %g)",
                             double(det));
    // The projection: positive x and y scales (a zero, negative or > 180 degree field of
    // view, or a mirror, gives <= 0) and a z row that depends on depth only.
    const Mat4& p = camera.projection;
    if (!(p.m[0][0] > 0.0f) || !(p.m[1][1] > 0.0f))
        return Status::error(kBad, "camera projection scales x by %g and y by %g; both must be "
                             "> 0 (a field of view outside (0, 180) degrees, or a mirror?)",
                             double(p.m[0][0]), double(p.m[1][1]));
    if (p.m[2][0] != 0.0f || p.m[2][1] != 0.0f)
        return Status::error(kBad, "camera projection's depth depends on x or y (%g, %g)",
                             double(p.m[2][0]), double(p.m[2][1]));
    if (camera.orthographic) {
        if (!row_is(p, 3, 0, 0, 0, 1))
            return Status::error(kBad, "orthographic camera's projection has last row (%g, %g, "
                                 "%g, %g), not (0, 0, 0, 1)", double(p.m[3][0]),
                                 double(p.m[3][1]), double(p.m[3][2]), double(p.m[3][3]));
        // z_ndc = m22·z_eye + m23 must grow with the distance -z_eye.
        if (!(p.m[2][2] < 0.0f))
            return Status::error(kBad, "orthographic camera: depth scale %g must be < 0 (far "
                                 "plane not beyond the near plane?)", double(p.m[2][2]));
    } else {
        if (!row_is(p, 3, 0, 0, -1, 0))
            return Status::error(kBad, "perspective camera's projection has last row (%g, %g, "
                                 "%g, %g), not (0, 0, -1, 0)", double(p.m[3][0]),
                                 double(p.m[3][1]), double(p.m[3][2]), double(p.m[3][3]));
        // At eye distance d: z_ndc = -m22 + m23 / d. The near plane (z_ndc = -1) lies at
        // d = m23 / (m22 - 1) and depth grows with d: both need m23 < 0 and m22 < 1. (The
        // far plane d = m23 / (m22 + 1) is then beyond it, or at infinity.)
        if (!(p.m[2][3] < 0.0f) || !(p.m[2][2] < 1.0f))
            return Status::error(kBad, "perspective camera's depth row (%g, %g) puts no near "
                                 "plane in front of the eye (near <= 0, or far <= near?)",
                                 double(p.m[2][2]), double(p.m[2][3]));
    }
    return Status::success();
}

// Clip -> screen: divide by w, then NDC [-1, 1] -> pixels (y flipped so that y grows
// downwards) and z_ndc [-1, 1] -> depth [0, 1].
Vec3 clip_to_screen(const Camera& camera, Vec4 clip) {
    float inv_w = 1.0f / clip.w;
    float nx = clip.x * inv_w, ny = clip.y * inv_w, nz = clip.z * inv_w;
    return {(nx * 0.5f + 0.5f) * float(camera.width), (0.5f - ny * 0.5f) * float(camera.height),
            nz * 0.5f + 0.5f};
}

// World -> screen: clip = P·V·p, then clip_to_screen.
Vec3 project(const Camera& camera, Vec3 world_point) {
    Vec4 p{world_point.x, world_point.y, world_point.z, 1.0f};
    return clip_to_screen(camera, camera.projection * (camera.view * p));
}

}  // namespace shitsukan
