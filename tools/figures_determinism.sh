#!/usr/bin/env bash
# make figures-determinism, after both drivers are built: the quick figures rendered by the g++
# driver on 2 threads and on 1 (--jobs) and by the clang++ driver must be the same files
# (images, SVG, CSV, OBJ; the .md notes and tables carry measured times and are not compared),
# and the g++ runs the same index apart from measured numbers (headings, outputs and the
# parameter rows).
#
# Usage: tools/figures_determinism.sh BUILD_DIR GCC_DRIVER CLANG_DRIVER
set -uo pipefail
cd "$(dirname "$0")/.."
b=$1 gcc_driver=$2 clang_driver=$3
rm -rf "$b/det-gcc" "$b/det-gcc-j1" "$b/det-clang"
echo "$gcc_driver --quick --jobs 2 --out $b/det-gcc"
"$gcc_driver" --quick --jobs 2 --out "$b/det-gcc" > /dev/null || exit 1
echo "$gcc_driver --quick --jobs 1 --out $b/det-gcc-j1"
"$gcc_driver" --quick --jobs 1 --out "$b/det-gcc-j1" > /dev/null || exit 1
echo "$clang_driver --quick --out $b/det-clang"
"$clang_driver" --quick --out "$b/det-clang" > /dev/null || exit 1
for d in det-gcc det-gcc-j1 det-clang; do
  (cd "$b/$d" && find . -type f ! -name '*.md' | LC_ALL=C sort | xargs sha256sum > "../$d.sha" &&
   grep -E '^(#|!\[|Output:)|\| (given|chosen here) \| [^|]*\|$' index.md > "../$d.index") || exit 1
done
if diff "$b/det-gcc.sha" "$b/det-gcc-j1.sha" > "$b/det.diff" &&
   diff "$b/det-gcc.index" "$b/det-gcc-j1.index" >> "$b/det.diff"; then
  echo "figures-determinism: $(wc -l < "$b/det-gcc.sha") files and $(wc -l < "$b/det-gcc.index") index lines identical with --jobs 2 and --jobs 1"
else
  echo "figures-determinism: --jobs 2 and --jobs 1 outputs differ:"; cat "$b/det.diff"; exit 1
fi
if diff "$b/det-gcc.sha" "$b/det-clang.sha" > "$b/det.diff"; then
  echo "figures-determinism: $(wc -l < "$b/det-gcc.sha") files identical between g++ and clang++"
else
  echo "figures-determinism: g++ and clang++ outputs differ:"; cat "$b/det.diff"; exit 1
fi
