  // page/start.js: window.viewpipe for scripts and the browser tests; then the start: the link read, the scene or lesson shown.
  // For scripts (and the browser tests): where a world point is drawn now, in client pixels.
  // With `stage`, in that stage's cell of the storyboard shown.
  window.viewpipe = {
    pixelOf(point, stage) {
      const k = stage === undefined || !board.built ? -1 : board.rest.cells.findIndex((cell) => cell.stage === stage);
      const cell = k < 0 ? null : board.rest.cells[k];
      const canvas = cell ? board.built[k].canvas : worldCanvas;
      const size = cell ? pictureSize(cell) : sizeOf(worldCanvas), frame = cell ? cell.rest : shown.frame;
      const { view, projection } = cameraMatrices(frame, size, cell ? size : data);
      const at = project(projection.multiply(view).multiply(matrixOf(frame.shown)), point, size);
      const rect = canvas.getBoundingClientRect();
      return at && { x: rect.left + at.x, y: rect.top + at.y };
    },
    // How many primitives the page draws: the core's display list, without what the reader leaves out.
    primitives: () => data.primitives.length,
    // The labels the core places for the view as the user has turned it (export pixels), and the stage's at rest.
    turnedLabels: () => labelsTurned(),
    restLabels: () => stageAt(state.stage).labels,
    traced: () => state.traced, // the vertex traced, [x, y, z] or null
    frame: () => shown.frame, // the frame drawn: its camera at rest (view, projection, focal) and stage matrix (shown)
    inFrontOfEye: (h) => inFrontOfEye(new THREE.Vector4(...h)), // the page's judgement of a point [x, y, z, w]
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
