#!/usr/bin/env bash
# ports/web/tests/test_dist.sh ZIP — the classroom bundle as a teacher gets it: the zip
# unpacked into a fresh folder, index.html opened from disk (file://, no server) in Debian's
# headless Chromium: the first panel must draw without a console error, and every source file
# any panel links to (SK.sourceFiles) must be in the unpacked folder.
set -euo pipefail
zip=${1:?usage: test_dist.sh ZIP}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 -c 'import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extractall(sys.argv[2])' "$zip" "$tmp"
root="$tmp/shitsukan-explorer"
[ -f "$root/index.html" ] && [ -f "$root/README.md" ] || { echo "test-dist: index.html or README.md missing in $zip"; exit 1; }
rc=0
node "$here/cdp.js" "file://$root/index.html" --timeout 120 --size 1280x720 \
  --wait "document.body.dataset.ready" \
  --eval "[document.body.dataset.ready, Array.from(document.querySelectorAll('canvas')).filter((c) => SK.canvasHash(c) !== 'empty').length].concat(SK.panels.flatMap((p) => SK.sourceFiles(p))).join('\n')" \
  > "$tmp/out.txt" 2> "$tmp/console.txt" || rc=$?
if [ $rc != 0 ]; then echo "test-dist: the bundle did not open cleanly ($rc):"; cat "$tmp/console.txt"; exit 1; fi
panel=$(sed -n 1p "$tmp/out.txt"); drawn=$(sed -n 2p "$tmp/out.txt")
[ "$drawn" -ge 1 ] || { echo "test-dist: panel $panel drew no canvas"; exit 1; }
missing=0; count=0
while read -r f; do
  count=$((count + 1))
  [ -f "$root/sources/$f.html" ] || { echo "test-dist: a panel links sources/$f.html, not in the bundle"; missing=1; }
done < <(tail -n +3 "$tmp/out.txt" | sort -u)
[ $missing = 0 ] || exit 1
echo "test-dist: $(basename "$zip") unpacked and opened from disk: panel $panel drew $drawn canvases; its $count linked source files are all inside"
