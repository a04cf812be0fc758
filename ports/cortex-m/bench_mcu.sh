#!/usr/bin/env bash
# ports/cortex-m/bench_mcu.sh DIR — `make bench-mcu`: runs DIR/{m4,m7,m0,rv32}/bench.elf
# (bench_main.cpp) under QEMU with -icount shift=0 and prints their `bench:` lines, then the
# rasterizer's per-triangle goal (<= 1,000 M4F instructions per triangle of the 48 x 24
# UV sphere's frame) beside the measured value.
set -euo pipefail
dir="$1"
here="$(dirname "$0")"
fail=0
out=""
for core in m4 m7 m0 rv32; do
    lines=$(bash "$here/qemu_run.sh" "$core" "$dir/$core/bench.elf" "" -icount shift=0) ||
        { echo "bench-mcu: $core failed: $lines"; fail=1; continue; }
    echo "$lines"
    out="$out$lines"$'\n'
done
# The goal is the per-triangle set-up: the frame with every fragment behind the depth buffer
# (binning, set-up, edge walks, depth tests); the whole frame (with the shading of its 6,164
# fragments) is printed beside it.
per_triangle=$(echo "$out" | sed -n 's/^bench: rasterized UV sphere.*, binned (M4F): \([0-9]*\) instructions per triangle .*/\1/p')
set_up=$(echo "$out" | sed -n 's/^bench: rasterized UV sphere.*, binned, set-up only .*(M4F): \([0-9]*\) instructions per triangle .*/\1/p')
if [ -n "$per_triangle" ] && [ -n "$set_up" ]; then
    verdict=$([ "$set_up" -le 1000 ] && echo met || echo MISSED)
    echo "bench: goal: <= 1000 M4F instructions per triangle for the 48x24 UV sphere in 16-row bands, binned, set-up (fragments behind the depth buffer): $set_up ($verdict); whole frame with shading: $per_triangle per triangle"
fi
exit "$fail"
