// paper_figures/hirota1998/layer_frame_draw.hpp — one frame of hirota1998 fig. 8: the unrolled
// four-layer bark at a kept time, the visible layer per lattice triangle (the surface bonded
// dark brown, lifted pale; middle (1) orange where the surface has fallen off), each layer with
// its cracks (the broken spring's face, width l - l0, at least 1 px). Shared by the figure
// (fig06_08_layers.cpp) and the web explorer's four-layer panel
// (ports/web/api/api_hirota1998_layers.cpp); the library alone, so WASM compiles it as it is.
//
//   LayeredBark bark;  bark.build(p);  bark.run(frames, n);
//   RasterCanvas c(img.view());
//   draw_layer_frame(c, bark, bark.frames()[0], {0, 0}, 12.0f);  // 12 px per cm
#pragma once

#include "shitsukan/bark/layered_bark.hpp"
#include "shitsukan/image/raster_canvas.hpp"

namespace shitsukan::figures::bark {

// Draws frame f at origin (top left of the patch), scale px per cm; the patch is
// N_H L0 1.1 cm high (room for the growth), periodic around (drawn shifted by one period both
// ways so the seam closes).
void draw_layer_frame(RasterCanvas& c, const LayeredBark& bark, const LayerFrame& f, Vec2 origin, float scale);

}  // namespace shitsukan::figures::bark
