// Tests for lib/shitsukan/image/plot: nice ticks, data <-> pixel mapping, clipping of
// series, heat-map cells without seams, axes on both canvases, errors.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "shitsukan/core/prng.hpp"
#include "shitsukan/image/plot.hpp"

using namespace shitsukan;

namespace {

const Rgb8 kWhite{255, 255, 255};

int count_of(const std::string& s, const std::string& what) {
    int n = 0;
    for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
}

Axes test_axes() {
    Axes a;
    a.corner = {20.0f, 10.0f};
    a.size = {100.0f, 80.0f};
    a.x_lo = -1.0;
    a.x_hi = 4.0;
    a.y_lo = 0.0;
    a.y_hi = 2.0;
    return a;
}

}  // namespace

TEST_CASE("nice_step: 1-2-5 steps for typical ranges") {
    CHECK(nice_step(0.0, 2.0 * kPiD, 7) == doctest::Approx(1.0));
    CHECK(nice_step(-1.2, 1.2, 6) == doctest::Approx(0.5));
    CHECK(nice_step(0.0, 100.0, 5) == doctest::Approx(20.0));
    CHECK(nice_step(0.0, 1.0, 10) == doctest::Approx(0.1));
    CHECK(nice_step(0.0, 0.003, 6) == doctest::Approx(0.0005));
    CHECK(nice_step(1.0, 1.0, 5) == 0.0);  // empty range: no ticks
    CHECK(nice_ticks(1.0, 1.0, 5).empty());
    std::vector<double> t = nice_ticks(-1.2, 1.2, 6);
    REQUIRE(t.size() == 5);
    CHECK(t[0] == -1.0);
    CHECK(t[2] == 0.0);
    CHECK(t[4] == 1.0);
}

TEST_CASE("nice_ticks over random ranges: 1-2-5 mantissa, inside the range, about target") {
    Pcg32 rng(2026u, 11u);
    for (int trial = 0; trial < 2000; ++trial) {
        double scale = std::pow(10.0, double(rng.uniform()) * 12.0 - 6.0);
        double lo = (double(rng.uniform()) * 2.0 - 1.0) * scale;
        double hi = lo + (0.01 + double(rng.uniform())) * scale;
        int target = 2 + int(rng.uniform() * 9.0f);
        double step = nice_step(lo, hi, target);
        REQUIRE(step > 0.0);
        double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-12));
        bool nice = std::fabs(mantissa - 1.0) < 1e-9 || std::fabs(mantissa - 2.0) < 1e-9 ||
                    std::fabs(mantissa - 5.0) < 1e-9 || std::fabs(mantissa - 10.0) < 1e-9;
        CAPTURE(lo);
        CAPTURE(hi);
        CAPTURE(step);
        CHECK(nice);
        std::vector<double> ticks = nice_ticks(lo, hi, target);
        // At most target + 1, except when a short range needed a smaller step to show 2.
        CHECK(int(ticks.size()) <= std::max(target + 1, 6));
        CHECK(int(ticks.size()) >= std::max(2, int(target / 2.5)));
        for (double v : ticks) {
            CHECK(v >= lo - 1e-9 * step);
            CHECK(v <= hi + 1e-9 * step);
        }
    }
}

TEST_CASE("format_tick: decimals from the step, no -0, %g for large values") {
    CHECK(format_tick(0.5, 0.5) == "0.5");
    CHECK(format_tick(1.0, 0.5) == "1.0");
    CHECK(format_tick(3 * 0.1, 0.1) == "0.3");
    CHECK(format_tick(-1e-17, 0.1) == "0.0");
    CHECK(format_tick(0.0005, 0.0005) == "0.0005");
    CHECK(format_tick(250.0, 50.0) == "250");
    CHECK(format_tick(-3.0, 1.0) == "-3");
    CHECK(format_tick(1e7, 1e6) == "1e+07");
    CHECK(format_tick(2e-5, 1e-5) == "2e-05");
}

