// Tests for lib/shitsukan/image/svg_canvas: well-formed XML, one element per call, escaping,
// limited precision, save errors.
#include <doctest/doctest.h>

#include <cctype>
#include <cstdio>
#include <string>
#include <vector>

#include "shitsukan/image/canvas.hpp"

using namespace shitsukan;

namespace {

// A small XML checker: tags balance, attributes are quoted, text and attribute values hold
// no raw '<' and only the five predefined entities or numeric references after '&'.
// Returns "" when well-formed, else what is wrong. Counts start tags by name.
struct XmlReport {
    std::string error;
    std::vector<std::pair<std::string, int>> counts;
    int count(const std::string& name) const {
        for (const auto& c : counts)
            if (c.first == name) return c.second;
        return 0;
    }
};

bool entity_ok(const std::string& s, std::size_t amp) {
    std::size_t semi = s.find(';', amp);
    if (semi == std::string::npos) return false;
    std::string e = s.substr(amp + 1, semi - amp - 1);
    if (e == "amp" || e == "lt" || e == "gt" || e == "quot" || e == "apos") return true;
    if (e.size() >= 2 && e[0] == '#') return true;
    return false;
}

XmlReport check_xml(const std::string& s) {
    XmlReport rep;
    std::vector<std::string> stack;
    std::size_t i = 0;
    auto fail = [&](const std::string& why) {
        rep.error = why + " at byte " + std::to_string(i);
        return rep;
    };
    bool root_seen = false;
    while (i < s.size()) {
        if (s[i] == '&' && !entity_ok(s, i)) return fail("bad entity");
        if (s[i] != '<') {
            if (stack.empty() && !std::isspace((unsigned char)s[i]))
                return fail("text outside root");
            ++i;
            continue;
        }
        if (s.compare(i, 2, "<?") == 0) {
            std::size_t e = s.find("?>", i);
            if (e == std::string::npos) return fail("unterminated <?");
            i = e + 2;
            continue;
        }
        bool closing = s.compare(i, 2, "</") == 0;
        std::size_t j = i + (closing ? 2 : 1);
        std::string name;
        while (j < s.size() && (std::isalnum((unsigned char)s[j]) || s[j] == ':' || s[j] == '-'))
            name += s[j++];
        if (name.empty()) return fail("tag without name");
        if (closing) {
            if (stack.empty() || stack.back() != name) return fail("unbalanced </" + name + ">");
            stack.pop_back();
            if (j >= s.size() || s[j] != '>') return fail("bad closing tag");
            i = j + 1;
            continue;
        }
        if (stack.empty() && root_seen) return fail("second root element");
        root_seen = true;
        // Attributes: name="value" pairs.
        std::vector<std::string> seen;
        while (true) {
            while (j < s.size() && std::isspace((unsigned char)s[j])) ++j;
            if (j >= s.size()) return fail("unterminated tag");
            if (s[j] == '>' || s.compare(j, 2, "/>") == 0) break;
            std::string attr;
            while (j < s.size() && s[j] != '=' && !std::isspace((unsigned char)s[j]))
                attr += s[j++];
            for (const auto& a : seen)
                if (a == attr) return fail("duplicate attribute " + attr);
            seen.push_back(attr);
            if (j >= s.size() || s[j] != '=' || j + 1 >= s.size() || s[j + 1] != '"')
                return fail("unquoted attribute " + attr);
            std::size_t e = s.find('"', j + 2);
            if (e == std::string::npos) return fail("unterminated attribute");
            for (std::size_t k = j + 2; k < e; ++k) {
                if (s[k] == '<') return fail("'<' in attribute");
                if (s[k] == '&' && !entity_ok(s, k)) return fail("bad entity in attribute");
            }
            j = e + 1;
        }
        bool found = false;
        for (auto& c : rep.counts)
            if (c.first == name) { ++c.second; found = true; }
        if (!found) rep.counts.push_back({name, 1});
        if (s[j] == '>') {
            stack.push_back(name);
            i = j + 1;
        } else {
            i = j + 2;
        }
    }
    if (!stack.empty()) return fail("unclosed <" + stack.back() + ">");
    if (!root_seen) return fail("no root element");
    return rep;
}

const Rgb8 kBlack{0, 0, 0};

}  // namespace

TEST_CASE("the XML checker itself rejects broken documents") {
    CHECK(check_xml("<svg><line/></svg>").error.empty());
    CHECK_FALSE(check_xml("<svg><line></svg>").error.empty());
    CHECK_FALSE(check_xml("<svg><text>a<b</text></svg>").error.empty());
    CHECK_FALSE(check_xml("<svg><text>a & b</text></svg>").error.empty());
    CHECK_FALSE(check_xml("<svg x=1></svg>").error.empty());
    CHECK_FALSE(check_xml("<svg></svg><svg></svg>").error.empty());
}

