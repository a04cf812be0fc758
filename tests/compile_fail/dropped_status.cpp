// Must NOT compile under -Werror: the Status of a lattice build is dropped (Status is
// [[nodiscard]]). `make check-api` compiles it twice: as is (must fail, naming nodiscard)
// and with -DSHITSUKAN_CHECKED (the result checked: must compile), so the check cannot pass
// because of an unrelated error.
#include "shitsukan/solid/lattice_store.hpp"

int main() {
    shitsukan::FractalParams params;
    params.R = 40;  // refused
    shitsukan::FractalLattice lattice;
#ifdef SHITSUKAN_CHECKED
    if (!lattice.build(params)) return 1;
#else
    lattice.build(params);
#endif
    return 0;
}
