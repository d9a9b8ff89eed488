#pragma once

// The lesson flow (Lesson menu): opening a lesson shows its first step, each
// step its scene, stage and world view; a question waits at the stage before
// the one it asks about, with the stage names, matrices and captions hidden,
// until it is answered or revealed. Authoring: a new lesson, or a step, from
// the view on screen. Failures are shown, not thrown.

#include <QObject>
#include <QString>

#include <array>
#include <vector>

#include "viewpipe/lesson.hpp"

class QMenu;
class QWidget;

namespace viewpipe::gui {

class ActionRegistry;
class Document;
class LessonDocument;
class LessonPanel;
class Messages;
class SceneFiles;
class Stepper;
class ViewDeck;

class LessonFlow : public QObject {
    Q_OBJECT
public:
    // A step's scene goes into `document`, its stage to `stepper`, its turn, layout and traced point to
    // `views`; `sceneFiles` asks about the scene's unsaved changes; dialogs and progress over `dialogParent`,
    // which owns the role.
    LessonFlow(Document* document, Stepper* stepper, ViewDeck* views, SceneFiles* sceneFiles, Messages& messages,
               QWidget* dialogParent);

    LessonDocument* lesson() { return lesson_; }
    LessonPanel* panel() { return panel_; }

    bool openLesson(const QString& path);
    // The same for a lesson already read from `path`.
    bool openLesson(Lesson lesson, const QString& path);
    bool saveLesson(const QString& path);
    bool saveLessonResults(const QString& path);
    // File ▸ Pack Lesson: the lesson open (as edited) with its scenes and meshes into `folder`, to travel.
    bool packLesson(const QString& folder);
    // A new lesson whose first step is the current view.
    void newLessonFromView();
    // The current view as a step after the one shown.
    void addLessonStepFromView();
    // The clicker: with a lesson open, the next step (a question not answered
    // yet is revealed first) or the one before; otherwise the next or previous stage.
    void advance(int by);
    // Asks about unsaved answers, steps and lesson edits; false: stay.
    bool confirmDiscardLesson();

    // While a lesson's question waits: no stage names, matrices or captions.
    bool hidesAnswers() const;
    // The matrix entries the step shown highlights at `stage` (none at other stages).
    std::vector<std::array<int, 2>> highlightedEntries(int stage) const;
    // The last stage a traced point's rows show with the picture at `stage`: in a lesson, that stage (stepShows).
    int lastTracedStage(int stage) const;
    // A scene as the step shown draws it, without what the step hides (shownAtStep); the scene itself with no
    // step shown. Every drawing of the window goes through it: an edit during a step keeps the step's hide.
    std::shared_ptr<const EvaluatedScene> asShown(const std::shared_ptr<const EvaluatedScene>& scene) const;

    // The Lesson menu's actions ("lesson.open", …) and the menu.
    void addActions(ActionRegistry& actions);
    void fillMenu(QMenu* menu, const ActionRegistry& actions);

signals:
    // A lesson is open and shows a step (true), or closed (false): its dock comes or goes.
    void lessonShown(bool open);
    // A step's scene was loaded into the document without drawing it: the window shows it anew.
    void sceneOpened();
    // The step shown asks for a panel ("matrices", "code", …) to the front.
    void panelWanted(const QString& name);
    // A step is set up, or the lesson closed: the stage's details (names, matrices, captions) follow.
    void stepShown();

private:
    void showLessonStep();
    // What the step shown lets the window show (the core's rule).
    StepShows shows() const;
    // The scene, stage and world view now, as a lesson step.
    LessonStep stepFromView() const;
    bool saveLessonAs(bool askForName = false);
    // Save My Answers: false when cancelled or refused.
    bool chooseAndSaveResults();

    Document* document_;
    Stepper* stepper_;
    ViewDeck* views_;
    SceneFiles* sceneFiles_;
    Messages& messages_;
    QWidget* dialogParent_;
    LessonDocument* lesson_;
    LessonPanel* panel_;
    int shownStep_ = -1;       // the step whose view is set up
    bool shownRevealed_ = false; // whether its answer was shown when it was last shown
    int shownGeneration_ = -1; // of the lesson it was in
    int shownOpening_ = -1;    // the lesson it was in (LessonDocument::openings)
    Scene shownStepScene_;     // its scene as the lesson had it
    std::string shownStepView_; // what it set up in the view besides its scene (stepView)
    QString shownFile_;        // the document's file it was shown on
    std::string drawnLook_;    // what the views leave out and highlight for it (stepShownJson)
    bool sceneDiscardConfirmed_ = false; // openLesson asked before the lesson replaced the scene
    bool keepView_ = false;    // the step about to be shown is the view on screen
};

} // namespace viewpipe::gui
