// paper_figures/fujimoto2000/terrain_mesh.cpp — fujimoto2000 fig. 21's terrain control mesh
// (terrain_mesh.hpp).
#include "fujimoto2000/terrain_mesh.hpp"

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/hash.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan::fujimoto2000 {
namespace {

// Screen "right" and "front" of the figure's camera (it looks along -x -z).
float screen_right(float x, float z) { return 0.7071f * (x - z); }
float screen_front(float x, float z) { return 0.7071f * (x + z); }

}  // namespace

float terrain_green_mask(float x, float z) {
    return clamp((screen_right(x, z) - 0.5f) * 1.1f, 0.0f, 1.0f) *
           clamp((screen_front(x, z) + 0.6f) * 1.1f, 0.0f, 1.0f);
}

// Chosen: 10 x 10 control points (7 x 7 spans) on [-3, 3]^2, flat base; a massif at the back,
// a second range to the left, a low green field at the front right. Colour per control point
// varies along both parameters: the height band (grass, rock, snow), a hashed tint per point
// and a slow drift (warmer rock towards +x, cooler towards +z); hashed variation seed 21.
WrControlMesh terrain_control_mesh(float delta) {
    const int n = 10;
    WrControlMesh m = make_control_mesh(n, n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            WrControlPoint& p = m.at(c, r);
            const float x = -3.0f + 6.0f * float(c) / float(n - 1);
            const float z = 3.0f - 6.0f * float(r) / float(n - 1);
            const float g = terrain_green_mask(x, z);
            float h =
                1.9f *
                    det_expf(-((x + 0.9f) * (x + 0.9f) / 1.6f + (z + 1.0f) * (z + 1.0f) / 1.6f)) +
                1.1f *
                    det_expf(-((x + 2.0f) * (x + 2.0f) / 0.8f + (z - 1.2f) * (z - 1.2f) / 1.4f)) +
                0.3f * hash_uniform(21, 0, c, r);
            h = (1.0f - g) * h + g * (0.06f + 0.08f * hash_uniform(21, 1, c, r));
            p.position = {x, 0.0f, z};
            p.height = h;
            const float warm =
                0.5f + 0.08f * x - 0.06f * z + 0.25f * (hash_uniform(21, 2, c, r) - 0.5f);
            const Vec3 grass = lerp(Vec3{0.30f, 0.50f, 0.22f}, Vec3{0.50f, 0.55f, 0.25f}, warm);
            const Vec3 rock = lerp(Vec3{0.42f, 0.42f, 0.44f}, Vec3{0.60f, 0.47f, 0.36f}, warm);
            const Vec3 snow{0.96f, 0.96f, 0.98f};
            Vec3 col = h < 0.6f ? lerp(grass, rock, h / 0.6f)
                                : lerp(rock, snow, clamp((h - 1.0f) / 0.6f, 0.0f, 1.0f));
            p.color = lerp(col, Vec3{0.28f, 0.62f, 0.20f}, g);
            p.delta = (1.0f - g) * delta + g * kTerrainDeltaGreen;
        }
    return m;
}

}  // namespace shitsukan::fujimoto2000
