// Tests for lib/shitsukan/image/raster_canvas: stroke coverage, polygon fill areas (even-odd),
// exact pixels without anti-aliasing, clipping (nothing written outside the view), text.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "shitsukan/image/canvas.hpp"
#include "shitsukan/image/font.hpp"

using namespace shitsukan;

namespace {

const Rgb8 kWhite{255, 255, 255};
const Rgb8 kBlack{0, 0, 0};

// Ink deposited on a white image by black drawing: sum over pixels of (255 - red) / 255.
double ink(const RgbImage& img) {
    double sum = 0.0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) sum += (255.0 - img.at(x, y).r) / 255.0;
    return sum;
}

int inked_pixels(const RgbImage& img) {
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) n += img.at(x, y) != kWhite;
    return n;
}

// A regular star polygon {points/step} (self-intersecting for step > 1).
std::vector<Vec2> star(Vec2 c, float r, int points, int step) {
    std::vector<Vec2> v;
    for (int i = 0; i < points; ++i) {
        float a = float(i * step) * kTwoPi / float(points) - kPi / 2;
        v.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
    }
    return v;
}

}  // namespace

TEST_CASE("anti-aliased line: total ink = capsule area (length x width + round caps)") {
    // Angles and widths across the usual range; the caps add pi·w²/4.
    const float angles[] = {0.0f, 0.3f, 0.7853982f, 1.2f, 1.5707964f, 2.5f};
    const float widths[] = {0.5f, 1.0f, 1.5f, 3.0f, 6.0f};
    for (float angle : angles)
        for (float w : widths) {
            RgbImage img(200, 200, kWhite);
            RasterCanvas canvas(img.view());
            float len = 120.0f;
            Vec2 c{100.3f, 99.6f};
            Vec2 d{0.5f * len * std::cos(angle), 0.5f * len * std::sin(angle)};
            canvas.line(c - d, c + d, kBlack, w);
            double expected = double(len) * w + kPiD * w * w / 4.0;
            CAPTURE(angle);
            CAPTURE(w);
            // 1%: the box-filter band coverage is exact across a straight stroke; caps and
            // pixels cut by both edges of a thin line take each edge as locally straight.
            CHECK(ink(img) == doctest::Approx(expected).epsilon(0.01));
        }
}

TEST_CASE("non-anti-aliased horizontal line sets exactly the expected pixels") {
    RgbImage img(40, 40, kWhite);
    RasterCanvas canvas(img.view(), false);
    canvas.line({10.0f, 20.5f}, {30.0f, 20.5f}, kBlack, 1.0f);  // centres 10.5 .. 29.5
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
            bool expect = y == 20 && x >= 10 && x < 30;
            CAPTURE(x);
            CAPTURE(y);
            CHECK((img.at(x, y) == kBlack) == expect);
            CHECK((img.at(x, y) == kWhite) == !expect);  // no partial values either
        }
    // Width 3 at an integer-plus-half row covers rows 19, 20, 21.
    RgbImage thick(40, 40, kWhite);
    RasterCanvas(thick.view(), false).line({5.5f, 20.5f}, {5.5f + 20.0f, 20.5f}, kBlack, 3.0f);
    int rows[40] = {0};
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) rows[y] += thick.at(x, y) == kBlack;
    CHECK(rows[18] == 0);
    CHECK(rows[19] > 0);
    CHECK(rows[20] == 23);  // centres 4.5 .. 26.5: the round caps reach 1.5 past the ends
    CHECK(rows[21] > 0);
    CHECK(rows[22] == 0);
}

TEST_CASE("non-anti-aliased diagonal line is 8-connected with one pixel per column") {
    RgbImage img(64, 64, kWhite);
    RasterCanvas canvas(img.view(), false);
    canvas.line({2.5f, 10.5f}, {60.5f, 39.5f}, kBlack, 1.0f);  // slope 1/2
    for (int x = 3; x < 60; ++x) {
        int n = 0;
        for (int y = 0; y < 64; ++y) n += img.at(x, y) == kBlack;
        CAPTURE(x);
        CHECK(n >= 1);
        CHECK(n <= 2);
    }
}

