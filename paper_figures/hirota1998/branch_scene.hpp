// paper_figures/hirota1998/branch_scene.hpp — hirota1998 fig. 11's 3D scene: the branching
// trunk's mesh grown to time t with Fig. 4's cracks as ribbons on it, and one view of it drawn
// by the library's rasterizer. Shared by the figure (fig09_11_branch.cpp) and the web
// explorer's branch panel (ports/web/api/api_hirota1998_branch.cpp); the library alone (no
// figure driver), so the WASM build compiles it as it is.
//
//   BranchBark b;  build_branch_bark(BranchBarkParams{}, b);
//   CrackRun run;  grow_branch_bark(b, CrackRunOptions{}, run);
//   BranchScene s = branch_scene(b, b.params.growth.duration, b.net.W.data(), 0.065f);
//   RgbImage img(512, 512);
//   draw_branch_view(s, fig11_camera(0, 512), Mat4::identity(), img.view());
#pragma once

#include "shitsukan/bark/branch_bark.hpp"
#include "shitsukan/geom/mesh.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/raster/camera.hpp"

namespace shitsukan::figures::bark {

struct BranchScene {
    TriangleMesh grown;   // the mesh with every node at its position at t (W of the run)
    TriangleMesh cracks;  // one ribbon per cracked spring, lifted 0.01 cm off the surface
    int broken = 0;       // broken springs among the cracked ones
};

// Crack ribbons (Fig. 4 on the mesh): C1-M-C2 widened by l - l0 along the spring (at least
// min_width cm). Cracked = broken by t, or intact in no intact triangle (opened by sliding:
// drawn at the minimum width, as fig05's map does). A spring on a cut end has one triangle: its
// ribbon stops at M, on the cut. W: the displacement field at t (the bark's net.W at the run's
// end, or a snapshot of run_cracking's).
BranchScene branch_scene(const BranchBark& bark, float t, const Vec3* W, float min_width);

// Fig. 11's two cameras (0: front, 1: 3/4 from above the crotch), size x size, y up.
Camera fig11_camera(int view, int size);
// The shape is z-up, the rasterizer's world y-up: the model turns it by -90 degrees about x
// first, then `turn` (about the crotch's point (2, 8, 0), y up). Bark brown and dark cracks,
// Lambert lit from the figure's light, on the figure's grey.
Status draw_branch_view(const BranchScene& scene, const Camera& camera, const Mat4& turn, RgbView target);

}  // namespace shitsukan::figures::bark
