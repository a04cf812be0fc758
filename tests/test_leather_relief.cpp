// Tests for lib/shitsukan/leather/relief and leather/maps: the relief of one scale (tokai1994
// §3.2, eq. 4) and the height/normal maps of a whole pattern. Patterns are built inline
// (regular squares and hexagons), labelled by brute-force point-in-polygon.
#include <doctest/doctest.h>
#include "measured.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <string>
#include <vector>

#include "shitsukan/core/prng.hpp"

#include "shitsukan/geom/polygon.hpp"
#include "shitsukan/leather/maps.hpp"
#include "shitsukan/leather/relief.hpp"
#include "shitsukan/leather/scale_division.hpp"

using namespace shitsukan;

namespace {

void add_polygon(ScalePattern* p, const std::vector<Vec2>& poly) {
    if (p->polygon_offsets.empty()) p->polygon_offsets.push_back(0);
    p->vertices.insert(p->vertices.end(), poly.begin(), poly.end());
    p->polygon_offsets.push_back(int(p->vertices.size()));
    p->centroids.push_back(to_float(polygon_centroid(poly.data(), int(poly.size()))));
}

// k x k squares tiling [0, 1]^2, counter-clockwise.
ScalePattern square_pattern(int k) {
    ScalePattern p;
    float h = 1.0f / float(k);
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            float x = float(i) * h, y = float(j) * h;
            add_polygon(&p, {{x, y}, {x + h, y}, {x + h, y + h}, {x, y + h}});
        }
    return p;
}

// Pointy-top hexagons of circumradius R over [0, 1]^2 (some stick out of the square).
ScalePattern hexagon_pattern(float R) {
    ScalePattern p;
    float w = std::sqrt(3.0f) * R;
    for (int row = -1; row * 1.5f * R < 1.0f + R; ++row)
        for (int col = -1; col * w < 1.0f + w; ++col) {
            Vec2 c{float(col) * w + (row & 1 ? 0.5f * w : 0.0f), float(row) * 1.5f * R};
            std::vector<Vec2> hex;
            for (int s = 0; s < 6; ++s) {
                float a = kPi / 6.0f + float(s) * kPi / 3.0f;
                hex.push_back(c + Vec2{std::cos(a), std::sin(a)} * R);
            }
            add_polygon(&p, hex);
        }
    return p;
}

bool inside(const Vec2* v, int n, Vec2 q) {
    bool in = false;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((v[i].y > q.y) != (v[j].y > q.y) &&
            q.x < (v[j].x - v[i].x) * (q.y - v[i].y) / (v[j].y - v[i].y) + v[i].x)
            in = !in;
    return in;
}

std::vector<int> brute_force_labels(const ScalePattern& p, int w, int h) {
    std::vector<int> labels(std::size_t(w) * std::size_t(h), -1);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            Vec2 q{(float(i) + 0.5f) * p.width / float(w), (float(j) + 0.5f) * p.height / float(h)};
            for (int k = 0; k < p.polygon_count(); ++k) {
                int n;
                const Vec2* v = p.polygon(k, &n);
                if (inside(v, n, q)) {
                    labels[std::size_t(j) * std::size_t(w) + std::size_t(i)] = k;
                    break;
                }
            }
        }
    return labels;
}

float angle_degrees(Vec3 a, Vec3 b) {
    float c = clamp(dot(normalize(a), normalize(b)), -1.0f, 1.0f);
    return std::acos(c) * 180.0f / kPi;
}

}  // namespace

TEST_CASE("relief: height at the centroid is z(0)·S, on the edge z(end) = 0, along a ray z(rho)") {
    const Vec2 sq[4] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    const Vec2 m{1, 1};
    CHECK(scale_size(sq, 4) == doctest::Approx(1.0f));  // 2·4 / 8: the inradius
    for (Table1Section which :
         {Table1Section::convex, Table1Section::concave, Table1Section::two_segment}) {
        BezierChain s = table1_section(which);
        ReliefOptions opt;
        ReliefSample r;
        scale_relief(sq, 4, m, m, s, opt, &r);
        CHECK(r.height == doctest::Approx(s.segments[0].p[0].y));
        CHECK(r.normal.z == 1.0f);
        scale_relief(sq, 4, m, {2.0f, 1.3f}, s, opt, &r);  // on the edge
        CHECK(r.rho == doctest::Approx(1.0f));
        CHECK(r.height == 0.0f);
        for (int k = 1; k < 10; ++k) {  // along the +x axis: |p - m| = 1, rho = x - 1
            float rho = float(k) / 10.0f;
            scale_relief(sq, 4, m, {1.0f + rho, 1.0f}, s, opt, &r);
            CHECK(r.edge_point.x == doctest::Approx(2.0f));
            CHECK(r.rho == doctest::Approx(rho));
            CHECK(r.height == doctest::Approx(section_at_r(s, rho).z).epsilon(1e-5));
        }
    }
}

