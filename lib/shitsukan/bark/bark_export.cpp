// The bark's crack network as CSV and SVG, the deformed trunk as a mesh (see bark_export.hpp).
#include "shitsukan/bark/bark_export.hpp"
#include "shitsukan/core/detmath.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "shitsukan/bark/crack_drawing.hpp"
#include "shitsukan/core/format_number.hpp"
#include "shitsukan/core/output_file.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan {

namespace {

// One CSV row: integers, and floats as the shortest decimal that reads back to the same
// float (core/format_number), no printf per number.
class CsvRow {
public:
    CsvRow& integer(long long v) {
        separate();
        char digits[24];
        int n = 0;
        unsigned long long u = v < 0 ? 0ull - static_cast<unsigned long long>(v)
                                     : static_cast<unsigned long long>(v);
        do {
            digits[n++] = char('0' + u % 10u);
            u /= 10u;
        } while (u != 0);
        if (v < 0) text_ += '-';
        while (n > 0) text_ += digits[--n];
        return *this;
    }
    CsvRow& real(float v) {
        separate();
        char buf[32];
        text_.append(buf, std::size_t(format_float_round_trip(buf, sizeof buf, v)));
        return *this;
    }
    void write(OutputFile& f) {
        text_ += '\n';
        f.write(text_.data(), text_.size());
        text_.clear();
        first_ = true;
    }

private:
    void separate() {
        if (!first_) text_ += ',';
        first_ = false;
    }
    std::string text_;
    bool first_ = true;
};

Status check_time(const BarkCylinder& bark, float t, const Vec3* W) {
    if (!W || bark.net.W.size() != bark.net.X.size())
        return Status::error(StatusCode::invalid_argument, "bark export: no displacement field");
    if (!(is_finite(t) && t >= 0.0f))
        return Status::error(StatusCode::invalid_argument, "bark export: time must be >= 0 "
                                                           "(got %g)", double(t));
    return Status::success();
}

}  // namespace

Status write_bark_csv(const BarkCylinder& bark, float t, const Vec3* W, const char* prefix) {
    SHITSUKAN_TRY(check_time(bark, t, W));
    if (!prefix) return Status::error(StatusCode::invalid_argument, "write_bark_csv: no prefix");
    const SpringNetwork& net = bark.net;
    OutputSet files;  // the three appear together or not at all
    {
        OutputFile f;
        SHITSUKAN_TRY(f.open(std::string(prefix) + "_nodes.csv"));
        f.print("id,c,r,u_cm,z_cm,area_cm2\n");
        CsvRow row;
        for (int p = 0; p < net.node_count(); ++p) {
            const Vec3 x = node_position(bark, std::uint32_t(p), t, W);
            row.integer(p).integer(bark.column_of(p)).integer(bark.row_of(p));
            row.real(x.x).real(x.y).real(bark.node_area[std::size_t(p)]).write(f);
        }
        SHITSUKAN_TRY(f.commit());
    }
    {
        OutputFile f;
        SHITSUKAN_TRY(f.open(std::string(prefix) + "_springs.csv"));
        f.print("id,i,j,c,r,dir,family,l0_cm,eps_c,t_break,width_cm\n");
        CsvRow row;
        for (std::size_t s = 0; s < net.springs.size(); ++s) {
            const BarkSpring& sp = net.springs[s];
            const bool broken = !intact_at(sp, t);
            const float width = broken ? crack_ribbon(bark, std::uint32_t(s), t, W).width : 0.0f;
            row.integer((long long)s).integer(sp.i).integer(sp.j);
            row.integer(sp.key >> 32).integer((sp.key >> 2) & 0x3fffffffu).integer(sp.key & 3u);
            row.integer(int(sp.family)).real(sp.l0).real(sp.eps_c);
            row.real(broken ? sp.t_break : -1.0f).real(width).write(f);
        }
        SHITSUKAN_TRY(f.commit());
    }
    OutputFile f;
    SHITSUKAN_TRY(f.open(std::string(prefix) + "_triangles.csv"));
    f.print("id,a,b,c,s_ab,s_bc,s_ca\n");
    for (std::size_t i = 0; i < bark.triangles.size() && !f.failed(); ++i) {
        const ConnectionTriangle& tri = bark.triangles[i];
        f.print("%zu,%u,%u,%u,%u,%u,%u\n", i, tri.node[0], tri.node[1], tri.node[2],
                tri.spring[0], tri.spring[1], tri.spring[2]);
    }
    SHITSUKAN_TRY(f.commit());
    return files.commit();
}