TEST_CASE("Axes: data corners map to the pixel rectangle, y up, inverse mapping") {
    Axes a = test_axes();
    REQUIRE(a.check().ok());
    Vec2 p = a.to_pixel(-1.0, 0.0);
    CHECK(p.x == doctest::Approx(20.0f));
    CHECK(p.y == doctest::Approx(90.0f));  // y_lo at the bottom
    p = a.to_pixel(4.0, 2.0);
    CHECK(p.x == doctest::Approx(120.0f));
    CHECK(p.y == doctest::Approx(10.0f));
    p = a.to_pixel(1.5, 0.5);
    CHECK(a.from_pixel_x(p.x) == doctest::Approx(1.5));
    CHECK(a.from_pixel_y(p.y) == doctest::Approx(0.5));
    CHECK(a.contains(4.0, 2.0));
    CHECK_FALSE(a.contains(4.01, 1.0));

    Axes bad = a;
    bad.x_hi = bad.x_lo;
    CHECK(bad.check().code() == StatusCode::invalid_argument);
    bad = a;
    bad.y_lo = NAN;
    CHECK_FALSE(bad.check().ok());
    bad = a;
    bad.size.x = 0.0f;
    CHECK_FALSE(bad.check().ok());
    bad = a;
    bad.x_lo = -1e308;
    bad.x_hi = 1e308;  // the span overflows
    CHECK_FALSE(bad.check().ok());

    SvgCanvas svg(300, 200);
    Axes in = axes_in(svg, 0, 1, 0, 1);
    PlotMargins m;
    CHECK(in.corner.x == m.left);
    CHECK(in.size.x == 300.0f - m.left - m.right);
    SvgCanvas tiny(30, 30);
    CHECK_FALSE(axes_in(tiny, 0, 1, 0, 1).check().ok());  // margins leave no data area
}

TEST_CASE("draw_axes: tick labels and titles on an SvgCanvas, nothing on bad axes") {
    SvgCanvas svg(640, 400);
    Axes a = axes_in(svg, 0.0, 2.0 * kPiD, -1.2, 1.2);
    REQUIRE(draw_axes(svg, a, {"sine & co", "x", "y"}).ok());
    std::string doc = svg.str();
    for (const char* label : {">0<", ">1<", ">2<", ">3<", ">4<", ">5<", ">6<", ">-1.0<",
                              ">-0.5<", ">0.0<", ">0.5<", ">1.0<", ">sine &amp; co<", ">x<",
                              ">y<"}) {
        CAPTURE(label);
        CHECK(count_of(doc, label) == 1);
    }
    CHECK(count_of(doc, "<text") == 7 + 5 + 3);
    CHECK(count_of(doc, "<rect") == 1);  // the frame

    SvgCanvas none(640, 400);
    Axes bad = a;
    bad.y_hi = -5.0;
    CHECK(draw_axes(none, bad).code() == StatusCode::invalid_argument);
    CHECK(none.element_count() == 0);
}

TEST_CASE("draw_axes on pixels: the frame is crisp and just outside the data area") {
    RgbImage img(200, 150, kWhite);
    RasterCanvas c(img.view());
    Axes a = test_axes();  // data area x [20, 120), y [10, 90)
    AxesStyle style;
    style.draw_grid = false;
    REQUIRE(draw_axes(c, a, AxesLabels(), style).ok());
    for (int y = 12; y < 88; ++y) {
        CHECK(img.at(19, y) == Rgb8{0, 0, 0});   // left frame column
        CHECK(img.at(120, y) == Rgb8{0, 0, 0});  // right frame column
        CHECK(img.at(20, y) == kWhite);          // data area untouched
        CHECK(img.at(119, y) == kWhite);
    }
}

TEST_CASE("plot_series: clipped to the data area, gaps at NaN, errors") {
    RgbImage img(160, 120, kWhite);
    RasterCanvas c(img.view());
    Axes a = test_axes();
    std::vector<float> xs, ys;
    for (int i = 0; i <= 200; ++i) {
        xs.push_back(-3.0f + 0.04f * float(i));  // from x = -3 to 5: beyond both ends
        ys.push_back(1.0f + 3.0f * std::sin(float(i) * 0.2f));  // -2 .. 4: beyond y too
    }
    REQUIRE(plot_series(c, a, xs.data(), ys.data(), int(xs.size()), Rgb8{0, 0, 0}, 2.0f).ok());
    int inside = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            if (img.at(x, y) == kWhite) continue;
            // Ink only within the data area plus the stroke's half width (and AA fringe).
            CAPTURE(x);
            CAPTURE(y);
            CHECK(x >= 18);
            CHECK(x < 122);
            CHECK(y >= 8);
            CHECK(y < 92);
            ++inside;
        }
    CHECK(inside > 200);

    // Gaps: a NaN splits the series; an excursion outside the area splits it too.
    SvgCanvas svg(200, 200);
    float gx[7] = {0.0f, 1.0f, NAN, 2.0f, 3.0f, 3.5f, 3.9f};
    float gy[7] = {0.5f, 1.0f, 1.0f, 1.0f, 1.5f, 9.0f, 1.0f};
    REQUIRE(plot_series(svg, a, gx, gy, 7, Rgb8{0, 0, 0}).ok());
    CHECK(count_of(svg.str(), "<polyline") == 3);  // [0,1], [2,3,exit], [re-entry,3.9]

    CHECK(plot_series(svg, a, gx, gy, -1, Rgb8{}).code() == StatusCode::invalid_argument);
    CHECK(plot_series(svg, a, static_cast<const float*>(nullptr), gy, 3, Rgb8{}).code() ==
          StatusCode::invalid_argument);
    CHECK(plot_series(svg, a, gx, gy, 3, Rgb8{}, 0.0f).code() == StatusCode::invalid_argument);
    auto f = [](double x) { return x; };
    CHECK(plot_function(svg, a, f, 1, Rgb8{}).code() == StatusCode::invalid_argument);
    SvgCanvas fs(200, 200);
    REQUIRE(plot_function(fs, a, f, 50, Rgb8{}).ok());
    CHECK(count_of(fs.str(), "<polyline") == 1);  // y = x leaves at x = 2: clipped, one piece
}

