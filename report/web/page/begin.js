// page/begin.js: the script opens; the page's data (the scene shown, the lesson) and small helpers every part uses.
// ViewPipe's page: draws the evaluated scene that the export wrote into
// #scene-data. Every matrix, framing, label place and transition frame comes
// from ViewPipe's core and report code, as the app's do: written by the
// export, and made anew by the same code compiled to WebAssembly
// (ViewPipeCore) when the scene is edited. This script only draws them and
// handles input.
(function () {
  'use strict';
  const page = opened(JSON.parse(document.getElementById('scene-data').textContent));
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
  // A lesson's data comes sealed (web_page.cpp): no answer is text in the page's source.
  function opened(data) {
    if (!data.sealed) return data;
    const key = new TextEncoder().encode(data.seal);
    const bytes = new Uint8Array(bytesOf(data.sealed));
    for (let k = 0; k < bytes.length; ++k) bytes[k] ^= key[k % key.length];
    return JSON.parse(new TextDecoder().decode(bytes));
  }
  // Text and hidden set where they differ: the same set again would have the page lay it out again.
  function setText(element, text) {
    if (element.textContent !== text) element.textContent = text;
  }
  function setHidden(element, hidden) {
    if (element.hidden !== hidden) element.hidden = hidden;
  }
  const floatsOf = (base64) => new Float32Array(bytesOf(base64));
  const matrixOf = (rows) => new THREE.Matrix4().set(...rows);
  const cssColor = (c, alpha = 1) =>
    `rgba(${Math.round(c[0] * 255)}, ${Math.round(c[1] * 255)}, ${Math.round(c[2] * 255)}, ${alpha})`;
  const identity = new THREE.Matrix4();

