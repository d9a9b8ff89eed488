  // page/download.js: files saved: JSON text (the scene, a lesson's answers); what is shown (the world view, or every stage at once) as PNG and SVG.
  function saveBlob(blob, name) {
    const link = document.createElement('a');
    link.href = URL.createObjectURL(blob);
    link.download = name;
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 10000); // once the download has begun
  }
  // JSON text downloaded as a file.
  const download = (text, name) => saveBlob(new Blob([text], { type: 'application/json' }), name);
  // The scene's title as a file name.
  const fileBase = () => (data.title || 'scene').replace(/[^A-Za-z0-9._-]+/g, '-').replace(/^-+|-+$/g, '').toLowerCase();

  // What is shown as drawn, as a PNG: the world view's picture and its labels, marks and points (the overlay; the
  // caption, legend and note are the page's text, not in the canvases); or every stage at once: each cell's
  // picture, the arrows, headers and footers where the core laid them out.
  function viewPng() {
    const picture = document.createElement('canvas');
    if (storyboardShown() && board.built) {
      const room = storyboardRoom(), ratio = window.devicePixelRatio || 1;
      picture.width = room.width * ratio;
      picture.height = room.height * ratio;
      const context = picture.getContext('2d');
      context.scale(ratio, ratio);
      context.fillStyle = cssColor(data.background);
      context.fillRect(0, 0, room.width, room.height);
      board.rest.cells.forEach((cell, k) => context.drawImage(board.built[k].canvas, cell.picture[0], cell.picture[1],
                                                                cell.picture[2] - cell.picture[0], cell.picture[3] - cell.picture[1]));
      for (const arrow of board.rest.arrows) {
        const path = new Path2D();
        arrow.points.forEach(([x, y], k) => (k ? path.lineTo(x, y) : path.moveTo(x, y)));
        if (arrow.surface) { context.fillStyle = cssColor(arrow.color); context.fill(path); }
        else { context.strokeStyle = cssColor(arrow.color); context.lineWidth = arrow.lineWidth; context.stroke(path); }
      }
      for (const text of board.rest.texts) {
        context.fillStyle = cssColor(text.color);
        for (const run of textRuns(text, board.rest)) {
          context.font = run.font;
          context.fillText(run.text, run.x, run.y);
        }
      }
    } else {
      picture.width = worldCanvas.width;
      picture.height = worldCanvas.height;
      const context = picture.getContext('2d');
      context.drawImage(worldCanvas, 0, 0);
      context.drawImage(worldOverlay, 0, 0, picture.width, picture.height);
    }
    return new Promise((done) => picture.toBlob(done, 'image/png'));
  }
  // A storyboard's header or footer as runs placed in the storyboard: each one's font, x and baseline.
  function textRuns(text, result) {
    const [x0, y0, , y1] = text.box;
    const px = text.minor ? result.smallSize : result.labelSize, weight = text.minor ? '' : 'bold ';
    const top = y0 + ((y1 - y0) - px) / 2;
    return runPlaces(measuring, text.runs, px, weight).map((run) => ({ ...run, x: x0 + run.x, y: top + run.y }));
  }
  const escape = (text) => String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
  const rgb = (c) => `rgb(${c.map((v) => Math.round(v * 255)).join(', ')})`;
  const number = (x) => Number(x.toFixed(2));
  // A figure's line or face as SVG.
  function shapeSvg(shape) {
    const points = shape.points.map(([x, y]) => `${number(x)},${number(y)}`).join(' ');
    return shape.surface
      ? `<polygon points="${points}" fill="${rgb(shape.color)}" fill-opacity="${shape.opacity}"/>`
      : `<polyline points="${points}" fill="none" stroke="${rgb(shape.color)}" stroke-opacity="${shape.opacity}" ` +
        `stroke-width="${shape.lineWidth}" stroke-linecap="round" stroke-linejoin="round"/>`;
  }
  // Runs of text placed (runPlaces, moved) as SVG text.
  const runsSvg = (runs, color) => runs.map((run) => `<text x="${number(run.x)}" y="${number(run.y)}" fill="${rgb(color)}" ` +
                                                    `style="font: ${escape(run.font)}; white-space: pre">${escape(run.text)}</text>`);
  // A placed label as the page draws it (drawView): its leader, its backdrop, its runs; `fonts` the picture's text sizes.
  function labelSvg(label, fonts) {
    const out = [];
    const [x0, y0, x1, y1] = label.box;
    if (label.leader) {
      const [ax, ay] = label.anchor;
      out.push(`<line x1="${number(ax)}" y1="${number(ay)}" x2="${number(Math.min(Math.max(ax, x0), x1))}" ` +
               `y2="${number(Math.min(Math.max(ay, y0), y1))}" stroke="${rgb(label.color)}" stroke-opacity="0.8"/>`);
    }
    out.push(`<rect x="${number(x0)}" y="${number(y0)}" width="${number(x1 - x0)}" height="${number(y1 - y0)}" ` +
             `fill="${rgb(data.background)}" fill-opacity="${data.labelBackdropOpacity}"/>`);
    const { px, weight } = labelFont(measuring, label, 1, fonts);
    const top = y0 + ((y1 - y0) - px) / 2;
    const runs = runPlaces(measuring, label.runs, px, weight).map((run) => ({ ...run, x: x0 + run.x, y: top + run.y }));
    return out.concat(runsSvg(runs, label.color));
  }
  const svgOpening = (width, height, title) => [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}px" height="${height}px" viewBox="0 0 ${width} ${height}">`,
    `<title>${escape(title)}</title>`, `<rect width="${width}" height="${height}" fill="${rgb(data.background)}"/>`];
  // The world view as the core draws it for the SVG export (drawFigure: its shapes back to front and its labels
  // placed, for the view as turned), at the export's size; null where the core cannot draw the scene.
  function viewSvg() {
    const figure = askAboutTurned('stageFigure');
    if (!figure) return null;
    const out = svgOpening(figure.width, figure.height, worldCanvas.getAttribute('aria-label'));
    for (const shape of figure.shapes) out.push(shapeSvg(shape));
    for (const label of figure.labels) out.push(...labelSvg(label, data));
    out.push('</svg>');
    return out.join('\n');
  }
  // Every stage at once as the core draws it (each cell's figure, for the view as turned, in its picture), then
  // the arrows, headers and footers; null where the core cannot draw the scene.
  function storyboardSvg() {
    if (!coreDraws() || !board.rest) return null;
    const room = storyboardRoom();
    const result = askStoryboard(room, turnedCameras(board.rest), true);
    if (!result) return null;
    const out = svgOpening(room.width, room.height, storyboardSection.getAttribute('aria-label') + `: ${data.title}`);
    const fonts = { fontSize: result.labelSize, smallFontSize: result.smallSize };
    for (const cell of result.cells) {
      out.push(`<g transform="translate(${number(cell.picture[0])} ${number(cell.picture[1])})">`);
      for (const shape of cell.shapes) out.push(shapeSvg(shape));
      for (const label of cell.labels) out.push(...labelSvg(label, fonts));
      out.push('</g>');
    }
    for (const arrow of result.arrows) out.push(shapeSvg(arrow));
    for (const text of result.texts) out.push(...runsSvg(textRuns(text, result), text.color));
    out.push('</svg>');
    return out.join('\n');
  }
  // A lesson's moment is its step (its stage may be a question's answer).
  const viewName = (suffix) => `${fileBase()}-${lesson ? `step-${state.step + 1}` : storyboardShown() ? 'storyboard'
                                                : `stage-${state.stage}`}.${suffix}`;
  const saveNote = document.getElementById('save-note');
  document.getElementById('save-png').addEventListener('click', async () => saveBlob(await viewPng(), viewName('png')));
  document.getElementById('save-svg').addEventListener('click', () => {
    const svg = storyboardShown() ? storyboardSvg() : viewSvg();
    saveNote.textContent = svg ? '' : coreFailed || (data.filesLeftOut
      ? 'The SVG is drawn by ViewPipe\'s core, which needs the scene\'s meshes: this page was saved without them.'
      : 'The SVG is drawn by ViewPipe\'s core, which is still loading.');
    if (svg) saveBlob(new Blob([svg], { type: 'image/svg+xml' }), viewName('svg'));
  });
