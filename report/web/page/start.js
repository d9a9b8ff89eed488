  // page/start.js: window.viewpipe for scripts and the browser tests; then the start: the link read, the scene or lesson shown.
  // For scripts (and the browser tests): where a world point is drawn now, in client pixels.
  window.viewpipe = {
    pixelOf(point) {
      const size = sizeOf(worldCanvas);
      const { view, projection } = cameraMatrices(shown.frame, size);
      const at = project(projection.multiply(view).multiply(matrixOf(shown.frame.shown)), point, size);
      const rect = worldCanvas.getBoundingClientRect();
      return at && { x: rect.left + at.x, y: rect.top + at.y };
    },
    // How many primitives the page draws: the core's display list, without what the reader leaves out.
    primitives: () => data.primitives.length,
    // The labels the core places for the view as the user has turned it (export pixels), and the stage's at rest.
    turnedLabels: () => labelsTurned(),
    restLabels: () => stageAt(state.stage).labels,
  };

  readFragment();
  const first = { stage: state.stage, step: state.step };
  state.stage = -1;
  if (lesson) {
    buildLesson();
    shownScene = -1;
    goToStep(first.step, true);
  } else {
    useScene(0);
    showLayout();
    goTo(first.stage);
  }
  body.dataset.ready = '1';