TEST_CASE("polyline joins are painted once: a bent-straight polyline equals one line") {
    for (bool aa : {true, false}) {
        RgbImage one(120, 60, kWhite), two(120, 60, kWhite);
        RasterCanvas a(one.view(), aa), b(two.view(), aa);
        Rgb8 gray{100, 100, 100};
        a.line({10.2f, 30.3f}, {110.7f, 35.1f}, gray, 4.0f);
        Vec2 mid = {10.2f + 0.37f * (110.7f - 10.2f), 30.3f + 0.37f * (35.1f - 30.3f)};
        Vec2 pts[3] = {{10.2f, 30.3f}, mid, {110.7f, 35.1f}};
        b.polyline(pts, 3, gray, 4.0f);
        int worst = 0;
        for (int y = 0; y < 60; ++y)
            for (int x = 0; x < 120; ++x)
                worst = std::max(worst, std::abs(int(one.at(x, y).r) - int(two.at(x, y).r)));
        CHECK(worst <= 1);  // float rounding of the split point only
    }
}

TEST_CASE("filled polygons: area equals the analytic area (< 1% for big shapes)") {
    struct Shape {
        const char* name;
        std::vector<Vec2> points;
        double area;
    };
    std::vector<Shape> shapes;
    shapes.push_back({"triangle", {{20.3f, 30.1f}, {380.6f, 60.7f}, {150.2f, 370.9f}}, 0.0});
    {
        // Shoelace area of the triangle.
        auto& p = shapes.back().points;
        shapes.back().area = 0.5 * std::fabs(double(p[1].x - p[0].x) * (p[2].y - p[0].y) -
                                             double(p[2].x - p[0].x) * (p[1].y - p[0].y));
    }
    {
        // A rotated square of side 200.
        std::vector<Vec2> sq;
        for (int i = 0; i < 4; ++i) {
            float a = 0.4f + float(i) * kPi / 2;
            sq.push_back({200.0f + 141.42136f * std::cos(a), 200.0f + 141.42136f * std::sin(a)});
        }
        shapes.push_back({"rotated square", sq, 200.0 * 200.0});
    }
    // Concave: an L of two 300x100 arms sharing a 100x100 corner.
    shapes.push_back({"concave L",
                      {{50, 50}, {150, 50}, {150, 250}, {350, 250}, {350, 350}, {50, 350}},
                      100.0 * 300.0 + 200.0 * 100.0});
    // Ring in ONE contour: outer square, then the inner square, joined by a bridge that is
    // walked there and back (even-odd cancels the bridge, leaves a hole).
    shapes.push_back({"square with hole (one contour, even-odd)",
                      {{40, 40}, {360, 40}, {360, 360}, {40, 360}, {40, 40},
                       {120, 120}, {120, 280}, {280, 280}, {280, 120}, {120, 120}},
                      320.0 * 320.0 - 160.0 * 160.0});
    // Pentagram {5/2}: even-odd leaves the central pentagon empty: area = 5 point triangles.
    {
        double R = 180.0;
        // Star {5/2}: inner pentagon circumradius r = R·cos(72°)/cos(36°).
        double r = R * std::cos(2 * kPiD / 5) / std::cos(kPiD / 5);
        double pentagon = 2.5 * r * r * std::sin(2 * kPiD / 5);
        double full_star = 5.0 * R * r * std::sin(kPiD / 5);  // star outline incl. centre
        shapes.push_back({"pentagram (even-odd)", star({200, 200}, float(R), 5, 2),
                          full_star - pentagon});
    }
    for (const Shape& s : shapes) {
        for (bool aa : {true, false}) {
            RgbImage img(400, 400, kWhite);
            RasterCanvas canvas(img.view(), aa);
            canvas.fill_polygon(s.points.data(), int(s.points.size()), kBlack);
            CAPTURE(s.name);
            CAPTURE(aa);
            CHECK(ink(img) == doctest::Approx(s.area).epsilon(0.01));
        }
    }
}

