  // page/core.js: what the page asks of the core (WebAssembly): a scene evaluated, its mesh files, text measured for it.
  // ---- The core, compiled to WebAssembly ------------------------------------------
  let core = null; // once loaded
  // The scene's numbers as the CLI prints them (`viewpipe pipeline SCENE --json`), or why the core refuses the scene.
  function showOutcome(outcome) {
    if (!outcome.error && !lesson) { // a lesson's later answers are among its numbers
      setText(document.getElementById('json-left-out'), data.filesLeftOut);
      setText(document.getElementById('pipeline-json'), outcome.pipeline);
    }
    const error = document.getElementById('scene-error');
    setText(error, outcome.error);
    setHidden(error, !outcome.error);
  }
  // The meshes a scene names, into the core's file system under their names.
  function putFiles(files) {
    for (const [path, bytes] of Object.entries(files)) {
      const outcome = core.putFile(path, new Uint8Array(bytesOf(bytes)));
      if (outcome.error) return outcome;
    }
    return { text: '', error: '' };
  }
  function evaluateScene() {
    if (!core) return;
    let outcome = putFiles(data.files);
    if (!outcome.error && !data.filesLeftOut) outcome = core.pipelineJson(data.scene);
    showOutcome({ pipeline: outcome.text, error: outcome.error });
    return outcome.text;
  }

  // Text as the page draws it (drawRuns), measured: the core places labels and lays out captions with this.
  const measuring = document.createElement('canvas').getContext('2d');
  const measured = new Map(); // the same labels come back at every stage and every edit: set a font once
  function measureRuns(runs, px, bold) {
    const key = `${px} ${bold} ${JSON.stringify(runs)}`;
    if (!measured.has(key)) {
      if (measured.size > 10000) measured.clear(); // a long session's edits each bring new numbers
      const weight = bold ? 'bold ' : '';
      measuring.font = weight + fontOf(px);
      const line = measuring.measureText('Ág');
      measured.set(key, [runsWidth(measuring, runs, px, weight), line.fontBoundingBoxAscent + line.fontBoundingBoxDescent]);
    }
    return measured.get(key);
  }

  // The scene evaluated anew by the core: what the page draws and the JSON view; or why the core refuses it.
  // The page's picture as the core lays it out, with what the reader leaves out and where the legend goes.
  const viewOptions = () => ({ width: data.width, height: data.height, fontSize: data.fontSize, minFontSize: data.minFontSize,
                               lineScale: data.lineScale, framing: data.framing, dark: data.dark,
                               hidden: state.hidden, legend: state.legend, zoom: madeWith.zoom });
  // Only the stage shown is made at rest; the others and each step's frames are asked for when shown.
  function evaluateText(text, files, filesLeftOut) {
    const outcome = core.evaluate(text, JSON.stringify(viewOptions()), measureRuns, Math.max(0, state.stage));
    if (outcome.error) return { error: outcome.error };
    const page = Object.assign(JSON.parse(outcome.page), { scene: text, files, filesLeftOut });
    return { page, pipeline: outcome.pipeline, error: '' };
  }
  // Stage k at rest ({rest, ghost, layout, labels} besides its names and matrices) and the step from stage k to
  // the next, as the core made them, asked for when first shown after an edit and kept until the next.
  function stageAt(k) {
    const stage = stages[k];
    if (!stage.rest) Object.assign(stage, JSON.parse(core.stageView(data.scene, JSON.stringify(viewOptions()), k, measureRuns).text));
    return stage;
  }
  function transitionFrames(k) {
    if (!data.transitions[k] && coreDraws()) {
      const outcome = core.transition(data.scene, JSON.stringify(viewOptions()), k, measureRuns);
      data.transitions[k] = outcome.error ? null : JSON.parse(outcome.text);
    }
    return data.transitions[k] || null;
  }