Status write_crack_svg(const BarkCylinder& bark, float t, const Vec3* W, const char* path,
                       float px_per_cm) {
    SHITSUKAN_TRY(check_time(bark, t, W));
    if (!path) return Status::error(StatusCode::invalid_argument, "write_crack_svg: no path");
    if (!(is_finite(px_per_cm) && px_per_cm > 0.0f && px_per_cm <= 10000.0f))
        return Status::error(StatusCode::invalid_argument,
                             "write_crack_svg: px_per_cm must be in (0, 10000] (got %g)",
                             double(px_per_cm));
    const float C = bark.circumference * (1.0f + hoop_strain(bark.params, t));
    const float H = bark.H0 * (1.0f + axial_strain(bark.params, t));
    const double s = px_per_cm, w = double(C) * s, h = double(H) * s;
    OutputFile f;
    SHITSUKAN_TRY(f.open(path));
    f.print("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.1f\" height=\"%.1f\" "
            "viewBox=\"0 0 %.3f %.3f\">\n"
            "<!-- hirota1998: unrolled bark at t = %g s; u to the right, z up; cracks as "
            "Fig. 4 (width l - l0) -->\n<rect width=\"100%%\" height=\"100%%\" "
            "fill=\"#1c140e\"/>\n<g fill=\"#b08a62\">\n",
            w, h, w, h, double(t));
    auto point = [&](Vec3 p) {
        f.print("%.2f,%.2f ", double(p.x) * s, h - double(p.y) * s);
    };
    for (const ConnectionTriangle& tri : bark.triangles) {
        f.print("<polygon points=\"");
        for (int k = 0; k < 3; ++k) point(corner_position(bark, tri.corner[k], tri.node[k], t, W));
        f.print("\"/>\n");
    }
    f.print("</g>\n<g fill=\"#1c140e\">\n");
    std::vector<CrackRibbon> cracks;
    SHITSUKAN_TRY(crack_ribbons(bark, t, W, cracks));
    for (const CrackRibbon& r : cracks) {
        Vec3 quads[2][4];
        ribbon_quads(r, quads);
        for (auto& quad : quads) {
            f.print("<polygon points=\"");
            for (const Vec3& p : quad) point(p);
            f.print("\"/>\n");
        }
    }
    f.print("</g>\n</svg>\n");
    return f.commit();
}

Status make_trunk_mesh(const BarkCylinder& bark, float t, const Vec3* W, TriangleMesh& out) {
    SHITSUKAN_TRY(check_time(bark, t, W));
    out = TriangleMesh{};
    const int N_R = bark.params.N_R, N_H = bark.params.N_H, n = N_R * N_H;
    const float R = bark.R0 + bark.params.delta_r * t;
    const float C = bark.circumference * (1.0f + hoop_strain(bark.params, t));
    const float H = bark.H0 * (1.0f + axial_strain(bark.params, t));
    auto add = [&](Vec3 x) {  // unrolled (u, z) -> the trunk
        const float angle = x.x / R;
        const Vec3 radial{det_sin(angle), 0.0f, det_cos(angle)};
        return out.add_vertex({R * radial.x, x.y, R * radial.z}, radial, {x.x / C, x.y / H});
    };
    for (int p = 0; p < n; ++p) add(node_position(bark, std::uint32_t(p), t, W));
    for (int r = 0; r < N_H; ++r) {  // column 0 again, one circumference on: closes the seam
        Vec3 x = node_position(bark, std::uint32_t(bark.node(0, r)), t, W);
        x.x += C;
        add(x);
    }
    for (const ConnectionTriangle& tri : bark.triangles) {
        std::uint32_t v[3];
        for (int k = 0; k < 3; ++k) {
            const bool across = tri.corner[k].x > bark.net.X[tri.node[k]].x + 0.5f * bark.circumference;
            v[k] = across ? std::uint32_t(n + bark.row_of(int(tri.node[k]))) : tri.node[k];
        }
        // The lattice triangles are clockwise in (u, z); seen from outside (u right, z up)
        // counter-clockwise is the front: reverse.
        out.add_triangle(v[0], v[2], v[1]);
    }
    return Status::success();
}

}  // namespace shitsukan
