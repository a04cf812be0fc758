// shitsukan/core/progress.hpp — how long work reports how far it is (the library never prints:
// the caller decides, e.g. the `shitsukan` tool draws a line on stderr).
//
// Manual
//   // void show(float fraction, void* user): 0 .. 1, non-decreasing, 1 at the end
//   auto show = [](float fraction, void* user) { *static_cast<float*>(user) = fraction; };
//   float last = 0.0f;
//   Progress progress{show, &last};
//   // Status s = bake_solid_texture(..., progress);   // render/solid_bake.hpp
//   progress.report(0.5f);                             // calls show when set, else nothing
//
// The same callback shape as libnoise's per-row callback and hirota1998's BarkProgress
// (bark/crack_events.hpp), so one function serves both. Calls are made from the calling
// thread, at most a few hundred per job (chosen here: per row block, not per pixel).
// small-device: yes (inline, no allocation)
#pragma once

namespace shitsukan {

using ProgressFn = void (*)(float fraction, void* user);

struct Progress {
    ProgressFn fn = nullptr;
    void* user = nullptr;
    void report(float fraction) const {
        if (fn) fn(fraction, user);
    }
};

}  // namespace shitsukan
