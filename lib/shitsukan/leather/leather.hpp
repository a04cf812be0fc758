// shitsukan/leather/leather.hpp — tokai1994, "A Method for Rendering Skins or Leathers of
// Reptiles" (Tokai, Yasuda, Yokoi, Toriwaki, IPSJ Journal, 1994): the files in the order to
// read them beside the paper, and everything in one include.
//
//   §3.1 processing 1-2, eq. (1)  seed_layout.hpp        where the seeds go, how they move
//   §3.1 processing 3, figs. 2-7  scale_division.hpp     the two-stage Voronoi division (uses
//                                                        geom/voronoi.hpp, planar_subdivision)
//   §3.1 processing 4, figs. 8-10 edge_perturbation.hpp  every edge bent once, shared by both
//                                                        scales
//   §3.1 -> §3.2                  scale_pattern.hpp      the hand-off: polygons tiling the plane
//   §2, fig. 7's claims           scale_statistics.hpp   corners per scale, widths by column
//   §3.2, eqs. (2)-(4), fig. 12   relief.hpp             one scale's height and normal from a
//                                                        Bezier cross-section (Table 1)
//   §3.2                          scale_labels.hpp,      the whole pattern as label, height and
//                                 maps.hpp               normal maps
//   §5, figs. 17-19               products.hpp           the handbag and the belt
//
// Manual (a crocodile belly's maps):
//   ScaleParams prm;        // scale_division.hpp's two-stage division (see its manual)
//   ScalePattern pattern;
//   Status s = generate_scale_pattern(prm, &pattern);
//   LeatherMaps maps;       // then the label, height and normal maps
//   if (s) s = make_leather_maps(pattern, 256, 256, table1_section(Table1Section::convex),
//                                ReliefOptions{}, &maps);
//   return s;
#pragma once
#include "shitsukan/leather/seed_layout.hpp"
#include "shitsukan/leather/scale_division.hpp"
#include "shitsukan/leather/edge_perturbation.hpp"
#include "shitsukan/leather/scale_pattern.hpp"
#include "shitsukan/leather/scale_statistics.hpp"
#include "shitsukan/leather/relief.hpp"
#include "shitsukan/leather/scale_labels.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/products.hpp"
