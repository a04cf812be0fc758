// shitsukan/raster/camera.hpp — perspective and orthographic cameras.
//
// Manual
//   Camera cam = perspective_camera({3, 2, 4}, {0, 0, 0}, {0, 1, 0}, 35.0f, 512, 512);
//   Vec3 eye{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
//   Camera ortho = orthographic_camera(eye, target, up, 1.2f /*half height*/, 512, 512);
//   // Options (defaults): near 0.05, far 100 (perspective_camera's last two arguments).
//   // cam.view (world -> eye, right-handed, looking down -z), cam.projection (eye -> clip,
//   // OpenGL convention: NDC z in [-1, 1]), cam.width / cam.height (the full frame in pixels).
//   Vec3 screen = project(cam, {0.5f, 0.5f, 0.5f});  // x right, y down, pixels; z depth in [0, 1]
//   Vec3 same = clip_to_screen(cam, cam.projection * (cam.view * Vec4{0.5f, 0.5f, 0.5f, 1.0f}));
//   // clip_to_screen: the same mapping from homogeneous clip coordinates (w > 0); the
//   // rasterizer maps its vertices with the same operations.
//   // Ranges: fov_y_degrees in (0, 180), 0 < near_plane < far_plane, half_height > 0,
//   // width, height >= 1, everything finite, eye != target, up not parallel to target - eye.
//   // perspective_camera / orthographic_camera do not check them; make_perspective_camera /
//   // make_orthographic_camera do (a Status naming the bad value), and draw_mesh() /
//   // draw_edges() refuse a camera that fails validate_camera().
//   Camera checked;
//   Status s = make_perspective_camera(eye, target, up, 35.0f, 512, 512, 0.05f, 100.0f, checked);
//   return s;
#pragma once

#include "shitsukan/core/status.hpp"
#include "shitsukan/core/vec.hpp"

namespace shitsukan {

struct Camera {
    Mat4 view = Mat4::identity();
    Mat4 projection = Mat4::identity();
    Vec3 eye{0, 0, 0};      // world position of the eye (for specular terms)
    bool orthographic = false;
    int width = 0, height = 0;  // full frame
};

Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up);
Camera perspective_camera(Vec3 eye, Vec3 target, Vec3 up, float fov_y_degrees, int width,
                          int height, float near_plane = 0.05f, float far_plane = 100.0f);
Camera orthographic_camera(Vec3 eye, Vec3 target, Vec3 up, float half_height, int width,
                           int height, float near_plane = 0.05f, float far_plane = 100.0f);
// Checked builders: the very camera perspective_camera / orthographic_camera make (same
// bits), or invalid_argument naming the offending value (then out is left unchanged).
Status make_perspective_camera(Vec3 eye, Vec3 target, Vec3 up, float fov_y_degrees, int width,
                               int height, float near_plane, float far_plane, Camera& out);
Status make_orthographic_camera(Vec3 eye, Vec3 target, Vec3 up, float half_height, int width,
                                int height, float near_plane, float far_plane, Camera& out);

// Is this a camera the rasterizer can use? A frame of at least 1 x 1 pixels; finite view,
// projection and eye; a view that is a rotation (rows of its 3x3 part orthonormal within
// kCameraTolerance, determinant +1: no mirror) plus a translation; a projection of the kind
// the flag says — perspective: last row (0, 0, -1, 0), or orthographic: (0, 0, 0, 1) — with
// positive x and y scales (no mirror), no x/y terms in its z row, and depth growing with the
// distance from a near plane in front of the eye (perspective) up to a far plane beyond it.
// Catches what the unchecked builders make of bad input (eye == target, up parallel to the
// view direction, fov outside (0, 180), near <= 0, far <= near, NaN/inf), except a fov
// beyond 360 degrees, which tan() cannot tell from its value modulo 360.
Status validate_camera(const Camera& camera);
constexpr float kCameraTolerance = 1e-3f;  // chosen here: float look_at is good to ~1e-6

Vec3 project(const Camera& camera, Vec3 world_point);
Vec3 clip_to_screen(const Camera& camera, Vec4 clip);

}  // namespace shitsukan
