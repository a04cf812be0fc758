#!/usr/bin/env bash
# ports/cortex-m/footprint.sh — what the firmwares of this port cost on the device.
#   footprint.sh modules MAP    flash, initialised data and zeroed RAM per library module (and
#                               the port, and the C runtime) in a firmware, summed from the GNU
#                               ld map file's input sections after --gc-sections
#   footprint.sh firmwares DIR  `make footprint-mcu`: runs DIR/{m4,m0,rv32}-{lattice,marble,
#                               lattice_runtime_beta,lattice_messages}.elf (footprint_main.cpp)
#                               under QEMU and prints one `footprint:` line each: flash = text
#                               + data, RAM = data + bss + the main stack's high-water mark
#                               (the reserved stack itself not counted), with the goal beside
#                               it where the port has one
set -euo pipefail
here="$(dirname "$0")"

# goal CORE VARIANT: the flash goal in bytes, or nothing (the port's goals: the
# lattice firmware in 8 KB on the M0, the marble cube in 32 KB everywhere).
goal() {
    case "$1-$2" in
        m0-lattice) echo 8192 ;;
        *-marble) echo 32768 ;;
    esac
}

firmwares() {
    local dir="$1" fail=0 core variant elf out stack size_tool name g digest first status label
    local digest_lattice='' digest_marble=''
    for core in m4 m0 rv32; do
        case "$core" in
            m4) name="Cortex-M4F, -Os, newlib-nano"; size_tool=arm-none-eabi-size ;;
            m0) name="Cortex-M0, soft-float, -Os, newlib-nano"; size_tool=arm-none-eabi-size ;;
            rv32) name="RV32IMAC, soft-float, -Os, picolibc"; size_tool=riscv64-unknown-elf-size ;;
        esac
        for variant in lattice marble lattice_runtime_beta lattice_messages; do
            elf="$dir/$core-$variant.elf"
            out=$(bash "$here/qemu_run.sh" "$core" "$elf") || { echo "footprint-mcu: $core $variant failed: $out"; fail=1; continue; }
            echo "$out"
            # the same frame and lattice on every core (the firmwares are built with -flto,
            # the transcripts without: these digests are the transcript's bits too)
            digest=$(echo "$out" | sed -n 's/.* fnv \([0-9a-f]*\),.*/\1/p')
            first="digest_${variant%%_*}"  # the variants print the lattice firmware's digest
            if [ -z "${!first:-}" ]; then printf -v "$first" '%s' "$digest"
            elif [ "${!first}" != "$digest" ]; then
                echo "footprint-mcu: $core $variant digest $digest differs from the first core's ${!first}"; fail=1
            fi
            stack=$(echo "$out" | sed -n 's/.*main stack used \([0-9]*\) bytes/\1/p')
            reserved=$(( $(nm "$elf" 2>/dev/null | awk '$3 == "_estack" { e = $1 } $3 == "_sstack" { s = $1 } END { print "0x" e " - 0x" s }') ))
            g=$(goal "$core" "$variant")
            # mcu.mk: every Status checked, none printed (core/status.hpp), but in the variant
            # that measures what keeping the arguments costs
            status="Status without arguments"
            case "$variant" in
                lattice_runtime_beta) label="lattice firmware, eq. (2)'s amplitudes computed on the device" ;;
                lattice_messages) label="lattice firmware, messages kept"; status="Status with arguments" ;;
                *) label="$variant firmware" ;;
            esac
            "$size_tool" "$elf" | awk -v v="$label" -v n="$name, $status" -v s="$stack" -v r="$reserved" -v g="$g" 'NR == 2 {
                flash = $1 + $2
                printf "footprint: %s (%s): flash %d bytes%s, RAM %d bytes (data %d + bss %d + stack used %d)\n", \
                    v, n, flash, g == "" ? "" : sprintf(" (goal <= %d: %s)", g, flash <= g ? "met" : "MISSED"), \
                    $2 + $3 - r + s, $2, $3 - r, s }'
        done
    done
    return "$fail"
}

case "${1:-}" in
    firmwares) firmwares "$2"; exit $? ;;
    modules) shift ;;
    *) echo "usage: footprint.sh modules MAP | firmwares DIR" >&2; exit 2 ;;
esac
awk '
/^Linker script and memory map/ { on = 1; next }
!on { next }
# an input section: " .text.name  0xADDR  0xSIZE  file" on one line, or the name alone
# followed by a line " 0xADDR 0xSIZE file"
/^ \.(text|rodata|data|bss)/ {
    sec = $1
    if (NF >= 4 && $2 ~ /^0x/) { add(sec, $3, $4) } else { pending = sec }
    next
}
pending != "" && $1 ~ /^0x/ && NF >= 3 { add(pending, $2, $3); pending = ""; next }
{ pending = "" }
function hex(s,   i, n) {
    n = 0; s = tolower(substr(s, 3))
    for (i = 1; i <= length(s); ++i) n = n * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
    return n
}
function add(sec, size, obj,   kind, mod, n) {
    n = hex(size)
    kind = sec ~ /^\.bss/ ? "bss" : (sec ~ /^\.data/ ? "data" : "flash")
    if (obj ~ /\/lib\/shitsukan\//) { mod = obj; sub(/.*\/lib\/shitsukan\//, "", mod); sub(/\/.*/, "", mod) }
    else if (obj ~ /ports\/(cortex-m|riscv)\/soft_float/) mod = "C/C++ runtime (C library, libgcc)"
    else if (obj ~ /ports\/(cortex-m|riscv)/) mod = "port (startup, transcript, buffers)"
    else mod = "C/C++ runtime (C library, libgcc)"
    total[mod, kind] += n; mods[mod] = 1
}
END {
    printf "%-38s %8s %8s %9s\n", "module", "flash", "data", "bss"
    for (m in mods) printf "%-38s %8d %8d %9d\n", m, total[m, "flash"], total[m, "data"], total[m, "bss"]
}' "$1" | (read -r header; echo "$header"; sort)
