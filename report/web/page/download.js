  // page/download.js: files saved: JSON text (the scene, a lesson's answers); the world view as PNG and SVG.
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

  // The world view as drawn, as a PNG: the picture and its labels, marks and points (the overlay); the caption,
  // legend and note are the page's text, not in the canvases.
  function viewPng() {
    const picture = document.createElement('canvas');
    picture.width = worldCanvas.width;
    picture.height = worldCanvas.height;
    const context = picture.getContext('2d');
    context.drawImage(worldCanvas, 0, 0);
    context.drawImage(worldOverlay, 0, 0, picture.width, picture.height);
    return new Promise((done) => picture.toBlob(done, 'image/png'));
  }
  // The world view as the core draws it for the SVG export (drawFigure: its shapes back to front and its labels
  // placed, for the view as turned), at the export's size; null where the core cannot draw the scene.
  function viewSvg() {
    const figure = askAboutTurned('stageFigure');
    if (!figure) return null;
    const escape = (text) => String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
    const rgb = (c) => `rgb(${c.map((v) => Math.round(v * 255)).join(', ')})`;
    const number = (x) => Number(x.toFixed(2));
    const { width, height } = figure;
    const out = [`<svg xmlns="http://www.w3.org/2000/svg" width="${width}px" height="${height}px" viewBox="0 0 ${width} ${height}">`,
                 `<title>${escape(worldCanvas.getAttribute('aria-label'))}</title>`,
                 `<rect width="${width}" height="${height}" fill="${rgb(data.background)}"/>`];
    for (const shape of figure.shapes) {
      const points = shape.points.map(([x, y]) => `${number(x)},${number(y)}`).join(' ');
      out.push(shape.surface
        ? `<polygon points="${points}" fill="${rgb(shape.color)}" fill-opacity="${shape.opacity}"/>`
        : `<polyline points="${points}" fill="none" stroke="${rgb(shape.color)}" stroke-opacity="${shape.opacity}" ` +
          `stroke-width="${shape.lineWidth}" stroke-linecap="round" stroke-linejoin="round"/>`);
    }
    // The labels as the page draws them at the export's size (drawWorld).
    for (const label of figure.labels) {
      const [x0, y0, x1, y1] = label.box;
      if (label.leader) {
        const [ax, ay] = label.anchor;
        out.push(`<line x1="${number(ax)}" y1="${number(ay)}" x2="${number(Math.min(Math.max(ax, x0), x1))}" ` +
                 `y2="${number(Math.min(Math.max(ay, y0), y1))}" stroke="${rgb(label.color)}" stroke-opacity="0.8"/>`);
      }
      out.push(`<rect x="${number(x0)}" y="${number(y0)}" width="${number(x1 - x0)}" height="${number(y1 - y0)}" ` +
               `fill="${rgb(data.background)}" fill-opacity="${data.labelBackdropOpacity}"/>`);
      const { px, weight } = labelFont(measuring, label, 1);
      const top = y0 + ((y1 - y0) - px) / 2;
      for (const run of runPlaces(measuring, label.runs, px, weight))
        out.push(`<text x="${number(x0 + run.x)}" y="${number(top + run.y)}" fill="${rgb(label.color)}" ` +
                 `style="font: ${escape(run.font)}; white-space: pre">${escape(run.text)}</text>`);
    }
    out.push('</svg>');
    return out.join('\n');
  }
  // A lesson's moment is its step (its stage may be a question's answer).
  const viewName = (suffix) => `${fileBase()}-${lesson ? `step-${state.step + 1}` : `stage-${state.stage}`}.${suffix}`;
  const saveNote = document.getElementById('save-note');
  document.getElementById('save-png').addEventListener('click', async () => saveBlob(await viewPng(), viewName('png')));
  document.getElementById('save-svg').addEventListener('click', () => {
    const svg = viewSvg();
    saveNote.textContent = svg ? '' : coreFailed || (data.filesLeftOut
      ? 'The SVG is drawn by ViewPipe\'s core, which needs the scene\'s meshes: this page was saved without them.'
      : 'The SVG is drawn by ViewPipe\'s core, which is still loading.');
    if (svg) saveBlob(new Blob([svg], { type: 'image/svg+xml' }), viewName('svg'));
  });
