// ports/web/tests/cdp.js — drives Debian's headless Chromium over the DevTools protocol on a
// pipe (--remote-debugging-pipe), with node's standard library alone (no npm).
//
//   node ports/web/tests/cdp.js URL --wait 'JS expression' [--timeout S] [--screenshot F.png]
//        [--size WxH] [--eval 'JS expression']
//
// Opens URL, polls the --wait expression (evaluated in the page) until it is truthy, then
// prints the value of --eval (default: the --wait value) on stdout, writes the screenshot,
// and prints every console message, uncaught exception and log entry of the page on stderr
// prefixed "console:". Exit status: 0 when the wait succeeded and nothing was logged at
// level error; 3 on a console error or exception; 4 on time-out; 1 on any other failure.
// Real time throughout (no virtual time): a Web Worker's work is waited for, and
// performance.now() measures real milliseconds.
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { parseArgs, waitAndReport } = require('./driver_common.js');

async function main() {
  const o = parseArgs(process.argv.slice(2), 'cdp.js', '1280x900');
  const [width, height] = o.size.split('x').map(Number);
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'sk-chromium-'));
  const browser = spawn(process.env.CHROMIUM || 'chromium',
    ['--headless', '--no-sandbox', '--remote-debugging-pipe', '--disable-gpu',
     '--user-data-dir=' + profile, '--window-size=' + width + ',' + height, 'about:blank'],
    { stdio: ['ignore', 'ignore', 'ignore', 'pipe', 'pipe'] });
  const toBrowser = browser.stdio[3], fromBrowser = browser.stdio[4];
  let nextId = 1, buffered = '', errors = 0;
  const pending = new Map();
  const send = (method, params = {}, sessionId) => new Promise((resolve, reject) => {
    const id = nextId++;
    pending.set(id, { resolve, reject, method });
    const msg = { id, method, params };
    if (sessionId) msg.sessionId = sessionId;
    toBrowser.write(JSON.stringify(msg) + '\0');
  });
  const log = (level, text) => {
    process.stderr.write('console: ' + level + ': ' + text + '\n');
    if (level === 'error' || level === 'exception') ++errors;
  };
  fromBrowser.on('data', (chunk) => {
    buffered += chunk.toString('utf8');
    let end;
    while ((end = buffered.indexOf('\0')) >= 0) {
      const msg = JSON.parse(buffered.slice(0, end));
      buffered = buffered.slice(end + 1);
      if (msg.id && pending.has(msg.id)) {
        const p = pending.get(msg.id);
        pending.delete(msg.id);
        if (msg.error) p.reject(new Error(p.method + ': ' + msg.error.message));
        else p.resolve(msg.result);
      } else if (msg.method === 'Runtime.consoleAPICalled') {
        const text = msg.params.args.map((a) => a.value !== undefined ? String(a.value) : (a.description || a.type)).join(' ');
        log(msg.params.type === 'error' ? 'error' : msg.params.type, text);
      } else if (msg.method === 'Runtime.exceptionThrown') {
        const d = msg.params.exceptionDetails;
        log('exception', (d.exception && d.exception.description) || d.text);
      } else if (msg.method === 'Log.entryAdded') {
        log(msg.params.entry.level, msg.params.entry.text + ' ' + (msg.params.entry.url || ''));
      }
    }
  });
  const finish = (code) => {
    browser.kill('SIGKILL');
    try { fs.rmSync(profile, { recursive: true, force: true }); } catch (e) { /* best effort */ }
    process.exit(code);
  };
  try {
    const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
    const { sessionId } = await send('Target.attachToTarget', { targetId, flatten: true });
    await send('Runtime.enable', {}, sessionId);
    await send('Log.enable', {}, sessionId);
    await send('Page.enable', {}, sessionId);
    await send('Emulation.setDeviceMetricsOverride',
      { width, height, deviceScaleFactor: 1, mobile: false }, sessionId);
    await send('Page.navigate', { url: o.url }, sessionId);
    const evaluate = async (expr) => {
      const r = await send('Runtime.evaluate', { expression: expr, returnByValue: true }, sessionId);
      if (r.exceptionDetails) return undefined;
      return r.result.value;
    };
    return finish(await waitAndReport('cdp', o, {
      evaluate,
      screenshot: async () => (await send('Page.captureScreenshot', { format: 'png' }, sessionId)).data,
      errors: () => errors,
    }));
  } catch (e) {
    process.stderr.write('cdp: ' + e.message + '\n');
    return finish(1);
  }
}
main();