TEST_CASE("SvgCanvas: well-formed document, one element per call") {
    SvgCanvas svg(320, 200, Rgb8{255, 255, 255});
    Vec2 pts[5] = {{10, 10}, {50, 20}, {90, 10}, {70, 60}, {20, 50}};
    int sizes[2] = {3, 2};
    svg.line({0, 0}, {100, 100}, kBlack, 1.5f);
    svg.line({0, 100}, {100, 0}, kBlack);
    svg.polyline(pts, 5, kBlack, 2.0f);
    svg.polygon_outline(pts, 5, kBlack);
    svg.fill_polygon(pts, 5, Rgb8{200, 0, 0});
    svg.fill_contours(pts, sizes, 2, kBlack);
    svg.fill_rect({5, 5}, {-3, 10}, kBlack);
    svg.rect_outline({5, 5}, {30, 10}, kBlack, 2.0f);
    for (int i = 0; i < 6; ++i) svg.marker({150.0f + 20 * i, 100}, MarkerShape(i), 10, kBlack);
    svg.text({10, 150}, "two\nlines", kBlack, 2);
    const std::string doc = svg.str();
    XmlReport rep = check_xml(doc);
    INFO(doc);
    REQUIRE(rep.error.empty());
    CHECK(rep.count("svg") == 1);
    CHECK(rep.count("line") == 2);
    CHECK(rep.count("polyline") == 1);
    CHECK(rep.count("polygon") == 3);  // outline, fill, triangle marker
    CHECK(rep.count("path") == 3);     // contours, cross, plus
    CHECK(rep.count("rect") == 4);     // background, fill, outline, square marker
    CHECK(rep.count("circle") == 2);   // dot, circle
    CHECK(rep.count("text") == 2);     // one per line
    CHECK(svg.element_count() == 2 + 1 + 3 + 3 + 4 + 2 + 2);
    CHECK(doc.find("fill-rule=\"evenodd\"") != std::string::npos);
    CHECK(doc.find("viewBox=\"0 0 320 200\"") != std::string::npos);
    // The negative-width rectangle is normalised.
    CHECK(doc.find("<rect x=\"2\" y=\"5\" width=\"3\" height=\"10\"") != std::string::npos);
}

TEST_CASE("SvgCanvas: text is escaped, UTF-8 kept, control characters replaced") {
    SvgCanvas svg(100, 100);
    svg.text({1, 2}, "a<b & \"c\" 'd' > \u03ba\x01\xff", kBlack, 1);
    const std::string doc = svg.str();
    REQUIRE(check_xml(doc).error.empty());
    const std::string expected =
        ">a&lt;b &amp; &quot;c&quot; &apos;d&apos; &gt; \u03ba\xEF\xBF\xBD\xEF\xBF\xBD</text>";
    CHECK(doc.find(expected) != std::string::npos);
    // textLength pins the line to the bitmap font's width: 19 characters, 19·6 - 1 pixels.
    CHECK(doc.find("textLength=\"113\"") != std::string::npos);
    CHECK(xml_escape("&&") == "&amp;&amp;");
}

TEST_CASE("SvgCanvas: numbers have at most two decimals and no '-0'; non-finite is skipped") {
    SvgCanvas svg(10, 10);
    svg.line({1.23456f, -0.001f}, {2.5f, 3.0f}, kBlack, 1.0f / 3.0f);
    std::string doc = svg.str();
    CHECK(doc.find("x1=\"1.23\" y1=\"0\" x2=\"2.5\" y2=\"3\" stroke=\"#000000\" "
                   "stroke-width=\"0.33\"") != std::string::npos);
    int before = svg.element_count();
    Vec2 bad[3] = {{0, 0}, {NAN, 1}, {2, 2}};
    svg.fill_polygon(bad, 3, kBlack);
    svg.line({INFINITY, 0}, {1, 1}, kBlack);
    svg.text({NAN, 0}, "x", kBlack);
    svg.marker({0, NAN}, MarkerShape::dot, 3, kBlack);
    svg.polyline(bad, 3, kBlack);
    svg.fill_polygon(bad, 2, kBlack);  // too few points
    CHECK(svg.element_count() == before);
    CHECK(svg.str() == doc);
}

TEST_CASE("SvgCanvas: save writes str(), errors name the path") {
    SvgCanvas svg(20, 20);
    svg.fill_rect({1, 1}, {5, 5}, kBlack);
    const char* path = "build/test_svg_canvas.svg";
    REQUIRE(svg.save(path).ok());
    std::FILE* f = std::fopen(path, "rb");
    REQUIRE(f != nullptr);
    std::string back;
    char buf[256];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) back.append(buf, n);
    std::fclose(f);
    std::remove(path);
    CHECK(back == svg.str());
    Status s = svg.save("/nonexistent-dir/x.svg");
    CHECK(s.code() == StatusCode::io_error);
    CHECK(std::string(s.message()).find("/nonexistent-dir/x.svg") != std::string::npos);
    CHECK(svg.save("").code() == StatusCode::invalid_argument);
}
