// Tests for lib/shitsukan/solid/smooth_lattice: a tileable marble slice tiled 2 x 2 has no
// seam and no crease along the lattice's node planes with the smooth refinement (value and
// gradient jumps there like the interior's), where eq. (6)'s lattice shows both; opposite
// faces of the periodic smooth lattice stay equal bit for bit; the displacements are kept.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "shitsukan/image/image.hpp"
#include "shitsukan/render/solid_bake.hpp"
#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/solid/okada1987_presets.hpp"
#include "shitsukan/solid/periodic_lattice.hpp"
#include "shitsukan/solid/smooth_lattice.hpp"
#include "shitsukan/solid/turbulence.hpp"

using namespace shitsukan;

namespace {

// The density G' of the tileable marble slice (the whole period, wrapped).
FloatImage tile_density(const LatticeView& lattice, int size) {
    SolidMaterial m = okada1989_marble(kOkada1987MarbleK);
    m.layer_period = tileable_layer_period(kOkada1989LayerPeriod, lattice.R);
    SolidSlice slice;
    slice.origin = {0, 32, 0};
    slice.extent = float(1 << lattice.R);
    slice.wrap = true;
    RgbImage rgb;
    FloatImage density;
    REQUIRE(render_solid_slice(lattice, m, slice, size, size, rgb, &density));
    return density;
}

// Per column boundary c | c+1 of the image tiled 2 x 2 (indices wrap): the mean over rows of
// the second difference |d(c-1) - 2 d(c) ... | across it, i.e. the jump of the gradient.
std::vector<double> column_creases(const FloatImage& d) {
    const int w = d.width(), h = d.height();
    std::vector<double> out;
    out.resize(std::size_t(w));
    for (int c = 0; c < w; ++c) {
        double sum = 0.0;
        for (int y = 0; y < h; ++y) {
            auto at = [&](int x) { return double(d.at(((x % w) + w) % w, y)); };
            sum += std::fabs((at(c + 2) - at(c + 1)) - (at(c) - at(c - 1)));  // slope change
        }
        out[std::size_t(c)] = sum / h;
    }
    return out;
}

double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// The crease of D along the plane x = X of the lattice repeated every 2^R: the mean over a
// slice's rows of |D(X + e) - 2 D(X) + D(X - e)|, e = a quarter of a lattice unit (the change
// of slope across the plane; 0 where D is smooth), at y = 32.
double plane_crease(const LatticeView& l, int X) {
    const int n = 1 << l.R;
    double sum = 0.0;
    for (int j = 0; j < 4 * n; ++j) {
        const float z = (float(j) + 0.5f) * 0.25f;
        auto d = [&](float x) { return double(periodic_turbulence(l, Vec3{x, 32.0f, z})); };
        sum += std::fabs(d(float(X) + 0.25f) - 2.0 * d(float(X)) + d(float(X) - 0.25f));
    }
    return sum / (4 * n);
}

}  // namespace

TEST_CASE("smooth lattice: no seam or node-plane crease in D and the tileable marble, 2 x 2") {
    FractalParams p = okada1987_lattice_params();
    PeriodicLattice periodic;
    REQUIRE(periodic.build(p));
    SmoothLattice smooth;
    REQUIRE(smooth.build(periodic.view(), LatticeWrap::periodic));
    const int n = 1 << p.R;
    double eq6[3] = {0, 0, 0};
    for (int pass = 0; pass < 2; ++pass) {
        const LatticeView l = pass == 0 ? periodic.view() : smooth.view();
        double last = 0.0;  // the last level's planes (odd X): every lattice unit has them
        for (int X = 1; X < n; X += 2) last += plane_crease(l, X) / (n / 2);
        const double seam = plane_crease(l, 0) / last, level1 = plane_crease(l, n / 2) / last,
                     level2 = plane_crease(l, n / 4) / last;
        const std::string name = pass == 0 ? "eq. (6)" : "smooth";
        MESSAGE(name << ": crease / the last level's: seam " << seam
                                                   << ", level-1 plane " << level1
                                                   << ", level-2 plane " << level2);
        if (pass == 0) {
            CHECK(seam > 2.5);  // the seam and crease the issue measured
            CHECK(level1 > 2.5);
            eq6[0] = seam, eq6[1] = level1, eq6[2] = level2;
        } else {  // measured 1.4, 2.0, 1.6: a residue at the coarse planes (more of their nodes
                  // carry the larger displacements of levels that only one or two
                  // cubic steps spread before eq. (6)'s linear interpolation), no seam
            CHECK(seam < 1.6);
            CHECK(level1 < 2.2);
            CHECK(level2 < 2.2);
            CHECK(seam < 0.3 * eq6[0]);
            CHECK(level1 < 0.5 * eq6[1]);
            CHECK(level2 < 0.6 * eq6[2]);
        }
    }
    // the marble's G' tiled 2 x 2: slope change at the seam like the median column's
    const std::vector<double> ours = column_creases(tile_density(smooth.view(), 256));
    const double ms = median(ours);
    MESSAGE("marble G', smooth: seam column " << ours[255] / ms << "x the median");
    CHECK(ours[255] / ms < 2.0);
    const FloatImage d = tile_density(smooth.view(), 256);
    double seam = 0.0, inner = 0.0;  // value jumps at the seam like the interior's
    for (int y = 0; y < 256; ++y) {
        seam += std::fabs(double(d.at(0, y)) - double(d.at(255, y)));
        inner += std::fabs(double(d.at(135, y)) - double(d.at(134, y)));
    }
    CHECK(seam < 2.0 * inner + 0.25);
}

TEST_CASE("smooth lattice: opposite faces equal, corners kept, displacements of a Type I kept") {
    FractalParams p = okada1987_lattice_params();
    p.R = 4;
    PeriodicLattice periodic;
    REQUIRE(periodic.build(p));
    SmoothLattice smooth;
    REQUIRE(smooth.build(periodic.view(), LatticeWrap::periodic));
    const LatticeView v = smooth.view();
    const int n = 1 << p.R;
    for (int a = 0; a <= n; ++a)
        for (int b = 0; b <= n; ++b) {
            CHECK(v.at(0, a, b) == v.at(n, a, b));
            CHECK(v.at(a, 0, b) == v.at(a, n, b));
            CHECK(v.at(a, b, 0) == v.at(a, b, n));
        }
    FractalLattice type1;
    REQUIRE(type1.build(p));
    REQUIRE(smooth.build(type1.view(), LatticeWrap::clamp));
    CHECK(smooth.view().at(0, 0, 0) == type1.view().at(0, 0, 0));
    CHECK(smooth.view().at(n, n, n) == type1.view().at(n, n, n));
    // level 1's edge midpoint has no outer points: the mean of its parents, as eq. (1)
    CHECK(smooth.view().at(n / 2, 0, 0) == doctest::Approx(type1.view().at(n / 2, 0, 0)));
    LatticeView empty;
    CHECK(smooth.build(empty, LatticeWrap::clamp).code() == StatusCode::invalid_argument);
}
