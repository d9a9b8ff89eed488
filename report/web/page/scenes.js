  // page/scenes.js: the scene shown switched (useScene): both views and the panels built anew.
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
    if (fromEdit) return; // drawn once the edit's panels are set (one layout)
    drawProjected();
    evaluateScene();
    if (!lesson) buildFields();
    showCode();
  }

