#!/usr/bin/env bash
# ports/cortex-m/porting_numbers.sh [GUIDE] — rewrites the measured block of ports/PORTING.md
# (between the "numbers:begin" and "numbers:end" markers) with the `bench:` and `footprint:`
# lines that `make bench-mcu` and `make footprint-mcu` print now, verbatim, and the flash per
# module of the Cortex-M4F transcript firmware (footprint.sh modules): the guide's numbers are
# never typed by hand. Run from the repository root after building (it runs both targets).
set -euo pipefail
guide="${1:-ports/PORTING.md}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
make --no-print-directory bench-mcu 2>&1 | grep '^bench:' > "$tmp/bench"
make --no-print-directory footprint-mcu 2>&1 | grep '^footprint:' > "$tmp/footprint"
make --no-print-directory build/mcu/m4/transcript.elf > /dev/null
bash "$(dirname "$0")/footprint.sh" modules build/mcu/m4/transcript.map > "$tmp/modules"
[ -s "$tmp/bench" ] && [ -s "$tmp/footprint" ] || { echo "porting_numbers.sh: no bench/footprint lines"; exit 1; }
{
    echo '`make bench-mcu` (QEMU `-icount shift=0`: instructions, not cycles), '"$(git rev-parse --short HEAD 2>/dev/null || echo '?')"':'
    echo
    echo '```'
    cat "$tmp/bench"
    echo '```'
    echo
    echo '`make footprint-mcu` (flash = text + data; RAM = data + bss + the stack high-water mark):'
    echo
    echo '```'
    cat "$tmp/footprint"
    echo '```'
    echo
    echo 'Flash per module of the transcript firmware on the Cortex-M4F (`-Os`, newlib-nano, after'
    echo '`--gc-sections`; `footprint.sh modules build/mcu/m4/transcript.map`, bss includes the'
    echo "transcript's 65^3 table and band buffers):"
    echo
    echo '```'
    cat "$tmp/modules"
    echo '```'
} > "$tmp/block"
awk -v block="$tmp/block" '
/<!-- numbers:begin -->/ { print; while ((getline line < block) > 0) print line; skip = 1; next }
/<!-- numbers:end -->/ { skip = 0 }
!skip { print }' "$guide" > "$tmp/guide"
grep -q '<!-- numbers:end -->' "$tmp/guide" || { echo "porting_numbers.sh: markers missing in $guide"; exit 1; }
cp "$tmp/guide" "$guide"
echo "porting_numbers.sh: $(wc -l < "$tmp/bench") bench and $(wc -l < "$tmp/footprint") footprint lines written into $guide"
