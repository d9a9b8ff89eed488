// The page's speed: what an edit asks of the core, natively against
// WebAssembly (Node, and Chromium where the page runs it), and in headless Chromium (SwiftShader) the first picture
// after loading, an edit of one field evaluated and redrawn, the view moved and
// a number of the camera's code dragged (opengl-perspective: the house's Foley
// view has no code). Side by side
// in one run; results in docs/performance.md. Run from the source folder,
// after building, under Xvfb (the export draws the page's stages):
//   xvfb-run -a node --experimental-websocket bench/page_bench.mjs build
import { spawn, spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

const build = resolve(process.argv[2] || 'build');
const house = resolve('data/scenes/house.json');
const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
const sleep = (ms) => new Promise((done) => setTimeout(done, ms));

// Natively: Google Benchmark's median.
const native = spawnSync(join(build, 'bench/page_bench'), ['--benchmark_format=json', '--benchmark_repetitions=5',
                                                            '--benchmark_report_aggregates_only=true'], { encoding: 'utf8' });
if (native.status !== 0) throw new Error('page_bench failed: ' + native.stderr);
const nativeMs = JSON.parse(native.stdout).benchmarks.find((b) => b.aggregate_name === 'median').real_time;

// WebAssembly in Node: the same work through the module's evaluate, text measured as page_bench.cpp measures it.
const ViewPipeCore = createRequire(import.meta.url)(join(build, 'web/viewpipe-core.js'));
const core = await ViewPipeCore();
const sceneText = readFileSync(house, 'utf8');
const options = JSON.stringify({ width: 1280, height: 720, fontSize: 20, minFontSize: 20, lineScale: 1, framing: 'together', dark: false });
const fixedWidth = (runs, px) => [0.6 * px * runs.reduce((n, run) => n + new TextEncoder().encode(run[0]).length, 0), px];
const wasm = [];
for (let k = 0; k < 23; ++k) {
  const start = performance.now();
  const outcome = core.evaluate(sceneText, options, fixedWidth, 0);
  if (outcome.error) throw new Error(outcome.error);
  if (k >= 3) wasm.push(performance.now() - start);
}
const wasmMs = median(wasm);

// Chromium: the exported page, loaded and edited.
const folder = mkdtempSync(join(tmpdir(), 'viewpipe-page-bench-'));
for (const [scene, out] of [[house, folder], [resolve('data/scenes/opengl-perspective.json'), join(folder, 'code')]]) {
  const exported = spawnSync(join(build, 'bin/viewpipe'), ['export', scene, '--format', 'html', '--out', out, '--quiet']);
  if (exported.status !== 0) throw new Error('export failed: ' + exported.stderr);
}
const port = 9300 + Math.floor(Math.random() * 500);
const chrome = spawn('chromium', ['--headless', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
                                  '--window-size=1280,720', `--remote-debugging-port=${port}`,
                                  `--user-data-dir=${join(folder, 'profile')}`, 'about:blank'], { stdio: 'ignore' });
let targets = null;
for (let k = 0; k < 100 && !targets; ++k) {
  try { targets = await (await fetch(`http://127.0.0.1:${port}/json`)).json(); } catch { await sleep(100); }
}
const socket = new WebSocket(targets.find((t) => t.type === 'page').webSocketDebuggerUrl);
await new Promise((done) => { socket.onopen = done; });
let id = 0;
const pending = new Map();
socket.onmessage = (event) => {
  const message = JSON.parse(event.data);
  if (pending.has(message.id)) { pending.get(message.id)(message.result); pending.delete(message.id); }
};
const send = (method, params = {}) => new Promise((done) => { pending.set(++id, done); socket.send(JSON.stringify({ id, method, params })); });
const evaluate = async (expression) =>
  (await send('Runtime.evaluate', { expression, returnByValue: true, awaitPromise: true })).result.value;

const loads = [], edits = [], turns = [], drags = [];
for (let run = 0; run < 5; ++run) {
  await send('Page.navigate', { url: 'file://' + join(folder, 'scene.html') });
  let ready = 0; // milliseconds from the navigation's start to the first picture (polled every 10 ms)
  while (!ready) {
    ready = await evaluate("document.body && document.body.dataset.ready === '1' ? performance.now() : 0");
    if (!ready) await sleep(10);
  }
  loads.push(ready);
  while (!(await evaluate("document.body.dataset.core === '1'"))) await sleep(10);
  // One field edited, evaluated by the core and drawn (until the next frame); the first two edits of a load
  // are left out, while the browser still compiles the module's hot code.
  edits.push(...await evaluate(`(async () => {
    const times = [];
    for (let k = 0; k < 12; ++k) {
      const field = document.querySelector("input[aria-label='view.prp[0]']");
      field.value = String(8 + (k % 2) * 12);
      const start = performance.now();
      field.dispatchEvent(new Event('change'));
      await new Promise((done) => requestAnimationFrame(() => done()));
      times.push(performance.now() - start);
    }
    return times.slice(2);
  })()`));
  // The view moved by a wheel step (zoomed out, a new camera each step; turning asks the same): the core places
  // the labels anew for the moved camera and the picture is drawn (until the next frame). Each step's labels must
  // differ from the last step's, or the core was not asked.
  turns.push(...await evaluate(`(async () => {
    const times = [];
    const world = document.getElementById('world');
    let before = JSON.stringify(window.viewpipe.turnedLabels());
    for (let k = 0; k < 12; ++k) {
      const start = performance.now();
      world.dispatchEvent(new WheelEvent('wheel', { deltaY: 1, bubbles: true, cancelable: true }));
      await new Promise((done) => requestAnimationFrame(() => done()));
      times.push(performance.now() - start);
      const now = JSON.stringify(window.viewpipe.turnedLabels());
      if (now === before || now === 'null') throw new Error('the labels were not placed anew at wheel step ' + k);
      before = now;
    }
    return times.slice(2);
  })()`));
}
// The same work through the same module in Chromium, where the page runs it (its V8 is not Node's): a module of
// the page's own, the first round left out while the browser compiles its hot code.
const wasmInChromium = [];
for (let round = 0; round < 3; ++round) {
  const times = await evaluate(`(async () => {
    const core = await ViewPipeCore();
    const measure = ${fixedWidth.toString()};
    const times = [];
    for (let k = 0; k < 20; ++k) {
      const start = performance.now();
      const outcome = core.evaluate(${JSON.stringify(sceneText)}, ${JSON.stringify(options)}, measure, 0);
      if (outcome.error) throw new Error(outcome.error);
      times.push(performance.now() - start);
    }
    return times;
  })()`);
  if (round > 0) wasmInChromium.push(...times);
}
// A number of the camera's code dragged (a real mouse, as CDP gives it), 4 pixels a move: from the move to the
// frame after the scene's edit drew it.
for (let run = 0; run < 5; ++run) {
  await send('Page.navigate', { url: 'file://' + join(folder, 'code', 'scene.html') });
  while (!(await evaluate("document.body && document.body.dataset.core === '1'"))) await sleep(10);
  const [x, y] = await evaluate(`(() => {
    document.getElementById('code-editor').open = true;
    const fovy = document.querySelector("#camera-code [aria-label^='fovy']");
    fovy.scrollIntoView({ block: 'center' });
    const r = fovy.getBoundingClientRect();
    return [r.x + r.width / 2, r.y + r.height / 2];
  })()`);
  await send('Input.dispatchMouseEvent', { type: 'mousePressed', x, y, button: 'left', clickCount: 1 });
  for (let k = 1; k <= 12; ++k) {
    await evaluate(`(() => {
      window.benchJson = document.getElementById('pipeline-json').textContent;
      window.benchMoved = null;
      document.getElementById('camera-code').addEventListener('pointermove', () => { window.benchMoved ??= performance.now(); },
                                                              { capture: true, once: true });
    })()`);
    await send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: x + 4 * k, y, button: 'left', buttons: 1 });
    // Until the first frame whose callbacks find the edit made (as move_view waits for the frame after its
    // change): the page's own, ahead of this one, may make it in that frame.
    const ms = await evaluate(`new Promise((done) => {
      const poll = () => requestAnimationFrame(() => {
        if (document.getElementById('pipeline-json').textContent !== window.benchJson) done(performance.now() - window.benchMoved);
        else poll();
      });
      poll();
    })`);
    if (k > 2) drags.push(ms);
  }
  await send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: x + 48, y, button: 'left', clickCount: 1 });
}
socket.close();
const exited = new Promise((done) => chrome.once('exit', done));
chrome.kill();
await exited;
rmSync(folder, { recursive: true, force: true, maxRetries: 5 });

const row = (name, ms, ratio) => console.log(`| ${name} | ${ms.toFixed(1)} ms | ${ratio} |`);
console.log('| run | median | ratio |');
console.log('|---|---|---|');
row('PageEvaluate/native/house', nativeMs, '1');
row('PageEvaluate/wasm/house (Node)', wasmMs, `**${(wasmMs / nativeMs).toFixed(1)}×** native`);
row('PageEvaluate/wasm/house (Chromium)', median(wasmInChromium), `**${(median(wasmInChromium) / nativeMs).toFixed(1)}×** native`);
row('Page/chromium/first_picture', median(loads), `${(median(loads) / 2000).toFixed(2)} of the 2 s allowed`);
row('Page/chromium/edit_one_field', median(edits),
    `${(median(edits) / 100).toFixed(2)} of the 100 ms allowed; **${(median(edits) / median(turns)).toFixed(2)}×** move_view`);
row('Page/chromium/move_view', median(turns), `${(median(turns) / (1000 / 60)).toFixed(1)} frames at 60 Hz`);
row('Page/chromium/drag_code_number', median(drags), `**${(median(drags) / median(turns)).toFixed(2)}×** move_view`);
