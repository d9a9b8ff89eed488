  // page/tracing.js: a vertex traced through the stages: the one a click picks (the core's, as the app picks), or the next one with T.
  let vertices = new Float32Array(0);
  // In the world view, or in `canvas` where `frame` is drawn at `size` for `picture` (a storyboard's cell).
  function trace(event, canvas = worldCanvas, frame = shown && shown.frame, size = sizeOf(worldCanvas), picture = data) {
    if (!frame || !core) return; // the core picks: it loads a moment after the first picture
    const rect = canvas.getBoundingClientRect();
    const { view, projection } = cameraMatrices(frame, size, picture);
    const clipFromWorld = projection.multiply(view).multiply(matrixOf(frame.shown));
    const outcome = core.pickVertex(vertices, JSON.stringify(rowsOf(clipFromWorld)), JSON.stringify([size.width, size.height]),
                                    JSON.stringify([event.clientX - rect.left, event.clientY - rect.top]),
                                    JSON.stringify([innerWidth, innerHeight]), JSON.stringify(frame.cut || null));
    setTraced(outcome.error ? null : JSON.parse(outcome.text));
  }

  // T traces the next vertex drawn (Shift+T the one before): tracing without a mouse.
  let tracedIndex = -1;
  function traceNext(step) {
    const count = vertices.length / 3;
    for (let n = 1; n <= count; ++n) {
      const k = ((tracedIndex + step * n) % count + count) % count;
      const point = [vertices[3 * k], vertices[3 * k + 1], vertices[3 * k + 2]];
      if (!kept(shown.frame.cut, point)) continue;
      tracedIndex = k;
      setTraced(point);
      return;
    }
  }
  function setTraced(point) {
    state.traced = point;
    const traced = showTrace();
    drawShown();
    if (point) document.getElementById('live').textContent =
      `Traced the vertex${traced ? ' ' + traced.spoken : ''}: its coordinates after each stage are in the table.`;
  }

