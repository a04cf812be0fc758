// hirota1998 Table 3 measured in photograph-sized views of the trunk (see photograph_views.hpp).
#include "shitsukan/bark/photograph_views.hpp"

#include <algorithm>

namespace shitsukan {

int photograph_view_columns(int N_R) {
    return std::max(1, (N_R + 1) / 3);  // N_R / 3 rounded to the nearest column
}

Status measure_photograph_views(const BarkCylinder& bark, const RegionReport& regions,
                                int view_columns, PhotographViews& out) {
    const int N_R = bark.params.N_R;
    if (view_columns < 1 || view_columns > N_R)
        return Status::error(StatusCode::invalid_argument,
                             "measure_photograph_views: the view must be 1..%d columns wide "
                             "(got %d)",
                             N_R, view_columns);
    if (regions.label.size() != std::size_t(bark.net.node_count()))
        return Status::error(StatusCode::invalid_argument,
                             "measure_photograph_views: the report labels %zu nodes, the bark "
                             "has %d (measure_regions on this bark first)",
                             regions.label.size(), bark.net.node_count());
    out = PhotographViews{};
    out.view_columns = view_columns;
    double regions_shown = 0, mean_w = 0, mean_h = 0, max_w = 0, max_h = 0, full = 0;
    for (int c0 = 0; c0 < N_R; ++c0) {  // the view covers columns c0 .. c0 + view_columns - 1
        int shown = 0;
        bool spans = false;
        double sw = 0, sh = 0;
        float xw = 0, xh = 0;
        for (const BarkRegion& r : regions.regions) {
            const int offset = (r.first_column - c0 + N_R) % N_R;
            if (r.wraps || offset + r.columns > view_columns) continue;  // not shown whole
            ++shown;
            sw += r.width, sh += r.height;
            xw = std::max(xw, r.width), xh = std::max(xh, r.height);
            spans = spans || r.full_height;
        }
        if (!shown) continue;
        ++out.views;
        regions_shown += shown;
        mean_w += sw / shown, mean_h += sh / shown, max_w += xw, max_h += xh;
        full += spans;
    }
    if (out.views) {
        const double n = out.views;
        out.regions_per_view = float(regions_shown / n);
        out.mean_width = float(mean_w / n), out.mean_height = float(mean_h / n);
        out.max_width = float(max_w / n), out.max_height = float(max_h / n);
        out.full_height_share = float(full / n);
    }
    return Status::success();
}

}  // namespace shitsukan
