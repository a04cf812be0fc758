#!/usr/bin/env bash
# ports/web/tests/screenshots.sh WEB_DIR OUT_DIR — every panel of the explorer at 1280x720 in
# headless Chromium (OUT_DIR/<panel>.png), and the IST panel in Firefox ESR
# (OUT_DIR/firefox-fujimoto2000-ist.png), for a person to look at (make web-screenshots).
set -euo pipefail
web=${1:?usage: screenshots.sh WEB_DIR OUT_DIR}
out=${2:?usage: screenshots.sh WEB_DIR OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
page="file://$(cd "$web" && pwd)/index.html"
mkdir -p "$out"
panels=$(grep -ho "\bid: '[a-z0-9-]*'" "$here"/../page/panels/*.js | sed "s/id: '\(.*\)'/\1/")
for p in $panels; do
  node "$here/cdp.js" "$page#$p" --timeout 120 --size 1280x720 --wait "document.body.dataset.ready === '$p'" \
    --screenshot "$out/$p.png" > /dev/null 2> "$out/$p.console" || { echo "screenshots: $p failed:"; cat "$out/$p.console"; exit 1; }
  echo "screenshots: $out/$p.png"
done
node --experimental-websocket --no-warnings "$here/bidi.js" "$page#fujimoto2000-ist" --timeout 120 --size 1280x720 \
  --wait "document.body.dataset.ready === 'fujimoto2000-ist'" --screenshot "$out/firefox-fujimoto2000-ist.png" > /dev/null
echo "screenshots: $out/firefox-fujimoto2000-ist.png (Firefox ESR)"
