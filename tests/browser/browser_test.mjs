// The browser client in real headless Chromium against a real `specula serve`, driven over the Chrome
// DevTools Protocol over its --remote-debugging-pipe (no npm packages; any Node from Debian 12's 18 up).
//   node browser_test.mjs PATH/TO/specula [SCREENSHOT-DIR]
// Checks: the page shows the mirror scene (its canvas screenshot against `specula render` of the same
// camera and time, PSNR bound below), the overlay shows statistics, a scripted drag changes the view,
// a blank or stale canvas fails, and at several window sizes the statistics panel is one line inside
// the window, clear of every control, whose details open with one click (screenshots of each to look at).
import { spawn, spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { inflateSync } from 'node:zlib';

const specula = process.argv[2];
const keepDir = process.argv[3];  // optional: the screenshots are kept there
if (keepDir) mkdirSync(keepDir, { recursive: true });
const work = mkdtempSync(join(tmpdir(), 'specula-browser-'));
const kMinPsnr = 30;          // dB: the page's JPEG (quality 85) against the lossless render
const kMinChangeAfterDrag = 4; // mean absolute difference in grey levels between views before and after the drag
// Window sizes the statistics panel is laid out at: a laptop, a desktop, and narrow (the controls under the view).
const kWindowSizes = [[1000, 700], [1600, 900], [600, 800]];
let failures = 0;
const check = (description, ok, detail = '') => {
  console.log(`${ok ? 'ok' : 'FAIL'} - ${description}${detail ? `: ${detail}` : ''}`);
  if (!ok) failures++;
};

// Starts a process and resolves with it once `pattern` appears in its output.
function startAndWaitFor(command, args, pattern, timeoutMs) {
  return new Promise((resolve, reject) => {
    const child = spawn(command, args, { stdio: ['ignore', 'pipe', 'pipe'] });
    let output = '';
    const timer = setTimeout(() => reject(new Error(`${command} did not print ${pattern} in ${timeoutMs} ms:\n${output}`)), timeoutMs);
    const onData = (data) => {
      output += data;
      const match = output.match(pattern);
      if (match) { clearTimeout(timer); resolve({ child, match }); }
    };
    child.stdout.on('data', onData);
    child.stderr.on('data', onData);
    child.on('exit', (code) => { clearTimeout(timer); reject(new Error(`${command} exited ${code}:\n${output}`)); });
  });
}

// A minimal CDP client over Chromium's --remote-debugging-pipe (it reads commands from its fd 3 and
// writes replies to its fd 4, each JSON message ending in a NUL byte), with flattened target sessions.
class Cdp {
  constructor(child) {
    this.commands = child.stdio[3];
    this.nextId = 1;
    this.waiting = new Map();
    let pending = Buffer.alloc(0);
    child.stdio[4].on('data', (chunk) => {
      pending = Buffer.concat([pending, chunk]);
      for (let end = pending.indexOf(0); end >= 0; end = pending.indexOf(0)) {
        this.receive(JSON.parse(pending.subarray(0, end).toString('utf8')));
        pending = pending.subarray(end + 1);
      }
    });
  }
  receive(message) {
    const waiter = this.waiting.get(message.id);
    if (!waiter) return;
    this.waiting.delete(message.id);
    if (message.error) waiter.reject(new Error(JSON.stringify(message.error)));
    else waiter.resolve(message.result);
  }
  send(method, params = {}, sessionId = undefined) {
    const id = this.nextId++;
    this.commands.write(`${JSON.stringify({ id, method, params, sessionId })}\0`);
    return new Promise((resolve, reject) => this.waiting.set(id, { resolve, reject }));
  }
}

// PNG (8-bit RGB or RGBA, not interlaced) → { width, height, rgba }.
function decodePng(bytes) {
  let offset = 8, width = 0, height = 0, colourType = 0;
  const data = [];
  while (offset < bytes.length) {
    const length = bytes.readUInt32BE(offset);
    const type = bytes.toString('ascii', offset + 4, offset + 8);
    const body = bytes.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0); height = body.readUInt32BE(4); colourType = body[9];
      if (body[8] !== 8 || body[12] !== 0 || (colourType !== 2 && colourType !== 6)) throw new Error('unsupported PNG');
    } else if (type === 'IDAT') data.push(body);
    offset += 12 + length;
  }
  const channels = colourType === 6 ? 4 : 3;
  const raw = inflateSync(Buffer.concat(data));
  const stride = width * channels;
  const out = new Uint8Array(width * height * 4);
  let previous = new Uint8Array(stride);
  for (let y = 0; y < height; y++) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const current = new Uint8Array(stride);
    for (let i = 0; i < stride; i++) {
      const a = i >= channels ? current[i - channels] : 0, b = previous[i], c = i >= channels ? previous[i - channels] : 0;
      const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
      const predictor = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][filter];
      current[i] = (line[i] + predictor) & 255;
    }
    for (let x = 0; x < width; x++)
      for (let k = 0; k < 4; k++) out[(y * width + x) * 4 + k] = k < channels ? current[x * channels + k] : 255;
    previous = current;
  }
  return { width, height, rgba: out };
}

