#!/usr/bin/env bash
# ports/cortex-m/test_mcu.sh DIR [FIGURES] — run by `make test-mcu` after it built, in DIR,
# host_transcript, host_clang_O0, {m0,m4,m7,rv32}/transcript.elf and png_fnv (and
# build/paper_figures). Runs the transcript on the host (gcc -O2, clang -O0) and under QEMU
# (qemu_run.sh: Cortex-M0 micro:bit, Cortex-M4F mps2-an386, Cortex-M7 mps2-an500, RV32IMAC
# virt); fails unless the six transcripts are byte-identical and the fig. 10a frame equals the
# host's paper figure PNG.
set -euo pipefail
dir="$1"
figures="${2:-build/paper_figures}"
fail=0

"$dir/host_transcript" > "$dir/host.txt" || { echo "test-mcu: host transcript failed"; cat "$dir/host.txt"; exit 1; }
"$dir/host_clang_O0" > "$dir/host_clang_O0.txt" || { echo "test-mcu: clang -O0 transcript failed"; exit 1; }
if cmp -s "$dir/host.txt" "$dir/host_clang_O0.txt"; then
    echo "test-mcu: host clang -O0 transcript == host gcc -O2 transcript"
else
    echo "test-mcu: host clang -O0 transcript differs from gcc -O2:"; diff "$dir/host.txt" "$dir/host_clang_O0.txt" || true
    fail=1
fi
# The four devices run at once (the M0's soft-float run is the long one); then compared.
here="$(dirname "$0")"
declare -A pid start  # per core
for core in m0 m4 m7 rv32; do
    rm -f "$dir/$core.txt"
    start[$core]=$(date +%s)
    (bash "$here/qemu_run.sh" "$core" "$dir/$core/transcript.elf" "$dir/$core.txt"; rc=$?
     echo $(( $(date +%s) - ${start[$core]} )) > "$dir/$core.seconds"; exit $rc) &
    pid[$core]=$!
done
for core in m0 m4 m7 rv32; do
    if ! wait "${pid[$core]}"; then
        echo "test-mcu: $core exited with an error; its transcript:"; cat "$dir/$core.txt"; exit 1
    fi
    echo "test-mcu: $core ran in $(cat "$dir/$core.seconds") s (wall clock, the four QEMUs at once)"
    if cmp -s "$dir/host.txt" "$dir/$core.txt"; then
        echo "test-mcu: $core transcript == host transcript ($(wc -l < "$dir/host.txt") lines)"
    else
        echo "test-mcu: $core transcript differs from the host's:"
        diff "$dir/host.txt" "$dir/$core.txt" || true
        fail=1
    fi
done

# fig. 10a: the device frame's digest against the host's paper figure.
"$figures" --only okada1987/fig10a --out "$dir/figures" > "$dir/figures.log"
want=$(sed -n 's/^fig10a \(512x512 rgb fnv [0-9a-f]*\)$/\1/p' "$dir/host.txt")
got=$("$dir/png_fnv" "$dir/figures/okada1987/fig10a.png")
if [ -n "$want" ] && [ "$want" = "$got" ]; then
    echo "test-mcu: fig10a frame on the devices == paper figure okada1987/fig10a.png ($got)"
else
    echo "test-mcu: fig10a frame ($want) differs from paper figure okada1987/fig10a.png ($got)"
    fail=1
fi
grep -q '^end ok$' "$dir/host.txt" || { echo "test-mcu: the transcript reports errors"; fail=1; }
for core in m4 m0; do
    echo "test-mcu: footprint of the $core transcript firmware by module (-Os, newlib-nano):"
    bash "$here/footprint.sh" modules "$dir/$core/transcript.map"
done
[ "$fail" = 0 ] && echo "test-mcu: all six transcripts are identical: host (gcc -O2, clang -O0), Cortex-M0, Cortex-M4F, Cortex-M7 and RV32IMAC (gcc -Os)"
exit "$fail"