TEST_CASE("relief: the edge point p lies on the boundary, beyond x, for star-shaped polygons") {
    // A non-convex but star-shaped polygon (a notch in the right edge).
    const Vec2 poly[6] = {{0, 0}, {2, 0}, {2, 0.8f}, {1.6f, 1.0f}, {2, 1.2f}, {0, 2}};
    Vec2 m{0.8f, 0.8f};
    for (int k = 0; k < 64; ++k) {
        float a = kTwoPi * float(k) / 64.0f;
        Vec2 x = m + Vec2{std::cos(a), std::sin(a)} * 0.3f;
        EdgeHit hit = scale_edge_point(poly, 6, m, x);
        REQUIRE(hit.inside);
        CHECK(length(hit.p - m) >= 0.3f - 1e-5f);
        CHECK(std::fabs(cross(normalize(hit.p - m), normalize(x - m))) < 1e-4f);  // on the ray
        CHECK(hit.edge_distance > 0.0f);
        CHECK(hit.edge_distance <= length(hit.p - m) + 1e-5f);
    }
}

TEST_CASE("relief: normals are unit, point up, and follow eq. (4) along the ray") {
    const Vec2 hex[6] = {{1, 0},  {0.5f, 0.866f},   {-0.5f, 0.866f},
                         {-1, 0}, {-0.5f, -0.866f}, {0.5f, -0.866f}};
    BezierChain s = table1_section(Table1Section::convex);
    ReliefOptions opt;
    for (int k = 0; k < 500; ++k) {
        float a = float(k) * 2.3999632f, rr = std::sqrt(float(k) / 500.0f) * 0.85f;
        Vec2 x{rr * std::cos(a), rr * std::sin(a)};
        ReliefSample r;
        scale_relief(hex, 6, {0, 0}, x, s, opt, &r);
        CHECK(length(r.normal) == doctest::Approx(1.0f).epsilon(1e-5));
        CHECK(r.normal.z > 0.0f);
        if (r.r > 0.0f && r.r < section_r_last(s)) {
            // eq. (4): (n_x, n_y) parallel to p - m, n_z / n_r = -dr / dz.
            SectionSample q = section_at_r(s, r.r);
            Vec2 u = normalize(r.edge_point);
            float nr = r.normal.x * u.x + r.normal.y * u.y;
            CHECK(std::fabs(cross(Vec2{r.normal.x, r.normal.y}, u)) < 1e-5f);
            if (std::fabs(q.dz) > 1e-3f)
                CHECK(r.normal.z / nr == doctest::Approx(-q.dr / q.dz).epsilon(1e-3));
        }
    }
}