TEST_CASE("fill_contours: a hole in a second contour, same as the bridged single contour") {
    Vec2 pts[8] = {{40, 40}, {360, 40}, {360, 360}, {40, 360},
                   {120, 120}, {280, 120}, {280, 280}, {120, 280}};
    int sizes[2] = {4, 4};
    RgbImage img(400, 400, kWhite);
    RasterCanvas canvas(img.view());
    canvas.fill_contours(pts, sizes, 2, kBlack);
    CHECK(ink(img) == doctest::Approx(320.0 * 320.0 - 160.0 * 160.0).epsilon(1e-4));
    CHECK(img.at(200, 200) == kWhite);
    CHECK(img.at(80, 200) == kBlack);
    // The generic Canvas default (bridges) must give the same pixels.
    RgbImage ref(400, 400, kWhite);
    RasterCanvas rc(ref.view());
    rc.Canvas::fill_contours(pts, sizes, 2, kBlack);
    int differ = 0;
    for (int y = 0; y < 400; ++y)
        for (int x = 0; x < 400; ++x) differ += img.at(x, y) != ref.at(x, y);
    CHECK(differ == 0);
}

TEST_CASE("non-anti-aliased fills of pixel-aligned shapes hit exact pixels") {
    RgbImage img(50, 50, kWhite);
    RasterCanvas canvas(img.view(), false);
    Vec2 quad[4] = {{10, 5}, {30, 5}, {30, 25}, {10, 25}};
    canvas.fill_polygon(quad, 4, kBlack);
    canvas.fill_rect({35, 30}, {-5, 10}, Rgb8{0, 0, 255});  // negative width: x in [30, 35)
    for (int y = 0; y < 50; ++y)
        for (int x = 0; x < 50; ++x) {
            Rgb8 expect = kWhite;
            if (x >= 10 && x < 30 && y >= 5 && y < 25) expect = kBlack;
            if (x >= 30 && x < 35 && y >= 30 && y < 40) expect = Rgb8{0, 0, 255};
            CAPTURE(x);
            CAPTURE(y);
            CHECK(img.at(x, y) == expect);
        }
    // Anti-aliased, integer corners give the same exact pixels (full coverage only).
    RgbImage aa(50, 50, kWhite);
    RasterCanvas(aa.view()).fill_polygon(quad, 4, kBlack);
    CHECK(inked_pixels(aa) == 400);
    CHECK(ink(aa) == doctest::Approx(400.0));
}

TEST_CASE("fill_rect with anti-aliasing deposits the exact fractional area") {
    RgbImage img(40, 40, kWhite);
    RasterCanvas(img.view()).fill_rect({5.25f, 7.5f}, {10.5f, 3.25f}, kBlack);
    CHECK(ink(img) == doctest::Approx(10.5 * 3.25).epsilon(0.005));  // 8-bit rounding
}

TEST_CASE("rect_outline: square corners, ring area = outer - inner") {
    RgbImage img(100, 100, kWhite);
    RasterCanvas(img.view()).rect_outline({20, 20}, {60, 40}, kBlack, 2.0f);
    CHECK(ink(img) == doctest::Approx(62.0 * 42.0 - 58.0 * 38.0).epsilon(0.005));
    CHECK(img.at(19, 19) == kBlack);  // the corner pixel is fully inside (square join)
    CHECK(img.at(50, 40) == kWhite);
}