TEST_CASE("plot_scatter: points outside the data area or non-finite are skipped") {
    SvgCanvas svg(200, 200);
    Axes a = test_axes();
    float xs[6] = {0.0f, 1.0f, 5.0f, NAN, 2.0f, -1.0f};
    float ys[6] = {1.0f, 1.5f, 1.0f, 1.0f, -0.1f, 0.0f};
    REQUIRE(plot_scatter(svg, a, xs, ys, 6, MarkerShape::dot, 5.0f, Rgb8{}).ok());
    CHECK(count_of(svg.str(), "<circle") == 3);  // (0,1), (1,1.5), the corner (-1,0)
    CHECK(plot_scatter(svg, a, xs, ys, 6, MarkerShape::dot, -1.0f, Rgb8{}).code() ==
          StatusCode::invalid_argument);
}

TEST_CASE("plot_heatmap: every pixel of the area is exactly one cell's colour (no seams)") {
    FloatImage field(7, 5);
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 7; ++i) field.at(i, j) = float(i + 7 * j);
    for (bool aa : {true, false}) {
        RgbImage img(160, 120, kWhite);
        RasterCanvas c(img.view(), aa);
        Axes a = test_axes();
        a.size = {97.0f, 61.0f};  // not a multiple of the cell counts
        ValueRange r{0.0f, 34.0f};
        REQUIRE(plot_heatmap(c, a, field.view(), ColorMap::perceptual, r).ok());
        for (int y = 10; y < 71; ++y)
            for (int x = 20; x < 117; ++x) {
                // The cell under the pixel centre, row 0 at the top.
                int i = int((x + 0.5 - 20.0) / 97.0 * 7.0), j = int((y + 0.5 - 10.0) / 61.0 * 5.0);
                Rgb8 expect = colormap(ColorMap::perceptual, float(i + 7 * j) / 34.0f);
                CAPTURE(x);
                CAPTURE(y);
                CHECK(img.at(x, y) == expect);
            }
        CHECK(img.at(19, 40) == kWhite);
        CHECK(img.at(117, 40) == kWhite);
        CHECK(img.at(60, 71) == kWhite);
    }
    SvgCanvas svg(200, 200);
    CHECK(plot_heatmap(svg, test_axes(), FloatView{}, ColorMap::gray, {0, 1}).code() ==
          StatusCode::invalid_argument);
    CHECK(plot_heatmap(svg, test_axes(), field.view(), ColorMap::gray, {2, 1}).code() ==
          StatusCode::invalid_argument);
    CHECK(svg.element_count() == 0);
}

TEST_CASE("draw_colorbar: hi at the top, lo at the bottom, labelled") {
    RgbImage img(100, 140, kWhite);
    RasterCanvas c(img.view());
    REQUIRE(draw_colorbar(c, {10, 10}, {12, 100}, ColorMap::gray, {0.0f, 1.0f}).ok());
    CHECK(img.at(15, 10).r >= 253);  // top row: t = 1 - 0.5/100
    CHECK(img.at(15, 109).r <= 2);   // bottom row
    CHECK(img.at(15, 60).r < img.at(15, 59).r + 1);
    SvgCanvas svg(100, 140);
    REQUIRE(draw_colorbar(svg, {10, 10}, {12, 100}, ColorMap::gray, {-1.0f, 1.0f}).ok());
    std::string doc = svg.str();
    CHECK(count_of(doc, ">-1.0<") == 1);
    CHECK(count_of(doc, ">1.0<") == 1);
    CHECK(draw_colorbar(svg, {0, 0}, {0, 10}, ColorMap::gray, {0, 1}).code() ==
          StatusCode::invalid_argument);
}
