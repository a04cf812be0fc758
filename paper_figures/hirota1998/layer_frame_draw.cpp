// paper_figures/hirota1998/layer_frame_draw.cpp — one frame of hirota1998 fig. 8
// (layer_frame_draw.hpp).
#include "hirota1998/layer_frame_draw.hpp"

#include <algorithm>
#include <vector>

namespace shitsukan::figures::bark {
namespace {

// Seam-correct x next to ref (the patch is periodic around with period P).
Vec3 near_x(Vec3 x, float ref, float P) {
    while (x.x - ref > 0.5f * P) x.x -= P;
    while (ref - x.x > 0.5f * P) x.x += P;
    return x;
}

}  // namespace

void draw_layer_frame(RasterCanvas& c, const LayeredBark& bark, const LayerFrame& f, Vec2 origin,
                float scale) {
    const BarkCylinder& lat = bark.lattice();
    const LayeredParams& p = bark.params();
    const float Ps = f.surface_period, Pm = f.middle1_period;
    const Rgb8 bonded{92, 70, 52}, lifted{150, 124, 98}, exposed{196, 120, 62};
    const float height_px = float(p.N_H) * p.species.L0 * 1.1f * scale;
    auto px = [&](Vec3 x) { return Vec2{origin.x + x.x * scale, origin.y + height_px - x.y * scale}; };
    // Painter's order: middle (1) everywhere (it shows where the surface has fallen), then the
    // surface where it is still on the trunk; each layer with its own cracks.
    for (int layer = 0; layer < 2; ++layer) {
        const bool surface = layer == 1;
        const std::vector<Vec3>& pos = surface ? f.surface_position : f.middle1_position;
        const std::vector<std::uint8_t>& broken_springs = surface ? f.surface_broken : f.middle1_broken;
        const float Pl = surface ? Ps : Pm;
        c.set_antialias(false);
        for (const ConnectionTriangle& tri : lat.triangles) {
            const bool on = f.surface_alive[tri.node[0]] && f.surface_alive[tri.node[1]] &&
                            f.surface_alive[tri.node[2]];
            if (surface && !on) continue;
            Vec3 x[3];
            for (int k = 0; k < 3; ++k) x[k] = near_x(pos[tri.node[k]], pos[tri.node[0]].x, Pl);
            Rgb8 col = exposed;
            if (surface)
                col = f.surface_bonded[tri.node[0]] && f.surface_bonded[tri.node[1]] &&
                              f.surface_bonded[tri.node[2]]
                          ? bonded
                          : lifted;
            for (float shift : {0.0f, -Pl, Pl}) {
                const Vec2 pts[3] = {px(x[0] + Vec3{shift, 0, 0}), px(x[1] + Vec3{shift, 0, 0}),
                                     px(x[2] + Vec3{shift, 0, 0})};
                c.fill_polygon(pts, 3, col);
            }
        }
        c.set_antialias(true);
        // Cracks: the broken spring's face, width l - l0 (at least 1 px).
        for (int s = 0; s < lat.net.spring_count(); ++s) {
            const BarkSpring& sp = lat.net.springs[std::size_t(s)];
            if (!broken_springs[std::size_t(s)]) continue;
            if (surface && !(f.surface_alive[sp.i] && f.surface_alive[sp.j])) continue;  // fell off
            const Vec3 a = pos[sp.i], b = near_x(pos[sp.j], a.x, Pl);
            const float l = length(b - a), w = std::max(l - sp.l0, 1.0f / scale);
            const Vec3 m = (a + b) * 0.5f, along = (b - a) * (1.0f / l);
            const Vec3 face{-along.y, along.x, 0.0f};
            const float half = 0.5f * lat.spring_face[std::size_t(s)] * 1.05f;
            for (float shift : {0.0f, -Pl, Pl}) {
                const Vec3 sh{shift, 0, 0};
                const Vec2 q[4] = {px(m + sh + face * half - along * (0.5f * w)),
                                   px(m + sh + face * half + along * (0.5f * w)),
                                   px(m + sh - face * half + along * (0.5f * w)),
                                   px(m + sh - face * half - along * (0.5f * w))};
                c.fill_polygon(q, 4, Rgb8{24, 16, 10});
            }
        }
    }
}

}  // namespace shitsukan::figures::bark
