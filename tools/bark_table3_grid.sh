#!/usr/bin/env bash
# tools/bark_table3_grid.sh — hirota1998 Table 3 over a grid of the four shared chosen values
# (D, sigma, the final hoop and axial strains; Table 2 as printed, no per-species value): how
# many of Table 3's twelve numbers can one shared setting meet, and does any put the widths in
# the paper's order? docs/papers/hirota1998.md §4 prints its summary.
#
#   bash tools/bark_table3_grid.sh [out.md]     # about 30 minutes on 2 cores
#
# Runs `build/bark_table3_sweep set D sigma hoop axial 1 seeds` (tools/bark_table3_sweep.cpp)
# for a coarse grid over 3 seeds and a fine grid round its best points over 5 seeds, two at a
# time, then tools/bark_table3_grid.py counts, per setting, the numbers met as table03 judges
# them (means within 20 %, max within 30 %, camphor's max height over 20 cm) and the order.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build/bark_table3_grid.md}
make -s build/libshitsukan.a
g++ -std=c++17 -O2 -ffp-contract=off -Ilib tools/bark_table3_sweep.cpp build/libshitsukan.a \
    -o build/bark_table3_sweep
list=$(mktemp)
trap 'rm -f "$list"' EXIT
{
    echo "0.55 0.0175 1.0 1.0 3"  # as chosen (bark_params.hpp)
    # coarse, 3 seeds: D x sigma x hoop x axial
    for D in 0.60 0.65 0.70 0.75 0.80; do for s in 0.0125 0.015 0.0175; do
        for h in 1.0 1.1; do for a in 1.0 1.02; do echo "$D $s $h $a 3"; done; done
    done; done
    for D in 0.70 0.75 0.80 0.85 0.90; do for s in 0.0125 0.015; do
        for h in 1.1 1.2 1.3; do for a in 1.0 1.01 1.02; do echo "$D $s $h $a 3"; done; done
    done; done
    # fine, 5 seeds, round the coarse grid's best points
    for D in 0.725 0.75 0.775; do for s in 0.014 0.015 0.016; do
        for h in 1.05 1.1 1.15; do for a in 1.0 1.005 1.01; do echo "$D $s $h $a 5"; done; done
    done; done
    for D in 0.70 0.72; do for s in 0.0125 0.013; do
        for a in 1.015 1.02; do echo "$D $s 1.0 $a 5"; done
    done; done
} | awk '!seen[$0]++' > "$list"  # the two coarse grids share some points
echo "bark_table3_grid: $(wc -l < "$list") settings" >&2
xargs -P2 -L1 sh -c 'echo "$4 $(build/bark_table3_sweep set $0 $1 $2 $3 1 $4)"' < "$list" |
    python3 tools/bark_table3_grid.py > "$out"
echo "bark_table3_grid: wrote $out" >&2
