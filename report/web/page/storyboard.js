  // page/storyboard.js: every stage at once (#layout=storyboard): the core's storyboard, each cell drawn by drawView; a click traces.
  // ---- The storyboard -------------------------------------------------------------
  const storyboardSection = document.getElementById('storyboard');
  const storyboardArrows = document.getElementById('storyboard-arrows');
  const storyboardNote = document.getElementById('storyboard-note');
  const layoutButton = document.getElementById('layout');
  // One WebGL context draws every cell, each copied into a 2D canvas of its own: however many stages, the
  // browser's limit on contexts is not reached.
  let storyboardRenderer = null;
  let board = { key: '', rest: null, turnedKey: '', turned: null, built: null }; // the core's answers, the cells built
  const storyboardShown = () => state.layout === 'storyboard';
  function drawShown() { if (storyboardShown()) drawStoryboard(); else drawWorld(); }

  // The storyboard in place of the world view and the panels beside it; or those back.
  function showLayout() {
    const on = storyboardShown();
    body.classList.toggle('storyboard', on);
    storyboardSection.hidden = !on;
    layoutButton.setAttribute('aria-pressed', String(on));
    // The buttons save what is shown.
    document.getElementById('save-buttons').setAttribute('aria-label', on ? 'Save every stage at once as shown' :
                                                         'Save the world view as shown');
    document.getElementById('save-png').textContent = on ? 'Storyboard as PNG' : 'View as PNG';
    document.getElementById('save-svg').textContent = on ? 'Storyboard as SVG' : 'View as SVG';
    if (on) drawStoryboard();
    else { drawWorld(); drawProjected(); }
  }
  function toggleLayout() {
    state.layout = storyboardShown() ? 'stages' : 'storyboard';
    writeFragment();
    showLayout();
  }
  layoutButton.addEventListener('click', toggleLayout);

  const storyboardRoom = () => {
    const box = storyboardSection.getBoundingClientRect();
    return { width: Math.floor(box.width), height: Math.floor(box.height) };
  };
  const pictureSize = (cell) => ({ width: cell.picture[2] - cell.picture[0], height: cell.picture[3] - cell.picture[1] });
  // The core's storyboard for `room` through `cameras` (null: each cell at rest); `shapes`: each cell's lines and faces too.
  function askStoryboard(room, cameras, shapes) {
    const outcome = core.storyboard(data.scene, JSON.stringify(viewOptions()), JSON.stringify(room),
                                    JSON.stringify(state.traced), cameras, measureRuns, shapes);
    return outcome.error ? null : JSON.parse(outcome.text);
  }
  // The cameras of the view as the user turned it, one a cell, for the core; null at rest.
  const turnedCameras = (rest) => !userMoved() ? 'null' : JSON.stringify(rest.cells.map((cell) => {
    const { view, projection } = cameraMatrices(cell.rest, pictureSize(cell), pictureSize(cell));
    return rowsOf(projection.multiply(view));
  }));
  // The core's storyboard for `room` at rest, and each cell's labels for the view as the user turned it (placed
  // anew by the core through each cell's camera; null where it cannot).
  function storyboardOf(room) {
    const ask = (cameras) => askStoryboard(room, cameras, false);
    const key = `${room.width} ${room.height} ${JSON.stringify(state.traced)} ${choicesKey()} ${data.scene}`;
    if (board.key !== key) board = { key, rest: ask('null'), turnedKey: '', turned: null, built: null };
    const rest = board.rest;
    if (!rest || !userMoved()) return { rest, labels: rest && rest.cells.map((cell) => cell.labels) };
    const cameras = turnedCameras(rest);
    if (board.turnedKey !== cameras) Object.assign(board, { turnedKey: cameras, turned: ask(cameras) });
    return { rest, labels: rest.cells.map((cell, k) => board.turned ? board.turned.cells[k].labels : null) };
  }

  // Each cell (its header, picture and footer) and the arrows between them, where the core laid them out.
  function buildStoryboard(result, room) {
    storyboardSection.querySelectorAll('.cell').forEach((cell) => cell.remove());
    storyboardArrows.setAttribute('width', room.width);
    storyboardArrows.setAttribute('height', room.height);
    storyboardArrows.textContent = '';
    for (const arrow of result.arrows) {
      const shape = document.createElementNS('http://www.w3.org/2000/svg', arrow.surface ? 'polygon' : 'polyline');
      shape.setAttribute('points', arrow.points.map((p) => p.join(',')).join(' '));
      if (arrow.surface) shape.setAttribute('fill', cssColor(arrow.color));
      else Object.entries({ fill: 'none', stroke: cssColor(arrow.color), 'stroke-width': arrow.lineWidth })
        .forEach(([name, value]) => shape.setAttribute(name, value));
      storyboardArrows.appendChild(shape);
    }
    const place = (element, box, origin) => Object.assign(element.style, {
      left: `${box[0] - origin[0]}px`, top: `${box[1] - origin[1]}px`,
      width: `${box[2] - box[0]}px`, height: `${box[3] - box[1]}px` });
    return result.cells.map((cell, k) => {
      const element = document.createElement('div');
      element.className = 'cell';
      element.dataset.stage = cell.stage;
      const origin = [cell.header[0], cell.header[1]];
      place(element, [cell.header[0], cell.header[1], cell.footer[2], cell.footer[3]], [0, 0]);
      // Texts: each cell's header, then its footer.
      const [header, footer] = [result.texts[2 * k], result.texts[2 * k + 1]].map((text) => {
        const line = document.createElement('div');
        line.className = text.minor ? 'footer' : 'header';
        place(line, text.box, origin);
        Object.assign(line.style, { width: 'auto', fontSize: `${text.minor ? result.smallSize : result.labelSize}px`,
                                    lineHeight: `${text.box[3] - text.box[1]}px`, color: cssColor(text.color) });
        setRichText(line, text.text);
        return line;
      });
      const picture = document.createElement('div');
      picture.className = 'picture';
      place(picture, cell.picture, origin);
      const canvas = document.createElement('canvas');
      canvas.setAttribute('role', 'img');
      canvas.setAttribute('aria-label', `Stage ${stages[cell.stage].listText}, beside every other stage: the scene ` +
                          `drawn with this stage's matrices, the ${result.texts[2 * k + 1].spoken}`);
      picture.appendChild(canvas);
      element.append(header, picture, footer);
      storyboardSection.appendChild(element);
      return { element, canvas };
    });
  }

  function drawStoryboard() {
    if (!storyboardShown()) return;
    const room = storyboardRoom();
    const why = coreFailed || (data.filesLeftOut ? "The storyboard is drawn by ViewPipe's core, which cannot read " +
                'the meshes this page left out.' : !core ? "The storyboard is drawn by ViewPipe's core, which is loading." : '');
    const { rest, labels } = why ? {} : storyboardOf(room);
    storyboardNote.textContent = why || (!rest ? "ViewPipe's core could not lay out the storyboard." :
                                         !rest.cells.length ? 'The window leaves no room for every stage at once.' : '');
    if (storyboardNote.textContent) {
      storyboardSection.querySelectorAll('.cell').forEach((cell) => cell.remove());
      storyboardArrows.textContent = '';
      board.built = null;
      return;
    }
    if (!board.built) board.built = buildStoryboard(rest, room);
    storyboardRenderer = storyboardRenderer || makeRenderer(document.createElement('canvas'));
    const fonts = { fontSize: rest.labelSize, smallFontSize: rest.smallSize };
    rest.cells.forEach((cell, k) => {
      const { element, canvas } = board.built[k];
      const size = pictureSize(cell);
      drawView({ renderer: storyboardRenderer, overlay: canvas, size, picture: size, fonts, frame: cell.rest,
                 atRest: true, ghost: cell.ghost, stage: cell.stage, traced: rest.traced, labels: labels[k], copied: true });
      element.classList.toggle('current', cell.stage === state.stage);
    });
    body.dataset.storyboardDrawn = String((Number(body.dataset.storyboardDrawn) || 0) + 1); // for the browser tests
  }

  // Dragging any cell turns every one, the wheel zooms them all; a click traces the vertex it picks in every cell.
  let boardDrag = null;
  storyboardSection.addEventListener('pointerdown', (event) => {
    boardDrag = { x: event.clientX, y: event.clientY, yaw: state.yaw, pitch: state.pitch, moved: false };
    storyboardSection.setPointerCapture(event.pointerId);
  });
  storyboardSection.addEventListener('pointermove', (event) => {
    if (!boardDrag) return;
    const dx = event.clientX - boardDrag.x, dy = event.clientY - boardDrag.y;
    if (Math.hypot(dx, dy) > 3) boardDrag.moved = true;
    if (boardDrag.moved) changeView({ yaw: boardDrag.yaw + dx * 0.4, pitch: boardDrag.pitch + dy * 0.4 });
  });
  storyboardSection.addEventListener('pointerup', (event) => {
    const clicked = boardDrag && !boardDrag.moved;
    boardDrag = null;
    if (!clicked || !board.built) return;
    const inside = ({ canvas }) => {
      const r = canvas.getBoundingClientRect();
      return event.clientX >= r.left && event.clientX < r.right && event.clientY >= r.top && event.clientY < r.bottom;
    };
    const k = board.built.findIndex(inside);
    if (k < 0) return;
    const cell = board.rest.cells[k], size = pictureSize(cell);
    trace(event, board.built[k].canvas, cell.rest, size, size);
  });
  storyboardSection.addEventListener('wheel', (event) => {
    event.preventDefault();
    changeView({ zoom: state.zoom * Math.pow(1.1, -Math.sign(event.deltaY)) });
  }, { passive: false });

