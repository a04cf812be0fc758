// shitsukan/bark/crack_regions.hpp — hirota1998 Table 3: the regions bounded by cracks.
//
// Manual
//   CylinderParams params;  params.N_R = 16;  params.N_H = 12;  // a small trunk (chosen 128 x 64)
//   params.species = species_preset(Species::camphor);
//   BarkCylinder bark;
//   Status s = build_cylinder(params, bark);
//   CrackRun run;
//   if (s) s = grow_and_crack(bark, CrackRunOptions{}, run);
//   if (!s) return s;
//   float T = params.T;
//   const Vec3* W = bark.net.W.data();
//   RegionReport rep;
//   s = measure_regions(bark, params.T, bark.net.W.data(), rep);
//   // rep.mean_width, rep.mean_height, rep.max_width, rep.max_height   // cm, as Table 3
//   // rep.regions[i]: nodes, width, height, wraps, full_height; rep.label[p]: node p's region
//   RegionOptions section;  section.end_rows = 2;   // Table 3's section: kSectionEndRows at
//   if (s) s = measure_regions(bark, T, W, rep, section);  // full size; -1 labels outside it
//   return s;
//   #include "shitsukan/bark/crack_events.hpp"
//
// Table 3 reports "the dimensions of the area surrounded by cracks" (horizontal x vertical:
// around the trunk x along it), mean and max, and the text calls them "the vertical and
// horizontal crack spacings". Both are measured here:
//
// Regions (primary). A central-force triangular lattice has a zero-energy mechanism: along a
// lattice line a crack opens by sliding once one of the two diagonal families across it has
// broken, while the other family only rotates. Plain connectivity over intact springs would
// then merge regions a visible crack separates. So (chosen here, docs/papers/hirota1998.md §2):
//   1. a triangle is intact when its three springs are; a spring is strong when it belongs to
//      an intact triangle;
//   2. regions are the connected components of nodes over strong springs;
//   3. a region's width and height are its node extents at time t (unrolled around the trunk,
//      carried across the seam spring by spring) plus one cell (a_h and L0, grown); a region
//      that closes around the trunk wraps (width = the circumference); a region spanning the
//      whole height (within 1.5 rows) is full height;
//   4. regions of fewer than min_nodes (chosen here: 3) are crumbs at crack junctions.
//   5. each region's columns: the shortest arc of lattice columns around the trunk holding its
//      nodes (for the photograph views Table 3 is compared in, photograph_views.hpp).
// Mean and max of width and height are taken separately, as Table 3 does. The figures measure
// a section away from the cylinder's cut ends (RegionOptions::end_rows, kSectionEndRows).
//
// Intercepts (secondary, the text's "crack spacings"): along each ring of nodes the distance
// between consecutive changes of region, and along each column the same vertically.
#pragma once

#include <cstdint>
#include <vector>

#include "shitsukan/bark/cylinder_lattice.hpp"

namespace shitsukan {

struct BarkRegion {
    int nodes = 0;
    float width = 0, height = 0;  // cm at the measured time
    bool wraps = false, full_height = false;
    // The lattice columns it covers: first_column .. first_column + columns - 1 (mod N_R), the
    // shortest arc around the trunk holding all its nodes; columns = N_R when it wraps.
    // photograph_views.hpp uses it to tell which regions a view shows whole.
    int first_column = 0, columns = 0;
};

struct RegionReport {
    std::vector<BarkRegion> regions;    // kept regions (>= min_nodes), in order of first node
    std::vector<std::int32_t> label;    // per node: index into regions, -1 for crumbs
    int components = 0;                 // all components, crumbs included
    float mean_width = 0, mean_height = 0, max_width = 0, max_height = 0;
    int wrapped = 0, full_height = 0;
    // Intercepts: spacings between region changes around rings / along columns (cm).
    float intercept_mean_width = 0, intercept_max_width = 0;
    float intercept_mean_height = 0, intercept_max_height = 0;
    int columns_uncut = 0;              // columns with no change of region over the height
};

constexpr int kMinRegionNodes = 3;  // chosen here: single nodes at junctions are crumbs

// chosen here: Table 3 is measured on a section of the trunk away from its cut ends, as one
// measures a photograph of a long trunk (the paper's observed column) and as its own simulated
// column was measured "on these patterns" (§3.2, Fig. 5). The simulated cylinder's top and
// bottom are free edges a real trunk does not have: within a shear-lag length of them the
// axial stress is relieved and horizontal cracks hardly form (pine, 128 x 64, seeds 1998, 1,
// 2: rows 0-5 and 59-63 break fewer than 1 % of their axial springs, the middle rows 4-14 %),
// and the regions touching them hang from the edge as combs several blocks wide. 8 rows
// (2.6 cm) leave that band out with a margin of two.
constexpr int kSectionEndRows = 8;

struct RegionOptions {
    int min_nodes = kMinRegionNodes;  // smaller components are crumbs
    // Rows left out at the top and at the bottom: the section measured (0 = the whole
    // cylinder). Springs leaving the section do not connect; a region spanning the section's
    // height is full height.
    int end_rows = 0;
};

// Measures at time t with displacement field W (valid at t); a spring counts as broken when
// its t_break is in [0, t].
Status measure_regions(const BarkCylinder& bark, float t, const Vec3* W, RegionReport& out,
                       const RegionOptions& options = RegionOptions{});

// strong[s] = spring s intact at t and in at least one intact triangle.
void strong_springs(const BarkCylinder& bark, float t, std::vector<std::uint8_t>* strong);

}  // namespace shitsukan
