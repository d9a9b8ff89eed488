// The core compiled to WebAssembly (web/, what the page runs) gives what the
// CLI gives: `viewpipe pipeline SCENE --json` for every scene in data/scenes,
// every key and text alike and every number within a few ulp (Eigen sums some
// products in another order without SIMD: docs/numerics.md), and for refused
// scenes and meshes the same "field.path: reason" the CLI prints after "FILE: ".
// Usage: node core_module_test.js VIEWPIPE_EXE MODULE_JS DATA_DIR
'use strict';
const assert = require('assert');
const { spawnSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [viewpipe, modulePath, dataDir] = process.argv.slice(2);
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'viewpipe-core-module-'));
let failures = 0;

function check(name, body) {
  try {
    body();
    console.log(`ok ${name}`);
  } catch (error) {
    failures += 1;
    console.log(`FAILED ${name}\n${error.message}`);
  }
}

// Equal texts, or where they part, with a little of each around it.
function sameText(got, expected) {
  if (got === expected) return;
  let at = 0;
  while (at < got.length && got[at] === expected[at]) at += 1;
  const around = (text) => JSON.stringify(text.slice(Math.max(0, at - 60), at + 60));
  assert.fail(`the texts part at character ${at}:\n  module ${around(got)}\n  CLI    ${around(expected)}`);
}

const kUlps = 4;
// Units in the last place between two doubles.
function ulpsApart(a, b) {
  const bits = new BigInt64Array(new Float64Array([a, b]).buffer);
  const ordered = (x) => (x < 0n ? -(x & 0x7fffffffffffffffn) : x);
  const d = ordered(bits[0]) - ordered(bits[1]);
  return Number(d < 0n ? -d : d);
}

// The CLI's JSON and the module's: the same keys, texts and structure, numbers
// within kUlps; returns how many numbers differ at all.
// A depth resolution's step is where the stored depth next changes, found by
// bisection: an ulp in the distance can move it to the neighbouring stored
// value, a relative 2^-24 for 32-bit depth.
const kStepShare = 1e-6;
function sameJson(got, expected, where = '$') {
  if (typeof expected === 'number') {
    assert.strictEqual(typeof got, 'number', `${where}: not a number`);
    const apart = ulpsApart(got, expected);
    const bisected = /\.depth\.resolution\.\d+\.step$/.test(where);
    const near = bisected ? Math.abs(got - expected) <= kStepShare * Math.abs(expected) : apart <= kUlps;
    assert.ok(near, `${where}: ${got} against the CLI's ${expected} (${apart} ulp)`);
    return apart > 0 ? 1 : 0;
  }
  if (expected === null || typeof expected !== 'object') {
    assert.strictEqual(got, expected, where);
    return 0;
  }
  assert.strictEqual(Array.isArray(got), Array.isArray(expected), where);
  assert.deepStrictEqual(Object.keys(got), Object.keys(expected), where);
  return Object.keys(expected).reduce((n, key) => n + sameJson(got[key], expected[key], `${where}.${key}`), 0);
}

function cli(scene) {
  const run = spawnSync(viewpipe, ['pipeline', scene, '--json'], { encoding: 'utf8' });
  return { status: run.status, stdout: run.stdout, stderr: run.stderr };
}

function scenesUnder(dir) {
  return fs.readdirSync(dir, { withFileTypes: true }).flatMap((entry) => {
    const file = path.join(dir, entry.name);
    return entry.isDirectory() ? scenesUnder(file) : file.endsWith('.json') ? [file] : [];
  });
}

// A scene beside its files, for the CLI; the same files given to the module.
function writeScene(name, scene, files = {}) {
  const dir = path.join(work, name);
  fs.mkdirSync(dir, { recursive: true });
  for (const [file, bytes] of Object.entries(files)) fs.writeFileSync(path.join(dir, file), bytes);
  const text = typeof scene === 'string' ? scene : JSON.stringify(scene, null, 2);
  fs.writeFileSync(path.join(dir, 'scene.json'), text);
  return { file: path.join(dir, 'scene.json'), text, files };
}

const house = JSON.parse(fs.readFileSync(path.join(dataDir, 'scenes', 'house.json'), 'utf8'));
const triangle = 'v 0 0 30\nv 16 0 30\nv 8 16 30\nf 1 2 3\n';

