  // page/core-loading.js: the core loaded (or why not): the scene evaluated, the Scene and Code panels built.
  let coreFailed = ''; // why the core did not load, if it did not
  ViewPipeCore().catch((error) => {
    coreFailed = `ViewPipe's core could not start in this browser (${error && error.message ? error.message : error}): ` +
      'the stages are shown at rest, neither turned nor zoomed, and nothing can be changed or checked.';
    const shown = document.getElementById('scene-error');
    shown.textContent = coreFailed;
    shown.hidden = false;
    return null;
  }).then((module) => {
    if (!module) return;
    core = module;
    const pipeline = evaluateScene();
    if (!lesson) {
      for (const dialect of JSON.parse(core.codeDialects()))
        dialectPicker.add(new Option(dialect.title, dialect.name));
      // With the camera's choices, which the core lists; a field being typed in keeps its text and focus.
      const typing = fields.contains(document.activeElement) ? document.activeElement : null;
      const text = typing && typing.value; // buildFields may set the same field in place
      buildFields();
      if (typing) {
        const again = fields.querySelector(`[data-path='${typing.dataset.path}']:not(.field)`);
        if (again) { again.value = text; again.focus(); }
      }
      showCode();
      edits.entries = [{ page: data, pipeline, text: data.scene, files: data.files }];
      edits.at = 0;
      if (!openLink() && choicesKey() !== defaultChoices) drawChoices(); // a link's choices: the core draws them
      showEdits();
      if (filesBeforeCore) openFiles(filesBeforeCore);
    }
    body.dataset.core = '1';
    if (state.traced) showPanels(); // the trace, which the core writes
    drawShown(); // the storyboard, which the core draws; the world view, which it turns as the reader asks
  });

