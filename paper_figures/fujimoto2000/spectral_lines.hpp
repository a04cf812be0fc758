// paper_figures/fujimoto2000/spectral_lines.hpp — how much of a relief is a regular lattice:
// the share of its power spectrum held by isolated spectral lines (figs. 17-18's panels (4)(5)
// must read as §4.1's "mountain ranges", not as a regular quilt of bumps).
//
// The field (n x n samples of the relief over the patch, row-major) is windowed by a Hann
// window in both directions and transformed by a 2-D discrete Fourier transform. A bin is a
// spectral line when its power exceeds `line_factor` times the mean power of the 16 bins on
// the square ring two bins around it (the window's main lobe is one bin wide each side, so
// the ring is the line's own background). The share is the power of the lines over the total
// power, both counted at wavenumbers of at least `min_wavenumber` cycles per patch (the
// coarse shape below it is the control mesh's, not the relief's texture). A regular lattice
// of bumps puts its power into a few lines (share towards 1); an irregular relief spreads it
// over the whole spectrum (share towards 0).
#pragma once

#include <complex>
#include <vector>

namespace shitsukan::fujimoto2000 {

// In place: a[k] = sum_j a[j] exp(-2 pi i j k / n), n = a.size() >= 1 (mixed radix, by the
// smallest prime factor at each level; a prime length falls back to the direct sum).
void discrete_fourier_transform(std::vector<std::complex<double>>& a);

// The share described above; 0 for n < 5 or a field without power.
double spectral_line_share(const std::vector<double>& field, int n, double min_wavenumber,
                           double line_factor);

}  // namespace shitsukan::fujimoto2000
