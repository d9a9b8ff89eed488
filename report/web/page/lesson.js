  // page/lesson.js: a lesson: its steps (goToStep), questions asked, checked and answered, the answers saved.
  // Per step: the last answer checked ({typed, right}; typed as the core's checkAnswer takes it), how many were,
  // and whether its question is closed (answered, or its answer shown without one).
  const checked = [];
  const tries = [];
  const closed = [];
  // While a step's question is open the page shows no stage texts (names, matrices, captions), as the app (stepShows).
  const asking = () => !!lesson && !!lesson.steps[state.step].question && !closed[state.step];
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
    document.getElementById('json-view').hidden = true; // every stage's matrices: later questions' answers
    document.getElementById('save').addEventListener('click', saveResults);
  }

  // The results file as the app writes it, made by the core (resultsToJson).
  function saveResults() {
    const live = document.getElementById('live');
    if (!core) return void (live.textContent = coreFailed || 'The page is still loading: save again in a moment.');
    const steps = lesson.steps.map((step, k) => step.question && {
      scene: page.scenes[step.scene].scene, question: step.question.source,
      given: checked[k] ? checked[k].typed : null, tries: tries[k] || 0, closed: !!closed[k] });
    const outcome = core.lessonResults(lesson.title, JSON.stringify(steps));
    if (outcome.error) return void (live.textContent = outcome.error);
    download(outcome.text, 'lesson-results.json');
  }

  // The question of a step: the student answers, the answer is checked, then shown.
  function showQuestion(step, index) {
    const box = document.getElementById('question');
    box.textContent = '';
    const question = step.question;
    body.classList.toggle('asking', asking());
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
        typeset(shownMatrix, question.matrixLatex); // the core's, exact where it reads so
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
        read = () => ({ order: order.slice() }); // as checked, not as moved after
        break;
      }
    }
    const check = document.createElement('button');
    check.type = 'submit';
    check.textContent = 'Check';
    // For a class that predicted aloud: the answer without one taken; the results record it as revealed.
    const show = document.createElement('button');
    show.type = 'button';
    show.className = 'show-answer';
    show.textContent = 'Show Answer';
    form.append(check, show);
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
    // The question closed: the verdict (right, wrong, or none: shown unanswered), the answer, why, the step's
    // caption, and (when just closed) the stage it is about.
    const close = (verdict, justClosed) => {
      form.querySelectorAll('input, button').forEach((control) => { control.disabled = true; });
      const said = { right: 'Right.', wrong: `Not quite: the answer is ${answerText}.`, shown: `The answer is ${answerText}.` };
      setRichText(feedback, said[verdict]);
      feedback.className = 'feedback ' + verdict;
      body.classList.remove('asking');
      setRichText(document.getElementById('step-caption'), step.caption);
      reveal.hidden = false;
      reveal.textContent = '';
      const answer = document.createElement('p');
      setRichText(answer, `Answer: ${answerText}.`);
      reveal.appendChild(answer);
      if (question.explanation) {
        const why = document.createElement('p');
        setRichText(why, question.explanation);
        reveal.appendChild(why);
      }
      if (!justClosed) return;
      state.traced = step.tracedAnswered;
      if (step.revealedStage !== state.stage) goTo(step.revealedStage, true);
      else { showPanels(); drawWorld(); }
      // Read once answered: the verdict, why, and the step's text (kept back while asking: it may hold the answer).
      const saidPlain = { right: 'Right.', wrong: `Not quite: the answer is ${question.answerPlain}.`,
                          shown: `The answer is ${question.answerPlain}.` };
      live.textContent = saidPlain[verdict] +
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
      // A text that is no number, refused with the core's reason ("z: is empty: ..."): no try counted.
      if (outcome.error) return say(outcome.error + '.');
      const right = JSON.parse(outcome.text).right;
      tries[index] = (tries[index] || 0) + 1;
      checked[index] = { typed, right }; // the last answer checked counts
      if (!right && tries[index] < question.tries) { // tried again, the answer kept back
        tryAgain();
        live.textContent = feedback.textContent;
        return;
      }
      closed[index] = true;
      close(right ? 'right' : 'wrong', true);
    });
    show.addEventListener('click', () => {
      closed[index] = true;
      close(checked[index] ? 'wrong' : 'shown', true); // a wrong try before stays the answer given
    });
    // Back at a step: a closed question stays closed, a try used is said.
    if (closed[index]) close(!checked[index] ? 'shown' : checked[index].right ? 'right' : 'wrong', false);
    else if (tries[index]) tryAgain();
  }

  function goToStep(index, jump) {
    index = Math.max(0, Math.min(lesson.steps.length - 1, index));
    const step = lesson.steps[index];
    const sameScene = step.scene === shownScene;
    state.step = index;
    useScene(step.scene);
    Object.assign(state, { yaw: step.yaw, pitch: step.pitch, zoom: step.zoom });
    state.traced = asking() ? step.tracedAsking : step.tracedAnswered; // the core's rule, as the app marks it
    document.getElementById('step-title').textContent = `Step ${index + 1} of ${lesson.steps.length}`;
    // The caption often says what the answer is: it comes with it (close).
    setRichText(document.getElementById('step-caption'), asking() ? '' : step.caption);
    showQuestion(step, index);
    // Asking about stage K, the view waits before it: the answer comes with K's transition.
    const shownStage = asking() ? step.askingStage : step.revealedStage;
    const from = state.stage;
    if (sameScene && !jump && Math.abs(shownStage - from) === 1) goTo(shownStage, true);
    else goTo(shownStage, false);
    // While a question waits, its step's text is kept back (it may give the answer away), as on the screen.
    document.getElementById('live').textContent = `Step ${index + 1} of ${lesson.steps.length}. ` +
      (step.question && !closed[index] ? 'Question: ' + step.question.promptPlain : step.captionPlain);
  }

