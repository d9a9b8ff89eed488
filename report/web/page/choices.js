  // page/choices.js: what is drawn: the reader's toggles of what is left out, the legend's place and the zoom, as export's --hide, --legend and --zoom.
  // ---- What is drawn ------------------------------------------------------------------
  // The names and places are the core's (the page's data lists them); the core draws the scene without what
  // is left out (withoutHidden, as the app and the CLI), so each choice is the scene evaluated anew.
  const leaveOut = document.getElementById('leave-out');
  const legendPlace = document.getElementById('legend-place');
  const zoomField = document.getElementById('zoom');
  const drawnNote = document.getElementById('drawn-note');
  function buildChoices() {
    leaveOut.querySelectorAll('label').forEach((label) => label.remove());
    for (const { name, title } of data.hideChoices) {
      const label = document.createElement('label');
      const box = document.createElement('input');
      box.type = 'checkbox';
      box.value = name;
      box.addEventListener('change', () => choose({
        hidden: box.checked ? [...state.hidden, name].sort() : state.hidden.filter((hidden) => hidden !== name) }));
      label.append(box, ` ${title}`);
      leaveOut.appendChild(label);
    }
    legendPlace.textContent = '';
    for (const { name, title } of data.legendChoices) legendPlace.add(new Option(title, name));
    [zoomField.min, zoomField.max] = data.viewLimits.zoom;
    showChoices();
  }
  legendPlace.addEventListener('change', () => choose({ legend: legendPlace.value }));
  zoomField.addEventListener('change', () => {
    const zoom = Number(zoomField.value);
    if (zoomField.value && Number.isFinite(zoom)) changeView({ zoom });
    showChoices(); // within the core's limits
  });
  // The controls as the state has them (a link opened, the wheel turned).
  function showChoices() {
    leaveOut.querySelectorAll('input').forEach((box) => { box.checked = state.hidden.includes(box.value); });
    legendPlace.value = state.legend;
    if (document.activeElement !== zoomField) zoomField.value = String(Number(state.zoom.toFixed(3)));
  }
  const choicesKey = () => JSON.stringify([state.hidden, state.legend]);
  const defaultChoices = JSON.stringify([madeWith.hidden, madeWith.legend]);
  function choose(change) {
    Object.assign(state, change);
    writeFragment();
    drawChoices();
  }
  // The scene shown evaluated anew with the choices made, at the stage shown, the traced vertex kept.
  function drawChoices() {
    showChoices();
    drawnNote.textContent = coreDraws() ? '' : coreFailed || (data.filesLeftOut
      ? "What is drawn is chosen by ViewPipe's core, which needs the scene's meshes: this page was saved without them."
      : "What is drawn is chosen by ViewPipe's core, which is still loading.");
    if (!coreDraws()) return;
    const entry = edits.entries[edits.at];
    const outcome = evaluateText(data.scene, data.files, data.filesLeftOut);
    if (outcome.error) return void (drawnNote.textContent = outcome.error);
    Object.assign(entry, { page: outcome.page, pipeline: outcome.pipeline });
    const traced = state.traced;
    turned = { key: '', labels: null }; // placed for the scene as drawn before, the same text
    showEntry(entry);
    if (traced) setTraced(traced);
  }
  buildChoices();
