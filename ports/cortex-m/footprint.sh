#!/usr/bin/env bash
# ports/cortex-m/footprint.sh MAP — flash, initialised data and zeroed RAM per library module
# (and the port, and the C/C++ runtime) in a firmware, summed from the GNU ld map file's
# input sections after --gc-sections: what each feature costs on the device.
set -euo pipefail
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
    else if (obj ~ /ports\/cortex-m/) mod = "port (startup, transcript, buffers)"
    else mod = "C/C++ runtime (newlib-nano, libgcc)"
    total[mod, kind] += n; mods[mod] = 1
}
END {
    printf "%-38s %8s %8s %9s\n", "module", "flash", "data", "bss"
    for (m in mods) printf "%-38s %8d %8d %9d\n", m, total[m, "flash"], total[m, "data"], total[m, "bss"]
}' "$1" | (read -r header; echo "$header"; sort)
