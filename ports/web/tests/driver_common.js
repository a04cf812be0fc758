// ports/web/tests/driver_common.js — what cdp.js (Chromium) and bidi.js (Firefox) share: the
// command line, and the run once the page is loading (wait for an expression, print a value,
// take the screenshot, choose the exit status). Each driver supplies the protocol:
//
//   const o = parseArgs(process.argv.slice(2), 'cdp.js', '1280x900');
//   const code = await waitAndReport('cdp', o, { evaluate, screenshot, errors });
//
// evaluate(expr) resolves to the expression's value in the page (undefined if it threw),
// screenshot() to the viewport as base64 PNG, errors() to the count of console errors and
// uncaught exceptions so far. Exit status: 0 when the wait succeeded and nothing was logged at
// level error; 3 on a console error or exception; 4 on time-out.
'use strict';
const fs = require('fs');

function parseArgs(argv, name, size) {
  const o = { url: null, wait: 'true', timeout: 120, screenshot: null, size, evaluate: null };
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    if (a === '--wait') o.wait = argv[++i];
    else if (a === '--timeout') o.timeout = Number(argv[++i]);
    else if (a === '--screenshot') o.screenshot = argv[++i];
    else if (a === '--size') o.size = argv[++i];
    else if (a === '--eval') o.evaluate = argv[++i];
    else if (!o.url) o.url = a;
    else throw new Error('unexpected argument ' + a);
  }
  if (!o.url) throw new Error('usage: ' + name + ' URL [--wait EXPR] [--eval EXPR] [--timeout S] [--screenshot F] [--size WxH]');
  return o;
}

async function waitAndReport(name, o, page) {
  const deadline = Date.now() + o.timeout * 1000;
  let value;
  for (;;) {
    value = await page.evaluate(o.wait);
    if (value) break;
    if (page.errors()) {  // an uncaught exception or console error: no point waiting longer
      process.stderr.write(name + ': the page logged an error; stopped waiting for: ' + o.wait + '\n');
      return 3;
    }
    if (Date.now() > deadline) {
      process.stderr.write(name + ': timed out after ' + o.timeout + ' s waiting for: ' + o.wait + '\n');
      const body = await page.evaluate('document.body ? document.body.innerText.slice(0, 2000) : ""');
      process.stderr.write(name + ': page text: ' + body + '\n');
      return 4;
    }
    await new Promise((r) => setTimeout(r, 100));
  }
  if (o.evaluate) value = await page.evaluate(o.evaluate);
  process.stdout.write((typeof value === 'string' ? value : JSON.stringify(value)) + '\n');
  if (o.screenshot) fs.writeFileSync(o.screenshot, Buffer.from(await page.screenshot(), 'base64'));
  await new Promise((r) => setTimeout(r, 200));  // late console messages
  return page.errors() ? 3 : 0;
}

module.exports = { parseArgs, waitAndReport };
