  // page/tracing.js: a vertex traced through the stages: the one nearest a click, or the next one with T.
  let vertices = new Float32Array(0);
  function trace(event) {
    if (!shown) return;
    const rect = worldCanvas.getBoundingClientRect();
    const size = sizeOf(worldCanvas);
    const { view, projection } = cameraMatrices(shown.frame, size);
    const clipFromWorld = projection.multiply(view).multiply(matrixOf(shown.frame.shown));
    let best = null, bestDistance = 12;
    for (let k = 0; k < vertices.length; k += 3) {
      const point = [vertices[k], vertices[k + 1], vertices[k + 2]];
      const at = project(clipFromWorld, point, size);
      if (!at || !kept(shown.frame.cut, point)) continue;
      const distance = Math.hypot(at.x - (event.clientX - rect.left), at.y - (event.clientY - rect.top));
      if (distance < bestDistance) best = point, bestDistance = distance;
    }
    setTraced(best);
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
    showTrace();
    drawShown();
    if (point) document.getElementById('live').textContent =
      `Traced the vertex (${point.map(format).join(', ')}): its coordinates after each stage are in the table.`;
  }