TEST_CASE("relief: convex scales are raised, concave sunken with a rim, two-segment stepped") {
    const Vec2 sq[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    auto h = [&](Table1Section w, float x) {
        ReliefSample r;
        scale_relief(sq, 4, {0, 0}, {x, 0}, table1_section(w), ReliefOptions{}, &r);
        return r.height;
    };
    CHECK(h(Table1Section::convex, 0.0f) > h(Table1Section::convex, 0.97f) + 0.09f);
    CHECK(h(Table1Section::concave, 0.0f) < h(Table1Section::concave, 0.84f) - 0.09f);
    // fig. 15: a peak at m, a ring valley, the step at r = 0.6, then down to the groove.
    CHECK(h(Table1Section::two_segment, 0.3f) < h(Table1Section::two_segment, 0.0f) - 0.1f);
    CHECK(h(Table1Section::two_segment, 0.3f) < h(Table1Section::two_segment, 0.6f) - 0.1f);
    CHECK(h(Table1Section::two_segment, 0.95f) == 0.0f);
}

TEST_CASE("relief maps: the normal map is the gradient of the height map") {
    const int size = 384;
    for (bool hex : {false, true}) {
        ScalePattern p = hex ? hexagon_pattern(0.11f) : square_pattern(4);
        std::vector<int> labels = brute_force_labels(p, size, size);
        for (ReliefNormal rule : {ReliefNormal::height_gradient, ReliefNormal::eq4}) {
            ReliefOptions opt;
            opt.normal_rule = rule;
            LeatherMaps maps;
            REQUIRE(make_leather_maps(p, labels.data(), size, size,
                                      table1_section(Table1Section::convex), opt, maps)
                        .ok());
            CHECK(maps.max_height > 0.0f);
            const float texel = 1.0f / float(size);
            std::vector<float> errors;
            for (int j = 2; j < size - 2; ++j)
                for (int i = 2; i < size - 2; ++i) {
                    int id = labels[std::size_t(j * size + i)];
                    bool same = true;  // skip the boundary pixels (the groove's corner)
                    for (int dj = -2; dj <= 2; ++dj)
                        for (int di = -2; di <= 2; ++di)
                            same = same && labels[std::size_t((j + dj) * size + i + di)] == id;
                    if (!same || id < 0) continue;
                    float hx = (maps.at_height(i + 1, j) - maps.at_height(i - 1, j)) / (2 * texel);
                    float hy = (maps.at_height(i, j + 1) - maps.at_height(i, j - 1)) / (2 * texel);
                    Vec3 n = maps.at_normal(i, j);
                    CHECK(length(n) == doctest::Approx(1.0f).epsilon(1e-5));
                    errors.push_back(angle_degrees(n, {-hx, -hy, 1.0f}));
                }
            std::sort(errors.begin(), errors.end());
            float median = errors[errors.size() / 2];
            float p90 = errors[errors.size() * 9 / 10];
            MEASURED(
                std::string(hex ? "hexagons" : "squares")
                << ", " << std::string(rule == ReliefNormal::eq4 ? "eq. (4)" : "height gradient")
                << ": angle(normal map, FD gradient of height map) median " << median
                << " deg, 90th percentile " << p90 << " deg over " << errors.size() << " pixels");
            if (rule == ReliefNormal::height_gradient) {
                CHECK(median < 0.05f);  // exact up to float and the FD at creases
                CHECK(p90 < 2.0f);      // measured 0.21 (squares), 1.1 (hexagons): fan creases
            } else {
                // eq. (4) ignores the tilt across the ray and uses the ray length, not S:
                // measured median 1.8 / 1.2 deg, 90th percentile 13.6 / 9.4 deg.
                CHECK(median < 2.5f);
                CHECK(p90 < 15.0f);
            }
        }
    }
}

TEST_CASE("relief maps: exports (16-bit height, RGB normal map, relief mesh)") {
    ScalePattern p = square_pattern(2);
    const int w = 32, h = 16;
    std::vector<int> labels = brute_force_labels(p, w, h);
    LeatherMaps maps;
    REQUIRE(make_leather_maps(p, labels.data(), w, h, table1_section(Table1Section::convex),
                              ReliefOptions{}, maps)
                .ok());
    std::vector<std::uint16_t> h16(std::size_t(w * h));
    encode_height16(maps, h16.data());
    CHECK(*std::max_element(h16.begin(), h16.end()) == 65535);
    // Row flip: image row 0 is the map's top row (largest y).
    for (int i = 0; i < w; ++i) {
        float expect = maps.at_height(i, h - 1) / maps.max_height * 65535.0f;
        CHECK(std::fabs(float(h16[std::size_t(i)]) - expect) <= 0.5f);
    }
    std::vector<std::uint8_t> rgb(std::size_t(3 * w * h));
    encode_normal_rgb(maps, rgb.data());
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            Vec3 n = maps.at_normal(i, h - 1 - j);
            const std::uint8_t* px = &rgb[std::size_t(3 * (j * w + i))];
            for (int c = 0; c < 3; ++c)
                CHECK(std::fabs(float(px[c]) - (n[c] + 1.0f) * 127.5f) <= 0.5f);
        }
    // The encoding is OpenGL's (+y green, the tangent-space convention of glTF and Blender),
    // not DirectX's (-y): on a raised scale the slope toward the image top (pattern +y) has
    // green above 128, the slope toward the right red above 128, and z is never below 128.
    {
        ScalePattern one = square_pattern(1);
        const int n = 64;
        std::vector<int> one_labels = brute_force_labels(one, n, n);
        LeatherMaps m1;
        REQUIRE(make_leather_maps(one, one_labels.data(), n, n,
                                  table1_section(Table1Section::convex), ReliefOptions{}, m1)
                    .ok());
        std::vector<std::uint8_t> px(std::size_t(3 * n * n));
        encode_normal_rgb(m1, px.data());
        auto at = [&](int col, int row) { return &px[std::size_t(3 * (row * n + col))]; };
        const int near_edge = n * 42 / 100;  // rho ~ 0.85: on the falling flank of fig. 13a
        const std::uint8_t* top = at(n / 2, n / 2 - near_edge);
        const std::uint8_t* bottom = at(n / 2, n / 2 + near_edge);
        const std::uint8_t* right = at(n / 2 + near_edge, n / 2);
        CHECK(top[1] > 150);
        CHECK(bottom[1] < 105);
        CHECK(std::abs(int(top[0]) - 128) <= 1);
        CHECK(right[0] > 150);
        CHECK(std::abs(int(right[1]) - 128) <= 1);
        for (std::size_t k = 2; k < px.size(); k += 3) CHECK(px[k] >= 128);
    }
    TriangleMesh mesh;
    REQUIRE(make_relief_mesh(maps, 2, 1.0f, mesh).ok());
    CHECK(mesh.vertex_count() == 16 * 8);
    CHECK(mesh.triangle_count() == 2 * 15 * 7);
    CHECK(mesh.positions[0].z == maps.at_height(0, 0));
    CHECK(!make_relief_mesh(maps, 0, 1.0f, mesh).ok());
    CHECK(!make_relief_mesh(maps, 100, 1.0f, mesh).ok());
}

