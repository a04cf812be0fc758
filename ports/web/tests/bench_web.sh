#!/usr/bin/env bash
# ports/web/tests/bench_web.sh WEB_DIR — make bench-web: the explorer's speed and size against
# the goals of ports/web/README.md, printed as "bench:" lines (a bench, not a test: nothing
# fails on a slow machine). Chromium runs headless in real time (cdp.js, no virtual time);
# the timings carry the machine's load at the moment, so run it on a quiet machine to compare.
set -euo pipefail
web=${1:?usage: bench_web.sh WEB_DIR}
here=$(cd "$(dirname "$0")" && pwd)
page="file://$(cd "$web" && pwd)/index.html"
wasm="$web/hosted/shitsukan_web.wasm"
raw=$(wc -c < "$wasm")
gz=$(gzip -9c "$wasm" | wc -c)
echo "bench: .wasm $raw bytes raw, $gz bytes gzip -9 (goal for all five papers <= 409600 bytes gzip)"
echo "bench: one-file page $web/index.html $(wc -c < "$web/index.html") bytes (the .wasm inside as base64)"
for round in 1 2 3; do
  node "$here/cdp.js" "$page#bench" --timeout 300 --wait "document.body.dataset.bench" \
    --eval "document.getElementById('sk-selftest').textContent" 2>/dev/null | sed "s/^bench: /bench: run $round: /"
done
echo "bench: (wall-clock in headless Chromium on this machine, under its current load; the median of the moves is the number to compare)"
