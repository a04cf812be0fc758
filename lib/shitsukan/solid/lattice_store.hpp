// shitsukan/solid/lattice_store.hpp — host side: an owning Type I lattice with a memory
// budget, and saving/loading it as the paper kept its lattice on file (okada1987 §4.4:
// "file write 0.9 s").
//
// Manual
//   FractalParams params;                             // R = 6
//   FractalLattice lattice;
//   Status s = lattice.build(params);                 // refuses > 512 MiB (default budget)
//   if (s) s = lattice.build(params, 64u << 20);      // or a budget of your own
//   if (!s) return s;
//   Vec3 p{10.3f, 40.0f, 31.7f};
//   float d = turbulence(lattice.view(), p);
//   s = save_lattice("lattice.shl", lattice);         // raw little-endian float32 + header
//   FractalLattice back;
//   if (s) s = load_lattice("lattice.shl", back);
//   return s;
//   #include "shitsukan/solid/turbulence.hpp"
//
// File format (all little-endian): 8 bytes magic "SHKLAT01", int32 R, float32 beta,
// uint32 seed, uint32 noise source (0 hash, 1 sequential), float32 corners[8], then
// (2^R + 1)^3 float32 values, x fastest, then y, then z. Loading refuses non-finite values
// and bytes after the last value. Saving goes through core/output_file.hpp: the file appears
// complete or not at all, and a failure names the path and the reason.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shitsukan/core/assert.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/solid/fractal_lattice.hpp"

namespace shitsukan {

// The lattice's own budget; build() and load_lattice() also respect the process-wide memory
// budget (core/memory_budget.hpp): a lattice must fit both.
constexpr std::uint64_t kDefaultLatticeBudget = std::uint64_t(512) << 20;  // 512 MiB: R <= 8

class FractalLattice {
public:
    Status build(const FractalParams& params, std::uint64_t budget_bytes = kDefaultLatticeBudget);
    // The lattice's values; using it before a successful build() / load_lattice() aborts
    // naming the call whose Status was ignored.
    LatticeView view() const {
        SHITSUKAN_REQUIRE_BUILT(!values_.empty(), "FractalLattice::build() or load_lattice()",
                                "FractalLattice::view()");
        return view_;
    }
    const FractalParams& params() const { return params_; }
    bool empty() const { return values_.empty(); }
    std::size_t bytes() const { return values_.size() * sizeof(float); }

private:
    friend Status load_lattice(const std::string& path, FractalLattice& out,
                               std::uint64_t budget_bytes);
    FractalParams params_;
    std::vector<float> values_;
    LatticeView view_;
};

Status save_lattice(const std::string& path, const FractalLattice& lattice);
Status load_lattice(const std::string& path, FractalLattice& out,
                    std::uint64_t budget_bytes = kDefaultLatticeBudget);

}  // namespace shitsukan