const grey = (img, i) => 0.299 * img.rgba[i * 4] + 0.587 * img.rgba[i * 4 + 1] + 0.114 * img.rgba[i * 4 + 2];
function psnr(a, b) {
  let sum = 0;
  for (let i = 0; i < a.width * a.height; i++)
    for (let k = 0; k < 3; k++) sum += (a.rgba[i * 4 + k] - b.rgba[i * 4 + k]) ** 2;
  const mse = sum / (a.width * a.height * 3);
  return mse === 0 ? Infinity : 10 * Math.log10((255 * 255) / mse);
}
function meanAbsoluteGreyDifference(a, b) {
  let sum = 0;
  for (let i = 0; i < a.width * a.height; i++) sum += Math.abs(grey(a, i) - grey(b, i));
  return sum / (a.width * a.height);
}
function greyDeviation(a) {
  let sum = 0, squares = 0;
  const n = a.width * a.height;
  for (let i = 0; i < n; i++) { const g = grey(a, i); sum += g; squares += g * g; }
  return Math.sqrt(Math.max(0, squares / n - (sum / n) ** 2));
}

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

let server, browser;
// Signed resume: a server started again with the same secret resumes the page's session.
const secretFile = join(work, 'resume.secret');
writeFileSync(secretFile, 'browser-test-resume-secret-0123456789abcdef\n');
try {
  ({ child: server } = await startAndWaitFor(specula, ['serve', '--port', '0', '--scene', 'checker-sphere', '--resume-secret-file', secretFile],
    /listening on 127\.0\.0\.1:(\d+)/, 120000).then((r) => { r.port = Number(r.match[1]); return r; }).then((r) => {
    globalThis.serverPort = r.port; return r;
  }));
  const port = globalThis.serverPort;
  browser = spawn('chromium', ['--headless=new', '--no-sandbox', '--disable-gpu', '--no-first-run', '--remote-debugging-pipe',
    `--user-data-dir=${join(work, 'profile')}`, '--window-size=1000,600', 'about:blank'],
  { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'] });
  let browserLog = '';
  browser.stderr.on('data', (data) => { browserLog += data; });
  const cdp = new Cdp(browser);
  const version = await Promise.race([cdp.send('Browser.getVersion'),
    sleep(60000).then(() => { throw new Error(`Chromium did not answer over its pipe in 60 s:\n${browserLog}`); })]);
  check('Chromium answers over its DevTools pipe', Boolean(version.product), version.product);
  const { targetId } = await cdp.send('Target.createTarget', { url: 'about:blank' });
  const { sessionId } = await cdp.send('Target.attachToTarget', { targetId, flatten: true });
  const page = (method, params) => cdp.send(method, params, sessionId);
  const evaluate = async (expression) =>
    (await page('Runtime.evaluate', { expression, returnByValue: true, awaitPromise: true })).result.value;
  await page('Page.enable');
  await page('Emulation.setDeviceMetricsOverride', { width: 1000, height: 600, deviceScaleFactor: 1, mobile: false });

  // Waits until the page has drawn a full-quality still frame satisfying `accept`; returns it.
  async function stillFrame(accept, timeoutMs = 60000) {
    const deadline = Date.now() + timeoutMs;
    while (Date.now() < deadline) {
      const frame = await evaluate(`(() => { const s = window.specula, c = document.getElementById('frame');
        return s && s.frame && !s.decoding && s.frame.width === c.width && s.frame.height === c.height ? s.frame : null; })()`);
      if (frame && frame.still && accept(frame)) return frame;
      await sleep(100);
    }
    throw new Error(`no matching still frame within ${timeoutMs} ms; status: ${await evaluate("document.getElementById('status').textContent")}`);
  }
  async function screenshot(name) {
    const rect = await evaluate("(() => { const r = document.getElementById('frame').getBoundingClientRect(); return { x: r.x, y: r.y, width: r.width, height: r.height }; })()");
    const { data } = await page('Page.captureScreenshot', { format: 'png', clip: { ...rect, scale: 1 } });
    const bytes = Buffer.from(data, 'base64');
    writeFileSync(join(keepDir || work, name), bytes);
    return decodePng(bytes);
  }

  // Waits until the canvas's pixels match its box after a window resize; returns its width.
  async function canvasResizedToItsBox(timeoutMs = 10000) {
    const deadline = Date.now() + timeoutMs;
    while (Date.now() < deadline) {
      const width = await evaluate(`(() => { const c = document.getElementById('frame');
        return c.width === c.clientWidth && c.height === c.clientHeight ? c.width : 0; })()`);
      if (width) return width;
      await sleep(50);
    }
    throw new Error(`the canvas did not follow the window's size within ${timeoutMs} ms`);
  }
  async function saveWholePage(name) {
    const { data } = await page('Page.captureScreenshot', { format: 'png' });
    writeFileSync(join(keepDir || work, name), Buffer.from(data, 'base64'));
  }
  async function clickAt({ x, y }) {
    await page('Input.dispatchMouseEvent', { type: 'mousePressed', x, y, button: 'left', clickCount: 1 });
    await page('Input.dispatchMouseEvent', { type: 'mouseReleased', x, y, button: 'left', clickCount: 1 });
  }
  // The statistics panel's box, its summary's, and the boxes of the controls it must stay clear of.
  const statisticsLayout = () => evaluate(`(() => {
    const box = (element) => { const r = element.getBoundingClientRect(); return { left: r.left, top: r.top, right: r.right, bottom: r.bottom }; };
    const panel = document.getElementById('overlay'), summary = panel.querySelector('summary') || panel;  // a panel without one fails below
    const named = (element) => ({ name: element.id || element.tagName, ...box(element) });
    const controls = [document.getElementById('controls'), ...document.querySelectorAll('#controls button, #controls input, #controls select')];
    const s = box(summary);
    return {
      open: panel.open, text: panel.textContent, summary: summary.textContent, panel: box(panel),
      summaryLines: Math.round(summary.getBoundingClientRect().height / parseFloat(getComputedStyle(summary).lineHeight)),
      summaryCentre: { x: (s.left + s.right) / 2, y: (s.top + s.bottom) / 2 },
      detailsHeight: panel.querySelector('.statistics')?.getBoundingClientRect().height || 0,
      scrollWidth: panel.scrollWidth, clientWidth: panel.clientWidth,
      viewport: { width: innerWidth, height: innerHeight },
      controls: controls.map(named).filter((c) => c.right > c.left && c.bottom > c.top),
    };
  })()`);
  const intersects = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
  function checkClearOfControls(when, layout) {
    const { panel, viewport } = layout;
    const overlapped = layout.controls.filter((control) => intersects(panel, control)).map((control) => control.name);
    check(`${when}: the statistics panel overlaps no control`, layout.controls.length > 10 && overlapped.length === 0,
      `${overlapped.length} of ${layout.controls.length} controls overlapped${overlapped.length ? `: ${overlapped.join(', ')}` : ''}`);
    check(`${when}: the statistics panel lies inside the window`,
      panel.left >= 0 && panel.top >= 0 && panel.right <= viewport.width && panel.bottom <= viewport.height, JSON.stringify(panel));
  }

  const eye = '2.5,1.6,4.2', target = '0,0.6,0', fov = 45, timeMs = 3000;
  await page('Page.navigate', { url: `http://127.0.0.1:${port}/?eye=${eye}&target=${target}&fov=${fov}&time=${timeMs}&paused=1` });
  const first = await stillFrame((f) => f.sceneTimeMs === timeMs && Math.abs(f.camera.eye.x - 2.5) < 1e-3);
  const canvasSize = await evaluate("[document.getElementById('frame').width, document.getElementById('frame').height]");
  check('the frame fills the canvas one to one', first.width === canvasSize[0] && first.height === canvasSize[1], `${first.width}x${first.height} vs ${canvasSize}`);
  check('the paused view is anti-aliased (its still frame ran the passes at 4 sample points)',
    (first.stages || []).some((s) => s.name === 'anti-aliasing') && await evaluate("document.getElementById('stillSamples').value") === '4',
    JSON.stringify(first.stages));
  // The settings panel is the server's schema: a control per setting, with its choices or range.
  const schemaMismatches = await evaluate(`(async () => {
    const schema = await (await fetch('settings-schema.json')).json();
    const wrong = schema.settings.filter((s) => {
      const control = document.getElementById(s.field);
      if (!control) return true;
      if (s.type === 'choice') return [...control.options].map((o) => o.textContent).join() !== s.choices.map((c) => c.name).join();
      return Number(control.min) !== s.min || Number(control.max) !== s.max;
    });
    return { count: schema.settings.length, wrong: wrong.map((s) => s.name) };
  })()`);
  check('the settings panel has a control per setting of /settings-schema.json, with its choices or range',
    schemaMismatches.count >= 20 && schemaMismatches.wrong.length === 0, JSON.stringify(schemaMismatches));
  const overlay = await evaluate("document.getElementById('overlay').textContent");
  check('the overlay shows fps, latency, server timings and search statistics',
    /fps/.test(overlay) && /input → frame/.test(overlay) && /render [\d.]+ ms/.test(overlay) && /search: 1 mirrors/.test(overlay) && /plan: 1 mirror parts \([01] ray-cast, 0 own colour, 0 environment map, 0 facing away\) · drew 1 objects/.test(overlay) && /\d+ uncovered px ray-cast/.test(overlay), overlay);
  const pressKey = async (key) => {
    await page('Input.dispatchKeyEvent', { type: 'keyDown', key, text: key });
    await page('Input.dispatchKeyEvent', { type: 'keyUp', key });
  };
  await pressKey('o');  // hide the statistics overlay: compare the frame alone
  check('the O key hides the overlay', await evaluate("document.getElementById('overlay').hidden") === true);
  // A re-encoded still shows the pixels of the frame before it.
  const ownEstimate = await stillFrame((f) => f.accuracy &&
    Number(f.accuracy.frame) === Number(f.number) - (f.reencoded ? 1 : 0), 10000)
    .catch(() => null);
  check('a still view gets the live accuracy estimate of the frame on screen', ownEstimate !== null,
    JSON.stringify(await evaluate('(({ number, reencoded, still, accuracy }) => ({ number, reencoded, still, accuracy }))(window.specula.frame)')));
  const shot = await screenshot('browser-view.png');
  check('the canvas is not blank', greyDeviation(shot) > 10, `grey deviation ${greyDeviation(shot).toFixed(1)}`);

  const reference = join(work, 'reference.png');
  const render = spawnSync(specula, ['render', '--scene', 'checker-sphere', '--size', `${first.width}x${first.height}`,
    '--eye', eye, '--target', target, '--up', '0,1,0', '--fov', String(fov), '--time', String(timeMs / 1000), '--out', reference]);
  check('specula render renders the same view', render.status === 0, render.stderr?.toString());
  const expected = decodePng(readFileSync(reference));
  const similarity = psnr(shot, expected);
  check(`the screenshot matches specula render of that camera (PSNR >= ${kMinPsnr} dB)`, similarity >= kMinPsnr, `${similarity.toFixed(1)} dB`);

  // A scripted drag across the canvas orbits the camera; the canvas must show the new view.
  const rect = await evaluate("(() => { const r = document.getElementById('frame').getBoundingClientRect(); return { x: r.x + r.width / 2, y: r.y + r.height / 2 }; })()");
  await page('Input.dispatchMouseEvent', { type: 'mousePressed', x: rect.x, y: rect.y, button: 'left', clickCount: 1 });
  for (let step = 1; step <= 10; step++) {
    await page('Input.dispatchMouseEvent', { type: 'mouseMoved', x: rect.x + 15 * step, y: rect.y + 3 * step, button: 'left', buttons: 1 });
    await sleep(30);
  }
  await page('Input.dispatchMouseEvent', { type: 'mouseReleased', x: rect.x + 150, y: rect.y + 30, button: 'left', clickCount: 1 });
  const moved = await stillFrame((f) => Number(f.number) > Number(first.number) && Math.abs(f.camera.eye.x - 2.5) > 0.1);
  const after = await screenshot('browser-after-drag.png');
  const change = meanAbsoluteGreyDifference(shot, after);
  check('a drag changes the view (the canvas is not stale)', change >= kMinChangeAfterDrag, `mean grey change ${change.toFixed(1)}, eye.x ${moved.camera.eye.x.toFixed(2)}`);
  // The explosion map from the browser's controls: the planner off (every mirror searched), the
  // maps' look-ups (at most two a vertex, none climbing) drawn where they place the triangles.
  await evaluate(`(() => {
    for (const [id, value] of [['plan', 'PLAN_EVERYTHING'], ['search', 'SEARCH_EXPLOSION_MAP'], ['virtualPixels', 'PIXELS_AS_PLACED'],
                               ['extrusions', 'EXTRUSIONS_SEARCH']]) {
      const select = document.getElementById(id);
      select.value = value;
      select.dispatchEvent(new Event('change'));
    }
  })()`);
  const mapped = await stillFrame((f) => Number(f.number) > Number(moved.number) && f.search && Number(f.search.searched) > 0 &&
    Number(f.search.maxSteps) <= 2 && Number(f.search.coldStarts || 0) === 0);
  const mappedShot = await screenshot('browser-explosion-map.png');
  check('the explosion-map controls switch the server to map look-ups', greyDeviation(mappedShot) > 10,
    `${mapped.search.searched} vertices, max ${mapped.search.maxSteps} look-ups; status: ${await evaluate("document.getElementById('status').textContent")}`);
  check('the panel shows what the server implied: a picked search runs, ray-cast never',
    await evaluate("document.getElementById('rayCast').value") === 'RAY_CAST_NEVER');
  const latency = await evaluate('window.specula.latencyMs');
  check('input-to-frame latency is measured', typeof latency === 'number' && latency > 0, String(latency));

  // The server dies and comes back (same port, same secret): the page says it is reconnecting, then
  // that it resumed, with the dragged camera and the explosion-map settings.
  const exitedServer = new Promise((resolve) => server.on('exit', resolve));
  server.kill('SIGKILL');
  await exitedServer;
  let reconnecting = '';
  for (let i = 0; i < 50 && !/Reconnecting \(attempt 1 of 10\)/.test(reconnecting); i++) {
    reconnecting = await evaluate("document.getElementById('status').textContent");
    await sleep(50);
  }
  const { data: wholePage } = await page('Page.captureScreenshot', { format: 'png' });
  writeFileSync(join(keepDir || work, 'browser-reconnecting.png'), Buffer.from(wholePage, 'base64'));  // to look at
  check('when the server is gone the page says it is reconnecting', /Reconnecting \(attempt 1 of 10\) in .* to resume this view/.test(reconnecting), reconnecting);
  ({ child: server } = await startAndWaitFor(specula, ['serve', '--port', String(port), '--scene', 'checker-sphere', '--resume-secret-file', secretFile],
    /listening on 127\.0\.0\.1:(\d+)/, 120000));
  let resumed = null;
  for (let i = 0; i < 300 && !resumed; i++) {
    resumed = await evaluate("(() => { const s = window.specula; return s.reconnects >= 1 && s.welcome && s.welcome.resumed ? { welcome: s.welcome, status: document.getElementById('status').textContent } : null; })()");
    if (!resumed) await sleep(100);
  }
  check('the page reconnects and resumes its session on the restarted server', resumed !== null &&
    /camera, animation and settings restored/.test(resumed.status), JSON.stringify(resumed?.status));
  check('with the camera and settings it had', resumed !== null && Math.abs(resumed.welcome.camera.eye.x - moved.camera.eye.x) < 1e-3 &&
    resumed.welcome.settings.search === 'SEARCH_EXPLOSION_MAP' && resumed.welcome.settings.plan === 'PLAN_EVERYTHING',
    JSON.stringify(resumed?.welcome.camera.eye));

  await pressKey('o');
  check('the O key shows the overlay again', await evaluate("document.getElementById('overlay').hidden") === false);
  for (const [width, height] of kWindowSizes) {
    const size = `${width}x${height}`;
    await page('Emulation.setDeviceMetricsOverride', { width, height, deviceScaleFactor: 1, mobile: false });
    const canvasWidth = await canvasResizedToItsBox();
    await stillFrame((f) => f.width === canvasWidth);
    const closed = await statisticsLayout();
    await saveWholePage(`browser-statistics-${size}-closed.png`);
    check(`${size}: the statistics panel is closed, a one-line summary of fps, render time, size and plan`,
      !closed.open && closed.summaryLines === 1 &&
      /^\d+ fps · render [\d.]+ ms · mirror error [\d.]+ % \(≤ [\d.]+ %\) · \d+×\d+ · \d+ /.test(closed.summary),
      `${closed.summaryLines} lines: ${closed.summary}`);
    checkClearOfControls(`${size}, closed`, closed);
    await clickAt(closed.summaryCentre);
    const opened = await statisticsLayout();
    await saveWholePage(`browser-statistics-${size}-open.png`);
    check(`${size}: one click on the summary opens the details`, opened.open && opened.detailsHeight > 0 &&
      /plan: \d+ mirror parts/.test(opened.text), `open ${opened.open}, details ${opened.detailsHeight} px high`);
    check(`${size}: the details state the live accuracy estimate and plot it against render time`,
      /accuracy: frame \d+: [\d.]+ % of 256 mirror px wrong \(95 %: [\d.]+ % to [\d.]+ %\)/.test(opened.text) &&
      await evaluate("!!document.querySelector('#overlay .accuracy-plot')"), opened.text);
    check(`${size}: the open details fit the panel's width (no sideways scrolling)`, opened.scrollWidth <= opened.clientWidth,
      `content ${opened.scrollWidth} px wide in ${opened.clientWidth} px`);
    checkClearOfControls(`${size}, open`, opened);
    await clickAt(opened.summaryCentre);
    check(`${size}: a second click closes them`, !(await statisticsLayout()).open);
  }
  // Without a search no mirror part is planned: the summary names the method instead.
  const lastFrame = await evaluate('window.specula.frame.number');
  await evaluate(`(() => { const method = document.getElementById('method');
    method.value = 'NONE'; method.dispatchEvent(new Event('change')); })()`);
  await stillFrame((f) => Number(f.number) > Number(lastFrame) && (f.plan || []).length === 0);
  const unsearched = await evaluate("document.querySelector('#overlay summary').textContent");
  check('with reflections off the summary says so', / · none \(/.test(unsearched), unsearched);
} catch (error) {
  check('browser test ran', false, error.stack || String(error));
} finally {
  const exited = (child) => child && child.exitCode === null ? new Promise((resolve) => child.on('exit', resolve)) : null;
  const gone = [exited(browser), exited(server)];
  browser?.kill('SIGKILL');
  server?.kill('SIGTERM');
  await Promise.all(gone);
  rmSync(work, { recursive: true, force: true });
}
console.log(failures === 0 ? 'all browser checks passed' : `${failures} browser checks failed`);
process.exit(failures === 0 ? 0 : 1);
