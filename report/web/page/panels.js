  // page/panels.js: the stage list, legends, the matrices (KaTeX), the trace table; showRest shows a stage at rest.
  // ---- Panels -------------------------------------------------------------------
  const list = document.getElementById('stage-list');
  function buildPanels() {
    legend(document.getElementById('legend'), data.legend);
    legend(document.getElementById('projected-legend'), data.projected.legend);
    vertices = floatsOf(data.vertices);
  }
  // A panel built from `from` by `build`, unless it shows that already (an edit that leaves a panel as it was
  // would have the page lay it out again): what each element was built from, and its first and last nodes then.
  const builtFrom = new WeakMap();
  function buildOnce(element, from, build) {
    const key = JSON.stringify(from), built = builtFrom.get(element);
    if (built && built.key === key && built.first === element.firstChild && built.last === element.lastChild && built.first) return;
    build();
    builtFrom.set(element, { key, first: element.firstChild, last: element.lastChild });
  }
  function legend(element, entries) {
    buildOnce(element, entries, () => {
      element.textContent = '';
      for (const entry of entries) {
        const row = document.createElement('div');
        const swatch = document.createElement('i');
        if (entry.swatch === 'line') swatch.style.borderBottom = `3px solid ${cssColor(entry.color, entry.opacity)}`;
        else if (entry.swatch === 'dot') Object.assign(swatch.style, { width: '0.7em', borderRadius: '50%', background: cssColor(entry.color) });
        else swatch.style.background = cssColor(entry.color, Math.max(0.35, entry.opacity));
        const text = document.createElement('span');
        setRichText(text, entry.text);
        row.append(swatch, text);
        if (entry.canonical) row.dataset.canonical = '1';
        element.appendChild(row);
      }
      element.hidden = entries.length === 0;
    });
  }

  function typeset(element, latex) {
    buildOnce(element, latex, () => {
      try {
        katex.render(latex, element, { displayMode: true, throwOnError: true });
      } catch (error) {
        element.textContent = latex;
      }
    });
  }
  // The stages' names, left out while a question is open (a name may be its answer).
  function showStageList() {
    if (asking()) return void (list.textContent = '');
    buildOnce(list, stages.map((stage) => stage.list), () => {
      list.textContent = '';
      stages.forEach((stage, k) => {
        const item = document.createElement('li');
        setRichText(item, stage.list);
        item.tabIndex = -1;
        item.addEventListener('click', () => goTo(k, false));
        list.appendChild(item);
      });
    });
  }
  // The traced vertex after each stage, as the core writes it for the app's Matrices panel: the core's table
  // ({rows, verdict, spoken}), or null.
  function showTrace() {
    const element = document.getElementById('trace');
    if (asking()) return void (element.textContent = ''); // the trace follows the answer (its verdict may be it)
    if (!state.traced) {
      buildOnce(element, null, () => {
        element.innerHTML = '<p>Click a vertex of an object (or press T) to trace it through the stages.</p>';
      });
      return null;
    }
    element.textContent = coreFailed || (!core ? "The trace is computed by ViewPipe's core, which is loading." : '');
    if (!core) return null;
    // In a lesson, rows up to the stage shown: a later row may be a later question's answer.
    const outcome = core.traceTable(data.scene, JSON.stringify(state.traced), lesson ? state.stage : last);
    if (outcome.error) {
      element.textContent = outcome.error;
      return null;
    }
    const traced = JSON.parse(outcome.text);
    const table = document.createElement('table');
    table.innerHTML = '<caption>The traced vertex after each stage</caption><tr><th>stage</th><th>x</th><th>y</th><th>z</th><th>w</th></tr>';
    traced.rows.forEach((entry, k) => {
      const row = table.insertRow();
      for (const text of [entry.stage, ...entry.cells]) setRichText(row.insertCell(), text);
      if (k === state.stage) row.style.fontWeight = 'bold';
    });
    const verdict = document.createElement('p');
    setRichText(verdict, traced.verdict);
    element.replaceChildren(table, verdict);
    return traced;
  }
  // Each view's accessible name: the stage and what the view shows; no stage while a question is open (a name may
  // be its answer). The overlays' labels are the same picture's: left out of the names' tree.
  function nameViews() {
    const stage = asking() ? 'the stage this step asks about' : `stage ${stages[state.stage].listText}`;
    worldCanvas.setAttribute('aria-label', `World view, ${stage}: the scene drawn with this stage's matrices`);
    projectedCanvas.setAttribute('aria-label', `What the camera sees, beside ${stage}: the objects in the camera's window` +
                                 (data.projected.vanishing.length ? ', with their vanishing lines' : ''));
  }
  function showPanels() {
    const stage = stages[state.stage];
    body.dataset.stage = state.stage;
    showStageList();
    nameViews();
    if (asking()) { // the matrices, their names and the trace would give the answer away
      for (const id of ['matrix-title', 'symbolic', 'matrix', 'cumulative', 'trace'])
        document.getElementById(id).textContent = '';
      return;
    }
    list.querySelectorAll('li').forEach((item, k) => {
      if (k === state.stage) item.setAttribute('aria-current', 'step');
      else item.removeAttribute('aria-current');
    });
    const title = document.getElementById('matrix-title');
    buildOnce(title, stage.list, () => setRichText(title, stage.list));
    if (state.stage === 0) {
      document.getElementById('matrix').textContent = 'The world: no matrix yet.';
      document.getElementById('symbolic').textContent = '';
      document.getElementById('cumulative').textContent = '';
    } else {
      const symbolic = document.getElementById('symbolic');
      buildOnce(symbolic, stage.symbolic || null, () => {
        symbolic.textContent = '';
        if (!stage.symbolic) return;
        const matrix = document.createElement('div');
        matrix.className = 'symbolic';
        typeset(matrix, stage.symbolic.latex);
        symbolic.appendChild(matrix);
        for (const note of stage.symbolic.notes) {
          const line = document.createElement('p');
          line.className = 'definition';
          setRichText(line, note);
          symbolic.appendChild(line);
        }
      });
      // A lesson step's own form of its stage's matrix: the entries it highlights marked.
      const step = lesson && lesson.steps[state.step];
      const own = step && step.latex && step.latexStage === state.stage && step.scene === shownScene;
      typeset(document.getElementById('matrix'), own ? step.latex : stage.latex);
      typeset(document.getElementById('cumulative'), stage.cumulativeLatex);
    }
    showTrace();
    document.getElementById('live').textContent =
      `Stage ${state.stage} of ${last}: ${stage.listText}.` + (stage.claim ? ' ' + stage.claimText + '.' : '');
  }

  function showRest(k) {
    const stage = stageAt(k);
    shown = { frame: stage.rest, atRest: true, ghost: stage.ghost };
    drawShown();
  }

