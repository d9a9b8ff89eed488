  // page/drawing.js: drawWorld and drawView (objects, markers, the traced vertex, labels) and drawProjected, each time a view is drawn.
  function drawWorld() {
    if (!shown) return;
    const size = sizeOf(worldCanvas);
    placePictureText(size);
    // The canonical volume's line of the legend while it is drawn, as in the app.
    document.querySelectorAll('#legend [data-canonical]').forEach((row) => { row.hidden = !(shown.frame.canonical > 0); });
    const { frame, atRest, ghost } = shown;
    drawView({ renderer: world, overlay: worldOverlay, size, picture: data, fonts: data, frame, atRest, ghost,
               stage: state.stage, traced: state.traced,
               labels: !atRest ? null : core && userMoved() ? labelsTurned() : stageAt(state.stage).labels });
  }

  // One picture of the world: `frame` drawn by `renderer` at `size` (the picture `picture` was framed for,
  // fitted), with markers, the `traced` point and the `labels` placed (in picture pixels; null: each at a free
  // corner of its anchor) drawn on `overlay`; `copied`: the renderer's picture copied under them there.
  function drawView({ renderer, overlay, size, picture, fonts, frame, atRest, ghost, stage, traced, labels, copied }) {
    renderer.setSize(size.width, size.height, false);
    const { view, projection } = cameraMatrices(frame, size, picture);
    camera.matrix.getInverse(view);
    camera.matrixWorldNeedsUpdate = true;
    camera.projectionMatrix.copy(projection);
    camera.projectionMatrixInverse.getInverse(projection);
    const stageMatrix = matrixOf(frame.shown);
    const ghostMatrix = ghost ? matrixOf(ghost) : null;
    const cut = frame.cut ? new THREE.Vector4(...frame.cut) : noCut;
    const ratio = window.devicePixelRatio || 1;
    const widthScale = Math.max(1, fitScale(size, picture) * (core ? state.zoom : 1)) * ratio; // the core zooms
    for (const { object: thin, wide, primitive, ghost: isGhost } of items) {
      for (const object of [thin, wide]) {
        if (!object) continue;
        const uniforms = object.material.uniforms;
        let visible = true;
        if (primitive.canonical) {
          object.matrix.copy(identity);
          visible = frame.canonical > 0;
          uniforms.opacity.value = primitive.opacity * frame.canonical;
          object.material.transparent = uniforms.opacity.value < 1;
          uniforms.cut.value.copy(noCut);
        } else if (isGhost) {
          visible = !!ghostMatrix;
          if (ghostMatrix) object.matrix.copy(ghostMatrix);
          uniforms.cut.value.copy(cut);
        } else {
          object.matrix.copy(stageMatrix);
          uniforms.cut.value.copy(cut);
        }
        const cutHere = !!frame.cut && !primitive.canonical;
        object.visible = visible && (!wide || (object === wide) !== cutHere);
        if (object === wide) {
          uniforms.viewport.value.set(size.width * ratio, size.height * ratio);
          uniforms.width.value = primitive.lineWidth * widthScale;
        }
        object.matrixWorldNeedsUpdate = true;
      }
    }
    frameAxes.forEach((axes, k) => { axes.visible = atRest && k === stage; });
    render(renderer, worldScene, camera);

    const context = fitOverlay(overlay, size);
    if (copied) context.drawImage(renderer.domElement, 0, 0, size.width, size.height);
    const clipFromStage = projection.clone().multiply(view);
    const clipFromWorld = clipFromStage.clone().multiply(stageMatrix);
    const s = fitScale(size, picture);
    const markerScale = Math.max(0.5, s);
    for (const marker of data.markers) {
      if (!kept(frame.cut, marker.point)) continue;
      const tip = project(clipFromWorld, marker.point, size);
      if (!tip) continue;
      context.fillStyle = cssColor(marker.color);
      context.beginPath();
      if (marker.arrow) {
        const from = project(clipFromWorld, marker.from, size);
        if (!from) continue;
        const dx = tip.x - from.x, dy = tip.y - from.y, length = Math.hypot(dx, dy) || 1;
        const ux = dx / length, uy = dy / length, l = 3 * marker.size * markerScale, w = marker.size * markerScale;
        context.moveTo(tip.x, tip.y);
        context.lineTo(tip.x - l * ux - w * uy, tip.y - l * uy + w * ux);
        context.lineTo(tip.x - l * ux + w * uy, tip.y - l * uy - w * ux);
      } else {
        context.arc(tip.x, tip.y, marker.size * markerScale, 0, 2 * Math.PI);
      }
      context.fill();
    }
    if (traced) {
      const at = project(clipFromWorld, traced, size);
      if (at && kept(frame.cut, traced)) {
        context.strokeStyle = cssColor(data.ink);
        context.lineWidth = 2;
        context.beginPath();
        context.arc(at.x, at.y, 7, 0, 2 * Math.PI);
        context.stroke();
      }
    }
    const drawRuns = (runs, x, top, px, weight) => {
      context.textBaseline = 'alphabetic';
      for (const run of runPlaces(context, runs, px, weight)) {
        context.font = run.font;
        context.fillText(run.text, x + run.x, top + run.y);
      }
    };
    // Under a label, the picture's background: the lines it could not keep off run faintly under it.
    const backdrop = (x, y, width, height) => {
      context.fillStyle = cssColor(data.background, data.labelBackdropOpacity);
      context.fillRect(x, y, width, height);
    };
    if (labels) {
      // Where the core placed them, as in the app's pictures: picture pixels, fitted.
      const toView = pictureToView(size, picture);
      const place = (x, y) => ({ x: toView.x(x), y: toView.y(y) });
      for (const label of labels) {
        const [x0, y0, x1, y1] = label.box;
        const corner = place(x0, y0);
        const { px, weight } = labelFont(context, label, s, fonts);
        backdrop(corner.x, corner.y, (x1 - x0) * s, (y1 - y0) * s);
        context.fillStyle = cssColor(label.color);
        drawRuns(label.runs, corner.x, corner.y + ((y1 - y0) * s - px) / 2, px, weight);
        if (label.leader) {
          const anchor = place(label.anchor[0], label.anchor[1]);
          const nearest = place(Math.min(Math.max(label.anchor[0], x0), x1), Math.min(Math.max(label.anchor[1], y0), y1));
          context.strokeStyle = cssColor(label.color, 0.8);
          context.lineWidth = 1;
          context.beginPath();
          context.moveTo(anchor.x, anchor.y);
          context.lineTo(nearest.x, nearest.y);
          context.stroke();
        }
      }
    } else {
      // Moving between stages (or turned where the core cannot place them): each label at a corner of its
      // anchor that no label drawn before covers, or left out.
      const px = fonts.fontSize * Math.max(0.6, s);
      const taken = [];
      const overlaps = (a) => taken.some((b) => a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1);
      for (const label of data.labels) {
        if (label.minor || (label.fixed && frame.canonical < 0.5)) continue;
        if (!label.fixed && !kept(frame.cut, label.anchor)) continue;
        const at = project(label.fixed ? clipFromStage : clipFromWorld, label.anchor, size);
        if (!at) continue;
        const width = runsWidth(context, label.runs, px, 'bold '), gap = 4;
        const corners = [[gap, -gap - px], [gap, gap], [-gap - width, -gap - px], [-gap - width, gap]];
        for (const [dx, dy] of corners) {
          const box = { x0: at.x + dx, y0: at.y + dy, x1: at.x + dx + width, y1: at.y + dy + px };
          if (overlaps(box)) continue;
          taken.push(box);
          backdrop(box.x0, box.y0, width, px);
          context.fillStyle = cssColor(label.color);
          drawRuns(label.runs, box.x0, box.y0, px, 'bold ');
          break;
        }
      }
    }
  }

  function drawProjected() {
    const size = sizeOf(projectedCanvas);
    projected.setSize(size.width, size.height, false);
    // The window at the picture's shape, whole, as in the app.
    const stretch = data.projected.aspect / (size.width / size.height);
    const lx = 0.8 * Math.min(1, stretch), ly = 0.8 * Math.min(1, 1 / stretch); // room for the caption and legend
    projectedCamera.projectionMatrix.copy(new THREE.Matrix4().makeScale(lx, ly, 1).multiply(matrixOf(data.projected.clip)));
    projectedCamera.projectionMatrixInverse.getInverse(projectedCamera.projectionMatrix);
    render(projected, projectedScene, projectedCamera);
    const context = fitOverlay(projectedOverlay, size);
    // Marks in the picture's coordinates: the vanishing lines, the ring around faces that fight for depth; inside
    // the window (a point they run to outside it would take them across the heading, the legend and off the view).
    context.beginPath();
    context.rect((1 - lx) / 2 * size.width, (1 - ly) / 2 * size.height, lx * size.width, ly * size.height);
    context.clip();
    const marks = (segments, color, width) => {
      context.strokeStyle = color;
      context.lineWidth = width;
      context.beginPath();
      for (const [x0, y0, x1, y1] of segments) {
        context.moveTo((x0 * lx + 1) / 2 * size.width, (1 - y0 * ly) / 2 * size.height);
        context.lineTo((x1 * lx + 1) / 2 * size.width, (1 - y1 * ly) / 2 * size.height);
      }
      context.stroke();
    };
    marks(data.projected.vanishing, cssColor(data.projected.vanishingColor, 0.85), 1.5);
    marks(data.projected.zFighting, cssColor(data.projected.zFightingColor), 2.5);
  }

