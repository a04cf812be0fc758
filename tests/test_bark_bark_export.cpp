// bark/bark_export: every float of the CSV reads back to the same float (core/format_number).
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "shitsukan/bark/bark.hpp"

using namespace shitsukan;

namespace {
std::vector<std::vector<std::string>> read_csv(const std::string& path) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::stringstream ss(line);
        std::string cell;
        rows.emplace_back();
        while (std::getline(ss, cell, ',')) rows.back().push_back(cell);
    }
    return rows;
}
bool same_float(const std::string& text, float want) {
    float got = std::strtof(text.c_str(), nullptr);
    return std::memcmp(&got, &want, sizeof got) == 0;
}
}  // namespace

TEST_CASE("write_bark_csv: node positions, areas and spring values read back bit for bit") {
    CylinderParams p;
    p.N_R = 16, p.N_H = 12;
    p.species = species_preset(Species::chinese_tallow);
    BarkCylinder bark;
    REQUIRE(build_cylinder(p, bark).ok());
    CrackRun run;
    REQUIRE(grow_and_crack(bark, CrackRunOptions{}, run).ok());
    const std::string prefix = "build/test_bark_csv_roundtrip";
    REQUIRE(write_bark_csv(bark, p.T, bark.net.W.data(), prefix.c_str()).ok());
    const auto nodes = read_csv(prefix + "_nodes.csv");
    REQUIRE(int(nodes.size()) == bark.net.node_count());
    int wrong = 0;
    for (int i = 0; i < bark.net.node_count(); ++i) {
        const Vec3 x = node_position(bark, std::uint32_t(i), p.T, bark.net.W.data());
        const auto& r = nodes[std::size_t(i)];
        REQUIRE(r.size() == 6u);
        wrong += std::atoi(r[0].c_str()) != i;
        wrong += !same_float(r[3], x.x) + !same_float(r[4], x.y);
        wrong += !same_float(r[5], bark.node_area[std::size_t(i)]);
    }
    const auto springs = read_csv(prefix + "_springs.csv");
    REQUIRE(springs.size() == bark.net.springs.size());
    int broken = 0;
    for (std::size_t s = 0; s < springs.size(); ++s) {
        const BarkSpring& sp = bark.net.springs[s];
        const auto& r = springs[s];
        REQUIRE(r.size() == 11u);
        wrong += !same_float(r[7], sp.l0) + !same_float(r[8], sp.eps_c);
        const bool is_broken = !intact_at(sp, p.T);
        broken += is_broken;
        wrong += !same_float(r[9], is_broken ? sp.t_break : -1.0f);
    }
    CHECK(broken > 0);
    CHECK(wrong == 0);
    for (const char* part : {"_nodes.csv", "_springs.csv", "_triangles.csv"})
        std::remove((prefix + part).c_str());
}