TEST_CASE("markers: dot area, symmetric shapes, every shape draws") {
    for (float r : {0.3f, 0.7f, 1.0f, 2.5f, 10.0f}) {
        RgbImage img(60, 60, kWhite);
        RasterCanvas(img.view()).marker({30.2f, 29.7f}, MarkerShape::dot, 2.0f * r, kBlack);
        CAPTURE(r);
        // 8-bit rounding of a few rim pixels dominates for the smallest dots.
        CHECK(ink(img) == doctest::Approx(kPiD * r * r).epsilon(r < 1.0f ? 0.05 : 0.01));
    }
    const MarkerShape shapes[] = {MarkerShape::dot,   MarkerShape::circle, MarkerShape::square,
                                  MarkerShape::cross, MarkerShape::plus,   MarkerShape::triangle};
    std::vector<int> counts;
    for (MarkerShape s : shapes) {
        RgbImage m(40, 40, kWhite);
        RasterCanvas(m.view()).marker({20, 20}, s, 15.0f, kBlack);
        int n = inked_pixels(m);
        CHECK(n > 10);
        // Extent: nothing farther than size/2 + 1 from the centre.
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 40; ++x)
                if (m.at(x, y) != kWhite) {
                    CHECK(std::fabs(x + 0.5 - 20.0) <= 8.5);
                    CHECK(std::fabs(y + 0.5 - 20.0) <= 8.5);
                }
        // Left-right mirror symmetry about x = 20.
        int asym = 0;
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 20; ++x)
                asym += std::abs(int(m.at(x, y).r) - int(m.at(39 - x, y).r)) > 2;
        CHECK(asym == 0);
        counts.push_back(n);
    }
    // Filled dot inks more pixels than the hollow circle of the same size.
    CHECK(counts[0] > counts[1]);
}

TEST_CASE("nothing is written outside the view: guard band around a window") {
    // The view is a window inside a larger buffer; the border must keep its sentinel colour.
    const int W = 80, H = 60, G = 8;
    const Rgb8 sentinel{1, 2, 3};
    RgbImage buffer(W + 2 * G, H + 2 * G, sentinel);
    RgbView window = buffer.view().subview(G, G, W, H);
    fill(window, kWhite);
    for (bool aa : {true, false}) {
        RasterCanvas c(window, aa);
        const float inf = INFINITY, nan = NAN;
        // Partly outside on every side.
        c.line({-30, 10}, {100, 50}, kBlack, 5.0f);
        c.line({40, -20}, {40, 90}, kBlack, 9.0f);
        Vec2 big[4] = {{-50, -40}, {150, -30}, {120, 110}, {-40, 90}};
        c.fill_polygon(big, 4, Rgb8{200, 0, 0});
        c.polygon_outline(big, 4, kBlack, 7.0f);
        c.fill_rect({-10, -10}, {200, 200}, Rgb8{0, 200, 0});
        c.rect_outline({-3, -3}, {W + 6.0f, H + 6.0f}, kBlack, 10.0f);
        for (int i = 0; i < 6; ++i) {
            c.marker({-2.0f, 30.0f}, MarkerShape(i), 20.0f, kBlack);
            c.marker({W + 2.0f, H + 2.0f}, MarkerShape(i), 20.0f, kBlack);
        }
        c.text({-7, -4}, "clip me ABC", kBlack, 3);
        c.text({70, 50}, "clip me too", kBlack, 2);
        c.fill_disc({W / 2.0f, H / 2.0f}, 100.0f, Rgb8{0, 0, 200});
        c.circle_outline({0, 0}, 50.0f, kBlack, 4.0f);
        // Fully outside.
        c.line({-100, -100}, {-50, -20}, kBlack, 3.0f);
        c.fill_rect({W + 5.0f, 0}, {10, 10}, kBlack);
        Vec2 away[3] = {{200, 200}, {300, 200}, {250, 300}};
        c.fill_polygon(away, 3, kBlack);
        c.text({-500, 10}, "far left", kBlack, 2);
        // Huge and non-finite coordinates.
        c.line({-1e30f, 30}, {1e30f, 30}, kBlack, 2.0f);
        Vec2 huge[3] = {{-1e20f, -1e20f}, {1e20f, -1e20f}, {0, 1e20f}};
        c.fill_polygon(huge, 3, Rgb8{9, 9, 9});
        c.text({-2e9f, 2e9f}, "x", kBlack, 1000000);
        c.line({nan, 0}, {10, 10}, kBlack, 1.0f);
        c.line({0, 0}, {inf, 10}, kBlack, 1.0f);
        Vec2 bad[3] = {{0, 0}, {nan, 5}, {5, 5}};
        c.fill_polygon(bad, 3, kBlack);
        c.marker({nan, nan}, MarkerShape::dot, 5.0f, kBlack);
        c.fill_rect({0, 0}, {inf, 5}, kBlack);
        c.line({10, 10}, {20, 20}, kBlack, nan);
        c.text({nan, 0}, "nan", kBlack, 1);
    }
    for (int y = 0; y < buffer.height(); ++y)
        for (int x = 0; x < buffer.width(); ++x) {
            bool inside = x >= G && x < G + W && y >= G && y < G + H;
            if (!inside) {
                CAPTURE(x);
                CAPTURE(y);
                REQUIRE(buffer.at(x, y) == sentinel);
            }
        }
    // The huge triangle covers the whole window with its colour.
    CHECK(window.at(W / 2, 5) == Rgb8{9, 9, 9});
}

