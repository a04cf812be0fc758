// shitsukan/bark/bark.hpp — hirota1998, "A Physically-based Simulation Model of Growing Tree
// Barks" (Hirota, Kato, Kaneko, IPSJ Journal, 1998): the files in the order to read them
// beside the paper.
//
//   §3.1, Tables 1-2   bark_params.hpp       the parameters, Table 2's three species, what is
//                                            chosen here and why
//   §5.1, Fig. 9       connection_area.hpp   connection areas -> spring constants
//   §3.1               spring_network.hpp    a layer of nodes and springs on shear springs; its
//                                            equilibrium, node by node
//   §3.1, Fig. 3       cylinder_lattice.hpp  the two-layer cylinder: layout decoded from R0,
//                                            families, thresholds, growth
//   §3.1-3.2           crack_events.hpp      growth and cracking, one break at a time
//                      break_loop.hpp        (the break-relax-update loop both models share,
//                                            its observer)
//                      event_tree.hpp        (its next-event tree, canonical ties)
//   §3.1, Fig. 4       crack_drawing.hpp     a broken spring drawn as a crack of width l - l0
//   Table 3            crack_regions.hpp     regions bounded by cracks, crack spacings
//                      photograph_views.hpp  (their mean and max in photograph-sized views)
//   §3.2               spacing_estimate.hpp  the (reconstructed) largest-spacing estimate
//                      bark_export.hpp       CSV, SVG and the deformed trunk as a mesh
//   §4.1, Figs. 6-7    layer_schedule.hpp    the four layers' radii over time (role changes)
//   §4.2-4.3, Table 4  layered_bark.hpp      four layers over several cycles: peeling, drying,
//                                            falling off, new layers
//   §5.1-5.2, Fig. 10  branch_shape.hpp      a trunk with a branch (implicit, meshed), growth as
//                                            isotropic scaling + normal offset
//   §5.3, Figs. 9, 11  branch_bark.hpp       the springs on any mesh, cracking in 3D
//
// Manual (a camphor trunk, its Table 3 numbers):
//   CylinderParams p;  p.species = species_preset(Species::camphor);
//   BarkCylinder bark;  CrackRun run;  RegionReport rep;
//   Status s = build_cylinder(p, bark);
//   if (s) s = grow_and_crack(bark, CrackRunOptions{}, run);
//   if (s) s = measure_regions(bark, p.T, bark.net.W.data(), rep);
//   // rep.mean_width x rep.mean_height: about 1.9 x 10.5 cm (paper 1.58 x 11.6)
//   return s;
#pragma once

#include "shitsukan/bark/bark_export.hpp"
#include "shitsukan/bark/bark_params.hpp"
#include "shitsukan/bark/branch_bark.hpp"
#include "shitsukan/bark/branch_shape.hpp"
#include "shitsukan/bark/break_loop.hpp"
#include "shitsukan/bark/connection_area.hpp"
#include "shitsukan/bark/crack_drawing.hpp"
#include "shitsukan/bark/crack_events.hpp"
#include "shitsukan/bark/crack_regions.hpp"
#include "shitsukan/bark/event_tree.hpp"
#include "shitsukan/bark/layer_schedule.hpp"
#include "shitsukan/bark/layered_bark.hpp"
#include "shitsukan/bark/cylinder_lattice.hpp"
#include "shitsukan/bark/photograph_views.hpp"
#include "shitsukan/bark/spacing_estimate.hpp"
#include "shitsukan/bark/spring_network.hpp"
