  // page/camera-code.js: the camera as code (the app's Code panel): numbers dragged or stepped, pasted calls applied.
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
    setText(document.getElementById('code-note'), foley
      ? "This scene's camera is a Foley view (VRP, VPN, VUP, PRP): no graphics API writes it as code."
      : 'Drag a marked number left or right, or select it and press ↑ or ↓: each change is one undoable edit.');
    for (const id of ['camera-code', 'code-paste', 'apply-code']) setHidden(document.getElementById(id), foley);
    setHidden(document.querySelector('#code-editor .dialect'), foley);
    setHidden(document.querySelector('label[for=code-paste]'), foley);
    const before = code;
    code = foley ? null : JSON.parse(outcome.text);
    // The same code with other numbers (one dragged, or typed in the Scene panel): only the numbers set anew.
    const same = code && before && JSON.stringify(codeBetween(code)) === JSON.stringify(codeBetween(before));
    if (!same && codeView.firstChild) codeView.textContent = '';
    if (!code) return;
    const spans = same ? codeView.querySelectorAll('.code-number') : [];
    const between = codeBetween(code);
    code.numbers.forEach((number, k) => {
      if (!same) codeView.append(between[k]);
      const span = same ? spans[k] : document.createElement('span');
      const text = code.text.slice(number.start, number.end);
      if (span.textContent !== text) span.textContent = text;
      span.title = number.tooltip;
      span.setAttribute('aria-label', number.tooltip);
      span.setAttribute('aria-valuenow', number.value);
      if (same) return;
      span.className = 'code-number';
      span.dataset.index = k;
      span.tabIndex = 0;
      span.setAttribute('role', 'spinbutton');
      codeView.appendChild(span);
    });
    if (!same) codeView.append(between[code.numbers.length]);
    if (focusIndex !== undefined) codeView.querySelector(`[data-index='${focusIndex}']`).focus();
  }
  // The code's text around its numbers: before each, then after the last.
  function codeBetween(written) {
    const ends = [0, ...written.numbers.map((number) => number.end)];
    return [...written.numbers.map((number, k) => written.text.slice(ends[k], number.start)), written.text.slice(ends[ends.length - 1])];
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
    linkHeld = true;
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
    linkHeld = false;
    showCode(drag.index);
    writeFragment();
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