require(path.resolve(modulePath))().then((core) => {
  function pipeline(scene) {
    for (const [file, bytes] of Object.entries(scene.files || {})) {
      const put = core.putFile(file, Buffer.from(bytes));
      if (put.error) return put;
    }
    return core.pipelineJson(scene.text);
  }

  for (const file of scenesUnder(path.join(dataDir, 'scenes'))) {
    check(`the pipeline of ${path.relative(dataDir, file)}`, () => {
      const expected = cli(file);
      assert.strictEqual(expected.status, 0, expected.stderr);
      const text = fs.readFileSync(file, 'utf8');
      const files = {}; // its meshes, where the scene names them, as the page puts the files opened with it
      for (const object of JSON.parse(text).objects || [])
        if (object.type === 'mesh') files[object.path] = fs.readFileSync(path.resolve(path.dirname(file), object.path));
      const got = pipeline({ text, files });
      assert.strictEqual(got.error, '');
      if (got.text + '\n' === expected.stdout) return;
      const differing = sameJson(JSON.parse(got.text), JSON.parse(expected.stdout));
      console.log(`   ${differing} numbers an ulp or a few apart`);
    });
  }

  const withMesh = { ...house, objects: [{ type: 'mesh', path: 'meshes/triangle.obj' }], effects: ['cull'] };
  fs.mkdirSync(path.join(work, 'mesh', 'meshes'), { recursive: true });
  const truncatedPly = 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n' +
                       'property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\x00\x00';
  const cases = {
    'a mesh and an effect that reads it': writeScene('mesh', withMesh, { 'meshes/triangle.obj': triangle }),
    'malformed JSON': writeScene('malformed', '{"camera": '),
    'a wrong type': writeScene('type', { ...house, objects: 3 }),
    'a degenerate view': writeScene('vup', { ...house, view: { ...house.view, vup: house.view.vpn } }),
    'exact expressions (issue 46)': writeScene('exact', { ...house, view: { ...house.view, prp: ['20*sqrt(2)', '\u221A2', 84] } }),
    'a bad expression': writeScene('bad-exact', { ...house, view: { ...house.view, prp: [8, 6, '1/0'] } }),
    'a truncated PLY': writeScene('ply', { ...house, objects: [{ type: 'mesh', path: 'bad.ply' }] },
                                  { 'bad.ply': Buffer.from(truncatedPly, 'binary') }),
  };
  for (const [name, scene] of Object.entries(cases)) {
    check(name, () => {
      const expected = cli(scene.file);
      const got = pipeline(scene);
      if (expected.status === 0) {
        assert.strictEqual(got.error, '');
        sameText(got.text + '\n', expected.stdout);
      } else {
        assert.strictEqual(expected.status, 2, expected.stderr);
        // "FILE: field.path: reason", or "FILE:LINE:COLUMN: reason" for a syntax error.
        assert.ok(expected.stderr.startsWith(scene.file + ':'), expected.stderr);
        const after = expected.stderr.slice(scene.file.length + 1).replace(/^ /, '');
        assert.strictEqual(got.text, '');
        sameText(got.error + '\n', after);
      }
    });
  }

  // Answers checked as the app checks them (lesson.cpp's isRight and typedNumber): entry (1, 3) of the
  // house's SH_per is -2/21 (Foley's shear, -dop_x / dop_z, with the house's PRP (8, 6, 84) and window centre (0, 0):
  // -dop_x / dop_z = -8/84), right within 0.5 %.
  const entry = JSON.stringify({ kind: 'entry', prompt: 'p', stage: 4, row: 1, column: 3 });
  const checked = (typed) => core.checkAnswer(JSON.stringify(house), entry, JSON.stringify({ entry: typed }));
  for (const [typed, right] of [['-2/21', true], ['\u22122/21', true], ['-0.0952', true], ['-0.0947', false], ['2/21', false]]) {
    check(`the entry ${typed} is ${right ? 'right' : 'wrong'}`, () => {
      const outcome = checked(typed);
      assert.strictEqual(outcome.error, '');
      assert.deepStrictEqual(JSON.parse(outcome.text).right, right);
    });
  }
  check('text that is not a number is refused with its reason, not wrong', () => {
    assert.strictEqual(checked('about -0.1').error, 'entry: expected a number, sqrt(...) or ( at character 1 of "about -0.1"');
    assert.strictEqual(checked('2 +* 3').error, 'entry: expected a number, sqrt(...) or ( at character 4 of "2 +* 3"');
    assert.strictEqual(checked(' ').error, 'entry: is empty: type a number (a decimal, a fraction p/q, a root with sqrt(\u2026) or \u221a)');
  });
  // The house from its corner (VPN (1, 0, 1)): R's entry (1, 1) is sqrt(2)/2 and SH_per's (2, 3) is -13/36,
  // decided exactly; a decimal typed still counts within 0.5 %.
  const corner = fs.readFileSync(path.join(dataDir, 'scenes', 'house-corner.json'), 'utf8');
  const checkedAt = (stage, row, column, typed) => core.checkAnswer(corner,
    JSON.stringify({ kind: 'entry', prompt: 'p', stage, row, column }), JSON.stringify({ entry: typed }));
  for (const [stage, row, column, typed, right] of [[2, 1, 1, 'sqrt(2)/2', true], [2, 1, 1, '\u221a2/2', true],
    [2, 1, 1, '1/\u221a2', true], [2, 1, 1, '0.7071', true], [2, 1, 1, 'sqrt(3)/2', false],
    [4, 2, 3, '-13/36', true], [4, 2, 3, '-13/35', false]]) {
    check(`house-corner's entry (${row}, ${column}) of stage ${stage}: ${typed} is ${right ? 'right' : 'wrong'}`, () => {
      const outcome = checkedAt(stage, row, column, typed);
      assert.strictEqual(outcome.error, '');
      assert.strictEqual(JSON.parse(outcome.text).right, right);
    });
  }
  check('answers of the wrong type or out of range are refused by name', () => {
    const order = JSON.stringify({ kind: 'order', prompt: 'p' });
    const choice = JSON.stringify({ kind: 'choice', prompt: 'p', choices: ['a', 'b'], answer: 1 });
    const refused = (question, typed) => core.checkAnswer(JSON.stringify(house), question, JSON.stringify(typed)).error;
    assert.strictEqual(refused(choice, { choice: 'b' }), 'answer.choice: must be a whole number from 0 to 1');
    assert.strictEqual(refused(choice, { choice: 1.7 }), 'answer.choice: must be a whole number from 0 to 1');
    assert.strictEqual(refused(order, { order: [0, 0, 1, 2, 3] }), 'answer.order: must list each of the 5 stages once');
    assert.strictEqual(refused(order, { order: [0, 1, 2, 3, 9] }), 'answer.order: must be a whole number from 0 to 4');
    assert.strictEqual(JSON.parse(core.checkAnswer(JSON.stringify(house), order, JSON.stringify({ order: [0, 1, 2, 3, 4] })).text).right, true);
  });
  check('a point within the tolerance', () => {
    const where = JSON.stringify({ kind: 'where', prompt: 'p', point: [8, 6, 84], after: 3 });
    const outcome = core.checkAnswer(JSON.stringify(house), where, JSON.stringify({ where: ['0', '0.005', '0'] }));
    assert.deepStrictEqual(JSON.parse(outcome.text), { right: true, answer: [0, 0.005, 0] });
  });
  check('the results file as the app writes it: each typed answer beside its value, one shown unanswered', () => {
    const where = JSON.stringify({ kind: 'where', prompt: 'p', point: [8, 6, 84], after: 3 });
    const step = (question, given, tries, closed) => ({ scene: JSON.stringify(house), question, given, tries, closed });
    const outcome = core.lessonResults('t', JSON.stringify([
      step(entry, { entry: '-2/21' }, 1, true), null, step(where, { where: ['1/3', '0', '-1'] }, 1, false),
      step(where, null, 0, true), step(where, null, 0, false)]));
    assert.strictEqual(outcome.error, '');
    assert.deepStrictEqual(JSON.parse(outcome.text), { lesson: 't', answers: [
      { step: 1, kind: 'entry', answer: -2 / 21, typed: '-2/21', correct: true, tries: 1 },
      { step: 3, kind: 'where', answer: [1 / 3, 0, -1], typed: ['1/3', '0', '-1'], correct: false, tries: 1 },
      { step: 4, kind: 'where', answer: null, correct: false, revealed: true }] });
  });

  // The trace table as the app's Matrices panel writes it (report::traceTable), the page's: the house's
  // corner (0, 0, 54) after T(-PRP) is (-8, -6, -30), exact; a coordinate that does not read exactly in five
  // digits with a minus sign. The scene's meshes need not be at hand (a page may leave them out).
  check('the trace table, as the app writes it', () => {
    const scene = JSON.stringify({ ...house, objects: [{ type: 'mesh', path: 'not-here.obj' }] });
    const table = JSON.parse(core.traceTable(scene, JSON.stringify([0, 0, 54]), 5).text);
    assert.strictEqual(table.rows.length, 6);
    assert.deepStrictEqual(table.rows[3], { stage: '$T(-\\mathit{PRP})$', cells: ['$-8$', '$-6$', '$-30$', '$1$'] });
    assert.match(table.verdict, /^After the divide: \(.*\); inside the canonical volume\.$/);
    assert.strictEqual(table.spoken, '(0, 0, 54)');
    const third = JSON.parse(core.traceTable(scene, JSON.stringify([-1 / 3, 0, 54]), 3).text);
    assert.strictEqual(third.rows.length, 4);
    assert.deepStrictEqual(third.rows[3].cells, ['\u22128.3333', '$-6$', '$-30$', '$1$']);
    assert.strictEqual(third.verdict, '');
  });

  // A field typed into the page's Scene panel, put into the scene by the core (withTypedField, as scene_test checks
  // it natively): a decimal in a number's field is that number, other text stays text.
  check('a field typed, as the core puts it in', () => {
    const text = JSON.stringify(house);
    const typed = (path, value, number) => core.withTypedField(text, path, value, number);
    assert.deepStrictEqual(JSON.parse(typed('view.prp[0]', '+20.', true).text).view.prp, [20, 6, 84]);
    assert.deepStrictEqual(JSON.parse(typed('view.prp[1]', '1e3', true).text).view.prp, [8, 1000, 84]);
    assert.deepStrictEqual(JSON.parse(typed('view.prp[1]', '20*sqrt(2)', true).text).view.prp, [8, '20*sqrt(2)', 84]);
    assert.strictEqual(typed('view.nothing', '1', true).error, 'view.nothing: is not a field of the scene');
  });

  // The page's fields that hold an exact expression, by the core's field path; none for a scene of numbers.
  check('the expressions typed, by field path', () => {
    const typed = (view) => core.typedExpressions(JSON.stringify({ ...house, view: { ...house.view, ...view } }));
    assert.deepStrictEqual(JSON.parse(typed({ prp: ['20*sqrt(2)', '\u221A2', 84], front: '60' }).text),
                           { 'view.front': '60', 'view.prp[0]': '20*sqrt(2)', 'view.prp[1]': '\u221A2' });
    assert.deepStrictEqual(JSON.parse(typed({}).text), {});
    assert.strictEqual(typed({ prp: [8, 6, 'sqrt(-1)'] }).error,
                       'view.prp[2]: the square root of -1, a negative number, at character 1 of "sqrt(-1)"');
  });

  // An edit's page makes the stage shown only and leaves the steps out; asked for when shown, the others and
  // the steps are what an evaluation at that stage gives (natively, what the export writes: export_layout_tests).
  check("an edit's page leaves the other stages and the steps to be asked for, the same", () => {
    const text = JSON.stringify(house);
    const options = JSON.stringify({ width: 1280, height: 720, fontSize: 20, minFontSize: 20, lineScale: 1,
                                     framing: 'together', dark: false });
    const measure = (runs, px) => [0.6 * px * runs.reduce((n, run) => n + Buffer.byteLength(run[0]), 0), px];
    const atStage = (k) => JSON.parse(core.evaluate(text, options, measure, k).page);
    const atRest = ({ rest, ghost, layout, labels }) => ({ rest, ghost, layout, labels });
    const first = atStage(0);
    assert.ok(first.stages.length > 3);
    assert.ok(first.stages[0].labels.length > 0);
    for (let k = 1; k < first.stages.length; ++k) {
      assert.deepStrictEqual(atRest(first.stages[k]), atRest({}), `stage ${k} left out`);
      assert.ok(first.stages[k].frame && first.stages[k].latex, `stage ${k}'s frame and matrix kept`);
      assert.strictEqual(first.transitions[k - 1], null, `step ${k}`);
      const view = JSON.parse(core.stageView(text, options, k, measure).text);
      assert.ok(view.labels.length > 0);
      assert.deepStrictEqual(atRest(view), atRest(atStage(k).stages[k]), `stage ${k}`);
      const frames = JSON.parse(core.transition(text, options, k - 1, measure).text);
      assert.strictEqual(frames.length, 30);
      const end = frames[frames.length - 1].view, rest = view.rest.view;
      const size = Math.max(...rest.map(Math.abs));
      rest.forEach((v, c) => assert.ok(Math.abs(end[c] - v) <= 1e-12 * size, `step ${k} ends at rest: ${end} against ${rest}`));
    }
    assert.match(core.stageView(text, options, first.stages.length, measure).error, /no stage/);
    assert.match(core.transition(text, options, first.stages.length - 1, measure).error, /no step/);
  });

  fs.rmSync(work, { recursive: true, force: true });
  process.exit(failures ? 1 : 0);
});
