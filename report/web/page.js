// ViewPipe's page: draws the evaluated scene that the export wrote into
// #scene-data. Every matrix, framing, label place and transition frame comes
// from ViewPipe's core and report code, as the app's do: written by the
// export, and made anew by the same code compiled to WebAssembly
// (ViewPipeCore) when the scene is edited. This script only draws them and
// handles input.
(function () {
  'use strict';
  const page = JSON.parse(document.getElementById('scene-data').textContent);
  const lesson = page.lesson || null;
  let data = page.scenes[0]; // the scene shown
  let stages = data.stages;
  let last = stages.length - 1;
  const body = document.body;
  if (data.dark) body.classList.add('dark');

  function bytesOf(base64) {
    const text = atob(base64);
    const bytes = new Uint8Array(text.length);
    for (let k = 0; k < text.length; ++k) bytes[k] = text.charCodeAt(k);
    return bytes.buffer;
  }
  const floatsOf = (base64) => new Float32Array(bytesOf(base64));
  const matrixOf = (rows) => new THREE.Matrix4().set(...rows);
  const cssColor = (c, alpha = 1) =>
    `rgba(${Math.round(c[0] * 255)}, ${Math.round(c[1] * 255)}, ${Math.round(c[2] * 255)}, ${alpha})`;
  const identity = new THREE.Matrix4();

  // Unlit color; fragments on the eye's side of the near cut are thrown away
  // (under a perspective matrix they would be flung out towards infinity).
  const vertexShader = `
    uniform vec4 cut;
    varying float kept;
    void main() {
      kept = dot(cut, vec4(position, 1.0));
      gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
    }`;
  const fragmentShader = `
    uniform vec3 color;
    uniform float opacity;
    varying float kept;
    void main() {
      if (kept < 0.0) discard;
      gl_FragColor = vec4(color, opacity);
    }`;
  const noCut = new THREE.Vector4(0, 0, 0, 1);
  // `wide`: the wide lines' shader and its uniforms, for lines drawn as quads.
  function material(color, opacity, surface, wide) {
    return new THREE.ShaderMaterial({
      uniforms: {
        color: { value: new THREE.Color(color[0], color[1], color[2]) },
        opacity: { value: opacity },
        cut: { value: noCut.clone() },
        ...(wide ? wide.uniforms : {}),
      },
      vertexShader: wide ? wide.vertexShader : vertexShader, fragmentShader,
      transparent: opacity < 1,
      depthWrite: !surface && opacity >= 1,
      side: THREE.DoubleSide,
    });
  }
  // Lines as wide as the app draws them: WebGL draws lines one pixel wide, so
  // each segment is a quad whose ends are pushed apart on screen.
  const wideVertexShader = `
    uniform vec4 cut;
    uniform vec2 viewport;
    uniform float width;
    attribute vec3 other;
    attribute float side;
    varying float kept;
    void main() {
      kept = dot(cut, vec4(position, 1.0));
      vec4 p = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
      vec4 q = projectionMatrix * modelViewMatrix * vec4(other, 1.0);
      vec2 along = (q.xy / q.w - p.xy / p.w) * viewport;
      vec2 normal = length(along) > 0.0 ? normalize(vec2(-along.y, along.x)) : vec2(0.0);
      p.xy += normal / viewport * width * side * p.w;
      gl_Position = p;
    }`;
  function wideLines(primitive, opacity, order) {
    const ends = floatsOf(primitive.positions);
    const segments = ends.length / 6;
    const position = new Float32Array(segments * 12), other = new Float32Array(segments * 12);
    const side = new Float32Array(segments * 4), index = new Uint32Array(segments * 6);
    for (let k = 0; k < segments; ++k) {
      const a = ends.subarray(6 * k, 6 * k + 3), b = ends.subarray(6 * k + 3, 6 * k + 6);
      [a, a, b, b].forEach((end, j) => position.set(end, 12 * k + 3 * j));
      [b, b, a, a].forEach((end, j) => other.set(end, 12 * k + 3 * j));
      side.set([1, -1, -1, 1], 4 * k); // b's normal points the other way
      index.set([4 * k, 4 * k + 1, 4 * k + 2, 4 * k + 1, 4 * k + 3, 4 * k + 2], 6 * k);
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(position, 3));
    geometry.setAttribute('other', new THREE.BufferAttribute(other, 3));
    geometry.setAttribute('side', new THREE.BufferAttribute(side, 1));
    geometry.setIndex(new THREE.BufferAttribute(index, 1));
    const object = new THREE.Mesh(geometry, material(primitive.color, opacity, false, {
      vertexShader: wideVertexShader,
      uniforms: { viewport: { value: new THREE.Vector2(1, 1) }, width: { value: primitive.lineWidth } },
    }));
    object.matrixAutoUpdate = false;
    object.frustumCulled = false;
    object.renderOrder = order;
    return object;
  }

  function geometryOf(primitive) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(floatsOf(primitive.positions), 3));
    if (primitive.triangles) geometry.setIndex(new THREE.BufferAttribute(new Uint32Array(bytesOf(primitive.triangles)), 1));
    return geometry;
  }
  function drawable(geometry, primitive, opacity, order) {
    const object = primitive.surface ? new THREE.Mesh(geometry, material(primitive.color, opacity, true))
                                     : new THREE.LineSegments(geometry, material(primitive.color, opacity, false));
    object.matrixAutoUpdate = false;
    object.frustumCulled = false;
    object.renderOrder = order;
    return object;
  }

  function makeRenderer(canvas) {
    try {
      const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
      renderer.sortObjects = true; // by renderOrder: the scene's drawing order, back to front
      renderer.setPixelRatio(window.devicePixelRatio || 1);
      return renderer;
    } catch (error) {
      document.getElementById('caption').textContent = 'This page needs WebGL, which this browser did not give it.';
      throw error;
    }
  }

  // ---- The world view -------------------------------------------------------
  const worldCanvas = document.getElementById('world-canvas');
  const worldOverlay = document.getElementById('world-overlay');
  const world = makeRenderer(worldCanvas);
  const worldScene = new THREE.Scene();
  const camera = new THREE.Camera();
  camera.matrixAutoUpdate = false;
  let items = []; // {object, wide, primitive, ghost}: each drawable, its wide lines
  let frameAxes = null; // the fixed axes of the stage shown at rest

  // ---- What the camera sees ---------------------------------------------------
  const projectedCanvas = document.getElementById('projected-canvas');
  const projectedOverlay = document.getElementById('projected-overlay');
  const projected = makeRenderer(projectedCanvas);
  const projectedScene = new THREE.Scene();
  const projectedCamera = new THREE.Camera();
  projectedCamera.matrixAutoUpdate = false;
  // What a scene drew before is disposed once the scene has been drawn anew (render): three.js compiles a
  // shader program again when the last material using it goes, and an edit would compile every one.
  function retire(scene, object) {
    scene.remove(object);
    (scene.userData.retired = scene.userData.retired || []).push(object);
  }
  function clear(scene) {
    for (const child of [...scene.children]) retire(scene, child);
  }
  function render(renderer, scene, camera) {
    renderer.render(scene, camera);
    for (const object of scene.userData.retired || []) {
      object.geometry.dispose();
      object.material.dispose();
    }
    scene.userData.retired = [];
  }
  // The drawables of the scene shown, in both views.
  function buildViews() {
    clear(worldScene);
    clear(projectedScene);
    frameAxes = null;
    items = [];
    worldScene.background = new THREE.Color(...data.background);
    projectedScene.background = new THREE.Color(...data.projectedBackground);
    document.getElementById('projected').style.setProperty('--projected', cssColor(data.projectedBackground));
    data.primitives.forEach((primitive, k) => {
      const geometry = geometryOf(primitive);
      // Lines twice: wide, and one pixel wide where a divide's cut applies (a wide line's
      // ends cannot be pushed apart on screen where one of them has no image).
      const add = (opacity, order, ghost) => {
        const object = drawable(geometry, primitive, opacity, order);
        const wide = primitive.surface ? null : wideLines(primitive, opacity, order);
        for (const o of [object, wide]) if (o) worldScene.add(o);
        items.push({ object, wide, primitive, ghost });
      };
      add(primitive.opacity, 2 * k + 1, false);
      if (primitive.ghosted) add(primitive.opacity * data.ghostOpacity, 2 * k, true);
      // What the camera sees: the objects.
      if (primitive.object >= 0 && (primitive.surface || primitive.opacity >= 1))
        projectedScene.add(drawable(geometryOf(primitive), primitive, primitive.surface ? 0.35 : 1, k));
    });
    const windowOutline = { surface: false, positions: data.projected.window, color: data.projected.windowColor };
    projectedScene.add(drawable(geometryOf(windowOutline), windowOutline, 1, data.primitives.length));
  }

  // JSON text downloaded as a file.
  function download(text, name) {
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([text], { type: 'application/json' }));
    link.download = name;
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 10000); // once the download has begun
  }

  // ---- State ------------------------------------------------------------------
  const state = { stage: 0, step: 0, yaw: 0, pitch: 0, zoom: 1, figure: false, traced: null };
  let shown = null; // the frame drawn: {frame, atRest, ghost}
  let animation = null;
  let playing = null;
  let linkedStage = 0;

  function readFragment() {
    const values = new URLSearchParams(location.hash.slice(1));
    const number = (name, fallback) => {
      const value = Number(values.get(name));
      return values.has(name) && Number.isFinite(value) ? value : fallback;
    };
    linkedStage = Math.max(0, Math.round(number('stage', 0))); // the linked scene may have more stages
    state.stage = Math.min(last, linkedStage);
    state.step = lesson ? Math.min(lesson.steps.length - 1, Math.max(0, Math.round(number('step', 1) - 1))) : 0;
    state.yaw = number('yaw', 0);
    state.pitch = Math.max(-89, Math.min(89, number('pitch', 0)));
    state.zoom = Math.max(0.1, Math.min(20, number('zoom', 1)));
    state.figure = values.has('figure');
    body.classList.toggle('figure', state.figure);
    pendingLink = values.get('scene'); // for the core, once it is loaded
  }
  function writeFragment() {
    const values = new URLSearchParams();
    // A lesson's moment is its step (its stage would name a which_stage answer).
    if (lesson) values.set('step', state.step + 1);
    else values.set('stage', state.stage);
    if (state.yaw) values.set('yaw', state.yaw.toFixed(1));
    if (state.pitch) values.set('pitch', state.pitch.toFixed(1));
    if (state.zoom !== 1) values.set('zoom', state.zoom.toFixed(3));
    if (state.figure) values.set('figure', '');
    const linked = linkedSceneText();
    if (linked) values.set('scene', linked);
    history.replaceState(null, '', '#' + values.toString().replace(/=$|=(?=&)/g, ''));
  }
  const userMoved = () => state.yaw !== 0 || state.pitch !== 0 || state.zoom !== 1;

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
  // The export's picture fitted into the view, whole: pixels per export pixel.
  function fitScale(size) {
    return Math.min(size.width / data.width, size.height / data.height);
  }

  // The frame's camera with the user's orbit (about the focal point, in eye axes) and zoom.
  function cameraMatrices(frame, size) {
    const view = matrixOf(frame.view);
    const focal = new THREE.Vector3(...frame.focal).applyMatrix4(view);
    const turn = new THREE.Matrix4().makeRotationX(state.pitch * Math.PI / 180)
      .multiply(new THREE.Matrix4().makeRotationY(state.yaw * Math.PI / 180));
    const orbit = new THREE.Matrix4().makeTranslation(focal.x, focal.y, focal.z).multiply(turn)
      .multiply(new THREE.Matrix4().makeTranslation(-focal.x, -focal.y, -focal.z));
    const s = fitScale(size);
    // z scaled down: nothing in front of the eye is clipped by near and far planes while orbiting.
    const fit = new THREE.Matrix4().makeScale(data.width * s / size.width * state.zoom,
                                              data.height * s / size.height * state.zoom, 0.02);
    return { view: orbit.multiply(view), projection: fit.multiply(matrixOf(frame.projection)) };
  }

  // The stage's labels placed by the core for the view turned by the user, as at rest (in export pixels), as a
  // lesson's step shows the scene; null where the core cannot (not loaded, or the scene's meshes left out).
  let turned = { key: '', labels: null };
  function labelsTurned() {
    if (!core || data.filesLeftOut) return null;
    const exportSize = { width: data.width, height: data.height };
    const { view, projection } = cameraMatrices(stages[state.stage].rest, exportSize);
    const clip = projection.multiply(view).elements; // column by column
    const rows = [0, 1, 2, 3].flatMap((r) => [0, 1, 2, 3].map((c) => clip[4 * c + r]));
    const shown = JSON.stringify(lesson ? lesson.steps[state.step].shown : null);
    const key = `${state.stage} ${rows.join(' ')} ${data.scene.length} ${shown}`;
    if (turned.key !== key) {
      const outcome = core.placeLabels(data.scene, JSON.stringify(viewOptions()), state.stage, JSON.stringify(rows),
                                       measureRuns, shown);
      turned = { key, labels: outcome.error ? null : JSON.parse(outcome.text) };
    }
    return turned.labels;
  }

  function project(clipFromPoint, point, size) {
    const p = new THREE.Vector4(point[0], point[1], point[2], 1).applyMatrix4(clipFromPoint);
    if (!(p.w > 1e-12)) return null;
    return { x: (p.x / p.w + 1) / 2 * size.width, y: (1 - p.y / p.w) / 2 * size.height };
  }
  const kept = (cut, point) => !cut || cut[0] * point[0] + cut[1] * point[1] + cut[2] * point[2] + cut[3] >= 0;

  // The caption, legend and note where the stage's picture has them (its layout, in export pixels), fitted as it is.
  let placedText = '';
  function placePictureText(size) {
    const layout = stages[state.stage].layout;
    const key = `${state.stage} ${size.width} ${size.height}`;
    if (!layout || key === placedText) return;
    placedText = key;
    const s = fitScale(size);
    const setBox = (element, box) => Object.assign(element.style, {
      left: `${(box[0] - data.width / 2) * s + size.width / 2}px`, top: `${(box[1] - data.height / 2) * s + size.height / 2}px`,
      right: 'auto', bottom: 'auto', maxWidth: 'none', margin: '0' });
    const setText = (element, part) => {
      setBox(element, part.box);
      element.textContent = '';
      part.lines.forEach((line, k) => {
        if (k) element.append('\n');
        const span = document.createElement('span');
        setRichText(span, line);
        element.appendChild(span);
      });
      Object.assign(element.style, { fontSize: `${part.size * s}px`, lineHeight: `${(part.line || 1.25 * part.size) * s}px` });
    };
    setText(document.getElementById('caption'), layout.caption);
    setText(document.getElementById('note'), layout.note);
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

  function drawWorld() {
    if (!shown) return;
    const { frame, atRest, ghost } = shown;
    const size = sizeOf(worldCanvas);
    world.setSize(size.width, size.height, false);
    placePictureText(size);
    const { view, projection } = cameraMatrices(frame, size);
    camera.matrix.getInverse(view);
    camera.matrixWorldNeedsUpdate = true;
    camera.projectionMatrix.copy(projection);
    camera.projectionMatrixInverse.getInverse(projection);
    const stageMatrix = matrixOf(frame.shown);
    const ghostMatrix = ghost ? matrixOf(ghost) : null;
    const cut = frame.cut ? new THREE.Vector4(...frame.cut) : noCut;
    const ratio = window.devicePixelRatio || 1;
    const widthScale = Math.max(1, fitScale(size) * state.zoom) * ratio;
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
    if (frameAxes) frameAxes.visible = atRest;
    // The canonical volume's line of the legend while it is drawn, as in the app.
    document.querySelectorAll('#legend [data-canonical]').forEach((row) => { row.hidden = !(frame.canonical > 0); });
    render(world, worldScene, camera);

    const context = fitOverlay(worldOverlay, size);
    const clipFromStage = projection.clone().multiply(view);
    const clipFromWorld = clipFromStage.clone().multiply(stageMatrix);
    const s = fitScale(size);
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
    if (state.traced) {
      const at = project(clipFromWorld, state.traced, size);
      if (at && kept(frame.cut, state.traced)) {
        context.strokeStyle = cssColor(data.ink);
        context.lineWidth = 2;
        context.beginPath();
        context.arc(at.x, at.y, 7, 0, 2 * Math.PI);
        context.stroke();
      }
    }
    const drawRuns = (runs, x, top, px, weight) => {
      context.textBaseline = 'alphabetic';
      context.font = weight + fontOf(px);
      const baseline = top + context.measureText('Ág').fontBoundingBoxAscent;
      for (const run of runs) {
        context.font = runFont(run, px, weight);
        const shift = run[2] > 0 ? -data.scripts.rise * run[2] * px : -data.scripts.drop * run[2] * px;
        context.fillText(run[0], x, baseline + shift);
        x += context.measureText(run[0]).width;
      }
    };
    const placed = !atRest ? null : userMoved() ? labelsTurned() : stages[state.stage].labels;
    if (placed) {
      // Where the core placed them, as in the app's pictures: export pixels, fitted.
      const place = (x, y) => ({ x: (x - data.width / 2) * s + size.width / 2, y: (y - data.height / 2) * s + size.height / 2 });
      for (const label of placed) {
        const [x0, y0, x1, y1] = label.box;
        const corner = place(x0, y0);
        let px = (label.minor ? data.smallFontSize : data.fontSize) * s;
        const weight = label.minor ? '' : 'bold ';
        const width = runsWidth(context, label.runs, px, weight);
        if (width > (x1 - x0) * s) px *= (x1 - x0) * s / width;
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
      const px = data.fontSize * Math.max(0.6, s);
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
    // Marks in the picture's coordinates: the vanishing lines, the ring around faces that fight for depth.
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

  // ---- Panels -------------------------------------------------------------------
  const list = document.getElementById('stage-list');
  function buildPanels() {
    list.textContent = '';
    stages.forEach((stage, k) => {
      const item = document.createElement('li');
      setRichText(item, stage.list);
      item.tabIndex = -1;
      item.addEventListener('click', () => goTo(k, false));
      list.appendChild(item);
    });
    legend(document.getElementById('legend'), data.legend);
    legend(document.getElementById('projected-legend'), data.projected.legend);
    setRichText(document.getElementById('note'), data.note);
    vertices = floatsOf(data.vertices);
  }
  function legend(element, entries) {
    element.textContent = '';
    for (const entry of entries) {
      const row = document.createElement('div');
      const swatch = document.createElement('i');
      if (entry.swatch === 'line') swatch.style.borderBottom = `3px solid ${cssColor(entry.color, entry.opacity)}`;
      else if (entry.swatch === 'dot') Object.assign(swatch.style, { width: '0.7em', borderRadius: '50%', background: cssColor(entry.color) });
      else swatch.style.background = cssColor(entry.color, Math.max(0.35, entry.opacity));
      const text = document.createElement('span');
      setRichText(text, entry.text);
      row.append(swatch, text);
      if (entry.canonical) row.dataset.canonical = '1';
      element.appendChild(row);
    }
    element.hidden = entries.length === 0;
  }

  function typeset(element, latex) {
    try {
      katex.render(latex, element, { displayMode: true, throwOnError: true });
    } catch (error) {
      element.textContent = latex;
    }
  }
  function format(x) {
    return Math.abs(x) < 1e-12 ? '0' : Number(x.toPrecision(6)).toString();
  }
  function showTrace() {
    const element = document.getElementById('trace');
    if (!state.traced) {
      element.innerHTML = '<p>Click a vertex of an object (or press T) to trace it through the stages.</p>';
      return;
    }
    const table = document.createElement('table');
    table.innerHTML = '<caption>The traced vertex after each stage</caption><tr><th>stage</th><th>x</th><th>y</th><th>z</th><th>w</th></tr>';
    let p = new THREE.Vector4(...state.traced, 1);
    stages.forEach((stage, k) => {
      if (k > 0) p = stage.divides ? (p.w !== 0 ? p.clone().divideScalar(p.w) : p) : p.clone().applyMatrix4(matrixOf(stage.matrix));
      const row = table.insertRow();
      const cell = row.insertCell();
      if (k === 0) cell.textContent = 'world';
      else setRichText(cell, `$${stage.symbolMath}$`);
      for (const value of [p.x, p.y, p.z, p.w]) row.insertCell().textContent = format(value);
      if (k === state.stage) row.style.fontWeight = 'bold';
    });
    element.replaceChildren(table);
  }
  function showPanels() {
    const stage = stages[state.stage];
    list.querySelectorAll('li').forEach((item, k) => {
      if (k === state.stage) item.setAttribute('aria-current', 'step');
      else item.removeAttribute('aria-current');
    });
    setRichText(document.getElementById('matrix-title'), stage.list);
    if (state.stage === 0) {
      document.getElementById('matrix').textContent = 'The world: no matrix yet.';
      document.getElementById('symbolic').textContent = '';
      document.getElementById('cumulative').textContent = '';
    } else {
      const symbolic = document.getElementById('symbolic');
      symbolic.textContent = '';
      if (stage.symbolic) {
        const matrix = document.createElement('div');
        matrix.className = 'symbolic';
        typeset(matrix, stage.symbolic.latex);
        symbolic.appendChild(matrix);
        for (const note of stage.symbolic.notes) {
          const line = document.createElement('p');
          line.className = 'definition';
          setRichText(line, note);
          symbolic.appendChild(line);
        }
      }
      // A lesson step's own form of its stage's matrix: the entries it highlights marked.
      const step = lesson && lesson.steps[state.step];
      const own = step && step.latex && step.latexStage === state.stage && step.scene === shownScene;
      typeset(document.getElementById('matrix'), own ? step.latex : stage.latex);
      typeset(document.getElementById('cumulative'), stage.cumulativeLatex);
    }
    showTrace();
    document.getElementById('live').textContent =
      `Stage ${state.stage} of ${last}: ${stage.listText}.` + (stage.claim ? ' ' + stage.claimText + '.' : '');
    body.dataset.stage = state.stage;
  }

  function showRest(k) {
    if (frameAxes) retire(worldScene, frameAxes);
    const stage = stages[k];
    const axes = { surface: false, positions: stage.frame, color: data.frameColor };
    frameAxes = drawable(geometryOf(axes), axes, 1, 2 * data.primitives.length + 1);
    worldScene.add(frameAxes);
    shown = { frame: stage.rest, atRest: true, ghost: stage.ghost };
    drawWorld();
  }

  // ---- Moving between stages ------------------------------------------------------
  const kStepMilliseconds = 600;
  function goTo(k, animate) {
    k = Math.max(0, Math.min(last, k));
    if (animation) {
      cancelAnimationFrame(animation.request);
      clearTimeout(animation.deadline);
    }
    animation = null;
    const from = state.stage;
    state.stage = k;
    showPanels();
    writeFragment();
    if (!animate || Math.abs(k - from) !== 1) {
      showRest(k);
      body.dataset.moving = '';
      return;
    }
    // The app's transition, frame by frame; stepping back plays it backwards.
    const frames = data.transitions[Math.min(from, k)];
    const backwards = k < from;
    const start = performance.now();
    body.dataset.moving = '1';
    // The step ends on time even where frames are not drawn (a hidden tab, a busy machine).
    const finish = () => {
      if (!animation) return;
      cancelAnimationFrame(animation.request);
      clearTimeout(animation.deadline);
      animation = null;
      body.dataset.moving = '';
      showRest(k);
    };
    const tick = () => {
      const t = Math.min(1, (performance.now() - start) / kStepMilliseconds);
      if (t >= 1) return finish();
      const progress = backwards ? 1 - t : t;
      const index = Math.round(progress * frames.length) - 1;
      shown = { frame: index < 0 ? stages[Math.min(from, k)].rest : frames[index], atRest: false, ghost: null };
      drawWorld();
      animation.request = requestAnimationFrame(tick);
    };
    animation = { request: requestAnimationFrame(tick), deadline: setTimeout(finish, kStepMilliseconds + 100) };
  }
  function play() {
    const button = document.getElementById('play');
    if (playing) {
      clearInterval(playing);
      playing = null;
      button.textContent = 'Play';
      return;
    }
    if (state.stage === last) goTo(0);
    button.textContent = 'Pause';
    playing = setInterval(() => {
      if (state.stage >= last) return play();
      goTo(state.stage + 1, true);
    }, kStepMilliseconds + 900);
  }
  document.getElementById('previous').addEventListener('click', back);
  document.getElementById('next').addEventListener('click', forward);
  document.getElementById('play').addEventListener('click', play);

  function changeView(change) {
    Object.assign(state, change);
    state.pitch = Math.max(-89, Math.min(89, state.pitch));
    state.zoom = Math.max(0.1, Math.min(20, state.zoom));
    writeFragment();
    drawWorld();
  }
  // A lesson steps through its steps; a scene through its stages.
  function forward() { if (lesson) goToStep(state.step + 1); else goTo(state.stage + 1, true); }
  function back() { if (lesson) goToStep(state.step - 1); else goTo(state.stage - 1, true); }
  document.addEventListener('keydown', (event) => {
    if (event.altKey || event.ctrlKey || event.metaKey) return;
    const typing = [HTMLInputElement, HTMLTextAreaElement, HTMLSelectElement].some((kind) => event.target instanceof kind);
    if (typing) return; // typing an answer, a number or code
    const onButton = event.target instanceof Element && !!event.target.closest('button, summary, a, [role=spinbutton]');
    const orbit = event.shiftKey ? 10 : 0;
    switch (event.key) {
      case 'ArrowRight': if (orbit) changeView({ yaw: state.yaw + orbit }); else forward(); break;
      case 'ArrowLeft': if (orbit) changeView({ yaw: state.yaw - orbit }); else back(); break;
      case 'ArrowUp': if (orbit) changeView({ pitch: state.pitch - orbit }); else return; break;
      case 'ArrowDown': if (orbit) changeView({ pitch: state.pitch + orbit }); else return; break;
      case 'PageDown': forward(); break;
      case 'PageUp': case 'Backspace': back(); break;
      case 'Home': if (lesson) goToStep(0); else goTo(0); break;
      case 'End': if (lesson) goToStep(lesson.steps.length - 1); else goTo(last); break;
      case ' ': if (onButton) return; if (lesson) forward(); else play(); break;
      case '+': case '=': changeView({ zoom: state.zoom * 1.25 }); break;
      case '-': changeView({ zoom: state.zoom / 1.25 }); break;
      case '0': changeView({ yaw: 0, pitch: 0, zoom: 1 }); break;
      case 't': case 'T': traceNext(event.shiftKey ? -1 : 1); break;
      default: return;
    }
    event.preventDefault();
  });

  // Drag to orbit, wheel to zoom, click to trace the nearest vertex.
  const worldSection = document.getElementById('world');
  let drag = null;
  worldSection.addEventListener('pointerdown', (event) => {
    drag = { x: event.clientX, y: event.clientY, yaw: state.yaw, pitch: state.pitch, moved: false };
    worldSection.setPointerCapture(event.pointerId);
  });
  worldSection.addEventListener('pointermove', (event) => {
    if (!drag) return;
    const dx = event.clientX - drag.x, dy = event.clientY - drag.y;
    if (Math.hypot(dx, dy) > 3) drag.moved = true;
    if (drag.moved) changeView({ yaw: drag.yaw + dx * 0.4, pitch: drag.pitch + dy * 0.4 });
  });
  worldSection.addEventListener('pointerup', (event) => {
    if (drag && !drag.moved) trace(event);
    drag = null;
  });
  worldSection.addEventListener('wheel', (event) => {
    event.preventDefault();
    changeView({ zoom: state.zoom * Math.pow(1.1, -Math.sign(event.deltaY)) });
  }, { passive: false });

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
    drawWorld();
    if (point) document.getElementById('live').textContent =
      `Traced the vertex (${point.map(format).join(', ')}): its coordinates after each stage are in the table.`;
  }

  // A link pasted into the page open: its scene (if the core has it) and its moment.
  window.addEventListener('hashchange', () => {
    const before = { stage: state.stage, step: state.step };
    readFragment();
    const wanted = { stage: state.stage, step: state.step };
    Object.assign(state, before);
    if (lesson) goToStep(wanted.step, true);
    else if (!(core && openLink())) goTo(wanted.stage);
  });
  window.addEventListener('resize', () => { drawWorld(); drawProjected(); });

  // ---- The core, compiled to WebAssembly ------------------------------------------
  let core = null; // once loaded
  // The scene's numbers as the CLI prints them (`viewpipe pipeline SCENE --json`), or why the core refuses the scene.
  function showOutcome(outcome) {
    if (!outcome.error) {
      document.getElementById('json-left-out').textContent = data.filesLeftOut;
      document.getElementById('pipeline-json').textContent = outcome.pipeline;
    }
    const error = document.getElementById('scene-error');
    error.textContent = outcome.error;
    error.hidden = !outcome.error;
  }
  // The meshes a scene names, into the core's file system under their names.
  function putFiles(files) {
    for (const [path, bytes] of Object.entries(files)) {
      const outcome = core.putFile(path, new Uint8Array(bytesOf(bytes)));
      if (outcome.error) return outcome;
    }
    return { text: '', error: '' };
  }
  function evaluateScene() {
    if (!core) return;
    let outcome = putFiles(data.files);
    if (!outcome.error && !data.filesLeftOut) outcome = core.pipelineJson(data.scene);
    showOutcome({ pipeline: outcome.text, error: outcome.error });
    return outcome.text;
  }

  // Text as the page draws it (drawRuns), measured: the core places labels and lays out captions with this.
  const measuring = document.createElement('canvas').getContext('2d');
  const measured = new Map(); // the same labels come back at every stage and every edit: set a font once
  function measureRuns(runs, px, bold) {
    const key = `${px} ${bold} ${JSON.stringify(runs)}`;
    if (!measured.has(key)) {
      if (measured.size > 10000) measured.clear(); // a long session's edits each bring new numbers
      const weight = bold ? 'bold ' : '';
      measuring.font = weight + fontOf(px);
      const line = measuring.measureText('Ág');
      measured.set(key, [runsWidth(measuring, runs, px, weight), line.fontBoundingBoxAscent + line.fontBoundingBoxDescent]);
    }
    return measured.get(key);
  }

  // The scene evaluated anew by the core: what the page draws and the JSON view; or why the core refuses it.
  // The page's picture as the core lays it out.
  const viewOptions = () => ({ width: data.width, height: data.height, fontSize: data.fontSize, minFontSize: data.minFontSize,
                               lineScale: data.lineScale, fixedFraming: data.fixedFraming, dark: data.dark });
  function evaluateText(text, files, filesLeftOut) {
    const outcome = core.evaluate(text, JSON.stringify(viewOptions()), measureRuns);
    if (outcome.error) return { error: outcome.error };
    const page = Object.assign(JSON.parse(outcome.page), { scene: text, files, filesLeftOut });
    return { page, pipeline: outcome.pipeline, error: '' };
  }
  // ---- Editing the scene ------------------------------------------------------------
  // The view's or the camera's fields, each a text field holding what was typed; every edit is evaluated by the
  // core, which refuses what it cannot use with the field's path and the reason (the last valid picture stays).
  const fields = document.getElementById('scene-fields');
  // The scenes shown, for undo and redo: each with its meshes ({page, pipeline}, as the core evaluated it). Only
  // the scene shown and those the core cannot evaluate again (meshes left out) keep their pages; the others
  // keep their text and files and are evaluated anew when shown.
  const edits = { entries: [], at: -1, gesture: null };
  const kEditsKept = 100;
  let pendingLink = null; // the link's scene until the core has read it
  const originalScene = data.scene; // the page's own: a link holds any other
  const edited = () => data.scene !== originalScene;

  const pathText = (path) =>
    path.reduce((text, part) => typeof part === 'number' ? `${text}[${part}]` : (text ? `${text}.${part}` : part), '');
  // A field's row: its name, its inputs (added by the caller) and its refusal.
  function fieldRow(path, name) {
    const row = document.createElement('div');
    row.className = 'field';
    row.dataset.path = pathText(path);
    const label = document.createElement('label');
    label.textContent = name;
    row.appendChild(label);
    const refusal = document.createElement('p');
    refusal.className = 'field-error';
    refusal.id = `refusal-${row.dataset.path}`;
    refusal.hidden = true;
    row.appendChild(refusal);
    return row;
  }
  function buildFields() {
    fields.textContent = '';
    const scene = JSON.parse(data.scene);
    const root = scene.camera ? 'camera' : 'view';
    // The settings picked from a list (the API, the projection's type, ...), as the core lists them: a choice
    // is the scene with the core's change (switching glFrustum to gluPerspective rewrites its numbers).
    const choices = core ? JSON.parse(core.cameraChoices(data.scene).text || '[]') : [];
    for (const choice of choices) {
      const path = choice.field.split('.');
      const row = fieldRow(path, choice.title);
      const select = document.createElement('select');
      choice.options.forEach((option, k) => select.add(new Option(option, k)));
      select.selectedIndex = choice.chosen;
      select.dataset.path = JSON.stringify(path);
      select.id = `field-${row.dataset.path}`;
      row.querySelector('label').htmlFor = select.id;
      select.addEventListener('change', () => {
        const outcome = core.withCameraChoice(data.scene, choice.field, select.selectedIndex);
        if (outcome.error) {
          clearRefusals();
          select.selectedIndex = choice.chosen; // the camera's own, kept
          showRefusal(outcome.error, select);
          showEdits();
        } else {
          changeScene(outcome.text, select);
        }
      });
      row.insertBefore(select, row.querySelector('.field-error'));
      fields.appendChild(row);
    }
    const chosen = new Set(choices.map((choice) => choice.field));
    // One row per number, list of numbers or text; objects as groups.
    const add = (parent, value, path) => {
      if (chosen.has(pathText(path))) return;
      const numbers = Array.isArray(value) && value.every((v) => typeof v === 'number');
      if (value !== null && typeof value === 'object' && !numbers) {
        const group = document.createElement('fieldset');
        const title = document.createElement('legend');
        title.textContent = path[path.length - 1];
        group.appendChild(title);
        for (const [key, inner] of Object.entries(value)) add(group, inner, [...path, Array.isArray(value) ? Number(key) : key]);
        parent.appendChild(group);
        return;
      }
      const row = fieldRow(path, path[path.length - 1]);
      const label = row.querySelector('label');
      const refusal = row.querySelector('.field-error');
      const items = numbers ? value.map((v, k) => [v, [...path, k]]) : [[value, path]];
      for (const [item, itemPath] of items) {
        const input = document.createElement('input');
        input.type = 'text';
        input.spellcheck = false;
        input.autocomplete = 'off';
        if (typeof item === 'number') input.inputMode = 'decimal';
        input.value = input.defaultValue = typeof item === 'string' ? item : JSON.stringify(item);
        input.dataset.path = JSON.stringify(itemPath);
        input.dataset.kind = typeof item;
        input.setAttribute('aria-label', pathText(itemPath));
        input.addEventListener('change', () => editField(input));
        if (!label.htmlFor) {
          input.id = `field-${row.dataset.path}`;
          label.htmlFor = input.id;
        }
        row.insertBefore(input, refusal);
      }
      parent.appendChild(row);
    };
    add(fields, scene[root], [root]);
  }

  // A field's edit: its typed text put into the scene as written (a JSON number stays that number, digit for
  // digit; other text goes as text, for the core to say what it needs), the scene evaluated.
  // A number as people type it (+5, .5, 5., 007), as JSON writes it, its digits kept; else null.
  function jsonNumberOf(typed) {
    const parts = /^([+-]?)([0-9]*)(?:\.([0-9]*))?([eE][+-]?[0-9]+)?$/.exec(typed);
    if (!parts || !(parts[2] || parts[3])) return null;
    const whole = parts[2].replace(/^0+(?=[0-9])/, '') || '0';
    return (parts[1] === '-' ? '-' : '') + whole + (parts[3] ? '.' + parts[3] : '') + (parts[4] || '');
  }
  function editField(input) {
    const scene = JSON.parse(data.scene);
    const path = JSON.parse(input.dataset.path);
    const typed = input.value.trim();
    let holder = scene;
    for (const part of path.slice(0, -1)) holder = holder[part];
    const marker = '\u0000typed\u0000';
    const number = input.dataset.kind === 'number' ? jsonNumberOf(typed) : null;
    holder[path[path.length - 1]] = number !== null ? marker : typed;
    changeScene(JSON.stringify(scene, null, 2).replace(JSON.stringify(marker), number) + '\n', input);
  }

  function clearRefusals() {
    document.getElementById('editor-error').hidden = true;
    fields.querySelectorAll('.field').forEach((row) => {
      row.querySelector('.field-error').hidden = true;
      row.querySelectorAll('input, select').forEach((input) => {
        input.removeAttribute('aria-invalid');
        input.removeAttribute('aria-describedby');
      });
    });
  }
  // The refusal beside the field it names: the field its path falls in, else the first field under it.
  function showRefusal(error, input) {
    const path = error.slice(0, Math.max(0, error.indexOf(': ')));
    const rows = [...fields.querySelectorAll('.field')];
    const within = (inner, outer) => inner === outer || inner.startsWith(outer + '.') || inner.startsWith(outer + '[');
    const row = rows.find((r) => within(path, r.dataset.path)) || rows.find((r) => path && within(r.dataset.path, path)) ||
                (input && input.closest('.field'));
    if (!row) { // not a field's (a mesh, the scene's objects): under the buttons
      const general = document.getElementById('editor-error');
      general.textContent = error;
      general.hidden = false;
      return;
    }
    // Beside the field it names and, where another was edited (B typed, F named), beside that one too.
    const edited = input && input.closest('.field');
    for (const shown of edited && edited !== row ? [row, edited] : [row]) {
      const refusal = shown.querySelector('.field-error');
      refusal.textContent = error;
      refusal.hidden = false;
      for (const field of shown.querySelectorAll('input, select')) {
        field.setAttribute('aria-invalid', 'true');
        field.setAttribute('aria-describedby', refusal.id);
      }
    }
  }

  // A scene's text, evaluated: shown and kept for undo when the core takes it, else refused beside its field
  // with the last valid picture kept. `files`: the meshes it may name, if not the scene's shown. Whether it was taken.
  // `gesture`: edits of one drag, kept as one undoable edit.
  function changeScene(text, input, files, gesture) {
    if (!core) return false;
    clearRefusals();
    if (!files && data.filesLeftOut) { // the core cannot read meshes the page does not hold
      showRefusal("This page left the scene's meshes out: open the scene with its meshes to change it here.", null);
      showEdits();
      return false;
    }
    const outcome = evaluateText(text, files || data.files, files ? '' : data.filesLeftOut);
    if (outcome.error) {
      showOutcome(outcome);
      showRefusal(outcome.error, input);
      showEdits();
      return false;
    }
    const entry = { page: outcome.page, pipeline: outcome.pipeline, text, files: outcome.page.files };
    if (gesture && gesture === edits.gesture) edits.entries[edits.at] = entry; // the same drag: one edit
    else edits.entries.splice(edits.at + 1, Infinity, entry);
    edits.gesture = gesture || null;
    if (edits.entries.length > kEditsKept) edits.entries.shift();
    edits.at = edits.entries.length - 1;
    showEntry(edits.entries[edits.at], input);
    return true;
  }
  // A scene of the history shown at the stage shown (or `stage`), evaluated anew if it kept no page.
  function showEntry(entry, input, stage = state.stage) {
    if (!entry.page) {
      putFiles(entry.files); // its meshes, for it and the edits that follow
      const outcome = evaluateText(entry.text, entry.files, '');
      Object.assign(entry, { page: outcome.page, pipeline: outcome.pipeline });
    }
    for (const other of edits.entries)
      if (other !== entry && other.page && !other.page.filesLeftOut) other.page = null;
    clearRefusals();
    const index = shownScene;
    page.scenes[index] = entry.page;
    document.getElementById('title').textContent = entry.page.title;
    document.title = `${entry.page.title} · ViewPipe`;
    shownScene = -1;
    useScene(index, true);
    showOutcome({ pipeline: entry.pipeline, error: '' });
    const focused = input && input === document.activeElement ? input.dataset.path : null;
    buildFields();
    if (focused) fields.querySelector(`input[data-path='${focused}'], select[data-path='${focused}']`)?.focus();
    showCode();
    showEdits();
    state.stage = -1;
    goTo(Math.min(stage, last), false);
  }
  function undo() {
    // A refused value is undone first, alone: the fields show the scene shown again.
    if (refused()) {
      clearRefusals();
      buildFields();
      showOutcome({ error: '', pipeline: document.getElementById('pipeline-json').textContent });
      showEdits();
      return;
    }
    if (edits.at <= 0) return;
    edits.at -= 1;
    edits.gesture = null;
    showEntry(edits.entries[edits.at], null);
  }
  function redo() {
    if (edits.at >= edits.entries.length - 1) return;
    edits.at += 1;
    edits.gesture = null;
    showEntry(edits.entries[edits.at], null);
  }
  const refused = () => !!fields.querySelector('[aria-invalid]') || !document.getElementById('editor-error').hidden;
  function showEdits() {
    document.getElementById('undo').disabled = edits.at <= 0 && !refused();
    document.getElementById('redo').disabled = edits.at >= edits.entries.length - 1;
    document.getElementById('link-note').textContent = Object.keys(data.files).length || data.filesLeftOut
      ? 'This scene names mesh files, too large for a link: save it instead.' : '';
  }
  document.getElementById('undo').addEventListener('click', undo);
  document.getElementById('redo').addEventListener('click', redo);
  document.addEventListener('keydown', (event) => {
    if (!(event.ctrlKey || event.metaKey) || event.altKey || lesson) return;
    const key = event.key.toLowerCase();
    // Text typed and not yet applied is the field's own to undo, as in any text field.
    if (event.target instanceof HTMLInputElement && event.target.value !== event.target.defaultValue) return;
    if (event.target instanceof HTMLTextAreaElement) return;
    if (key === 'z' && !event.shiftKey) undo();
    else if (key === 'y' || (key === 'z' && event.shiftKey)) redo();
    else return;
    event.preventDefault();
  });
  // The scene as a file the app opens.
  document.getElementById('save-scene').addEventListener('click', () => {
    download(data.scene, (data.title || 'scene').replace(/[^A-Za-z0-9._-]+/g, '-').replace(/^-+|-+$/g, '').toLowerCase() + '.json');
  });

  // Files opened or dropped: meshes go into the core's file system under their names; a scene (JSON) among them
  // is evaluated with them, and meshes alone are added to the scene shown. The core's readers refuse what they
  // cannot read, with the CLI's messages.
  const meshFile = /\.(obj|ply|stl)$/i;
  let filesBeforeCore = null; // opened or dropped while the core loads: opened once it has
  async function openFiles(list) {
    if (lesson) return;
    const files = [...list];
    if (!core) {
      filesBeforeCore = files;
      return;
    }
    clearRefusals();
    const scene = files.find((f) => /\.json$/i.test(f.name));
    const meshes = files.filter((f) => meshFile.test(f.name));
    const kept = {};
    for (const mesh of meshes) {
      const bytes = new Uint8Array(await mesh.arrayBuffer());
      const outcome = core.putFile(mesh.name, bytes);
      if (outcome.error) return refuseFiles(`${mesh.name}: ${outcome.error}`);
      let binary = '';
      for (let k = 0; k < bytes.length; k += 0x8000) binary += String.fromCharCode(...bytes.subarray(k, k + 0x8000));
      kept[mesh.name] = btoa(binary);
    }
    let text;
    if (scene) {
      text = await scene.text();
    } else if (meshes.length) {
      const shown = JSON.parse(data.scene);
      shown.objects = shown.objects || [];
      for (const mesh of meshes)
        if (!shown.objects.some((o) => o.type === 'mesh' && o.path === mesh.name)) shown.objects.push({ type: 'mesh', path: mesh.name });
      text = JSON.stringify(shown, null, 2) + '\n';
    } else {
      return refuseFiles('Open a scene (.json) or meshes (.obj, .ply, .stl).');
    }
    changeScene(text, null, Object.assign({}, scene ? {} : data.files, kept));
  }
  function refuseFiles(error) {
    showRefusal(error, null);
    showEdits();
  }
  // The app's presets (File > Presets), the scenes without meshes: one opened is an undoable edit.
  const presetPicker = document.getElementById('presets');
  const presetGroups = new Map();
  (page.presets || []).forEach((preset, k) => {
    if (!presetGroups.has(preset.group)) {
      const group = preset.group ? document.createElement('optgroup') : presetPicker;
      if (preset.group) {
        group.label = preset.group;
        presetPicker.appendChild(group);
      }
      presetGroups.set(preset.group, group);
    }
    presetGroups.get(preset.group).appendChild(new Option(preset.name, k));
  });
  document.querySelector('#scene-editor .presets').hidden = !(page.presets || []).length || !!lesson;
  presetPicker.addEventListener('change', () => {
    const preset = page.presets[Number(presetPicker.value)];
    presetPicker.value = '';
    if (preset && core) changeScene(preset.scene, null, {});
  });
  const picker = document.getElementById('open-files');
  document.getElementById('open-scene').addEventListener('click', () => picker.click());
  picker.addEventListener('change', () => { openFiles(picker.files); picker.value = ''; });
  document.querySelector('main').addEventListener('dragover', (event) => { if (!lesson) event.preventDefault(); });
  document.querySelector('main').addEventListener('drop', (event) => {
    if (lesson) return;
    event.preventDefault();
    openFiles(event.dataTransfer.files);
  });

  // The scene in a link: its JSON as UTF-8 in base64url without padding (RFC 4648 §5).
  function base64url(text) {
    let binary = '';
    for (const byte of new TextEncoder().encode(text)) binary += String.fromCharCode(byte);
    return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
  }
  function fromBase64url(text) {
    const binary = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
    return new TextDecoder('utf-8', { fatal: true }).decode(Uint8Array.from(binary, (c) => c.charCodeAt(0)));
  }
  function linkedSceneText() {
    if (pendingLink && !core) return pendingLink;
    return !lesson && edited() && !Object.keys(data.files).length && !data.filesLeftOut ? base64url(data.scene) : null;
  }

  // The scene a link holds, if it is not the one shown: shown at the link's stage. Whether it was taken.
  function openLink() {
    const linked = pendingLink;
    if (!linked || linked === linkedSceneText()) return false;
    let text = null;
    try {
      text = fromBase64url(linked);
    } catch (error) {
      clearRefusals();
      refuseFiles("scene: the link's scene is not UTF-8 text in base64url");
      return false;
    }
    if (!changeScene(text, null)) return false;
    goTo(linkedStage);
    return true;
  }

  let coreFailed = ''; // why the core did not load, if it did not
  ViewPipeCore().catch((error) => {
    coreFailed = `ViewPipe's core could not start in this browser (${error && error.message ? error.message : error}): ` +
      'the stages are shown as exported, but nothing can be changed or checked.';
    const shown = document.getElementById('scene-error');
    shown.textContent = coreFailed;
    shown.hidden = false;
    return null;
  }).then((module) => {
    if (!module) return;
    core = module;
    const pipeline = evaluateScene();
    if (!lesson) {
      for (const dialect of JSON.parse(core.codeDialects()))
        dialectPicker.add(new Option(dialect.title, dialect.name));
      // With the camera's choices, which the core lists; a field being typed in keeps its text and focus.
      const typing = fields.contains(document.activeElement) ? document.activeElement : null;
      buildFields();
      if (typing) {
        const again = fields.querySelector(`[data-path='${typing.dataset.path}']:not(.field)`);
        if (again) { again.value = typing.value; again.focus(); }
      }
      showCode();
      edits.entries = [{ page: data, pipeline, text: data.scene, files: data.files }];
      edits.at = 0;
      openLink();
      showEdits();
      if (filesBeforeCore) openFiles(filesBeforeCore);
    }
    body.dataset.core = '1';
  });

  // ---- The camera as code ------------------------------------------------------------
  // The scene's look-at camera as each library writes it, by the core (the app's Code panel); a marked number
  // is dragged (one undoable edit a drag) or stepped with ↑ ↓, and pasted calls set the camera.
  const codeView = document.getElementById('camera-code');
  const dialectPicker = document.getElementById('code-dialect');
  const codeError = document.getElementById('code-error');
  let code = null; // {text, numbers: [{start, end, field, value, tooltip}]}
  let codeDrag = null; // {index, x, value, gesture, pending, frame}
  let gestures = 0;
  function showCode(focusIndex) {
    if (!core || lesson) return;
    const outcome = core.cameraCode(data.scene, dialectPicker.value);
    const foley = !!outcome.error;
    document.getElementById('code-note').textContent = foley
      ? "This scene's camera is a Foley view (VRP, VPN, VUP, PRP): no graphics API writes it as code."
      : 'Drag a marked number left or right, or select it and press ↑ or ↓: each change is one undoable edit.';
    for (const id of ['camera-code', 'code-paste', 'apply-code']) document.getElementById(id).hidden = foley;
    document.querySelector('#code-editor .dialect').hidden = foley;
    document.querySelector('label[for=code-paste]').hidden = foley;
    codeView.textContent = '';
    code = foley ? null : JSON.parse(outcome.text);
    if (!code) return;
    let at = 0;
    code.numbers.forEach((number, k) => {
      codeView.append(code.text.slice(at, number.start));
      const span = document.createElement('span');
      span.className = 'code-number';
      span.textContent = code.text.slice(number.start, number.end);
      span.title = number.tooltip;
      span.dataset.index = k;
      span.tabIndex = 0;
      span.setAttribute('role', 'spinbutton');
      span.setAttribute('aria-label', number.tooltip);
      span.setAttribute('aria-valuenow', number.value);
      codeView.appendChild(span);
      at = number.end;
    });
    codeView.append(code.text.slice(at));
    if (focusIndex !== undefined) codeView.querySelector(`[data-index='${focusIndex}']`).focus();
  }
  function refuseCode(error) {
    codeError.textContent = error;
    codeError.hidden = !error;
  }
  // A number of the code set: the scene with it, by the core, evaluated; refused with the core's reason.
  function setCodeNumber(index, value, gesture) {
    const number = code.numbers[index];
    if (Object.is(value, number.value)) return;
    const outcome = core.withCodeNumber(data.scene, number.field, value);
    refuseCode(outcome.error);
    if (!outcome.error) changeScene(outcome.text, null, undefined, gesture);
    if (!gesture) showCode(index);
  }
  const numberIndex = (event) => {
    const span = event.target instanceof Element && event.target.closest('.code-number');
    return span ? Number(span.dataset.index) : null;
  };
  codeView.addEventListener('pointerdown', (event) => {
    const index = numberIndex(event);
    if (index === null || event.button !== 0 || !Number.isFinite(code.numbers[index].value)) return;
    event.preventDefault();
    codeView.setPointerCapture(event.pointerId);
    codeDrag = { index, x: event.clientX, value: code.numbers[index].value, gesture: ++gestures, pending: null, frame: 0 };
  });
  codeView.addEventListener('pointermove', (event) => {
    if (!codeDrag) return;
    // A step a pixel; one evaluation a frame, of the last position.
    codeDrag.pending = core.steppedValue(codeDrag.value, Math.round(event.clientX - codeDrag.x));
    if (codeDrag.frame) return;
    codeDrag.frame = requestAnimationFrame(() => {
      const drag = codeDrag;
      if (!drag) return;
      drag.frame = 0;
      setCodeNumber(drag.index, drag.pending, drag.gesture);
    });
  });
  const endDrag = () => {
    if (!codeDrag) return;
    const drag = codeDrag;
    codeDrag = null;
    cancelAnimationFrame(drag.frame);
    if (drag.pending !== null) setCodeNumber(drag.index, drag.pending, drag.gesture);
    showCode(drag.index);
  };
  codeView.addEventListener('pointerup', endDrag);
  codeView.addEventListener('pointercancel', endDrag);
  codeView.addEventListener('keydown', (event) => {
    const index = numberIndex(event);
    const by = { ArrowUp: 1, ArrowDown: -1 }[event.key];
    if (index === null || !by || !Number.isFinite(code.numbers[index].value)) return;
    event.preventDefault();
    event.stopPropagation();
    setCodeNumber(index, core.steppedValue(code.numbers[index].value, by), null);
  });
  dialectPicker.addEventListener('change', () => showCode());
  document.getElementById('apply-code').addEventListener('click', () => {
    const outcome = core.withPastedCode(data.scene, document.getElementById('code-paste').value);
    refuseCode(outcome.error);
    if (!outcome.error) changeScene(outcome.text, null);
  });

  // ---- Scenes and lessons -------------------------------------------------------
  let shownScene = -1;
  // `fromEdit`: made anew from an edit, whose outcome is shown already.
  function useScene(index, fromEdit) {
    placedText = ''; // the new scene's caption, legend and note, even at the same stage
    if (index === shownScene) return;
    shownScene = index;
    data = page.scenes[index];
    stages = data.stages;
    last = stages.length - 1;
    state.traced = null;
    buildViews();
    buildPanels();
    drawProjected();
    if (fromEdit) return;
    evaluateScene();
    if (!lesson) buildFields();
    showCode();
  }

  // Text with inline math between dollar signs, typeset ("\$" is a dollar).
  function setRichText(element, text) {
    element.textContent = '';
    const parts = text.split(/(?<!\\)\$/);
    parts.forEach((part, k) => {
      if (k % 2 === 0) {
        element.append(part.replace(/\\\$/g, '$'));
      } else {
        const math = document.createElement('span');
        try {
          katex.render(part, math, { throwOnError: true });
        } catch (error) {
          math.textContent = part;
        }
        element.appendChild(math);
      }
    });
  }

  const results = []; // one entry per question answered: {step, kind, answer, correct, tries}
  const tries = []; // answers checked, per step
  const closed = []; // per step: its question's answer shown
  function buildLesson() {
    document.getElementById('title').textContent = lesson.title;
    document.getElementById('lesson').hidden = false;
    document.getElementById('scene-editor').hidden = true;
    document.getElementById('code-editor').hidden = true;
    body.classList.add('lesson');
    document.querySelector('header .keys').textContent =
      'Keys: ← → (or Page Up, Page Down, Space) go through the steps, Home and End; Shift+arrows or drag orbit, ' +
      '+ − zoom, 0 resets the view; answer a question, then Check (Enter).';
    document.querySelector('#stepper .buttons #play').hidden = true;
    document.getElementById('save').addEventListener('click', () => {
      download(JSON.stringify({ lesson: lesson.title, answers: results.filter(Boolean) }, null, 2), 'lesson-results.json');
    });
  }

  function matrixLatex(rows) {
    let latex = '\\begin{bmatrix}';
    for (let r = 0; r < 4; ++r)
      latex += rows.slice(4 * r, 4 * r + 4).map(format).join(' & ') + (r < 3 ? ' \\\\ ' : '');
    return latex + '\\end{bmatrix}';
  }

  // The question of a step: the student answers, the answer is checked, then shown.
  function showQuestion(step, index) {
    const box = document.getElementById('question');
    box.textContent = '';
    const question = step.question;
    body.classList.toggle('asking', !!question && !closed[index]);
    if (!question) return;
    const prompt = document.createElement('p');
    prompt.className = 'prompt';
    setRichText(prompt, question.prompt);
    box.appendChild(prompt);
    // Which stage the question is about, where naming it gives nothing away.
    if (question.stage && question.kind !== 'which_stage') {
      const about = document.createElement('p');
      about.className = 'about';
      const symbol = `$${data.stages[question.stage].symbolMath}$`;
      setRichText(about, question.kind === 'entry' ? `The matrix of stage ${question.stage}, ${symbol}.`
                                                   : `After stage ${question.stage}, ${symbol}.`);
      box.appendChild(about);
    }
    const form = document.createElement('form');
    box.appendChild(form);
    const feedback = document.createElement('p');
    feedback.className = 'feedback'; // read through #live, once
    let read = null; // the answer as the core's checkAnswer takes it, or null when none is picked
    const input = (label) => {
      const field = document.createElement('input');
      field.type = 'text';
      field.inputMode = 'decimal';
      field.setAttribute('aria-label', label);
      field.placeholder = label;
      form.appendChild(field);
      return field;
    };
    const picks = (labels) => {
      const group = document.createElement('div');
      group.setAttribute('role', 'radiogroup');
      labels.forEach((label, k) => {
        const option = document.createElement('label');
        const radio = document.createElement('input');
        radio.type = 'radio';
        radio.name = 'answer-' + index;
        radio.value = k;
        option.append(radio, ' ', label);
        group.appendChild(option);
      });
      form.appendChild(group);
      return () => {
        const chosen = form.querySelector('input[type=radio]:checked');
        return chosen ? Number(chosen.value) : null;
      };
    };
    const answerText = question.answerText; // as the app and the handout state it
    switch (question.kind) {
      case 'where': {
        const fields = ['x', 'y', 'z'].map(input);
        read = () => ({ where: fields.map((f) => f.value) });
        break;
      }
      case 'inside': {
        const chosen = picks(['inside the view volume', 'clipped away']);
        read = () => (chosen() === null ? null : { inside: chosen() === 0 });
        break;
      }
      case 'sign_w': {
        const signs = [1, 0, -1];
        const chosen = picks(['positive', 'zero', 'negative']);
        read = () => (chosen() === null ? null : { signW: signs[chosen()] });
        break;
      }
      case 'which_stage': {
        const shownMatrix = document.createElement('div');
        typeset(shownMatrix, matrixLatex(data.stages[question.stage].matrix));
        form.appendChild(shownMatrix);
        // Offered as the app and the handout offer them: the pipeline's order would give the answer's place away.
        const shownOrder = question.offered;
        const chosen = picks(shownOrder.map((k) => {
          const span = document.createElement('span');
          setRichText(span, question.choicesMath[k]);
          return span;
        }));
        read = () => (chosen() === null ? null : { choice: shownOrder[chosen()] });
        break;
      }
      case 'choice': {
        const labels = question.choices.map((choice, k) => {
          const span = document.createElement('span');
          setRichText(span, `${question.letters[k]} ${choice}`); // lettered as in the app and the handout
          return span;
        });
        const chosen = picks(labels);
        read = () => (chosen() === null ? null : { choice: chosen() });
        break;
      }
      case 'entry': {
        const field = input(`entry (${question.row}, ${question.column})`);
        read = () => ({ entry: field.value });
        break;
      }
      case 'order': {
        // The stages offered as the app and the handout offer them, moved with buttons.
        const order = question.offered.slice();
        const listOf = document.createElement('ol');
        listOf.className = 'order';
        const draw = () => {
          listOf.textContent = '';
          order.forEach((k, at) => {
            const item = document.createElement('li');
            const symbol = document.createElement('span');
            setRichText(symbol, question.choicesMath[k]);
            item.append(symbol, ' ');
            for (const [label, by] of [['↑', -1], ['↓', 1]]) {
              const button = document.createElement('button');
              button.type = 'button';
              button.textContent = label;
              button.setAttribute('aria-label', `move ${question.choicesSpoken[k]} ${by < 0 ? 'up' : 'down'}`);
              button.disabled = at + by < 0 || at + by >= order.length;
              button.addEventListener('click', () => {
                [order[at], order[at + by]] = [order[at + by], order[at]];
                draw();
                listOf.querySelectorAll('button')[2 * (at + by) + (by < 0 ? 0 : 1)].focus();
              });
              item.appendChild(button);
            }
            listOf.appendChild(item);
          });
        };
        draw();
        form.appendChild(listOf);
        read = () => ({ order });
        break;
      }
    }
    const check = document.createElement('button');
    check.type = 'submit';
    check.textContent = 'Check';
    form.appendChild(check);
    box.appendChild(feedback);
    const reveal = document.createElement('div');
    reveal.className = 'reveal';
    reveal.hidden = true;
    box.appendChild(reveal);
    const live = document.getElementById('live');
    const say = (text) => { feedback.textContent = text; live.textContent = text; };
    const tryAgain = () => {
      const left = question.tries - tries[index];
      feedback.className = 'feedback wrong';
      feedback.textContent = `Not quite. Try again: ${left === 1 ? 'one more try' : left + ' more tries'} before the answer is shown.`;
    };
    // The question closed: the verdict, the answer, why, and (when just answered) the stage it is about.
    const close = (correct, justAnswered) => {
      form.querySelectorAll('input, button').forEach((control) => { control.disabled = true; });
      setRichText(feedback, correct ? 'Right.' : `Not quite: the answer is ${answerText}.`);
      feedback.className = 'feedback ' + (correct ? 'right' : 'wrong');
      body.classList.remove('asking');
      reveal.hidden = false;
      reveal.textContent = '';
      const said = document.createElement('p');
      setRichText(said, `Answer: ${answerText}.`);
      reveal.appendChild(said);
      if (question.explanation) {
        const why = document.createElement('p');
        setRichText(why, question.explanation);
        reveal.appendChild(why);
      }
      if (!justAnswered) return;
      if (question.point) state.traced = question.point;
      const revealed = revealedStage(step);
      if (revealed !== state.stage) goTo(revealed, true);
      else { showPanels(); drawWorld(); }
      // Read once answered: the verdict, why, and the step's text (kept back while asking: it may hold the answer).
      live.textContent = (correct ? 'Right.' : `Not quite: the answer is ${question.answerPlain}.`) +
        (question.explanation ? ' ' + question.explanationPlain : '') + ' ' + step.captionPlain;
      body.dataset.answered = String(closed.filter(Boolean).length);
    };
    form.addEventListener('submit', (event) => {
      event.preventDefault();
      const typed = read();
      if (!typed) return say('Pick an answer first.');
      if (!core) return say(coreFailed || 'The page is still loading: check again in a moment.');
      // Checked by the core, as the app checks it.
      const outcome = core.checkAnswer(data.scene, question.source, JSON.stringify(typed));
      if (outcome.error === 'answer: unreadable')
        return say('Answer first: every field needs a number (a fraction such as p/q is fine).');
      if (outcome.error) return say(outcome.error);
      const checked = JSON.parse(outcome.text);
      tries[index] = (tries[index] || 0) + 1;
      // The last answer checked, and how many were.
      results[index] = { step: index + 1, kind: question.kind, answer: checked.answer, correct: checked.right, tries: tries[index] };
      if (!checked.right && tries[index] < question.tries) { // tried again, the answer kept back
        tryAgain();
        live.textContent = feedback.textContent;
        return;
      }
      closed[index] = true;
      close(checked.right, true);
    });
    // Back at a step: a closed question stays closed, a try used is said.
    if (closed[index]) close(results[index] ? results[index].correct : false, false);
    else if (tries[index]) tryAgain();
  }
  // The stage a step shows once its question is closed, or all along without one.
  const revealedStage = (step) =>
    step.question && step.question.stage ? Math.max(step.stage, step.question.stage) : step.stage;

  function goToStep(index, jump) {
    index = Math.max(0, Math.min(lesson.steps.length - 1, index));
    const step = lesson.steps[index];
    const sameScene = step.scene === shownScene;
    state.step = index;
    useScene(step.scene);
    Object.assign(state, { yaw: step.yaw, pitch: step.pitch, zoom: step.zoom });
    state.traced = (step.question && step.question.point) || step.trace || null; // the point asked about, as the app marks it
    document.getElementById('step-title').textContent = `Step ${index + 1} of ${lesson.steps.length}`;
    setRichText(document.getElementById('step-caption'), step.caption);
    showQuestion(step, index);
    // Asking about stage K, the view waits before it: the answer comes with K's transition.
    const question = step.question;
    const shownStage = closed[index] ? revealedStage(step)
      : question && question.stage && question.kind !== 'entry' ? Math.min(step.stage, question.stage - 1) : step.stage;
    const from = state.stage;
    if (sameScene && !jump && Math.abs(shownStage - from) === 1) goTo(shownStage, true);
    else goTo(shownStage, false);
    // While a question waits, its step's text is kept back (it may give the answer away), as on the screen.
    document.getElementById('live').textContent = `Step ${index + 1} of ${lesson.steps.length}. ` +
      (step.question && !closed[index] ? 'Question: ' + step.question.promptPlain : step.captionPlain);
  }

  // For scripts (and the browser tests): where a world point is drawn now, in client pixels.
  window.viewpipe = {
    pixelOf(point) {
      const size = sizeOf(worldCanvas);
      const { view, projection } = cameraMatrices(shown.frame, size);
      const at = project(projection.multiply(view).multiply(matrixOf(shown.frame.shown)), point, size);
      const rect = worldCanvas.getBoundingClientRect();
      return at && { x: rect.left + at.x, y: rect.top + at.y };
    },
    // The labels the core places for the view as the user has turned it (export pixels), and the stage's at rest.
    turnedLabels: () => labelsTurned(),
    restLabels: () => stages[state.stage].labels,
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
    goTo(first.stage);
  }
  body.dataset.ready = '1';
})();
