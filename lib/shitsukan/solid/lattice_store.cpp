// Host side: owning Type I lattice, file save/load.
#include "shitsukan/solid/lattice_store.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/core/output_file.hpp"

namespace shitsukan {
namespace {

const char kMagic[8] = {'S', 'H', 'K', 'L', 'A', 'T', '0', '1'};

Status check_budget(int R, std::uint64_t budget) {
    if (R < 0 || R > kTypeIMaxDepth)
        return Status::error(StatusCode::invalid_argument,
                             "Type I lattice: R must be in [0, %d] (got %d)", kTypeIMaxDepth, R);
    const std::uint64_t need = lattice_bytes(R);
    if (need > budget)
        return Status::error(StatusCode::too_large,
                             "Type I lattice: R = %d needs %llu bytes (%lld^3 floats), over the "
                             "budget of %llu bytes; use the Type III lattice",
                             R, static_cast<unsigned long long>(need),
                             static_cast<long long>(lattice_side(R)),
                             static_cast<unsigned long long>(budget));
    // The lattice's own budget (kDefaultLatticeBudget, or the caller's) and the process-wide
    // per-request one (core/memory_budget.hpp): the smaller decides.
    return check_memory_budget(need, "Type I lattice");
}

void put_u32(unsigned char* p, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
}
std::uint32_t get_u32(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}
std::uint32_t float_bits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}
float bits_float(std::uint32_t u) {
    float f;
    std::memcpy(&f, &u, 4);
    return f;
}

constexpr std::size_t kHeaderBytes = 8 + 4 * 4 + 8 * 4;

}  // namespace

Status FractalLattice::build(const FractalParams& params, std::uint64_t budget_bytes) {
    SHITSUKAN_TRY(validate_fractal_params(params, kTypeIMaxDepth));
    SHITSUKAN_TRY(check_budget(params.R, budget_bytes));
    std::vector<float> values(std::size_t(lattice_bytes(params.R) / sizeof(float)));
    LatticeView view;
    SHITSUKAN_TRY(
        build_fractal_lattice(params, values.data(), values.size() * sizeof(float), view));
    values_.swap(values);
    view_ = view;
    view_.values = values_.data();
    params_ = params;
    return Status::success();
}

Status save_lattice(const std::string& path, const FractalLattice& lattice) {
    if (lattice.empty())
        return Status::error(StatusCode::invalid_argument, "save_lattice: the lattice is empty");
    OutputFile out;
    SHITSUKAN_TRY(out.open(path));
    const FractalParams& p = lattice.params();
    unsigned char header[kHeaderBytes];
    std::memcpy(header, kMagic, 8);
    put_u32(header + 8, std::uint32_t(p.R));
    put_u32(header + 12, float_bits(p.beta));
    put_u32(header + 16, p.seed);
    put_u32(header + 20, std::uint32_t(p.noise));
    for (int i = 0; i < 8; ++i) put_u32(header + 24 + 4 * i, float_bits(p.corners[i]));
    out.write(header, kHeaderBytes);
    // Values in little-endian order, written in chunks.
    const LatticeView v = lattice.view();
    const std::size_t count = std::size_t(v.side) * std::size_t(v.side) * std::size_t(v.side);
    unsigned char chunk[4096 * 4];
    for (std::size_t i = 0; !out.failed() && i < count; i += 4096) {
        std::size_t n = count - i < 4096 ? count - i : 4096;
        for (std::size_t j = 0; j < n; ++j) put_u32(chunk + 4 * j, float_bits(v.values[i + j]));
        out.write(chunk, 4 * n);
    }
    return out.commit();
}

Status load_lattice(const std::string& path, FractalLattice& out, std::uint64_t budget_bytes) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f)
        return Status::error(StatusCode::io_error, "load_lattice: cannot open %s", path.c_str());
    unsigned char header[kHeaderBytes];
    if (std::fread(header, 1, kHeaderBytes, f) != kHeaderBytes ||
        std::memcmp(header, kMagic, 8) != 0) {
        std::fclose(f);
        return Status::error(StatusCode::io_error, "load_lattice: %s is not a lattice file",
                             path.c_str());
    }
    FractalParams p;
    p.R = int(get_u32(header + 8));
    p.beta = bits_float(get_u32(header + 12));
    p.seed = get_u32(header + 16);
    // The whole 32-bit field must name a source: masking it to a byte would read 256 as 0.
    const std::uint32_t noise = get_u32(header + 20);
    if (noise > std::uint32_t(NoiseSource::sequential)) {
        std::fclose(f);
        return Status::error(StatusCode::io_error,
                             "load_lattice: %s names an unknown noise source %lu", path.c_str(),
                             static_cast<unsigned long>(noise));
    }
    p.noise = NoiseSource(noise);
    for (int i = 0; i < 8; ++i) p.corners[i] = bits_float(get_u32(header + 24 + 4 * i));
    Status s = validate_fractal_params(p, kTypeIMaxDepth);
    if (s.ok()) s = check_budget(p.R, budget_bytes);
    if (!s.ok()) {
        std::fclose(f);
        return s;
    }
    const std::size_t side = std::size_t(lattice_side(p.R));
    std::vector<float> values(side * side * side);
    unsigned char chunk[4096 * 4];
    bool ok = true;
    std::size_t bad = values.size();  // first value that is not finite
    for (std::size_t i = 0; ok && i < values.size(); i += 4096) {
        std::size_t n = values.size() - i < 4096 ? values.size() - i : 4096;
        ok = std::fread(chunk, 1, 4 * n, f) == 4 * n;
        for (std::size_t j = 0; ok && j < n; ++j) {
            values[i + j] = bits_float(get_u32(chunk + 4 * j));
            if (bad == values.size() && !std::isfinite(values[i + j])) bad = i + j;
        }
    }
    const bool trailing = ok && std::fgetc(f) != EOF;
    std::fclose(f);
    if (!ok)
        return Status::error(StatusCode::io_error, "load_lattice: %s is truncated", path.c_str());
    if (trailing)
        return Status::error(StatusCode::io_error,
                             "load_lattice: %s has bytes after its %zu values (not a lattice "
                             "file of R = %d)",
                             path.c_str(), values.size(), p.R);
    if (bad < values.size())
        return Status::error(StatusCode::io_error,
                             "load_lattice: %s: value %zu is not finite (%g); D(P) promises a "
                             "number",
                             path.c_str(), bad, double(values[bad]));
    out.values_.swap(values);
    out.params_ = p;
    out.view_.values = out.values_.data();
    out.view_.R = p.R;
    out.view_.side = int(side);
    return Status::success();
}

}  // namespace shitsukan
