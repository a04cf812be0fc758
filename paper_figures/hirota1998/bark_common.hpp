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
    // One lock per key: figures running in parallel (the driver's --jobs) wait only for the
    // run they need, not for another key's build.
    struct Entry {
        std::mutex mutex;
        std::unique_ptr<T> value;
    };
    static std::mutex map_mutex;
    static std::map<int, std::unique_ptr<Entry>> memo;
    Entry* entry = nullptr;
    {
        std::lock_guard<std::mutex> lock(map_mutex);
        std::unique_ptr<Entry>& slot = memo[key];
        if (!slot) slot = std::make_unique<Entry>();
        entry = slot.get();
    }
    std::lock_guard<std::mutex> lock(entry->mutex);
    if (!entry->value) {
        auto value = std::make_unique<T>();
        SHITSUKAN_TRY(build(*value));
        entry->value = std::move(value);
    }
    *out = entry->value.get();
    return Status::success();
}

// chosen here: the species' trunks are 128 x 80 nodes (H0 = 26.4 cm; the library's default
// is 64 rows), so the section Table 3 is measured on is 21.9 cm tall at T.
constexpr int kSpeciesRows = 80;

// The section Table 3 is measured on (crack_regions.hpp: kSectionEndRows rows left out at
// each end; 3 in quick mode's 24-row trunk).
RegionOptions table3_section(bool quick);

// One species grown to T, measured at T, with snapshots at 0.6, 0.75, 0.9 and 1.0 T.
struct SpeciesRun {
    Species species;
    CylinderParams params;
    BarkCylinder bark;
    CrackRun run;
    RegionReport regions;  // Table 3's measure: the section away from the cut ends
    RegionReport whole;    // the whole cylinder, ends included (for comparison)
    double seconds = 0;  // build + growth + cracking
};

// Full size (128 x kSpeciesRows) or, in quick mode, 32 x 24. Computed once per process (thread-safe).
Status species_run(Species species, bool quick, const SpeciesRun** out);

// Records the parameters that matter (given by Table 2, chosen here) in the figure's table.
void record_parameters(FigureContext& ctx, const CylinderParams& p);

// Colours (chosen here: a grey-brown bark plate, near-black cracks).
extern const Rgb8 kBarkPlate;
extern const Rgb8 kCrack;

// The crack maps are drawn by the library (render/bark_crack_map.hpp: draw_crack_map), as for
// `shitsukan bark`; the figures pass these colours and their regions.

}  // namespace shitsukan::figures::bark
