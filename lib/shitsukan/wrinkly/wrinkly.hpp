// shitsukan/wrinkly/wrinkly.hpp — fujimoto2000, "Formalization and Superposed Construction of
// Wrinkly Surface" (Fujimoto, Ohno, IPSJ Journal, 2000): the files in the order to read them
// beside the paper, and everything in one include.
//
//   §2 (the IST family)           ist.hpp                its own reading order: axis, formula,
//                                                        digits, procedure, original IST
//   §3.1, the control mesh        control_mesh.hpp       WR control points: position, height
//   §3, eq. (15)                  wr_axis.hpp,           one axis's (F^k)^{-1}; an IST as that
//                                 wr_ist_axis.hpp        axis
//   §3, eq. (15)                  wr_surface.hpp         the wrinkly (WR) surface
//   §4.1, eqs. (16)-(19)          superposition.hpp      the superposed WR surface
//   §4.2, eq. (20)                hierarchical_sampling.hpp  sampling without the staircase
//   §4.2, §5                      wr_tessellation.hpp    adaptive polygonisation
//   §3.1, the shell               terrain_mesh.hpp       a control mesh from a height map; the
//                                                        periodic (wrapped) control mesh
//   eqs. (15), (20) as maps       terrain_maps.hpp       height and colour maps (tileable)
//
// Manual
//   WrControlMesh mesh = make_control_mesh(8, 8);          // control_mesh.hpp
//   for (int r = 0; r < 8; ++r)
//       for (int c = 0; c < 8; ++c)
//           mesh.at(c, r).position = {c / 7.0f, r / 7.0f, 0.0f}, mesh.at(c, r).height = 0.05f;
//   WrSurface surface;
//   Status s = make_wr_surface(mesh, SurfaceBasis::bspline, 3, surface);
//   if (!s) return s;
//   HierarchicalOptions o;  o.levels = 2;              // then mountains (superposition.hpp):
//   HierarchicalSampling hs;
//   s = sample_hierarchy(surface, o, hs);
//   SuperposedSample p = s ? superposed_sampled(surface, hs, 0.5f, 0.5f) : SuperposedSample{};
//   // More in wr_surface.hpp (a WR surface) and superposition.hpp (mountains).
//   return s;
#pragma once
#include "shitsukan/wrinkly/ist.hpp"
#include "shitsukan/wrinkly/control_mesh.hpp"
#include "shitsukan/wrinkly/wr_axis.hpp"
#include "shitsukan/wrinkly/wr_ist_axis.hpp"
#include "shitsukan/wrinkly/wr_surface.hpp"
#include "shitsukan/wrinkly/superposition.hpp"
#include "shitsukan/wrinkly/hierarchical_sampling.hpp"
#include "shitsukan/wrinkly/wr_tessellation.hpp"
#include "shitsukan/wrinkly/terrain_mesh.hpp"
#include "shitsukan/wrinkly/terrain_maps.hpp"
