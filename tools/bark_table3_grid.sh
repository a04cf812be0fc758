#!/usr/bin/env bash
# tools/bark_table3_grid.sh — hirota1998 Table 3 over a grid of the four shared chosen values
# (D, sigma, the final hoop and axial strains; Table 2 as printed, no per-species value): how
# many of Table 3's twelve numbers can one shared setting meet, and does any put the widths in
# the paper's order? docs/papers/hirota1998.md §4 prints its summary.
#
#   bash tools/bark_table3_grid.sh [out.md]     # about 30 minutes on 2 cores
#
# Runs `build/bark_table3_sweep set D sigma hoop axial 1 seeds` (tools/bark_table3_sweep.cpp)
# for a coarse grid over 3 seeds and a fine grid round its best points and past its edges over
# 5 seeds, two at a time, then tools/bark_table3_grid.py judges each setting as table03 does
# (means within 20 %, max within 30 %, camphor's max height over 20 cm in every seed) and counts.
set -euo pipefail
out=$(realpath -m "${1:-build/bark_table3_grid.md}")
cd "$(dirname "$0")/.."
make -s build/libshitsukan.a
g++ -std=c++17 -O2 -ffp-contract=off -Ilib tools/bark_table3_sweep.cpp build/libshitsukan.a \
    -o build/bark_table3_sweep
list=$(mktemp)
trap 'rm -f "$list" "$out.tmp"' EXIT
{
    echo "0.55 0.0175 1.0 1.0 5"  # as chosen (bark_params.hpp)
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
        for a in 1.015 1.02 1.025 1.03; do echo "$D $s 1.0 $a 5"; done
    done; done
    # 5 seeds, past the coarse grid's edges where its best max heights lie (sigma, axial)
    for D in 0.60 0.70; do for a in 1.02 1.03; do echo "$D 0.010 1.0 $a 5"; done; done
    for s in 0.020 0.0225; do echo "0.80 $s 1.0 1.02 5"; done
} | awk '!seen[$0]++' > "$list"  # the two coarse grids share some points
echo "bark_table3_grid: $(wc -l < "$list") runs" >&2
# A failed run fails the pipeline (xargs exits non-zero) and leaves any earlier $out in place.
xargs -P2 -L1 sh -c 'row=$(build/bark_table3_sweep set "$1" "$2" "$3" "$4" 1 "$5") &&
                     echo "$5 $row"' _ < "$list" |
    python3 tools/bark_table3_grid.py > "$out.tmp"
mv "$out.tmp" "$out"
echo "bark_table3_grid: wrote $out" >&2
