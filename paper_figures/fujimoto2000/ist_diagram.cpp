// paper_figures/fujimoto2000/ist_diagram.cpp — drawing the IST axes of figs 1-9.
#include "ist_diagram.hpp"

#include <cmath>

#include "shitsukan/image/font.hpp"

namespace shitsukan::figures {

namespace {

Rgb8 hsv(double h, double s, double v) {
    h = std::fmod(h, 360.0);
    if (h < 0) h += 360.0;
    double c = v * s, x = c * (1.0 - std::fabs(std::fmod(h / 60.0, 2.0) - 1.0)), m = v - c;
    double r = 0, g = 0, b = 0;
    int sector = int(h / 60.0);
    switch (sector) {
        case 0:
            r = c;
            g = x;
            break;
        case 1:
            r = x;
            g = c;
            break;
        case 2:
            g = c;
            b = x;
            break;
        case 3:
            g = x;
            b = c;
            break;
        case 4:
            r = x;
            b = c;
            break;
        default:
            r = c;
            b = x;
            break;
    }
    auto q = [](double t) {
        return std::uint8_t(std::lround(255.0 * (t < 0 ? 0 : t > 1 ? 1 : t)));
    };
    return Rgb8{q(r + m), q(g + m), q(b + m)};
}

Rgb8 darker(Rgb8 c, double f) {
    return Rgb8{std::uint8_t(c.r * f), std::uint8_t(c.g * f), std::uint8_t(c.b * f)};
}

bool is_dark(Rgb8 c) { return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b < 120.0; }

int divisor_at(const DiagramIst& ist, int base) {
    return ist.original ? 2 * ist_original_crossing(ist.original_ist, base) + 1 : ist.axis.n;
}

int stage_divisions(DiagramStage stage) { return stage.iterations + (stage.half ? 1 : 0); }

void collect(const DiagramIst& ist, int depth, DiagramStage stage, DiagramPiece piece,
             std::vector<double>* extents, std::vector<DiagramPiece>* out) {
    int level = int(piece.digits.size());
    extents->resize(std::size_t(2 * level + 2));
    (*extents)[std::size_t(2 * level)] = piece.start0;
    (*extents)[std::size_t(2 * level + 1)] = piece.end0;
    const double mid = 0.5 * (piece.start0 + piece.end0);
    if (level == depth) {
        IstPoint p = diagram_track(ist, mid, stage);
        int d = stage_divisions(stage);
        if (d >= depth) {
            piece.start = p.start;
            piece.end = p.end;
        } else {
            // The stage holds a coarser sub-interval (u^*: none divided yet): the piece sits
            // inside it at the same relative place, the map being affine there.
            double a0 = (*extents)[std::size_t(2 * d)], b0 = (*extents)[std::size_t(2 * d + 1)];
            double slope = (p.end - p.start) / (b0 - a0);
            piece.start = p.start + (piece.start0 - a0) * slope;
            piece.end = p.start + (piece.end0 - a0) * slope;
        }
        out->push_back(piece);
        return;
    }
    IstPoint where = diagram_track(ist, mid, DiagramStage{level, false});
    const int n = divisor_at(ist, where.base);
    for (int g = 0; g < n; ++g) {
        DiagramPiece child = piece;
        child.start0 = piece.start0 + (piece.end0 - piece.start0) * double(g) / double(n);
        child.end0 = piece.start0 + (piece.end0 - piece.start0) * double(g + 1) / double(n);
        child.digits.push_back(g);
        collect(ist, depth, stage, child, extents, out);
    }
}

}  // namespace

IstPoint diagram_track(const DiagramIst& ist, double u0, DiagramStage stage) {
    IstPoint p;
    if (ist.original) {
        ist_original_start(ist.original_ist, u0, &p);
        for (int k = 0; k < stage.iterations; ++k) ist_original_step(ist.original_ist, &p);
        return p;
    }
    const double* edges = ist.edge_data();
    ist_procedure_start(ist.axis, edges, u0, &p);
    for (int k = 0; k < stage.iterations; ++k) {
        ist_divide_and_shuffle_internally(ist.axis, edges, &p);
        ist_shuffle_externally(ist.axis, edges, &p);
    }
    if (stage.half) ist_divide_and_shuffle_internally(ist.axis, edges, &p);
    return p;
}

std::vector<DiagramPiece> diagram_pieces(const DiagramIst& ist, int depth, DiagramStage stage) {
    std::vector<DiagramPiece> out;
    std::vector<double> extents;
    for (int b = 0; b < ist.base_intervals(); ++b) {
        DiagramPiece base;
        base.start0 = ist.edge(b);
        base.end0 = ist.edge(b + 1);
        base.origin_base = b;
        collect(ist, depth, stage, base, &extents, &out);
    }
    return out;
}

DiagramRow diagram_row(const DiagramIst& ist, const std::string& name, int depth,
                       DiagramStage stage) {
    DiagramRow row;
    row.name = name;
    row.stage = stage;
    row.pieces = diagram_pieces(ist, depth, stage);
    return row;
}

Rgb8 diagram_colour(const DiagramIst& ist, double u0) {
    const int count = ist.base_intervals();
    int b = 0;
    while (b + 1 < count && u0 >= ist.edge(b + 1)) ++b;
    double rel = (u0 - ist.edge(b)) / (ist.edge(b + 1) - ist.edge(b));
    if (count == 1) return hsv(300.0 * rel, 0.55, 0.95);  // one base interval: hue by place
    // Hues far apart for neighbours (golden-angle steps), lightness by place in the base.
    double hue = std::fmod(b * 137.508, 360.0);
    return hsv(hue, 0.25 + 0.55 * rel, 0.97 - 0.35 * rel);
}

std::string diagram_label(const IstDiagram& d, const DiagramPiece& piece) {
    std::string digits;
    for (int g : piece.digits) digits += char(g < 10 ? '0' + g : 'a' + (g - 10));
    if (d.unit_labels) return digits;
    std::string base = std::to_string(piece.origin_base + d.first_label);
    return digits.empty() ? base : base + "." + digits;
}

float diagram_height(const IstDiagram& d, const DiagramLayout& layout) {
    float rows = float(d.rows.size());
    return layout.top + rows * layout.row_height + (rows - 1.0f) * layout.gap + 20.0f;
}

// The number of one piece over [x0, x1] x [y, y + h]: horizontally where it fits, else stacked
// one character a line (skipped where neither fits).
void draw_piece_label(Canvas& canvas, const std::string& label, Rgb8 ink, float x0, float x1,
                      float y, float h) {
    float w = x1 - x0;
    int scale = (text_width(label, 2) + 6 <= w && 9 * 2 + 4 <= h) ? 2 : 1;
    if (text_width(label, scale) + 3 <= w) {
        float tx = x0 + 0.5f * (w - float(text_width(label, scale)));
        canvas.text({std::floor(tx), std::floor(y + 0.5f * h - 4.5f * scale)}, label, ink, scale);
    } else {
        std::string head = label, tail;
        std::size_t dot = label.find('.');
        if (dot != std::string::npos) {
            head = label.substr(0, dot);
            tail = label.substr(dot + 1);
        } else {
            head = label.substr(0, 1);
            tail = label.substr(1);
        }
        int lines = 1 + int(tail.size());
        if (text_width(head, 1) + 2 > w || lines * 9 > h) return;
        float ty = y + 0.5f * (h - float(lines * 9));
        canvas.text({std::floor(x0 + 0.5f * (w - float(text_width(head, 1)))), std::floor(ty)},
                    head, ink, 1);
        for (std::size_t i = 0; i < tail.size(); ++i)
            canvas.text({std::floor(x0 + 0.5f * (w - 5.0f)), std::floor(ty + 9.0f * float(i + 1))},
                        std::string(1, tail[i]), ink, 1);
    }
}

void draw_ist_diagram(Canvas& canvas, const IstDiagram& d, const DiagramLayout& layout) {
    const Rgb8 black{0, 0, 0}, grey{90, 90, 90}, white{255, 255, 255};
    auto x_of = [&](double u) {
        return float(layout.left + (u - d.window0) / (d.window1 - d.window0) * layout.width);
    };
    auto y_of = [&](std::size_t r) {
        return layout.top + float(r) * (layout.row_height + layout.gap);
    };
    const float x_min = layout.left, x_max = layout.left + layout.width;
    if (!d.title.empty()) canvas.text({layout.left, layout.top - 66.0f}, d.title, black, 2);

    for (std::size_t r = 0; r < d.rows.size(); ++r) {
        const DiagramRow& row = d.rows[r];
        const float y = y_of(r), h = layout.row_height;
        canvas.text({6.0f, y + 0.5f * h - 8.0f}, row.name, black, 2);
        for (const DiagramPiece& piece : row.pieces) {
            float x0 = x_of(piece.start), x1 = x_of(piece.end);
            if (x1 <= x_min || x0 >= x_max) continue;
            float c0 = x0 < x_min ? x_min : x0, c1 = x1 > x_max ? x_max : x1;
            Rgb8 colour = diagram_colour(d.ist, 0.5 * (piece.start0 + piece.end0));
            canvas.fill_rect({c0, y}, {c1 - c0, h}, colour);
            if (x1 - x0 >= 3.0f) {
                if (x0 >= x_min) canvas.line({x0, y}, {x0, y + h}, grey, 1.0f);
            }
            if (row.show_label && !row.show_label(piece)) continue;
            // The number, horizontally where it fits, else stacked one character a line.
            std::string label = diagram_label(d, piece);
            if (label.empty()) continue;
            if (x0 < x_min || x1 > x_max) continue;
            draw_piece_label(canvas, label, is_dark(colour) ? white : black, x0, x1, y, h);
        }
        canvas.rect_outline({x_min, y}, {layout.width, h}, black, 1.0f);
        // Base-interval edges: fixed on every axis.
        for (int b = 0; b <= d.ist.base_intervals(); ++b) {
            float x = x_of(d.ist.edge(b));
            if (x < x_min - 0.5f || x > x_max + 0.5f) continue;
            canvas.line({x, y - 4.0f}, {x, y + h + 4.0f}, black, 2.5f);
        }
        // div: the next division marked under the axis (fig 6).
        if (row.tick_depth >= 0) {
            for (const DiagramPiece& piece : diagram_pieces(d.ist, row.tick_depth, row.stage)) {
                float x = x_of(piece.start);
                if (x < x_min || x > x_max) continue;
                canvas.line({x, y + h}, {x, y + h + 7.0f}, black, 1.0f);
            }
        }
    }
    // Base-interval numbers above the first row.
    if (!d.rows.empty() && !d.unit_labels) {
        for (int b = 0; b < d.ist.base_intervals(); ++b) {
            float x0 = x_of(d.ist.edge(b)), x1 = x_of(d.ist.edge(b + 1));
            if (x1 <= x_min || x0 >= x_max) continue;
            std::string label = std::to_string(b + d.first_label);
            float cx = 0.5f * ((x0 < x_min ? x_min : x0) + (x1 > x_max ? x_max : x1));
            canvas.text({std::floor(cx - 0.5f * float(text_width(label, 2))), y_of(0) - 26.0f},
                        label, black, 2);
        }
    }
    // Moves: the u^0 midpoint of each followed piece, from one axis to the next.
    if (d.follow) {
        for (std::size_t r = 0; r + 1 < d.rows.size(); ++r) {
            const DiagramRow& upper = d.rows[r];
            const DiagramRow& lower = d.rows[r + 1];
            for (const DiagramPiece& piece : lower.pieces) {
                if (!d.follow(piece)) continue;
                double mid = 0.5 * (piece.start0 + piece.end0);
                float xa = x_of(diagram_track(d.ist, mid, upper.stage).u);
                float xb = x_of(diagram_track(d.ist, mid, lower.stage).u);
                if (xa < x_min || xa > x_max || xb < x_min || xb > x_max) continue;
                Rgb8 colour = darker(diagram_colour(d.ist, mid), 0.6);
                float ya = y_of(r) + layout.row_height + (upper.tick_depth >= 0 ? 8.0f : 1.0f);
                float yb = y_of(r + 1) - 1.0f;
                canvas.line({xa, ya}, {xb, yb}, colour, 1.0f);
                canvas.marker({xb, yb - 2.0f}, MarkerShape::triangle, 4.0f, colour);
            }
        }
    }
}

}  // namespace shitsukan::figures