TEST_CASE("relief maps: bad input gets a clear status") {
    ScalePattern p = square_pattern(2);
    std::vector<int> labels = brute_force_labels(p, 8, 8);
    LeatherMaps maps;
    BezierChain s = table1_section(Table1Section::convex);
    CHECK(!make_leather_maps(p, labels.data(), 0, 8, s, ReliefOptions{}, maps).ok());
    CHECK(!make_leather_maps(p, nullptr, 8, 8, s, ReliefOptions{}, maps).ok());
    labels[9] = 4;  // only ids 0..3 exist
    Status st = make_leather_maps(p, labels.data(), 8, 8, s, ReliefOptions{}, maps);
    CHECK(!st.ok());
    CHECK(std::strstr(st.message(), "(1, 1)") != nullptr);
    labels[9] = 0;
    ReliefOptions bad;
    bad.edge_r = NAN;
    CHECK(!make_leather_maps(p, labels.data(), 8, 8, s, bad, maps).ok());
    bad = ReliefOptions{};
    bad.height_scale = -1.0f;
    CHECK(!make_leather_maps(p, labels.data(), 8, 8, s, bad, maps).ok());
    BezierChain backwards = s;
    backwards.segments[0].p[3].x = 0.3f;
    Status sb = make_leather_maps(p, labels.data(), 8, 8, backwards, ReliefOptions{}, maps);
    CHECK(!sb.ok());
    CHECK(std::strstr(sb.message(), "decreases") != nullptr);
    BezierChain nan_section = s;
    nan_section.segments[0].p[2].y = NAN;
    CHECK(!make_leather_maps(p, labels.data(), 8, 8, nan_section, ReliefOptions{}, maps).ok());
    // A hand-filled pattern: offsets past the vertices, going backwards, or NaN coordinates
    // are refused before anything reads through them (the sanitizer build would catch a read).
    ScalePattern torn = p;
    torn.polygon_offsets.back() += 8;
    Status so = make_leather_maps(torn, labels.data(), 8, 8, s, ReliefOptions{}, maps);
    CHECK(so.code() == StatusCode::invalid_argument);
    CHECK(std::strstr(so.message(), "polygon_offsets") != nullptr);
    ScalePattern backwards_offsets = p;
    std::swap(backwards_offsets.polygon_offsets[1], backwards_offsets.polygon_offsets[2]);
    Status sw =
        make_leather_maps(backwards_offsets, labels.data(), 8, 8, s, ReliefOptions{}, maps);
    CHECK(!sw.ok());
    CHECK(std::strstr(sw.message(), "vertices") != nullptr);
    ScalePattern nan_vertex = p;
    nan_vertex.vertices[5].x = NAN;
    Status sv = make_leather_maps(nan_vertex, labels.data(), 8, 8, s, ReliefOptions{}, maps);
    CHECK(std::strstr(sv.message(), "vertex 5") != nullptr);
    ScalePattern nan_centroid = p;
    nan_centroid.centroids[2].y = NAN;
    Status sc = make_leather_maps(nan_centroid, labels.data(), 8, 8, s, ReliefOptions{}, maps);
    CHECK(std::strstr(sc.message(), "centroid of polygon 2") != nullptr);
    // An infinite height (finite options can still overflow) encodes as 0, not as UB.
    REQUIRE(make_leather_maps(p, labels.data(), 8, 8, s, ReliefOptions{}, maps).ok());
    maps.heights[3] = INFINITY;
    maps.max_height = INFINITY;
    std::vector<std::uint16_t> h16(64, 7);
    encode_height16(maps, h16.data());
    for (std::uint16_t v : h16) CHECK(v == 0);  // every height times 65535 / inf
}

