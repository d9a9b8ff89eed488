#include "LessonFlow.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSignalBlocker>

#include <cmath>
#include <utility>

#include "ActionRegistry.h"
#include "AppPaths.h"
#include "Document.h"
#include "LessonDocument.h"
#include "LessonPanel.h"
#include "Messages.h"
#include "SceneFiles.h"
#include "StageViews.h"
#include "Stepper.h"
#include "ViewDeck.h"
#include "Waiting.h"
#include "export/LessonExport.h"
#include "viewpipe/stage.hpp"

namespace viewpipe::gui {

LessonFlow::LessonFlow(Document* document, Stepper* stepper, ViewDeck* views, SceneFiles* sceneFiles, Messages& messages,
                       QWidget* dialogParent)
    : QObject(dialogParent), document_(document), stepper_(stepper), views_(views), sceneFiles_(sceneFiles),
      messages_(messages), dialogParent_(dialogParent), lesson_(new LessonDocument(this)), panel_(new LessonPanel(lesson_))
{
    lesson_->setWorkRunner([dialogParent](const QString& what, const std::function<void()>& work) {
        waitShowingProgress(dialogParent, what, work);
    });
    connect(lesson_, &LessonDocument::stepChanged, this, &LessonFlow::showLessonStep);
    connect(panel_, &LessonPanel::addStepRequested, this, &LessonFlow::addLessonStepFromView);
    connect(panel_, &LessonPanel::saveResultsRequested, this, &LessonFlow::chooseAndSaveResults);
}

bool LessonFlow::hidesAnswers() const
{
    return lesson_->isOpen() && !shows().stageTexts;
}

int LessonFlow::lastTracedStage(int stage) const
{
    return lesson_->isOpen() ? std::min(stage, shows().lastStage) : stepper_->stageCount();
}

namespace {

// What a step sets up in the view besides its scene: what it hides and highlights, its turn, panel and layout.
std::string stepView(const LessonStep& step)
{
    return stepShownJson(step) + " " + std::to_string(step.yaw) + " " + std::to_string(step.pitch) + " " +
           std::to_string(step.zoom) + " " + step.panel + (step.storyboard ? " storyboard" : "");
}

} // namespace

std::shared_ptr<const EvaluatedScene> LessonFlow::asShown(const std::shared_ptr<const EvaluatedScene>& scene) const
{
    // The step's scene, as edited since: not another scene opened while the lesson is open.
    const bool stepShown = lesson_->isOpen() && shownStep_ == lesson_->step() && shownOpening_ == lesson_->openings() &&
                           document_->filePath() == shownFile_;
    return stepShown ? shownAtStep(scene, lesson_->currentStep()) : scene;
}

StepShows LessonFlow::shows() const
{
    const int k = lesson_->step();
    return stepShows(lesson_->currentStep(), lesson_->isRevealed(k), stepper_->stageCount());
}

std::vector<std::array<int, 2>> LessonFlow::highlightedEntries(int stage) const
{
    const bool stepShown =
        lesson_->isOpen() && shownStep_ == lesson_->step() && stage == revealedStage(lesson_->currentStep());
    return stepShown ? lesson_->currentStep().entries : std::vector<std::array<int, 2>>{};
}

void LessonFlow::addActions(ActionRegistry& actions)
{
    actions.add("lesson.open", tr("&Open Lesson…"), [this] {
        if (!confirmDiscardLesson())
            return;
        const QString path = QFileDialog::getOpenFileName(dialogParent_, tr("Open lesson"), lessonsDirectory(), tr("Lessons (*.json)"));
        if (!path.isEmpty())
            openLesson(path);
    }, QKeySequence(Qt::CTRL | Qt::Key_L));
    actions.add("lesson.new", tr("&New Lesson From View"), [this] {
        if (confirmDiscardLesson())
            newLessonFromView();
    });
    actions.add("lesson.save", tr("&Save Lesson"), [this] { saveLessonAs(); });
    actions.add("lesson.saveAs", tr("Save Lesson &As…"), [this] { saveLessonAs(true); });
    actions.add("lesson.addStep", tr("Add Step From &View"), [this] { addLessonStepFromView(); });
    actions.add("lesson.saveAnswers", tr("Save My &Answers…"), [this] { chooseAndSaveResults(); });
    actions.add("lesson.pack", tr("&Pack Lesson…"), [this] {
        if (lesson_->isOpen() && panel_->applyPendingEdits())
            packLesson(QFileDialog::getExistingDirectory(dialogParent_, tr("Pack the lesson into"), dialogPath()));
    });
    actions.add("lesson.close", tr("&Close Lesson"), [this] {
        if (confirmDiscardLesson())
            lesson_->close();
    });
}

void LessonFlow::fillMenu(QMenu* menu, const ActionRegistry& actions)
{
    actions.fill(menu, {"lesson.open"});
    QMenu* builtIn = menu->addMenu(tr("&Built-in Lessons"));
    for (const QFileInfo& info : QDir(lessonsDirectory()).entryInfoList({"*.json"}, QDir::Files, QDir::Name)) {
        QString title = info.completeBaseName();
        try {
            title = QString::fromStdString(loadLesson(info.absoluteFilePath().toStdString()).title);
        } catch (const InputError&) {
            continue; // a broken lesson is not offered
        }
        builtIn->addAction(title, this, [this, path = info.absoluteFilePath()] {
            if (confirmDiscardLesson())
                openLesson(path);
        });
    }
    actions.fill(menu, {"lesson.new", "-", "lesson.save", "lesson.saveAs", "lesson.pack", "lesson.addStep",
                        "lesson.saveAnswers", "lesson.close"});
    // These need a lesson open (Pack Lesson, in the File menu too, is followed there as well).
    connect(menu, &QMenu::aboutToShow, this, [this, &actions] {
        for (const char* id : {"lesson.save", "lesson.saveAs", "lesson.pack", "lesson.addStep", "lesson.saveAnswers", "lesson.close"})
            actions.action(id)->setEnabled(lesson_->isOpen());
    });
}

bool LessonFlow::openLesson(const QString& path)
{
    try {
        return openLesson(loadLesson(path.toStdString()), path);
    } catch (const InputError& e) {
        messages_.showMessage(tr("Cannot open the lesson %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
}

bool LessonFlow::openLesson(Lesson lesson, const QString& path)
{
    // Asked before the lesson replaces the one open: Cancel leaves both the lesson and the scene as they are.
    if (!(lesson.steps.front().scene == document_->scene()) && !sceneFiles_->confirmDiscard())
        return false;
    try {
        // Every step's scene is evaluated now (its meshes read, off the GUI thread): a step that cannot
        // be shown stops nothing later.
        EvaluatedLesson evaluated;
        waitShowingProgress(dialogParent_, tr("Opening %1…").arg(path.isEmpty() ? tr("the lesson") : QFileInfo(path).fileName()),
                            [&] { evaluated = lesson_->evaluate(lesson); });
        sceneDiscardConfirmed_ = true;
        lesson_->open(std::move(lesson), std::move(evaluated), path);
    } catch (const InputError& e) {
        messages_.showMessage(tr("Cannot open the lesson %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    return true;
}

void LessonFlow::showLessonStep()
{
    if (!lesson_->isOpen()) {
        shownStep_ = -1;
        stepper_->setLastStage(std::nullopt);
        emit lessonShown(false);
        drawnLook_.clear();
        views_->drawScene(); // whole again: the last step's hide and highlights go with the lesson
        stepper_->restart();
        emit stepShown();
        return;
    }
    emit lessonShown(true);
    const int k = lesson_->step();
    const LessonStep& step = lesson_->currentStep();
    // Another lesson, another step, or an edit that changed this step's scene: the step's view is set up.
    // An edit of the texts, an answer or a reveal keeps the view, and what the user changed in it.
    const bool sameLesson = lesson_->openings() == shownOpening_;
    const bool newStep = !keepView_ && (!sameLesson || k != shownStep_ || !(step.scene == shownStepScene_) ||
                                        stepView(step) != shownStepView_);
    keepView_ = false;
    const bool sceneConfirmed = std::exchange(sceneDiscardConfirmed_, false);
    bool sameScene = !newStep || step.scene == document_->scene();
    if (!sameScene && !sceneConfirmed && !sceneFiles_->confirmDiscard()) {
        // Cancel changes nothing: a step moved to goes back to the step shown; after an edit of the
        // lesson the view stays as the user left it (openLesson asked before a lesson replaced another).
        if (sameLesson && shownGeneration_ == lesson_->generation() && shownStep_ != k)
            return lesson_->goTo(shownStep_);
        sameScene = true;
    }
    if (!sameScene) { // the step's scene as the lesson evaluated it
        const QString file = QString::fromStdString(step.scene.file.string());
        {
            const QSignalBlocker drawn(document_);
            document_->load(lesson_->stepScene(k), file);
        }
        emit sceneOpened();
    }
    shownStep_ = k;
    shownGeneration_ = lesson_->generation();
    shownOpening_ = lesson_->openings();
    shownStepScene_ = step.scene;
    shownStepView_ = stepView(step);
    shownFile_ = document_->filePath();
    const std::string look = stepShownJson(step);
    if (newStep || look != drawnLook_) {
        if (stepper_->isAnimating())
            stepper_->goToStage(stepper_->target(), false);
        // What the step hides is not drawn, what it highlights is drawn wider; the picture stays at its stage.
        drawnLook_ = look;
        views_->drawScene();
        if (newStep) {
            if (!step.panel.empty())
                emit panelWanted(QString::fromStdString(step.panel));
            views_->orbit(step.yaw, step.pitch, step.zoom);
        }
        stepper_->goToStage(stepper_->stage(), false);
    }
    const bool revealed = !step.question || lesson_->isRevealed(k);
    // A storyboard step shows every stage once its question is answered (the storyboard would answer it).
    // On the step's arrival and its answer's, not on each edit of it (the user's S stays).
    if (newStep || (revealed && !shownRevealed_))
        views_->setStoryboardShown(step.storyboard && revealed);
    shownRevealed_ = revealed;
    views_->traceVertex(tracedAt(step, revealed)); // the point asked about, followed through the stages once answered
    const int stage = revealed ? revealedStage(step) : askingStage(step);
    // The answer comes with the transition to the stage asked about; a step to the next stage plays it too.
    stepper_->setLastStage(std::nullopt);
    stepper_->goToStage(stage, sameScene && (!newStep || std::abs(stage - stepper_->target()) == 1));
    stepper_->setLastStage(shows().lastStage);
    emit stepShown();
}

LessonStep LessonFlow::stepFromView() const
{
    LessonStep step;
    step.scene = document_->scene();
    // A scene with unsaved changes goes into the lesson itself, not as its file.
    step.scene.file = document_->isModified() || document_->filePath().isEmpty()
                          ? std::filesystem::path()
                          : std::filesystem::path(QFileInfo(document_->filePath()).absoluteFilePath().toStdString());
    const int stage = stepper_->target();
    step.stage = stage;
    const ScenePainter::Orbit orbit = views_->shown()->orbitAngles();
    // Readable numbers in the file: a tenth of a degree, a thousandth of the zoom.
    using L = ViewLimits;
    step.yaw = std::clamp(std::round(orbit.yaw * 10) / 10, -L::kYawDegrees, L::kYawDegrees);
    step.pitch = std::clamp(std::round(orbit.pitch * 10) / 10, -L::kPitchDegrees, L::kPitchDegrees);
    step.zoom = std::clamp(std::round(orbit.zoom * 1000) / 1000, L::kMinZoom, L::kMaxZoom);
    // The stage's name, for the author to go on from; not the picture's notes on framing and ghosts.
    step.caption = stageText(document_->pipeline().stages, std::size_t(stage), StageText::Caption);
    step.trace = views_->traced();
    step.storyboard = views_->storyboardShown();
    return step;
}

void LessonFlow::newLessonFromView()
{
    try {
        keepView_ = true;
        lesson_->create(tr("A new lesson").toStdString(), stepFromView());
        panel_->openEditor();
    } catch (const InputError& e) {
        messages_.showMessage(tr("Cannot make a lesson of this view: %1").arg(QString::fromStdString(e.what())));
    }
    keepView_ = false;
}

void LessonFlow::addLessonStepFromView()
{
    if (!lesson_->isOpen())
        return newLessonFromView();
    try {
        keepView_ = true; // the new step's view is the one on screen
        lesson_->insertStep(lesson_->step() + 1, stepFromView());
    } catch (const InputError& e) {
        messages_.showMessage(tr("Cannot add the step: %1").arg(QString::fromStdString(e.what())));
    }
    keepView_ = false;
}

bool LessonFlow::saveLesson(const QString& path)
{
    try {
        lesson_->save(path);
        const auto outside = filesOutside(lesson_->lesson(), QFileInfo(path).absolutePath().toStdString());
        if (outside.empty())
            messages_.showNote(tr("Saved %1").arg(path), 5000);
        else // the lesson works here; elsewhere only with these files
            messages_.showNote(
                tr("Saved %1. It uses %2 from outside its folder, such as %3: to take it to another machine, "
                   "File ▸ Pack Lesson… gathers them with it")
                    .arg(path, outside.size() == 1 ? tr("1 file") : tr("%1 files").arg(outside.size()),
                         QString::fromStdString(outside.front().string())),
                15000);
        return true;
    } catch (const InputError& e) {
        messages_.showMessage(tr("Cannot save the lesson: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
}

bool LessonFlow::saveLessonAs(bool askForName)
{
    if (!panel_->applyPendingEdits())
        return false;
    QString path = lesson_->filePath();
    // A built-in lesson is a copy's starting point, not a file to overwrite.
    if (askForName || path.isEmpty() || isBuiltInFile(path))
        path = chooseFileToSave(dialogParent_, tr("Save lesson"), path.isEmpty() ? "lesson.json" : path, tr("Lessons (*.json)"));
    return !path.isEmpty() && saveLesson(path);
}

bool LessonFlow::packLesson(const QString& folder)
{
    if (folder.isEmpty())
        return false;
    rememberDialogFolder(folder + "/");
    const QString name = lesson_->filePath().isEmpty() ? "lesson.json" : QFileInfo(lesson_->filePath()).fileName();
    if (isBuiltInFile(folder + "/" + name)) {
        messages_.showMessage(tr("Cannot pack the lesson into ViewPipe's own folder %1: choose one of yours").arg(folder));
        return false;
    }
    try {
        packLessonInto(lesson_->lesson(), name.toStdString(), folder.toStdString());
        messages_.showNote(tr("Packed %1 with its scenes and meshes into %2").arg(name, folder), 5000);
        return true;
    } catch (const std::exception& e) { // a refusal, or the file system's
        messages_.showMessage(tr("Cannot pack the lesson: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
}

bool LessonFlow::saveLessonResults(const QString& path)
{
    try {
        lesson_->saveResults(path);
        messages_.showNote(tr("Saved your answers to %1").arg(path), 5000);
        return true;
    } catch (const InputError& e) {
        messages_.showMessage(tr("Cannot save the answers: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
}

bool LessonFlow::chooseAndSaveResults()
{
    const QString path = chooseFileToSave(dialogParent_, tr("Save my answers"), "lesson-results.json", tr("Results (*.json)"));
    return !path.isEmpty() && saveLessonResults(path);
}

bool LessonFlow::confirmDiscardLesson()
{
    if (!panel_->applyPendingEdits()) {
        const auto answer = QMessageBox::question(dialogParent_, tr("Edits not applied"),
                                                  tr("%1\n\nDiscard the step's edits?").arg(messages_.lastMessage()),
                                                  QMessageBox::Discard | QMessageBox::Cancel);
        if (answer != QMessageBox::Discard)
            return false;
        panel_->discardPendingEdits();
    }
    if (lesson_->hasUnsavedAnswers()) {
        const auto answer = QMessageBox::question(dialogParent_, tr("Unsaved answers"),
                                                  tr("Your answers to the lesson's questions are not saved. Save them first?"),
                                                  QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
        if (answer == QMessageBox::Cancel)
            return false;
        if (answer == QMessageBox::Save && !chooseAndSaveResults())
            return false;
    }
    if (!lesson_->isModified())
        return true;
    const auto answer = QMessageBox::question(dialogParent_, tr("Unsaved lesson"),
                                              tr("The lesson has unsaved changes. Save them first?"),
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveLessonAs();
    return answer == QMessageBox::Discard;
}

void LessonFlow::advance(int by)
{
    if (!lesson_->isOpen())
        return stepper_->stepBy(by);
    if (!panel_->applyPendingEdits())
        return;
    if (by > 0 && lesson_->isAsking())
        return lesson_->reveal();
    lesson_->goTo(lesson_->step() + by);
}

} // namespace viewpipe::gui
