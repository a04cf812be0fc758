#!/usr/bin/env bash
# ports/cortex-m/qemu_run.sh CORE ELF [OUT] [EXTRA...] — runs a firmware of this port under
# QEMU with semihosting (text to OUT, or stdout without it), on the machine of its core:
#   m0    qemu-system-arm -M microbit       (Cortex-M0, 256 KB flash, 16 KB RAM)
#   m4    qemu-system-arm -M mps2-an386     (Cortex-M4F)
#   m7    qemu-system-arm -M mps2-an500     (Cortex-M7)
#   rv32  qemu-system-riscv32 -M virt       (RV32 in machine mode, -bios none)
# EXTRA goes to QEMU (e.g. -icount shift=0 for the benches). Exit status: the firmware's.
set -euo pipefail
core="$1"; elf="$2"; out="${3:-}"; shift $(( $# < 3 ? $# : 3 ))
case "$core" in
    m0) qemu=(qemu-system-arm -M microbit) ;;
    m4) qemu=(qemu-system-arm -M mps2-an386) ;;
    m7) qemu=(qemu-system-arm -M mps2-an500) ;;
    rv32) qemu=(qemu-system-riscv32 -M virt -bios none) ;;
    *) echo "qemu_run.sh: unknown core '$core' (m0, m4, m7, rv32)" >&2; exit 2 ;;
esac
if [ -n "$out" ]; then chardev="file,id=semi,path=$out"; else chardev="stdio,id=semi"; fi
exec timeout 900 "${qemu[@]}" "$@" -display none -monitor none -serial none \
    -chardev "$chardev" -semihosting-config enable=on,target=native,chardev=semi -kernel "$elf"