TEST_CASE("relief: the angular index finds the same edge point as the full scan") {
    ScalePattern p;
    REQUIRE(generate_scale_pattern(ScaleParams{}, p).ok());  // perturbed, ~86 vertices each
    std::vector<float> angles(p.vertices.size());
    Pcg32 rng(5);
    int indexed = 0, compared = 0;
    for (int i = 0; i < p.polygon_count(); ++i) {
        int n;
        const Vec2* poly = p.polygon(i, &n);
        Vec2 m = p.centroids[std::size_t(i)];
        float* a = angles.data() + p.polygon_offsets[std::size_t(i)];
        if (!make_angular_index(poly, n, m, a)) continue;
        ++indexed;
        for (int k = 0; k < 200; ++k) {
            // Points inside: a random fraction of the way to a random boundary point.
            Vec2 dir{std::cos(kTwoPi * rng.uniform()), std::sin(kTwoPi * rng.uniform())};
            EdgeHit edge = scale_edge_point(poly, n, m, m + dir * 1e-3f);
            Vec2 x = m + (edge.p - m) * (0.02f + 0.97f * rng.uniform());
            EdgeHit full = scale_edge_point(poly, n, m, x);
            EdgeHit fast = scale_edge_point_indexed(poly, n, m, x, a);
            CHECK(fast.inside == full.inside);
            CHECK(length(fast.p - full.p) <= 1e-6f);
            ++compared;
        }
    }
    CHECK(indexed == p.polygon_count());  // the pattern's polygons are star-shaped from m
    CHECK(compared > 0);
    // A clockwise polygon works the same way.
    Vec2 cw[7];
    for (int k = 0; k < 7; ++k) {
        float a = -kTwoPi * float(k) / 7.0f;
        cw[k] = Vec2{std::cos(a), std::sin(a)} * (1.0f + 0.2f * float(k % 2));
    }
    float cw_angles[7];
    REQUIRE(make_angular_index(cw, 7, {0, 0}, cw_angles));
    for (int k = 0; k < 100; ++k) {
        Vec2 x{rng.uniform(-0.6f, 0.6f), rng.uniform(-0.6f, 0.6f)};
        CHECK(length(scale_edge_point_indexed(cw, 7, {0, 0}, x, cw_angles).p -
                     scale_edge_point(cw, 7, {0, 0}, x).p) <= 1e-6f);
    }
    // Not star-shaped from m: refused.
    const Vec2 bow[6] = {{0, 0}, {2, 0}, {2, 2}, {1.9f, 0.2f}, {0.1f, 0.2f}, {0, 2}};
    float tmp[6];
    CHECK(!make_angular_index(bow, 6, {1.0f, 1.5f}, tmp));
}

TEST_CASE("relief: convex scales slope outwards over their inner part, concave inwards") {
    // What tells fig. 14's sunken scales from fig. 13's raised ones under one light: over the
    // inner part of a scale (rho 0.3-0.85, the floor and the rim's inner wall or the
    // shoulder) the normal's radial component n·(x - m)/|x - m| is, on average, > 0 for the
    // convex section (the surface falls outwards: lit on the light's side) and < 0 for the
    // concave one (it rises to the rim: lit on the far side).
    const Vec2 hex[6] = {{1, 0},  {0.5f, 0.866f},   {-0.5f, 0.866f},
                         {-1, 0}, {-0.5f, -0.866f}, {0.5f, -0.866f}};
    auto mean_radial = [&](Table1Section w) {
        double sum = 0;
        int n = 0;
        for (int k = 0; k < 2000; ++k) {
            const float a = float(k) * 2.3999632f, rr = 0.2f + 0.8f * float(k % 97) / 97.0f;
            const Vec2 x{rr * std::cos(a), rr * std::sin(a)};
            ReliefSample r;
            scale_relief(hex, 6, {0, 0}, x, table1_section(w), ReliefOptions{}, &r);
            if (r.rho < 0.3f || r.rho > 0.85f) continue;
            sum += double(r.normal.x * x.x + r.normal.y * x.y) / double(length(x));
            ++n;
        }
        REQUIRE(n > 500);
        return sum / double(n);
    };
    const double convex = mean_radial(Table1Section::convex);
    const double concave = mean_radial(Table1Section::concave);
    INFO("mean radial normal: convex " << convex << ", concave " << concave);
    CHECK(convex > 0.02);
    CHECK(concave < -0.02);
}

