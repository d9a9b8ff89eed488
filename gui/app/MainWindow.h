#pragma once

// The main window: the world view and the projected view with the panels in
// docks. It wires the roles, which hold the behaviour: the stepper (stages,
// Play), the scene's files, the lesson flow, the exports, present mode, the
// effects menu and the actions by id. The roles are given what they act on
// (the document, the stepper, the views) and the window as Messages, Look and
// their dialogs' parent; none of them knows this class. Widgets forward intent
// to the Document; the math is in core.

#include <QMainWindow>

#include <set>
#include <string>

#include "Document.h"
#include "Look.h"
#include "Messages.h"
#include "painter/ScenePainter.h"

namespace viewpipe::gui {

class AccuracyPanel;
class ActionRegistry;
class CodePanel;
class DepthPanel;
class EffectsMenu;
class Exports;
class LessonFlow;
class LessonPanel;
class MatrixPanel;
class ParameterPanel;
class PresentMode;
class SceneFiles;
class StagePanel;
class Stepper;
class ViewDeck;

class MainWindow : public QMainWindow, public Messages, public Look {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // The roles.
    Document* document() { return document_; }
    Stepper* stepper() { return stepper_; }
    SceneFiles* sceneFiles() { return sceneFiles_; }
    LessonFlow* lessonFlow() { return lessonFlow_; }
    Exports* exports() { return exports_; }
    PresentMode* presentMode() { return presentMode_; }
    const ActionRegistry* actions() const { return actions_; }
    EffectsMenu* effectsMenu() { return effectsMenu_; }

    // The panels and the painter.
    StagePanel* stagePanel() { return stagePanel_; }
    ParameterPanel* parameters() { return parameters_; }
    CodePanel* codePanel() { return code_; }
    MatrixPanel* matrices() { return matrices_; }
    AccuracyPanel* accuracy() { return accuracy_; }
    DepthPanel* depth() { return depth_; }
    LessonPanel* lessonPanel();
    ScenePainter* painter();
    // The layouts of stage views, one shown, and what they draw (the scene, the traced point, what is left out).
    ViewDeck* views() { return views_; }

    // Draws the views shown, or once the last ViewDeck::RenderHold ends if one is held.
    void renderNow();
    // View > Leave Out: what every view leaves out, by the names export --hide takes (for this session).
    void setHidden(const std::set<std::string>& hidden);
    // View > Classical Projection: a class of seed 001 for the scene's objects, one undoable edit.
    void chooseClassicalProjection();

    report::Theme theme() const override;
    void setTheme(report::Theme theme) override;
    // The text's size in points; 100 % of `open --text-scale` is kDefaultFontSize.
    static constexpr int kDefaultFontSize = 11;
    void setFontSize(int points, bool remember = true) override;
    int fontSize() const override { return fontSize_; }
    void setProjectedViewVisible(bool visible);
    // View > Storyboard: every stage at once in place of the world and projected views, or those again.
    // Not while a lesson's question waits: the storyboard names every stage and traces the point.
    void setStoryboardShown(bool shown);
    // Brings a dock to the front: "stages", "matrices", "parameters", "accuracy", "depth" or "code".
    void showPanel(const QString& name);
    // 1600x950, or less where the screen is smaller: every control stays on screen.
    void fitToScreen();

    // Shows an error or warning (status bar and, with popups enabled, a message box).
    void showMessage(const QString& text) override;
    // Whether errors also open a message box (besides the status bar).
    void setPopupsEnabled(bool enabled) { popups_ = enabled; }
    QString lastMessage() const override { return lastMessage_; }
    // In the status bar.
    void showNote(const QString& text, int milliseconds) override;

protected:
    bool event(QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void buildViews();
    void buildDocks();
    void addActions();
    void buildMenus();
    void fitDocksToText();
    void onDocumentChanged();
    // The scene just loaded into the document shown: widgets, view and stage anew;
    // nothing of the scene before (its traced vertex, its measurements) stays.
    void showOpenedScene();
    // The stage panel, matrices and captions for the stage shown and the
    // lesson's question (hidden while it waits); then draws the views.
    void showStageDetails();
    // The lesson's dock, given the room while a lesson is open (not while presenting), hidden once closed.
    void showLessonDock(bool open);
    // The stepper, panels, menus and title from the document, the picture being drawn.
    void refreshWidgets();
    void onCameraEdited(const CameraSpec<double>& camera, const std::map<std::string, std::string>& typed,
                        const QString& field);
    void updateCaptions();
    // The stage panel and the matrices: the stage's, or a note while a lesson's question waits.
    void updateMatrices();
    // While a question waits, the matrices in front (a note) give the views their room; the answer gives it back.
    void updateRoomWhileAsking();
    void fitDockMinimumWidths();
    static int asideMatricesWidth();
    // The traced point's rows, as far as a lesson's step lets them show (none while a question waits).
    void updateTrace();
    void updateTitle();

    Document* document_;
    ActionRegistry* actions_;
    ViewDeck* views_ = nullptr;
    Stepper* stepper_ = nullptr;
    SceneFiles* sceneFiles_ = nullptr;
    LessonFlow* lessonFlow_ = nullptr;
    Exports* exports_ = nullptr;
    PresentMode* presentMode_ = nullptr;
    EffectsMenu* effectsMenu_ = nullptr;

    StagePanel* stagePanel_ = nullptr;
    MatrixPanel* matrices_ = nullptr;
    AccuracyPanel* accuracy_ = nullptr;
    DepthPanel* depth_ = nullptr;
    ParameterPanel* parameters_ = nullptr;
    CodePanel* code_ = nullptr;

    int fontSize_ = kDefaultFontSize;
    bool popups_ = true;
    QString lastMessage_;
    bool matricesAside_ = false;
    int matricesWidth_ = 0; // while they step aside, the matrices' width the answer gives back
};

} // namespace viewpipe::gui
