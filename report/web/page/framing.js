  // page/framing.js: the picture fitted into a view, the camera as the user turned it, labels placed for it, points projected.
  // ---- Drawing ----------------------------------------------------------------
  function sizeOf(canvas) {
    const box = canvas.parentElement.getBoundingClientRect();
    return { width: Math.max(1, Math.round(box.width)), height: Math.max(1, Math.round(box.height)) };
  }
  function fitOverlay(overlay, size) {
    const ratio = window.devicePixelRatio || 1;
    overlay.width = size.width * ratio;
    overlay.height = size.height * ratio;
    const context = overlay.getContext('2d');
    context.setTransform(ratio, 0, 0, ratio, 0, 0);
    context.clearRect(0, 0, size.width, size.height);
    return context;
  }
  // The picture (the export's, or a storyboard cell's) fitted into the view, whole: pixels per picture pixel.
  function fitScale(size, picture = data) {
    return Math.min(size.width / picture.width, size.height / picture.height);
  }
  // The picture's pixels to the view's, x and y apart: the picture fitted, centred.
  function pictureToView(size, picture = data) {
    const s = fitScale(size, picture);
    return { x: (v) => (v - picture.width / 2) * s + size.width / 2, y: (v) => (v - picture.height / 2) * s + size.height / 2 };
  }

  // The frame's camera as the reader turned and zoomed it (the core's turnedCamera), the picture fitted into the
  // view whole, centred. Until the core has loaded (or where it could not), the frame's own camera: at rest.
  function cameraMatrices(frame, size, picture = data) {
    const turned = core && core.turnedCamera(frame.view, frame.projection, frame.focal, state.yaw, state.pitch, state.zoom);
    const view = matrixOf(turned ? turned.slice(0, 16) : frame.view);
    const projection = matrixOf(turned ? turned.slice(16) : frame.projection);
    const s = fitScale(size, picture);
    const fit = new THREE.Matrix4().makeScale(picture.width * s / size.width, picture.height * s / size.height, 1);
    return { view, projection: fit.multiply(projection) };
  }

  // The view as the user turned it, for the core: the stage's camera in the export's picture (stage coordinates ->
  // clip coordinates, row by row) and what a lesson's step shows of the scene.
  function turnedView() {
    const exportSize = { width: data.width, height: data.height };
    const { view, projection } = cameraMatrices(stageAt(state.stage).rest, exportSize);
    return { rows: rowsOf(projection.multiply(view)), shown: JSON.stringify(lesson ? lesson.steps[state.step].shown : null) };
  }
  // A matrix row by row, as the core takes a camera (three.js keeps it column by column).
  function rowsOf(matrix) {
    const m = matrix.elements;
    return [0, 1, 2, 3].flatMap((r) => [0, 1, 2, 3].map((c) => m[4 * c + r]));
  }
  // Whether the core can draw the scene shown: loaded, and with the scene's meshes.
  const coreDraws = () => !!core && !data.filesLeftOut;
  // The core's answer about the turned view: `ask` is placeLabels or stageFigure; null where it cannot answer.
  function askAboutTurned(ask) {
    if (!coreDraws()) return null;
    const { rows, shown } = turnedView();
    const outcome = core[ask](data.scene, JSON.stringify(viewOptions()), state.stage, JSON.stringify(rows), measureRuns, shown);
    return outcome.error ? null : JSON.parse(outcome.text);
  }

  // The stage's labels placed by the core for the view turned by the user, as at rest (in export pixels), as a
  // lesson's step shows the scene; null where the core cannot.
  let turned = { key: '', labels: null };
  function labelsTurned() {
    if (!coreDraws()) return null;
    const { rows, shown } = turnedView();
    const key = `${state.stage} ${rows.join(' ')} ${data.scene.length} ${shown}`;
    if (turned.key !== key) turned = { key, labels: askAboutTurned('placeLabels') };
    return turned.labels;
  }

  // The core's inFrontOfEye, on the core's reach: whether a point before the divide has an image the pictures draw.
  const inFrontOfEye = (p) => p.w > Math.max(Math.abs(p.x), Math.abs(p.y), Math.abs(p.z)) / data.drawnReach &&
    [p.x, p.y, p.z, p.w].every(Number.isFinite);
  function project(clipFromPoint, point, size) {
    const p = new THREE.Vector4(point[0], point[1], point[2], 1).applyMatrix4(clipFromPoint);
    if (!inFrontOfEye(p)) return null;
    return { x: (p.x / p.w + 1) / 2 * size.width, y: (1 - p.y / p.w) / 2 * size.height };
  }
  const kept = (cut, point) => !cut || cut[0] * point[0] + cut[1] * point[1] + cut[2] * point[2] + cut[3] >= 0;

