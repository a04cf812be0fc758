// ports/web/tests/bidi.js — drives Debian's headless Firefox ESR over WebDriver BiDi (the
// protocol Firefox serves on --remote-debugging-port), with node's standard library alone
// (node 20's WebSocket behind --experimental-websocket; no npm, no geckodriver).
//
//   node --experimental-websocket ports/web/tests/bidi.js URL --wait 'JS expression'
//        [--timeout S] [--screenshot F.png] [--size WxH] [--eval 'JS expression']
//
// The same contract as cdp.js (Chromium): opens URL, polls --wait until truthy, prints --eval,
// writes the screenshot (the viewport, WxH), prints the page's console messages and uncaught
// errors on stderr prefixed "console:". Exit 0 when the wait succeeded and nothing was logged
// at level error; 3 on a console error; 4 on time-out; 1 on any other failure.
// `firefox-esr --headless --screenshot` alone cannot check the page: it shoots at the load
// event, before the Web Worker has computed anything.
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { parseArgs, waitAndReport } = require('./driver_common.js');

// Starts Firefox on a free port (0: Firefox picks one and names it on stderr).
function startFirefox(profile, width, height) {
  return new Promise((resolve, reject) => {
    const browser = spawn(process.env.FIREFOX || 'firefox-esr',
      ['--headless', '--no-remote', '--profile', profile, '--remote-debugging-port=0',
       '--width=' + width, '--height=' + height, 'about:blank'],
      { stdio: ['ignore', 'ignore', 'pipe'] });
    let text = '';
    const timer = setTimeout(() => reject(new Error('Firefox did not announce its BiDi port: ' + text)), 60000);
    browser.stderr.on('data', (d) => {
      text += d.toString();
      const m = /WebDriver BiDi listening on (ws:\/\/\S+)/.exec(text);
      if (m) { clearTimeout(timer); resolve({ browser, url: m[1].replace(/\/$/, '') + '/session' }); }
    });
    browser.on('exit', (code) => reject(new Error('Firefox exited (' + code + '): ' + text)));
  });
}

async function main() {
  const o = parseArgs(process.argv.slice(2), 'bidi.js', '1280x720');
  const [width, height] = o.size.split('x').map(Number);
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'sk-firefox-'));
  let browser = null, errors = 0;
  const finish = (code) => {
    if (browser) browser.kill('SIGKILL');
    try { fs.rmSync(profile, { recursive: true, force: true }); } catch (e) { /* best effort */ }
    process.exit(code);
  };
  try {
    const started = await startFirefox(profile, width, height);
    browser = started.browser;
    const ws = new WebSocket(started.url);
    await new Promise((resolve, reject) => { ws.onopen = resolve; ws.onerror = () => reject(new Error('BiDi connection failed')); });
    let nextId = 1;
    const pending = new Map();
    ws.onmessage = (e) => {
      const msg = JSON.parse(e.data);
      if (msg.id && pending.has(msg.id)) {
        const p = pending.get(msg.id);
        pending.delete(msg.id);
        if (msg.type === 'error') p.reject(new Error(p.method + ': ' + msg.error + ': ' + msg.message));
        else p.resolve(msg.result);
      } else if (msg.method === 'log.entryAdded') {
        const level = msg.params.level, text = msg.params.text;
        process.stderr.write('console: ' + level + ': ' + text + '\n');
        if (level === 'error') ++errors;
      }
    };
    const send = (method, params = {}) => new Promise((resolve, reject) => {
      const id = nextId++;
      pending.set(id, { resolve, reject, method });
      ws.send(JSON.stringify({ id, method, params }));
    });
    await send('session.new', { capabilities: {} });
    await send('session.subscribe', { events: ['log.entryAdded'] });
    const tree = await send('browsingContext.getTree', {});
    const context = tree.contexts[0].context;
    await send('browsingContext.setViewport', { context, viewport: { width, height } });
    await send('browsingContext.navigate', { context, url: o.url, wait: 'complete' });
    const evaluate = async (expr) => {
      const r = await send('script.evaluate', { expression: expr, target: { context }, awaitPromise: false });
      if (r.type !== 'success') return undefined;
      return r.result.value;
    };
    return finish(await waitAndReport('bidi', o, {
      evaluate,
      screenshot: async () => (await send('browsingContext.captureScreenshot', { context })).data,
      errors: () => errors,
    }));
  } catch (e) {
    process.stderr.write('bidi: ' + e.message + '\n');
    return finish(1);
  }
}
main();
