  // page/editing.js: the Scene panel: its fields, the core's refusals beside them, the scenes kept for undo and redo.
  // ---- Editing the scene ------------------------------------------------------------
  // The view's or the camera's fields, each a text field holding what was typed; every edit is evaluated by the
  // core, which refuses what it cannot use with the field's path and the reason (the last valid picture stays).
  const fields = document.getElementById('scene-fields');
  // The scenes shown, for undo and redo: each with its meshes ({page, pipeline}, as the core evaluated it). Only
  // the scene shown and those the core cannot evaluate again (meshes left out) keep their pages; the others
  // keep their text and files and are evaluated anew when shown.
  const edits = { entries: [], at: -1, gesture: null };
  const kEditsKept = 100;
  let pendingLink = null; // the link's scene until the core has read it
  const originalScene = data.scene; // the page's own: a link holds any other
  const edited = () => data.scene !== originalScene;

  const pathText = (path) =>
    path.reduce((text, part) => typeof part === 'number' ? `${text}[${part}]` : (text ? `${text}.${part}` : part), '');
  // A field's row: its name, its inputs (added by the caller) and its refusal.
  function fieldRow(path, name) {
    const row = document.createElement('div');
    row.className = 'field';
    row.dataset.path = pathText(path);
    const label = document.createElement('label');
    label.textContent = name;
    row.appendChild(label);
    const refusal = document.createElement('p');
    refusal.className = 'field-error';
    refusal.id = `refusal-${row.dataset.path}`;
    refusal.hidden = true;
    row.appendChild(refusal);
    return row;
  }
  let fieldsShape = ''; // the rows built (paths, kinds, choices): an edit that keeps them sets their values in place
  let fieldChoices = new Map(); // each choice's field: the core's choice for the scene shown
  const fieldText = (value) => typeof value === 'string' ? value : JSON.stringify(value);
  function buildFields() {
    const scene = JSON.parse(data.scene);
    const root = scene.camera ? 'camera' : 'view';
    // The settings picked from a list (the API, the projection's type, ...), as the core lists them: a choice
    // is the scene with the core's change (switching glFrustum to gluPerspective rewrites its numbers).
    const choices = core ? JSON.parse(core.cameraChoices(data.scene).text || '[]') : [];
    fieldChoices = new Map(choices.map((choice) => [choice.field, choice]));
    const chosen = new Set(choices.map((choice) => choice.field));
    // The numbers typed as exact expressions ("20*sqrt(2)"), text in the scene's JSON, as the core read them.
    const typed = core ? JSON.parse(core.typedExpressions(data.scene).text || '{}') : {};
    const isNumber = (value, path) => typeof value === 'number' || pathText(path) in typed;
    const numbers = (value, path) => Array.isArray(value) && value.every((v, k) => isNumber(v, [...path, k]));
    const group = (value, path) => value !== null && typeof value === 'object' && !numbers(value, path);
    const items = (value, path) => numbers(value, path) ? value.map((v, k) => [v, [...path, k]]) : [[value, path]];
    const kindOf = (item, path) => isNumber(item, path) ? 'number' : typeof item;
    // Each row's path and its inputs' kinds: the same rows (a number dragged, a field edited) are kept and their
    // values set, so that the page lays out again only what changed.
    const shapeOf = (value, path) => chosen.has(pathText(path)) ? null : group(value, path)
      ? Object.entries(value).map(([key, inner]) => [key, shapeOf(inner, [...path, Array.isArray(value) ? Number(key) : key])])
      : items(value, path).map(([item, itemPath]) => [kindOf(item, itemPath), typeof item]);
    const shape = JSON.stringify([root, choices.map((choice) => [choice.field, choice.title, choice.options]),
                                  shapeOf(scene[root], [root])]);
    if (shape === fieldsShape) {
      for (const choice of choices)
        fields.querySelector(`select[data-path='${JSON.stringify(choice.field.split('.'))}']`).selectedIndex = choice.chosen;
      for (const input of fields.querySelectorAll('input')) {
        const text = fieldText(JSON.parse(input.dataset.path).reduce((value, part) => value[part], scene));
        if (input.value !== text || input.defaultValue !== text) input.value = input.defaultValue = text;
      }
      return;
    }
    fieldsShape = shape;
    fields.textContent = '';
    for (const choice of choices) {
      const path = choice.field.split('.');
      const row = fieldRow(path, choice.title);
      const select = document.createElement('select');
      choice.options.forEach((option, k) => select.add(new Option(option, k)));
      select.selectedIndex = choice.chosen;
      select.dataset.path = JSON.stringify(path);
      select.id = `field-${row.dataset.path}`;
      row.querySelector('label').htmlFor = select.id;
      select.addEventListener('change', () => {
        const outcome = core.withCameraChoice(data.scene, choice.field, select.selectedIndex);
        if (outcome.error) {
          clearRefusals();
          select.selectedIndex = fieldChoices.get(choice.field).chosen; // the camera's own, kept
          showRefusal(outcome.error, select);
          showEdits();
        } else {
          changeScene(outcome.text, select);
        }
      });
      row.insertBefore(select, row.querySelector('.field-error'));
      fields.appendChild(row);
    }
    // One row per number, list of numbers or text; objects as groups.
    const add = (parent, value, path) => {
      if (chosen.has(pathText(path))) return;
      if (group(value, path)) {
        const set = document.createElement('fieldset');
        const title = document.createElement('legend');
        title.textContent = path[path.length - 1];
        set.appendChild(title);
        for (const [key, inner] of Object.entries(value)) add(set, inner, [...path, Array.isArray(value) ? Number(key) : key]);
        parent.appendChild(set);
        return;
      }
      const row = fieldRow(path, path[path.length - 1]);
      const label = row.querySelector('label');
      const refusal = row.querySelector('.field-error');
      for (const [item, itemPath] of items(value, path)) {
        const input = document.createElement('input');
        input.type = 'text';
        input.spellcheck = false;
        input.autocomplete = 'off';
        if (typeof item === 'number') input.inputMode = 'decimal';
        input.value = input.defaultValue = fieldText(item);
        input.dataset.path = JSON.stringify(itemPath);
        input.dataset.kind = kindOf(item, itemPath);
        input.setAttribute('aria-label', pathText(itemPath));
        input.addEventListener('change', () => editField(input));
        if (!label.htmlFor) {
          input.id = `field-${row.dataset.path}`;
          label.htmlFor = input.id;
        }
        row.insertBefore(input, refusal);
      }
      parent.appendChild(row);
    };
    add(fields, scene[root], [root]);
  }

  // A field's edit: the scene with the text typed put in by the core (in a number's field a decimal is that
  // number, other text goes as text for the core to read, such as 20*sqrt(2) or √2/2, which the scene keeps as
  // typed, or to refuse), the scene evaluated.
  function editField(input) {
    if (!core) return;
    const outcome = core.withTypedField(data.scene, pathText(JSON.parse(input.dataset.path)), input.value,
                                        input.dataset.kind === 'number');
    if (outcome.error) {
      clearRefusals();
      showRefusal(outcome.error, input);
      showEdits();
      return;
    }
    changeScene(outcome.text, input);
  }

  function clearRefusals() {
    setHidden(document.getElementById('editor-error'), true);
    fields.querySelectorAll('.field').forEach((row) => {
      setHidden(row.querySelector('.field-error'), true);
      row.querySelectorAll('input, select').forEach((input) => {
        input.removeAttribute('aria-invalid');
        input.removeAttribute('aria-describedby');
      });
    });
  }
  // The refusal beside the field it names: the field its path falls in, else the first field under it.
  function showRefusal(error, input) {
    const path = error.slice(0, Math.max(0, error.indexOf(': ')));
    const rows = [...fields.querySelectorAll('.field')];
    const within = (inner, outer) => inner === outer || inner.startsWith(outer + '.') || inner.startsWith(outer + '[');
    const row = rows.find((r) => within(path, r.dataset.path)) || rows.find((r) => path && within(r.dataset.path, path)) ||
                (input && input.closest('.field'));
    if (!row) { // not a field's (a mesh, the scene's objects): under the buttons
      const general = document.getElementById('editor-error');
      general.textContent = error;
      general.hidden = false;
      return;
    }
    // Beside the field it names and, where another was edited (B typed, F named), beside that one too.
    const edited = input && input.closest('.field');
    for (const shown of edited && edited !== row ? [row, edited] : [row]) {
      const refusal = shown.querySelector('.field-error');
      refusal.textContent = error;
      refusal.hidden = false;
      for (const field of shown.querySelectorAll('input, select')) {
        field.setAttribute('aria-invalid', 'true');
        field.setAttribute('aria-describedby', refusal.id);
      }
    }
  }

  // A scene's text, evaluated: shown and kept for undo when the core takes it, else refused beside its field
  // with the last valid picture kept. `files`: the meshes it may name, if not the scene's shown. Whether it was taken.
  // `gesture`: edits of one drag, kept as one undoable edit.
  function changeScene(text, input, files, gesture) {
    if (!core) return false;
    clearRefusals();
    if (!files && data.filesLeftOut) { // the core cannot read meshes the page does not hold
      showRefusal("This page left the scene's meshes out: open the scene with its meshes to change it here.", null);
      showEdits();
      return false;
    }
    const outcome = evaluateText(text, files || data.files, files ? '' : data.filesLeftOut);
    if (outcome.error) {
      showOutcome(outcome);
      showRefusal(outcome.error, input);
      showEdits();
      return false;
    }
    const entry = { page: outcome.page, pipeline: outcome.pipeline, text, files: outcome.page.files };
    if (gesture && gesture === edits.gesture) edits.entries[edits.at] = entry; // the same drag: one edit
    else edits.entries.splice(edits.at + 1, Infinity, entry);
    edits.gesture = gesture || null;
    if (edits.entries.length > kEditsKept) edits.entries.shift();
    edits.at = edits.entries.length - 1;
    showEntry(edits.entries[edits.at], input);
    return true;
  }
  // A scene of the history shown at the stage shown (or `stage`), evaluated anew if it kept no page.
  function showEntry(entry, input, stage = state.stage) {
    if (!entry.page) {
      putFiles(entry.files); // its meshes, for it and the edits that follow
      const outcome = evaluateText(entry.text, entry.files, '');
      Object.assign(entry, { page: outcome.page, pipeline: outcome.pipeline });
    }
    for (const other of edits.entries)
      if (other !== entry && other.page && !other.page.filesLeftOut) other.page = null;
    clearRefusals();
    const index = shownScene;
    page.scenes[index] = entry.page;
    setText(document.getElementById('title'), entry.page.title);
    document.title = `${entry.page.title} · ViewPipe`;
    shownScene = -1;
    useScene(index, true);
    showOutcome({ pipeline: entry.pipeline, error: '' });
    const focused = input && input === document.activeElement ? input.dataset.path : null;
    buildFields();
    if (focused) fields.querySelector(`input[data-path='${focused}'], select[data-path='${focused}']`)?.focus();
    showCode();
    showEdits();
    state.stage = -1;
    goTo(Math.min(stage, last), false);
    drawProjected();
  }
  function undo() {
    // A refused value is undone first, alone: the fields show the scene shown again.
    if (refused()) {
      clearRefusals();
      buildFields();
      showOutcome({ error: '', pipeline: document.getElementById('pipeline-json').textContent });
      showEdits();
      return;
    }
    if (edits.at <= 0) return;
    edits.at -= 1;
    edits.gesture = null;
    showEntry(edits.entries[edits.at], null);
  }
  function redo() {
    if (edits.at >= edits.entries.length - 1) return;
    edits.at += 1;
    edits.gesture = null;
    showEntry(edits.entries[edits.at], null);
  }
  const refused = () => !!fields.querySelector('[aria-invalid]') || !document.getElementById('editor-error').hidden;
  function showEdits() {
    document.getElementById('undo').disabled = edits.at <= 0 && !refused();
    document.getElementById('redo').disabled = edits.at >= edits.entries.length - 1;
    setText(document.getElementById('link-note'), Object.keys(data.files).length || data.filesLeftOut
      ? 'This scene names mesh files, too large for a link: save it instead.' : '');
  }
  document.getElementById('undo').addEventListener('click', undo);
  document.getElementById('redo').addEventListener('click', redo);
  document.addEventListener('keydown', (event) => {
    if (!(event.ctrlKey || event.metaKey) || event.altKey || lesson) return;
    const key = event.key.toLowerCase();
    // Text typed and not yet applied is the field's own to undo, as in any text field.
    if (event.target instanceof HTMLInputElement && event.target.value !== event.target.defaultValue) return;
    if (event.target instanceof HTMLTextAreaElement) return;
    if (key === 'z' && !event.shiftKey) undo();
    else if (key === 'y' || (key === 'z' && event.shiftKey)) redo();
    else return;
    event.preventDefault();
  });