// fuzz_maps: edge_r = 3.5e-43 made every height infinite (NaN with height_scale 0) under an
// ok Status; a huge height_scale made the normals' squared length overflow.
TEST_CASE("leather maps: heights past kMaxReliefHeight are refused, steep normals stay unit") {
    ScaleParams prm;
    prm.D = prm.d = 0.25f;
    ScalePattern pattern;
    REQUIRE(generate_scale_pattern(prm, pattern).ok());
    const BezierChain section = table1_section(Table1Section::convex);
    LeatherMaps maps;
    ReliefOptions o;
    o.edge_r = 3.4892e-43f;
    o.height_scale = 0.0f;
    Status s = make_leather_maps(pattern, 32, 32, section, o, maps);
    CHECK(s.code() == StatusCode::out_of_range);
    CHECK(std::string(s.message()).find("edge_r") != std::string::npos);
    o.edge_r = 1.0f;
    o.height_scale = 3e38f;
    CHECK(make_leather_maps(pattern, 32, 32, section, o, maps).code() ==
          StatusCode::out_of_range);
    // Heights within the bound, normals whose components pass 1.8e19: unit, finite.
    for (ReliefNormal rule : {ReliefNormal::eq4, ReliefNormal::height_gradient}) {
        o.height_scale = 1e25f;
        o.normal_rule = rule;
        REQUIRE(make_leather_maps(pattern, 32, 32, section, o, maps).ok());
        for (const Vec3& n : maps.normals) {
            REQUIRE(std::isfinite(n.x));
            REQUIRE(std::isfinite(n.y));
            REQUIRE(std::isfinite(n.z));
            CHECK(std::fabs(length(n) - 1.0f) < 1e-5f);
        }
        for (float h : maps.heights) REQUIRE(std::isfinite(h));
    }
}

// fuzz_maps: a section drawn 1e-20 small (its r and z, and edge_r with it) gave normals whose
// squared length is lost below float's range: (dz, dr) near 1e-20 normalised to length 0.7 or
// to NaN. They are unit now, and still tilted where the scale slopes. (Not compared with the
// section at scale 1: invert_r's tolerance is absolute, so at 1e-20 it stops at the chord
// guess and the tilts differ.)
TEST_CASE("leather maps: a section drawn 1e-20 small still has unit normals, tilted on slopes") {
    ScaleParams prm;
    prm.D = prm.d = 0.25f;
    ScalePattern pattern;
    REQUIRE(generate_scale_pattern(prm, pattern).ok());
    BezierChain tiny = table1_section(Table1Section::convex);
    for (int i = 0; i < tiny.count; ++i)
        for (Vec2& p : tiny.segments[i].p) p = p * 1e-20f;
    for (ReliefNormal rule : {ReliefNormal::eq4, ReliefNormal::height_gradient}) {
        CAPTURE(int(rule));
        ReliefOptions o;
        o.normal_rule = rule;
        o.edge_r *= 1e-20f;
        LeatherMaps maps;
        REQUIRE(make_leather_maps(pattern, 32, 32, tiny, o, maps).ok());
        int sloped = 0;
        for (const Vec3& n : maps.normals) {
            REQUIRE(std::isfinite(n.x));
            REQUIRE(std::isfinite(n.y));
            REQUIRE(std::isfinite(n.z));
            CHECK(std::fabs(length(n) - 1.0f) < 1e-5f);
            CHECK(n.z >= 0.0f);
            sloped += n.z < 0.999f;
        }
        CHECK(sloped > 100);  // the slopes are there, not only the flat floor
    }
}