TEST_CASE("an empty view draws nothing and does not crash") {
    RasterCanvas c(RgbView{});
    CHECK(c.width() == 0);
    CHECK(c.height() == 0);
    c.line({0, 0}, {10, 10}, kBlack);
    Vec2 tri[3] = {{0, 0}, {5, 0}, {0, 5}};
    c.fill_polygon(tri, 3, kBlack);
    c.fill_polygon(nullptr, 0, kBlack);
    c.polyline(nullptr, 5, kBlack);
    c.text({0, 0}, "x", kBlack);
    c.clear(kBlack);
}

TEST_CASE("text: each lit font pixel becomes a scale x scale block at the snapped origin") {
    for (int scale : {1, 2, 3}) {
        RgbImage img(80, 40, kWhite);
        RasterCanvas(img.view()).text({3.4f, 2.6f}, "Ag", kBlack, scale);  // origin (3, 3)
        const Glyph* glyphs[2] = {&font_glyph('A'), &font_glyph('g')};
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 80; ++x) {
                int gx = (x - 3) / scale, gy = (y - 3) / scale;
                bool expect = false;
                if (x >= 3 && y >= 3) {
                    int ch = gx / kFontAdvance, col = gx % kFontAdvance;
                    if (ch < 2) expect = glyph_pixel(*glyphs[ch], col, gy);
                }
                CAPTURE(scale);
                CAPTURE(x);
                CAPTURE(y);
                CHECK((img.at(x, y) == kBlack) == expect);
            }
        // The ink stays inside the measured box.
        CHECK(text_width("Ag", scale) == 11 * scale);
    }
    // '\n' moves down by kFontLineAdvance·scale and back to the left edge.
    RgbImage a(40, 40, kWhite), b(40, 40, kWhite);
    RasterCanvas(a.view()).text({2, 2}, "x\ny", kBlack, 2);
    RasterCanvas cb(b.view());
    cb.text({2, 2}, "x", kBlack, 2);
    cb.text({2, 2 + 2.0f * kFontLineAdvance}, "y", kBlack, 2);
    int differ = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) differ += a.at(x, y) != b.at(x, y);
    CHECK(differ == 0);
}

TEST_CASE("clear paints every pixel") {
    RgbImage img(7, 5, kWhite);
    RasterCanvas c(img.view());
    c.clear(Rgb8{10, 20, 30});
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) CHECK(img.at(x, y) == Rgb8{10, 20, 30});
}
