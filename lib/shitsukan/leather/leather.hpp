// shitsukan/leather/leather.hpp — tokai1994, "A Method for Rendering Skins or Leathers of
// Reptiles" (Tokai, Yasuda, Yokoi, Toriwaki, IPSJ Journal, 1994): the files in the order to
// read them beside the paper, and everything in one include.
//
//   §3.1 processing 1-2, eq. (1)  seed_layout.hpp        where the seeds go, how they move
//                                                        (stage1_seeds, stage2_columns,
//                                                        stage2_row_seeds; fig. 3's lattices)
//   §3.1 processing 3, figs. 2-7  scale_division.hpp     the two-stage Voronoi division (uses
//                                                        geom/voronoi.hpp, planar_subdivision):
//       divide_scales = stage1_seeds (fig. 4, processings 1-2)
//                     -> stage1_vertical_division (processing 3)
//                     -> stage2_horizontal_division: per stage-1 polygon
//                        stage2_row_for_polygon (fig. 6, processings 1-2) and
//                        stage2_divide_polygon (processing 3), then the T-junction stitching
//                        weld_stage1_edge_points -> stitch_t_junctions (stitch_final_cells)
//   §3.1 processing 4, figs. 8-10 edge_perturbation.hpp  every edge bent once, shared by both
//                                                        scales:
//       midpoint_displacement (the pseudo-fractal of one edge, ref. 18)
//       perturb_subdivision (one stage, figs. 2-3): fan_centres -> bend_interior_edges
//                     -> shrink_until_star_shaped (assemble_polygon, star_shaped_check)
//       perturb_two_stage (figs. 5, 7): bend_stage1_edges -> find_stage1_pieces
//                     -> move_junctions_onto_curves -> bend_stage2_edges
//                     -> shrink_until_tiling (assemble_face: append_stage1_piece,
//                        append_stage2_curve)
//   §3.1 -> §3.2                  scale_pattern.hpp      the hand-off: polygons tiling the plane
//   §2, fig. 7's claims           scale_statistics.hpp   corners per scale, widths by column
//   §3.2, eqs. (2)-(4), fig. 12   relief.hpp             one scale's height and normal from a
//                                                        Bezier cross-section (Table 1)
//   §3.2                          scale_labels.hpp,      the whole pattern as label, height and
//                                 maps.hpp               normal maps (make_leather_maps:
//                                                        prepare_scale_tables, relief_row)
//   §5, figs. 17-19               products.hpp           the handbag and the belt
//   (not in the paper)            tileable.hpp           seamless tiling: the patterns on a
//                                                        torus (generate_tileable_pattern,
//                                                        torus_cover)
//
// Manual (a crocodile belly's maps):
//   ScaleParams prm;        // scale_division.hpp's two-stage division (see its manual)
//   ScalePattern pattern;
//   Status s = generate_scale_pattern(prm, pattern);
//   LeatherMaps maps;       // then the label, height and normal maps
//   if (s) s = make_leather_maps(pattern, 256, 256, table1_section(Table1Section::convex),
//                                ReliefOptions{}, maps);
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
#include "shitsukan/leather/tileable.hpp"
