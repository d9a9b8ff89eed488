  // page/stepping.js: moving between stages or steps (goTo, play, forward, back), turning the view: buttons, keys, drag, wheel.
  // ---- Moving between stages ------------------------------------------------------
  const kStepMilliseconds = data.stepMilliseconds; // the app's
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
    // The app's transition, frame by frame; stepping back plays it backwards.
    const frames = animate && Math.abs(k - from) === 1 && !storyboardShown() ? transitionFrames(Math.min(from, k)) : null;
    if (!frames) { // no step, or the storyboard (no world view to move)
      showRest(k);
      body.dataset.moving = '';
      return;
    }
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
      shown = { frame: index < 0 ? stageAt(Math.min(from, k)).rest : frames[index], atRest: false, ghost: null };
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
    keepViewInLimits();
    writeFragment();
    drawShown();
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
      case 's': case 'S': if (lesson) return; toggleLayout(); break;
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

