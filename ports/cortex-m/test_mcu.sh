#!/usr/bin/env bash
# ports/cortex-m/test_mcu.sh DIR — run by `make test-mcu` after it built, in DIR,
# host_transcript, m4/transcript.elf, m7/transcript.elf and png_fnv (and build/paper_figures).
# Runs the transcript on the host and under QEMU on mps2-an386 (Cortex-M4F) and mps2-an500
# (Cortex-M7); fails unless the three transcripts are byte-identical and the fig. 10a frame
# equals the host's paper figure PNG.
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
for pair in m4:mps2-an386 m7:mps2-an500; do
    core=${pair%%:*}; machine=${pair##*:}
    rm -f "$dir/$core.txt"
    start=$(date +%s)
    if ! timeout 900 qemu-system-arm -M "$machine" -display none -monitor none -serial none \
         -chardev file,id=semi,path="$dir/$core.txt" \
         -semihosting-config enable=on,target=native,chardev=semi \
         -kernel "$dir/$core/transcript.elf"; then
        echo "test-mcu: $core ($machine) exited with an error; its transcript:"; cat "$dir/$core.txt"; exit 1
    fi
    echo "test-mcu: $core ($machine) ran in $(( $(date +%s) - start )) s"
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
echo "test-mcu: footprint of the Cortex-M4F transcript firmware by module (-Os, newlib-nano):"
bash "$(dirname "$0")/footprint.sh" "$dir/m4/transcript.map"
[ "$fail" = 0 ] && echo "test-mcu: host (gcc -O2, clang -O0), Cortex-M4F and Cortex-M7 (gcc -Os) transcripts are identical"
exit "$fail"
