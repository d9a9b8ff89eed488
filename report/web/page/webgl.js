  // page/webgl.js: three.js shaders and materials (the near cut, wide lines), drawables, renderers; both views' scenes.
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
  let frameAxes = []; // each stage's fixed axes, drawn at rest where their stage is

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
    items = [];
    worldScene.background = new THREE.Color(...data.background);
    projectedScene.background = new THREE.Color(...data.projectedBackground);
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
    frameAxes = stages.map((stage) => {
      const axes = { surface: false, positions: stage.frame, color: data.frameColor };
      const object = drawable(geometryOf(axes), axes, 1, 2 * data.primitives.length + 1);
      worldScene.add(object);
      return object;
    });
    const windowOutline = { surface: false, positions: data.projected.window, color: data.projected.windowColor };
    projectedScene.add(drawable(geometryOf(windowOutline), windowOutline, 1, data.primitives.length));
  }

