// shitsukan/raster/camera.hpp — perspective and orthographic cameras.
//
// Manual
//   Camera cam = perspective_camera({3, 2, 4}, {0, 0, 0}, {0, 1, 0}, 35.0f, 512, 512);
//   Camera ortho = orthographic_camera(eye, target, up, 1.2f /*half height*/, 512, 512);
//   Options (defaults): near 0.05, far 100 (perspective_camera's last two arguments).
//   cam.view (world -> eye, right-handed, looking down -z), cam.projection (eye -> clip,
//   OpenGL convention: NDC z in [-1, 1]), cam.width / cam.height (the full frame in pixels).
//   project(cam, p) -> screen (x right, y down, pixels; z = depth in [0, 1]).
//   clip_to_screen(cam, clip) -> the same mapping from homogeneous clip coordinates (w > 0);
//   the rasterizer maps its vertices with the same operations.
//   Ranges: fov_y_degrees in (0, 180), 0 < near_plane < far_plane, half_height > 0,
//   width, height >= 1. These are not validated here; draw_mesh() checks the camera.
#pragma once

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
Vec3 project(const Camera& camera, Vec3 world_point);
Vec3 clip_to_screen(const Camera& camera, Vec4 clip);

}  // namespace shitsukan
