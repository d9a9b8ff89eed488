  // page/window-events.js: a link pasted into the page open (hashchange), the window resized.
  // A link pasted into the page open: its scene (if the core has it) and its moment.
  window.addEventListener('hashchange', () => {
    const before = { stage: state.stage, step: state.step }, drawnBefore = choicesKey();
    readFragment();
    showLayout();
    const wanted = { stage: state.stage, step: state.step };
    Object.assign(state, before);
    if (lesson) goToStep(wanted.step, true);
    else if (!(core && openLink())) {
      if (choicesKey() !== drawnBefore) drawChoices();
      goTo(wanted.stage);
    }
  });
  window.addEventListener('resize', () => { drawShown(); drawProjected(); });

