// paper_figures/fujimoto2000/ist_diagram.hpp — the IST diagrams of fujimoto2000 figs 1-9:
// the axes u^0 .. u^K (and u^{k.5}, u^*) drawn one above the other, every sub-interval a box
// coloured by where it came from on u^0, its number written in it where it fits, and thin
// lines following chosen sub-intervals from one axis to the next (the paper's marks).
//
//   IstDiagram d;  d.ist = DiagramIst::of(axis);  d.first_label = 4;
//   d.rows.push_back(DiagramRow::axis(d.ist, 1, false));      // u^1
//   draw_ist_diagram(canvas, d, layout);
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "shitsukan/image/canvas.hpp"
#include "shitsukan/wrinkly/ist.hpp"

namespace shitsukan::figures {

// An IST as the diagrams see it: the original IST (§2.1) or an IstAxis (unit / connected),
// both simulated by the library's step-by-step procedure.
struct DiagramIst {
    bool original = false;
    IstOriginal original_ist;
    IstAxis axis;
    std::vector<double> edges;  // B + 1 base-interval edges (empty: equal widths)

    int base_intervals() const {
        return original ? original_ist.base_intervals : axis.base_intervals;
    }
    const double* edge_data() const { return edges.empty() ? nullptr : edges.data(); }
    double edge(int i) const {
        return edges.empty() ? double(i) / double(base_intervals()) : edges[std::size_t(i)];
    }
};

// One sub-interval: its extent on u^0, where it sits on the row's axis, its number.
struct DiagramPiece {
    double start0 = 0, end0 = 0;
    double start = 0, end = 0;
    int origin_base = 0;
    std::vector<int> digits;  // alpha_1 .. alpha_depth
};

// Stage of a row: `iterations` full iterations, then (half) the div + in-shf of the next.
struct DiagramStage {
    int iterations = 0;
    bool half = false;
};

// Point of u^0 tracked to the stage: its position there (and the sub-interval holding it).
IstPoint diagram_track(const DiagramIst& ist, double u0, DiagramStage stage);

// All sub-intervals of `depth` divisions, placed at `stage` (u^*: depth K at stage 0).
std::vector<DiagramPiece> diagram_pieces(const DiagramIst& ist, int depth, DiagramStage stage);

struct DiagramRow {
    std::string name;           // "u^0", "u^1.5", "u*"
    DiagramStage stage;
    std::vector<DiagramPiece> pieces;
    int tick_depth = -1;        // also mark the divisions of this depth under the row (div)
    std::function<bool(const DiagramPiece&)> show_label;  // default: every piece
};

DiagramRow diagram_row(const DiagramIst& ist, const std::string& name, int depth,
                       DiagramStage stage);

struct IstDiagram {
    DiagramIst ist;
    std::string title;
    int first_label = 0;              // the number of base interval 0 in the labels
    bool unit_labels = false;         // write digits only (unit-IST: "012", not "0.012")
    double window0 = 0, window1 = 1;  // the part of [0, 1] drawn
    std::vector<DiagramRow> rows;
    // Lines between consecutive rows follow the u^0 midpoints of the pieces of the lower row
    // accepted by this filter (none when empty).
    std::function<bool(const DiagramPiece&)> follow;
};

struct DiagramLayout {
    float left = 84, top = 74, width = 1000;
    float row_height = 56, gap = 60;
};

// Colour of a sub-interval by origin: hue by base interval of origin (by position on u^0
// for a single base interval), lightness by position inside it.
Rgb8 diagram_colour(const DiagramIst& ist, double u0);

std::string diagram_label(const IstDiagram& d, const DiagramPiece& piece);

// Height the diagram needs with this layout.
float diagram_height(const IstDiagram& d, const DiagramLayout& layout);
void draw_ist_diagram(Canvas& canvas, const IstDiagram& d, const DiagramLayout& layout);

}  // namespace shitsukan::figures
