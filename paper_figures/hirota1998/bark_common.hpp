// paper_figures/hirota1998/bark_common.hpp — what the hirota1998 figures share: the species
// runs (memoised: fig04, fig05 and table03 use the same three simulations), the colours and
// the parameter table.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/bark/bark.hpp"
#include "shitsukan/image/canvas.hpp"
#include "shitsukan/render/bark_crack_map.hpp"

namespace shitsukan::figures::bark {

// Runs build(T&) once per key in this process (thread-safe: the figures of a paper share one
// simulation; fig04, fig05 and table03 the species runs, figs. 6-8 the four-layer run).
template <class T, class Build>
Status memoised(int key, Build build, const T** out) {
    static std::mutex mutex;
    static std::map<int, std::unique_ptr<T>> memo;
    std::lock_guard<std::mutex> lock(mutex);
    auto it = memo.find(key);
    if (it == memo.end()) {
        auto value = std::make_unique<T>();
        SHITSUKAN_TRY(build(*value));
        it = memo.emplace(key, std::move(value)).first;
    }
    *out = it->second.get();
    return Status::success();
}

// One species grown to T, measured at T, with snapshots at 0.6, 0.75, 0.9 and 1.0 T.
struct SpeciesRun {
    Species species;
    CylinderParams params;
    BarkCylinder bark;
    CrackRun run;
    RegionReport regions;
    double seconds = 0;  // build + growth + cracking
};

// Full size (128 x 64) or, in quick mode, 32 x 24. Computed once per process (thread-safe).
Status species_run(Species species, bool quick, const SpeciesRun** out);

// Records the parameters that matter (given by Table 2, chosen here) in the figure's table.
void record_parameters(FigureContext& ctx, const CylinderParams& p);

// Colours (chosen here: a grey-brown bark plate, near-black cracks).
extern const Rgb8 kBarkPlate;
extern const Rgb8 kCrack;

// The crack maps are drawn by the library (render/bark_crack_map.hpp: draw_crack_map), as for
// `shitsukan bark`; the figures pass these colours and their regions.

}  // namespace shitsukan::figures::bark
