// ports/web/api/api_hirota1998_branch.cpp — the C API of the hirota1998 branch panel (§5,
// figs. 9, 11): the branching trunk meshed, grown and cracked by the library
// (build_branch_bark, grow_branch_bark), its displacement field kept at evenly spaced times
// (run_cracking's snapshots), and the grown mesh with Fig. 4's crack ribbons drawn in 3D by the
// library's rasterizer (paper_figures/hirota1998/branch_scene.cpp, fig. 11's own scene), turned
// by yaw and pitch. State: the last run.
#include <cstdio>
#include <string>
#include <vector>

#include "api_common.hpp"
#include "hirota1998/branch_scene.hpp"
#include "shitsukan/bark/branch_bark.hpp"

using namespace shitsukan;
using namespace shitsukan::figures::bark;

namespace {

BranchBark g_branch;
CrackRun g_branch_run;
bool g_have_branch = false;
// Chosen here: the frames' times, t = k T / kBranchFrames (k = 1 .. kBranchFrames; t = 0 is
// the mesh as built).
constexpr int kBranchFrames = 20;

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

}  // namespace

// Meshes the branching trunk at edge length L0 (cm), grows it with r_h (length) and r_n (normal
// offset, cm) over T and cracks it with kappa (every spring) and sigma, as fig. 11 (the other
// parameters: BranchBarkParams' defaults). Floats: the time of every break, in order. Text:
// {nodes, springs, events, hash (break_sequence_hash of all events), T, frames}.
SK_API int sk_hirota1998_branch_run(float edge_length, float r_h, float r_n, float kappa, float sigma) {
    g_have_branch = false;
    BranchBarkParams p;
    p.edge_length = edge_length;
    p.growth.r_h = r_h;
    p.growth.r_n = r_n;
    p.kappa = kappa;
    p.sigma = sigma;
    Status s = build_branch_bark(p, g_branch);
    std::vector<float> times;
    for (int k = 1; k <= kBranchFrames; ++k) times.push_back(p.growth.duration * float(k) / float(kBranchFrames));
    CrackRunOptions o;
    o.snapshot_times = times.data();
    o.snapshot_count = int(times.size());
    Progress progress = skweb::progress();
    o.progress = progress.fn;
    o.progress_user = progress.user;
    if (s) s = grow_branch_bark(g_branch, o, g_branch_run);
    if (!s) return skweb::finish(s);
    g_have_branch = true;
    const int n = int(g_branch_run.breaks.size());
    std::vector<float>& out = skweb::floats();
    out.clear();
    for (const BreakEvent& e : g_branch_run.breaks) out.push_back(e.t);
    char hex[20];
    std::snprintf(hex, sizeof hex, "%016llx",
                  static_cast<unsigned long long>(break_sequence_hash(g_branch.net, g_branch_run, n)));
    skweb::text() = "{\"nodes\":" + std::to_string(g_branch.mesh.vertex_count()) +
                    ",\"springs\":" + std::to_string(g_branch.net.springs.size()) +
                    ",\"events\":" + std::to_string(n) + ",\"hash\":\"" + hex + "\",\"T\":" +
                    number(p.growth.duration) + ",\"frames\":" + std::to_string(kBranchFrames) + "}";
    return skweb::finish(Status::success());
}

// Frame `frame` (0 .. frames: t = frame T / frames) of the last run in 3D: fig. 11's camera
// `view` (0 front, 1 from above the crotch), the model turned by yaw and pitch about the
// crotch, size x size. Text: {t, broken (springs broken by t), cracked (ribbons drawn)}.
SK_API int sk_hirota1998_branch_view(int frame, int view, float yaw, float pitch, int size) {
    Status s = g_have_branch ? Status::success()
                             : Status::error(StatusCode::invalid_argument,
                                             "no branch run yet: call sk_hirota1998_branch_run first");
    if (s && (frame < 0 || frame > kBranchFrames))
        s = Status::error(StatusCode::out_of_range, "frame must be in 0..%d (got %d)", kBranchFrames, frame);
    if (s && (view < 0 || view > 1))
        s = Status::error(StatusCode::invalid_argument, "view must be 0 (front) or 1 (above) (got %d)", view);
    if (s && (size < 64 || size > 1024))
        s = Status::error(StatusCode::invalid_argument, "size must be in 64..1024 px (got %d)", size);
    if (!s) return skweb::finish(s);
    const float T = g_branch.params.growth.duration;
    const float t = T * float(frame) / float(kBranchFrames);
    std::vector<Vec3> zero;
    const Vec3* W = nullptr;
    if (frame == 0) {
        zero.assign(g_branch.net.W.size(), Vec3{0, 0, 0});
        W = zero.data();
    } else {
        W = g_branch_run.snapshots[std::size_t(frame - 1)].W.data();
    }
    // The figure's minimum crack width at 512 px (fig09_11_branch.cpp), scaled to the size.
    const BranchScene scene = branch_scene(g_branch, t, W, 0.065f * 512.0f / float(size));
    RgbImage img(size, size);
    s = draw_branch_view(scene, fig11_camera(view, size), Mat4::rotate_x(pitch) * Mat4::rotate_y(yaw), img.view());
    if (!s) return skweb::finish(s);
    skweb::set_picture(img);
    skweb::text() = "{\"t\":" + number(t) + ",\"broken\":" + std::to_string(scene.broken) +
                    ",\"ribbons\":" + std::to_string(scene.cracks.triangle_count() / 2) + "}";
    return skweb::finish(Status::success());
}
