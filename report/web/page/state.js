  // page/state.js: what is shown (stage, step, orbit, traced vertex, what is drawn), read from and written to the link's fragment.
  // ---- State ------------------------------------------------------------------
  const state = { stage: 0, step: 0, yaw: 0, pitch: 0, zoom: 1, figure: false, traced: null, layout: 'stages',
                  hidden: [], legend: 'best' }; // hidden and legend: the names export's --hide and --legend take
  // What the page was made with (export's --hide, --legend and --zoom): what is drawn at first, and where a link says nothing.
  const madeWith = { hidden: data.chosen.hidden, legend: data.chosen.legend, zoom: data.chosen.zoom };
  let shown = null; // the frame drawn: {frame, atRest, ghost}
  let animation = null;
  let playing = null;
  let linkedStage = 0;
  let linkHeld = false; // while a number is dragged: the link (the scene in base64, ~6 ms an edit) is written once it ends

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
    state.pitch = number('pitch', 0);
    state.zoom = number('zoom', madeWith.zoom);
    keepViewInLimits();
    state.figure = values.has('figure');
    // Every stage at once shows every stage's name and numbers: not in a lesson, whose questions ask for them.
    state.layout = !lesson && values.get('layout') === 'storyboard' ? 'storyboard' : 'stages';
    // What is drawn, by the names the core offers (a lesson's steps say it themselves).
    const offered = (choices, name) => !lesson && choices.some((choice) => choice.name === name);
    state.hidden = values.has('hide')
      ? values.get('hide').split(',').filter((name) => offered(data.hideChoices, name)).sort() : [...madeWith.hidden];
    state.legend = offered(data.legendChoices, values.get('legend')) ? values.get('legend') : madeWith.legend;
    body.classList.toggle('figure', state.figure);
    pendingLink = values.get('scene'); // for the core, once it is loaded
  }
  function writeFragment() {
    if (linkHeld) return;
    const values = new URLSearchParams();
    // A lesson's moment is its step (its stage would name a which_stage answer).
    if (lesson) values.set('step', state.step + 1);
    else values.set('stage', state.stage);
    if (state.yaw) values.set('yaw', state.yaw.toFixed(1));
    if (state.pitch) values.set('pitch', state.pitch.toFixed(1));
    if (state.zoom !== madeWith.zoom) values.set('zoom', state.zoom.toFixed(3));
    if (state.figure) values.set('figure', '');
    if (state.layout === 'storyboard') values.set('layout', 'storyboard');
    if (state.hidden.join(',') !== madeWith.hidden.join(',')) values.set('hide', state.hidden.join(','));
    if (state.legend !== madeWith.legend) values.set('legend', state.legend);
    const linked = linkedSceneText();
    if (linked) values.set('scene', linked);
    history.replaceState(null, '', '#' + values.toString().replace(/=$|=(?=&)/g, ''));
    showChoices();
  }
  // The view turned within the core's limits (the app's and the lesson files').
  function keepViewInLimits() {
    const { pitch, zoom } = data.viewLimits;
    state.pitch = Math.max(-pitch, Math.min(pitch, state.pitch));
    state.zoom = Math.max(zoom[0], Math.min(zoom[1], state.zoom));
  }
  const userMoved = () => state.yaw !== 0 || state.pitch !== 0 || state.zoom !== 1;

