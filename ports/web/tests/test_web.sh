#!/usr/bin/env bash
# ports/web/tests/test_web.sh WEB_DIR — make test-web: the page's self-test against the native
# reference, and the interaction test, in Debian's headless Chromium opening the single-file
# page from disk (cdp.js: the DevTools protocol over a pipe, real time, console captured).
#  1. WEB_DIR/native_reference writes the expected hashes (selftest_expected.js) beside the page
#  2. index.html#selftest: the page makes the same C API calls in WASM, hashes what it drew
#     and writes PASS/FAIL into the DOM; any difference fails
#  3. index.html#interaction: every panel opens and draws, a slider changes the picture and
#     its hash; a console error or uncaught exception on any panel fails
#     and the animated panels' event counts must equal the native runs' at the same settings
#  4. Firefox ESR (bidi.js, WebDriver BiDi): the same self-test must PASS, and a panel opened at
#     1280x720 must draw (screenshot WEB_DIR/firefox.png)
#  5. the classroom bundle ZIP (make web-dist), unpacked and opened from disk (test_dist.sh)
set -euo pipefail
web=${1:?usage: test_web.sh WEB_DIR [DIST_ZIP]}
zip=${2:-}
here=$(cd "$(dirname "$0")" && pwd)
page="file://$(cd "$web" && pwd)/index.html"
start=$(date +%s)

"$web/native_reference" --js "$web/selftest_expected.js" > "$web/native_reference.txt"
echo "test-web: native reference: $(grep -c '^selftest:' "$web/native_reference.txt") lines ($web/native_reference.txt)"

run() {  # run NAME URL-HASH DATASET-KEY [DRIVER]
  local name=$1 hash=$2 key=$3 driver=${4:-cdp.js} rc=0
  node --experimental-websocket --no-warnings "$here/$driver" "$page#$hash" --timeout 240 \
    --wait "document.body.dataset.$key" \
    --eval "document.getElementById('sk-selftest').textContent" \
    > "$web/test_$name.txt" 2> "$web/test_$name.console" || rc=$?
  head -1 "$web/test_$name.txt" | sed "s/^/test-web: $name: /"
  grep -E '^(FAIL|ok|panel)' "$web/test_$name.txt" | grep -v '^ok' | sed "s/^/test-web:   /" || true
  if [ $rc = 3 ]; then echo "test-web: $name: console errors:"; grep -E 'console: (error|exception)' "$web/test_$name.console"; return 1; fi
  if [ $rc != 0 ]; then echo "test-web: $name: the browser run failed ($rc):"; cat "$web/test_$name.console"; return 1; fi
  head -1 "$web/test_$name.txt" | grep -q '^PASS' || { echo "test-web: $name FAILED (see $web/test_$name.txt)"; return 1; }
}
run selftest selftest selftest
run interaction interaction interaction
# The animations' event counts (each panel's event slider at its default settings) against the
# native runs of the same settings (native_reference's text of the run).
events() {  # events PANEL NATIVE-CASE
  local page_n native_n
  page_n=$(sed -n "s/^events $1 //p" "$web/test_interaction.txt")
  native_n=$(grep -F "selftest-text: $2: " "$web/native_reference.txt" | sed 's/.*"events":\([0-9]*\).*/\1/')
  if [ -z "$page_n" ] || [ "$page_n" != "$native_n" ]; then
    echo "test-web: $1 animates ${page_n:-?} events, the native run has ${native_n:-?} ($2)"; return 1
  fi
  echo "test-web: events: $1 animates $page_n events = the native run's ($2)"
}
events hirota1998-growth "hirota1998 camphor run: events, hash"
events hirota1998-layers "hirota1998 figs. 6-8 four layers 24 x 16, 4 cycles"
events hirota1998-branch "hirota1998 fig. 11 branch run (L0 0.6)"
# Firefox ESR: the self-test's hashes, then one panel drawn at 1280x720 (looked at by a person:
# WEB_DIR/firefox.png). `firefox-esr --headless --screenshot` shoots at the load event, before
# the worker has drawn anything, so bidi.js waits for the panel instead.
run firefox-selftest selftest selftest bidi.js
rc=0
node --experimental-websocket --no-warnings "$here/bidi.js" "$page#fujimoto2000-ist" --timeout 120 --size 1280x720 \
  --wait "document.body.dataset.ready" --screenshot "$web/firefox.png" \
  --eval "Array.from(document.querySelectorAll('#panel-fujimoto2000-ist canvas')).filter((c) => SK.canvasHash(c) !== 'empty').length" \
  > "$web/test_firefox-panel.txt" 2> "$web/test_firefox-panel.console" || rc=$?
if [ $rc != 0 ] || [ "$(cat "$web/test_firefox-panel.txt")" -lt 1 ]; then
  echo "test-web: Firefox did not draw the IST panel ($rc):"; cat "$web/test_firefox-panel.console"; exit 1
fi
echo "test-web: firefox-panel: fujimoto2000-ist drew $(cat "$web/test_firefox-panel.txt") canvas(es) at 1280x720 ($web/firefox.png)"
if [ -n "$zip" ]; then bash "$here/test_dist.sh" "$zip"; fi
echo "test-web: passed in $(( $(date +%s) - start )) s (native hashes = WASM hashes in Chromium and Firefox; slider changes the picture; no console error; the bundle opens from disk)"
