// fuzz/fuzz_lattice_load.cpp — load_lattice on any file contents (budget 4 MiB). Contract: a
// non-ok Status, or a lattice whose every value is finite and whose size matches its R.
#include <cmath>
#include <cstdio>
#include <string>
#include <unistd.h>

#include "fuzz_input.hpp"
#include "shitsukan/solid/lattice_store.hpp"

using namespace shitsukan;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string path = "/tmp/shitsukan-fuzz-lattice-" + std::to_string(getpid());
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return 0;
    std::fwrite(data, 1, size, f);
    std::fclose(f);
    FractalLattice lat;
    Status s = load_lattice(path, lat, std::uint64_t(4) << 20);
    if (!s) return 0;
    const LatticeView v = lat.view();
    const long side = v.side;
    FUZZ_REQUIRE(side == (1L << v.R) + 1);
    for (long i = 0; i < side * side * side; ++i) FUZZ_REQUIRE(std::isfinite(v.values[i]));
    return 0;
}
