  // page/picture-text.js: the caption, legend and note placed as the stage's picture lays them out; label runs' fonts.
  // The caption, legend and note where the stage's picture has them (its layout, in export pixels), fitted as it is.
  let placedText = '';
  function placePictureText(size) {
    const layout = stageAt(state.stage).layout;
    const key = `${state.stage} ${asking()} ${size.width} ${size.height}`;
    if (!layout || key === placedText) return;
    placedText = key;
    const s = fitScale(size);
    const { x, y } = pictureToView(size);
    const setBox = (element, box) => Object.assign(element.style, {
      left: `${x(box[0])}px`, top: `${y(box[1])}px`, right: 'auto', bottom: 'auto', maxWidth: 'none', margin: '0' });
    const setPart = (element, part) => {
      setBox(element, part.box);
      buildOnce(element, part.lines, () => {
        element.textContent = '';
        part.lines.forEach((line, k) => {
          if (k) element.append('\n');
          const span = document.createElement('span');
          setRichText(span, line);
          element.appendChild(span);
        });
      });
      Object.assign(element.style, { fontSize: `${part.size * s}px`, lineHeight: `${(part.line || 1.25 * part.size) * s}px` });
    };
    const caption = document.getElementById('caption');
    // Under the text, over what runs behind it; from the picture's edge to the view's. Made anew where they moved.
    const backdrops = layout.backdrops.map((box) => {
      const left = box[0] <= 0 ? 0 : x(box[0]), top = box[1] <= 0 ? 0 : y(box[1]);
      const bottom = box[3] >= data.height ? size.height : y(box[3]);
      return { left: `${left}px`, top: `${top}px`, width: `${x(box[2]) - left}px`, height: `${bottom - top}px` };
    });
    const placed = [...caption.parentNode.querySelectorAll('.backdrop')];
    if (JSON.stringify(placed.map((backdrop) => backdrop.dataset.box)) !== JSON.stringify(backdrops.map((box) => JSON.stringify(box)))) {
      placed.forEach((backdrop) => backdrop.remove());
      for (const box of backdrops) {
        const backdrop = document.createElement('div');
        backdrop.className = 'backdrop';
        backdrop.dataset.box = JSON.stringify(box);
        Object.assign(backdrop.style, box);
        caption.before(backdrop);
      }
    }
    setPart(caption, asking() ? { ...layout.caption, lines: [] } : layout.caption); // the stage's name and claim
    setPart(document.getElementById('note'), layout.note);
    const legend = document.getElementById('legend');
    legend.hidden = !layout.legend;
    if (!layout.legend) return;
    const { box, size: textSize, row, swatch, padding } = layout.legend;
    setBox(legend, box);
    Object.assign(legend.style, { fontSize: `${textSize * s}px`, padding: `${padding * s}px`, boxSizing: 'border-box',
                                  width: `${(box[2] - box[0]) * s}px`, height: `${(box[3] - box[1]) * s}px` });
    legend.querySelectorAll('div').forEach((entry) => { entry.style.height = `${row * s}px`; entry.style.gap = `${padding * s}px`; });
    legend.querySelectorAll('i').forEach((mark) => { // half its slot, centred, as the app's legend draws it; a dot round
      const width = mark.style.borderRadius ? 0.4 * swatch / 3 : swatch / 2;
      Object.assign(mark.style, { width: `${width * s}px`, height: mark.style.borderRadius ? `${width * s}px` : '',
                                  margin: `0 ${(swatch - width) / 2 * s}px` });
    });
  }

  // A label's runs (the core's math: [text, italic, level]) as the PNG sets them: scripts smaller, moved off the line.
  const fontOf = (px) => `${px}px "DejaVu Sans", "Segoe UI", Helvetica, Arial, sans-serif`;
  const runFont = (run, px, weight) =>
    (run[1] ? 'italic ' : '') + weight + fontOf(px * Math.pow(data.scripts.scale, Math.abs(run[2])));
  function runsWidth(context, runs, px, weight) {
    return runs.reduce((width, run) => {
      context.font = runFont(run, px, weight);
      return width + context.measureText(run[0]).width;
    }, 0);
  }

  // Where each run of a label goes from its top left corner: its font, x, and y of its baseline.
  function runPlaces(context, runs, px, weight) {
    context.font = weight + fontOf(px);
    const baseline = context.measureText('Ág').fontBoundingBoxAscent;
    let x = 0;
    return runs.map((run) => {
      const font = runFont(run, px, weight);
      const shift = run[2] > 0 ? -data.scripts.rise * run[2] * px : -data.scripts.drop * run[2] * px;
      const place = { text: run[0], font, x, y: baseline + shift };
      context.font = font;
      x += context.measureText(run[0]).width;
      return place;
    });
  }
  // A placed label's size (its kind's, smaller where its box is narrower) and weight, at `s` pixels per picture
  // pixel; `fonts`: the picture's text sizes (a storyboard cell's are the storyboard's).
  function labelFont(context, label, s, fonts = data) {
    const weight = label.minor ? '' : 'bold ';
    const px = (label.minor ? fonts.smallFontSize : fonts.fontSize) * s, room = (label.box[2] - label.box[0]) * s;
    const width = runsWidth(context, label.runs, px, weight);
    return { px: width > room ? px * room / width : px, weight };
  }
