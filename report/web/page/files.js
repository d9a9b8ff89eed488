  // page/files.js: the scene saved; files opened or dropped; the app's presets; the scene in a link.
  // The scene as a file the app opens.
  document.getElementById('save-scene').addEventListener('click', () => {
    download(data.scene, fileBase() + '.json');
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
    if (!scene && !meshes.length) return refuseFiles('Open a scene (.json) or meshes (.obj, .ply, .stl).');
    // The scene opened, or the one shown with the meshes; each mesh goes where the scene looks for a file of its
    // name (such as ../meshes/letter-f.obj), replacing what was there, else under its name, added to the scene shown.
    let text = scene ? await scene.text() : data.scene;
    const named = JSON.parse(core.meshPaths(text)); // none where it is no scene: the core says why as it reads it
    const wherever = (name) => named.filter((where) => where.split(/[\\/]/).pop() === name);
    const kept = {};
    for (const mesh of meshes) {
      const bytes = new Uint8Array(await mesh.arrayBuffer());
      let binary = '';
      for (let k = 0; k < bytes.length; k += 0x8000) binary += String.fromCharCode(...bytes.subarray(k, k + 0x8000));
      const wanted = wherever(mesh.name);
      for (const where of wanted.length ? wanted : [mesh.name]) {
        const outcome = core.putFile(where, bytes);
        if (outcome.error) return refuseFiles(`${mesh.name}: ${outcome.error}`);
        kept[where] = btoa(binary);
      }
    }
    if (!scene) {
      const shown = JSON.parse(data.scene);
      shown.objects = shown.objects || [];
      for (const mesh of meshes)
        if (!wherever(mesh.name).length) shown.objects.push({ type: 'mesh', path: mesh.name });
      text = JSON.stringify(shown, null, 2) + '\n';
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

