// hirota1998 Table 3: regions bounded by cracks and the crack spacings (see crack_regions.hpp).
#include "shitsukan/bark/crack_regions.hpp"

#include <algorithm>
#include <cmath>

namespace shitsukan {

namespace {

// Is node p inside the measured section (end_rows rows left out at the top and the bottom)?
bool in_window(const BarkCylinder& bark, int p, int end_rows) {
    const int r = bark.row_of(p);
    return r >= end_rows && r < bark.params.N_H - end_rows;
}

int find_root(std::vector<std::int32_t>& parent, int a) {
    while (parent[std::size_t(a)] != a) {
        parent[std::size_t(a)] = parent[std::size_t(parent[std::size_t(a)])];
        a = parent[std::size_t(a)];
    }
    return a;
}

// Seam-free displacement from node p to node q along spring s at time t.
Vec3 spring_offset(const BarkCylinder& bark, const BarkSpring& sp, std::uint32_t p, float t,
                   const Vec3* W) {
    const Vec3 d = sp.n * sp.l0;  // reference i -> j, seam-corrected by construction
    const Vec3 grown = cylinder_anchor(bark, d, t);
    Vec3 off = grown + (W[sp.j] - W[sp.i]) * t;
    return p == sp.i ? off : -off;
}

}  // namespace

void strong_springs(const BarkCylinder& bark, float t, std::vector<std::uint8_t>* strong) {
    const auto& springs = bark.net.springs;
    strong->assign(springs.size(), 0);
    for (const ConnectionTriangle& tri : bark.triangles) {
        bool intact = true;
        for (std::uint32_t s : tri.spring) intact = intact && intact_at(springs[s], t);
        if (intact)
            for (std::uint32_t s : tri.spring) (*strong)[s] = 1;
    }
}

namespace {

// Step 2: connected components over strong springs (union-find; roots are the smallest node).
// component[p] numbers them in order of their first node; size[k] counts their nodes.
void strong_components(const SpringNetwork& net, const std::vector<std::uint8_t>& strong,
                       std::vector<std::int32_t>* component, std::vector<std::int32_t>* size) {
    const int n = net.node_count();
    std::vector<std::int32_t> parent(static_cast<std::size_t>(n));
    for (int p = 0; p < n; ++p) parent[std::size_t(p)] = p;
    for (std::size_t s = 0; s < net.springs.size(); ++s) {
        if (!strong[s]) continue;
        const int a = find_root(parent, int(net.springs[s].i));
        const int b = find_root(parent, int(net.springs[s].j));
        if (a != b) parent[std::size_t(std::max(a, b))] = std::min(a, b);
    }
    component->assign(static_cast<std::size_t>(n), -1);
    size->clear();
    for (int p = 0; p < n; ++p) {
        const int root = find_root(parent, p);
        if ((*component)[std::size_t(root)] < 0) {
            (*component)[std::size_t(root)] = std::int32_t(size->size());
            size->push_back(0);
        }
        (*component)[std::size_t(p)] = (*component)[std::size_t(root)];
        ++(*size)[std::size_t((*component)[std::size_t(p)])];
    }
}

// The cell a node stands for, grown to time t (width around, height along).
struct GrownCell {
    float C, width, height, full;  // circumference, cell, "full height" extent of the window
};

GrownCell grown_cell(const BarkCylinder& bark, float t, int end_rows) {
    const float et = hoop_strain(bark.params, t), ez = axial_strain(bark.params, t);
    GrownCell g;
    g.C = bark.circumference * (1.0f + et);
    g.width = bark.a_h * (1.0f + et);
    g.height = bark.params.species.L0 * (1.0f + ez);
    g.full = (float(bark.params.N_H - 2 * end_rows) - 1.5f) * g.height;
    return g;
}

// Step 3: each component's extents, by a walk over strong springs carrying the unrolled
// position across the seam; a walk that meets a node again half a circumference away closes
// around the trunk.
void region_extents(const BarkCylinder& bark, float t, const Vec3* W,
                    const std::vector<std::uint8_t>& strong,
                    const std::vector<std::int32_t>& component,
                    const std::vector<std::int32_t>& size, const RegionOptions& options,
                    RegionReport* out) {
    const SpringNetwork& net = bark.net;
    const int n = net.node_count();
    const GrownCell cell = grown_cell(bark, t, options.end_rows);
    std::vector<Vec3> pos(static_cast<std::size_t>(n));
    std::vector<std::uint8_t> seen(static_cast<std::size_t>(n), 0);
    std::vector<std::uint32_t> stack;
    std::vector<std::int32_t> region_of_component(size.size(), -1);
    for (int start = 0; start < n; ++start) {
        if (seen[std::size_t(start)] || !in_window(bark, start, options.end_rows)) continue;
        const int comp = component[std::size_t(start)];
        BarkRegion region;
        region.nodes = size[std::size_t(comp)];
        pos[std::size_t(start)] = node_position(bark, std::uint32_t(start), t, W);
        seen[std::size_t(start)] = 1;
        stack.assign(1, std::uint32_t(start));
        Vec3 lo = pos[std::size_t(start)], hi = lo;
        while (!stack.empty()) {
            const std::uint32_t p = stack.back();
            stack.pop_back();
            for (std::uint32_t e = net.adj_begin[p]; e < net.adj_begin[p + 1]; ++e) {
                const std::uint32_t s = net.adj[e].s, q = net.adj[e].q;
                if (!strong[s]) continue;
                const Vec3 x = pos[p] + spring_offset(bark, net.springs[s], p, t, W);
                if (seen[q]) {
                    if (std::fabs(x.x - pos[q].x) > 0.5f * cell.C) region.wraps = true;
                    continue;
                }
                seen[q] = 1;
                pos[q] = x;
                lo = vmin(lo, x), hi = vmax(hi, x);
                stack.push_back(q);
            }
        }
        if (region.nodes < options.min_nodes) continue;  // step 4: crumbs are not regions
        region.width = region.wraps ? cell.C : std::min(cell.C, hi.x - lo.x + cell.width);
        region.height = hi.y - lo.y + cell.height;
        region.full_height = hi.y - lo.y >= cell.full;
        region_of_component[std::size_t(comp)] = std::int32_t(out->regions.size());
        out->regions.push_back(region);
    }
    out->label.resize(static_cast<std::size_t>(n));
    for (int p = 0; p < n; ++p)
        out->label[std::size_t(p)] =
            in_window(bark, p, options.end_rows)
                ? region_of_component[std::size_t(component[std::size_t(p)])]
                : -1;
}

// Step 5: each region's arc of columns. Its occupied columns, sorted; the largest circular gap
// between two occupied columns is what the region leaves out, the rest is its arc.
void region_columns(const BarkCylinder& bark, RegionReport* out) {
    const int N_R = bark.params.N_R;
    std::vector<std::uint64_t> occupied;  // (region, column) pairs
    for (std::size_t p = 0; p < out->label.size(); ++p)
        if (out->label[p] >= 0)
            occupied.push_back(std::uint64_t(out->label[p]) << 32 |
                               std::uint32_t(bark.column_of(int(p))));
    std::sort(occupied.begin(), occupied.end());
    occupied.erase(std::unique(occupied.begin(), occupied.end()), occupied.end());
    for (std::size_t a = 0; a < occupied.size();) {
        std::size_t b = a;
        while (b < occupied.size() && occupied[b] >> 32 == occupied[a] >> 32) ++b;
        BarkRegion& region = out->regions[std::size_t(occupied[a] >> 32)];
        auto column = [&](std::size_t k) { return int(occupied[k] & 0xffffffffu); };
        // The gap after the last occupied column runs round to the first.
        int gap = column(a) + N_R - column(b - 1), first = column(a);
        for (std::size_t k = a + 1; k < b; ++k)
            if (column(k) - column(k - 1) > gap) gap = column(k) - column(k - 1), first = column(k);
        region.first_column = first;
        region.columns = region.wraps ? N_R : N_R - gap + 1;
        a = b;
    }
}

// Table 3: mean and max of width and of height, separately.
void table3_statistics(RegionReport* out) {
    double sw = 0, sh = 0;
    for (const BarkRegion& r : out->regions) {
        sw += r.width, sh += r.height;
        out->max_width = std::max(out->max_width, r.width);
        out->max_height = std::max(out->max_height, r.height);
        out->wrapped += r.wraps, out->full_height += r.full_height;
    }
    if (!out->regions.empty()) {
        out->mean_width = float(sw / double(out->regions.size()));
        out->mean_height = float(sh / double(out->regions.size()));
    }
}

// The text's "crack spacings": changes of component around each ring and along each column.
void crack_intercepts(const BarkCylinder& bark, float t, int end_rows,
                      const std::vector<std::int32_t>& component, RegionReport* out) {
    const int N_R = bark.params.N_R, r0 = end_rows, r1 = bark.params.N_H - end_rows;
    const GrownCell cell = grown_cell(bark, t, end_rows);
    double iw = 0, ih = 0;
    int nw = 0, nh = 0;
    auto comp = [&](int c, int r) { return component[std::size_t(bark.node(c, r))]; };
    for (int r = r0; r < r1; ++r) {
        std::vector<int> cuts;
        for (int c = 0; c < N_R; ++c)
            if (comp(c, r) != comp(c + 1 == N_R ? 0 : c + 1, r)) cuts.push_back(c);
        for (std::size_t k = 0; k < cuts.size(); ++k) {
            const int gap = k + 1 < cuts.size() ? cuts[k + 1] - cuts[k] : cuts[0] + N_R - cuts[k];
            const float w = float(gap) * cell.width;
            iw += w, ++nw;
            out->intercept_max_width = std::max(out->intercept_max_width, w);
        }
    }
    for (int c = 0; c < N_R; ++c) {
        int last = -1;
        for (int r = r0; r + 1 < r1; ++r)
            if (comp(c, r) != comp(c, r + 1)) {
                if (last >= 0) {
                    const float h = float(r - last) * cell.height;
                    ih += h, ++nh;
                    out->intercept_max_height = std::max(out->intercept_max_height, h);
                }
                last = r;
            }
        if (last < 0) ++out->columns_uncut;
    }
    if (nw) out->intercept_mean_width = float(iw / nw);
    if (nh) out->intercept_mean_height = float(ih / nh);
}

}  // namespace

Status measure_regions(const BarkCylinder& bark, float t, const Vec3* W, RegionReport& out,
                       const RegionOptions& options) {
    if (!W)
        return Status::error(StatusCode::invalid_argument,
                             "measure_regions: null displacement field W");
    if (!(is_finite(t) && t >= 0.0f))
        return Status::error(StatusCode::invalid_argument,
                             "measure_regions: time must be >= 0 (got %g)", double(t));
    if (options.min_nodes < 1 || options.end_rows < 0 ||
        2 * options.end_rows + 2 > bark.params.N_H)
        return Status::error(StatusCode::invalid_argument,
                             "measure_regions: min_nodes must be >= 1 and end_rows in [0, %d] "
                             "(got %d, %d)",
                             bark.params.N_H / 2 - 1, options.min_nodes, options.end_rows);
    out = RegionReport{};
    std::vector<std::uint8_t> strong;
    strong_springs(bark, t, &strong);                       // step 1
    for (std::size_t s = 0; s < strong.size(); ++s)         // the measured section only
        if (!in_window(bark, int(bark.net.springs[s].i), options.end_rows) ||
            !in_window(bark, int(bark.net.springs[s].j), options.end_rows))
            strong[s] = 0;
    std::vector<std::int32_t> component, size;
    strong_components(bark.net, strong, &component, &size);  // step 2
    out.components = int(size.size());
    region_extents(bark, t, W, strong, component, size, options, &out);  // steps 3-4
    region_columns(bark, &out);                                          // step 5
    table3_statistics(&out);
    crack_intercepts(bark, t, options.end_rows, component, &out);
    return Status::success();
}

}  // namespace shitsukan
