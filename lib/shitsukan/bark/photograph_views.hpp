// shitsukan/bark/photograph_views.hpp — hirota1998 Table 3 measured as on a photograph of the
// trunk: the regions one front view shows whole, their mean and their largest, over every view
// around the trunk.
//
// Manual
//   CylinderParams params;  params.N_R = 32;  params.N_H = 24;  // a small trunk (chosen 128 x 80)
//   params.species = species_preset(Species::chinese_tallow);
//   BarkCylinder bark;
//   CrackRun run;
//   RegionReport regions;
//   PhotographViews views;
//   Status s = build_cylinder(params, bark);
//   if (s) s = grow_and_crack(bark, CrackRunOptions{}, run);
//   RegionOptions section;  section.end_rows = 3;  // the photograph's height: the section
//   if (s) s = measure_regions(bark, params.T, bark.net.W.data(), regions, section);
//   if (s) s = measure_photograph_views(bark, regions, photograph_view_columns(params.N_R), views);
//   // views.mean_width x views.mean_height, views.max_width x views.max_height: cm, as Table 3
//   return s;
//   #include "shitsukan/bark/crack_events.hpp"
//   #include "shitsukan/bark/crack_regions.hpp"
//
// Why views (chosen here, docs/papers/hirota1998.md §4). §3.2 compares the simulated patterns
// with photographs of real bark (Fig. 5) and gives Table 3 as "the vertical and horizontal crack
// spacings measured on these patterns"; the observed column comes from trees of radius 5-10 cm
// (note *3), and camphor's "(>20)" says the strips run out of a picture about 20 cm tall. So the
// max is the largest region in such a picture, not the largest among every region around a
// whole simulated trunk (hundreds, where one block merged across a crack that stops short is
// nearly always present). A view:
//   - is as tall as the measured section (crack_regions.hpp, RegionOptions::end_rows): a region
//     running out at the top or the bottom is measured by what shows, as "(>20)" is;
//   - is a third of the circumference wide (photograph_view_columns): the face a front view
//     shows at least half-size (within 60 degrees of the line of sight, cos 60 = 1/2); about
//     the trunk's diameter, as wide as a photograph of the trunk;
//   - shows a region whole when its arc of columns (BarkRegion::first_column, columns) lies
//     within the view: a region cut by the view's side has no width to read, and one that
//     closes around the trunk is never whole.
// Each of the N_R positions of the view (one per column) gives the mean and the largest width
// and height of the regions it shows whole; the statistics are the means over the positions
// that show any, so the max is the largest region one expects in a photograph.
#pragma once

#include "shitsukan/bark/crack_regions.hpp"

namespace shitsukan {

struct PhotographViews {
    int view_columns = 0;         // the view's width in lattice columns
    int views = 0;                // positions (of N_R) showing at least one region whole
    float regions_per_view = 0;   // regions shown whole, mean over those positions
    // cm, means over the positions of each view's mean and largest (as measure_regions')
    float mean_width = 0, mean_height = 0, max_width = 0, max_height = 0;
    float full_height_share = 0;  // of those positions, the share showing a region spanning
                                  // the section
};

// A third of the circumference, rounded to whole columns (at least 1).
int photograph_view_columns(int N_R);

// regions: measure_regions' report on bark (its section is the views' height). Refuses a view
// outside [1, N_R] columns and a report of another lattice.
Status measure_photograph_views(const BarkCylinder& bark, const RegionReport& regions,
                                int view_columns, PhotographViews& out);

}  // namespace shitsukan
