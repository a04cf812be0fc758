// small-device: yes (no allocation, no exceptions)
#include "shitsukan/raster/camera.hpp"

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
    float f = 1.0f / std::tan(fov_y_degrees * (kPi / 180.0f) * 0.5f);  // cot(fov / 2)
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
