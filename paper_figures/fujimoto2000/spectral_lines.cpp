// paper_figures/fujimoto2000/spectral_lines.cpp — see spectral_lines.hpp.
#include "fujimoto2000/spectral_lines.hpp"

#include <cmath>
#include <cstddef>

#include "shitsukan/core/detmath.hpp"
#include "shitsukan/core/scalar.hpp"

namespace shitsukan::fujimoto2000 {
namespace {

using Complex = std::complex<double>;

// The length-`len` transform of in[0], in[stride], ... into out[0 .. len); w[t] =
// exp(-2 pi i t / n) for the full length n, and len divides n (decimation in time).
void transform(const Complex* in, std::size_t stride, std::size_t len,
               const std::vector<Complex>& w, Complex* out) {
    if (len == 1) {
        out[0] = in[0];
        return;
    }
    std::size_t p = 2;
    while (p * p <= len && len % p != 0) ++p;
    if (len % p != 0) p = len;  // prime: the direct sum
    const std::size_t m = len / p, n = w.size(), step = n / len;
    std::vector<Complex> sub(len);
    for (std::size_t r = 0; r < p; ++r) transform(in + r * stride, stride * p, m, w, &sub[r * m]);
    for (std::size_t k = 0; k < len; ++k) {
        // The products written out: std::complex's operator* checks for infinities.
        double re = 0, im = 0;
        const std::size_t km = k % m, t = k * step % n;
        for (std::size_t r = 0, tr = 0; r < p; ++r, tr = (tr + t) % n) {
            const Complex a = w[tr], b = sub[r * m + km];
            re += a.real() * b.real() - a.imag() * b.imag();
            im += a.real() * b.imag() + a.imag() * b.real();
        }
        out[k] = Complex(re, im);
    }
}

// w[t] = exp(-2 pi i t / n).
std::vector<Complex> twiddles(std::size_t n) {
    std::vector<Complex> w(n);
    for (std::size_t t = 0; t < n; ++t) {
        const double x = -2.0 * kPiD * double(t) / double(n);
        w[t] = Complex(det_cos(x), det_sin(x));
    }
    return w;
}

// In place, with the twiddles of a.size() (scratch: a copy of the input).
void transform_in_place(std::vector<Complex>& a, const std::vector<Complex>& w,
                        std::vector<Complex>& scratch) {
    scratch = a;
    transform(scratch.data(), 1, a.size(), w, a.data());
}

}  // namespace

void discrete_fourier_transform(std::vector<Complex>& a) {
    if (a.size() < 2) return;
    std::vector<Complex> scratch;
    transform_in_place(a, twiddles(a.size()), scratch);
}

double spectral_line_share(const std::vector<double>& field, int n, double min_wavenumber,
                           double line_factor) {
    if (n < 5 || field.size() != std::size_t(n) * std::size_t(n)) return 0.0;
    const std::size_t m = std::size_t(n);
    double mean = 0;
    for (double x : field) mean += x;
    mean /= double(field.size());
    std::vector<double> hann(m);
    for (std::size_t i = 0; i < m; ++i)
        hann[i] = 0.5 - 0.5 * det_cos(2.0 * kPiD * (double(i) + 0.5) / double(n));
    // Rows, then columns.
    const std::vector<Complex> w = twiddles(m);
    std::vector<Complex> f(m * m), line(m), scratch;
    for (std::size_t j = 0; j < m; ++j) {
        for (std::size_t i = 0; i < m; ++i) line[i] = (field[j * m + i] - mean) * hann[i] * hann[j];
        transform_in_place(line, w, scratch);
        for (std::size_t i = 0; i < m; ++i) f[j * m + i] = line[i];
    }
    std::vector<double> power(m * m);
    for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t j = 0; j < m; ++j) line[j] = f[j * m + i];
        transform_in_place(line, w, scratch);
        for (std::size_t j = 0; j < m; ++j) power[j * m + i] = std::norm(line[j]);
    }
    auto wavenumber = [n](int i) { return double(i <= n / 2 ? i : i - n); };
    double total = 0, lines = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double kx = wavenumber(i), ky = wavenumber(j);
            if (kx * kx + ky * ky < min_wavenumber * min_wavenumber) continue;
            const double p = power[std::size_t(j) * m + std::size_t(i)];
            double ring = 0;
            for (int dj = -2; dj <= 2; ++dj)
                for (int di = -2; di <= 2; ++di)
                    if (di == -2 || di == 2 || dj == -2 || dj == 2)
                        ring += power[std::size_t((j + dj + n) % n) * m +
                                      std::size_t((i + di + n) % n)];
            total += p;
            if (p > line_factor * ring / 16.0) lines += p;
        }
    return total > 0 ? lines / total : 0.0;
}

}  // namespace shitsukan::fujimoto2000
