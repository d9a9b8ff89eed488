#pragma once

// The main window: the world view and the projected view with the panels in
// docks. It wires the roles, which hold the behaviour: the stepper (stages,
// Play), the scene's files, the lesson flow, the exports, present mode, the
// effects menu and the actions by id. Widgets forward intent to the Document;
// the math is in core.

#include <QImage>
#include <QMainWindow>

#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "Document.h"
#include "painter/ScenePainter.h"

class QStackedWidget;

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
class StagePair;
class StagePanel;
class StageViews;
class Stepper;
class StoryboardView;

class MainWindow : public QMainWindow {
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

    // The scene just loaded into the document shown: widgets, view and stage anew;
    // nothing of the scene before (its traced vertex, its measurements) stays.
    void showOpenedScene();
    // The stage panel, matrices and captions for the stage shown and the
    // lesson's question (hidden while it waits); then draws both views.
    void showStageDetails();
    // Draws both views, or once the last RenderHold ends if one is held.
    void renderNow();
    // Held through an operation that changes several things (opening a
    // scene, entering Present): the views are drawn once, at its end.
    class RenderHold {
    public:
        explicit RenderHold(MainWindow& window);
        ~RenderHold();
        RenderHold(const RenderHold&) = delete;
        RenderHold& operator=(const RenderHold&) = delete;

    private:
        MainWindow& window_;
    };
    // The views shown: the world and projected views, or the storyboard.
    StageViews* shownViews() const;
    // Every layout framed as at first, then turned and zoomed (a lesson step's turn).
    void orbitViews(double yaw, double pitch, double zoom);

    // Draws the document's scene in every view, without what the lesson step shown hides and View > Leave Out names.
    void drawScene();
    // The scene every view draws, as drawScene left it.
    const std::shared_ptr<const EvaluatedScene>& shownScene() const { return shown_; }
    // View > Leave Out: what every view leaves out, by the names export --hide takes (for this session).
    void setHidden(const std::set<std::string>& hidden);
    const std::set<std::string>& hidden() const { return hidden_; }
    // Follows a world point through the stages in the Matrices panel (a click on a vertex does this).
    void traceVertex(const std::optional<Vec3<double>>& point);
    const std::optional<Vec3<double>>& traced() const { return traced_; }
    // View > Classical Projection: a class of seed 001 for the scene's objects, one undoable edit.
    void chooseClassicalProjection();

    void setTheme(report::Theme theme);
    // The text's size in points; 100 % of `open --text-scale` is kDefaultFontSize.
    static constexpr int kDefaultFontSize = 11;
    // `remember`: kept in the user's settings for the next start.
    void setFontSize(int points, bool remember = true);
    int fontSize() const { return fontSize_; }
    void setProjectedViewVisible(bool visible);
    // View > Storyboard: every stage at once in place of the world and projected views, or those again.
    // Not while a lesson's question waits: the storyboard names every stage and traces the point.
    void setStoryboardShown(bool shown);
    bool storyboardShown() const;
    StoryboardView* storyboard() { return storyboard_; }
    // Brings a dock to the front: "stages", "matrices", "parameters", "accuracy", "depth" or "code".
    void showPanel(const QString& name);
    // 1600x950, or less where the screen is smaller: every control stays on screen.
    void fitToScreen();

    // Shows an error or warning (status bar and, with popups enabled, a message box).
    void showMessage(const QString& text);
    // Whether errors also open a message box (besides the status bar).
    void setPopupsEnabled(bool enabled) { popups_ = enabled; }
    // The last error or warning shown.
    QString lastMessage() const { return lastMessage_; }
    // Asks about the scene's unsaved changes; false: stay.
    bool confirmDiscard();

protected:
    bool event(QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    int renderHolds_ = 0;
    bool renderWanted_ = false; // asked for while held

    void buildViews();
    void buildDocks();
    void addActions();
    void buildMenus();
    void fitDocksToText();
    void onDocumentChanged();
    // The stepper, panels, menus and title from the document, the picture being drawn.
    void refreshWidgets();
    void onCameraEdited(const CameraSpec<double>& camera, const std::map<std::string, std::string>& typed,
                        const QString& field);
    void updateCaptions();
    // The stage panel and the matrices: the stage's, or a note while a lesson's question waits.
    void updateMatrices();
    // The traced point's rows, as far as a lesson's step lets them show (none while a question waits).
    void updateTrace();
    void updateTitle();

    Document* document_;
    ActionRegistry* actions_;
    // Every layout of stage views; one is shown.
    std::vector<StageViews*> layouts() const;
    QStackedWidget* views_ = nullptr;
    StagePair* pair_ = nullptr; // the world and projected views
    StoryboardView* storyboard_ = nullptr;
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

    std::optional<Vec3<double>> traced_;
    std::shared_ptr<const EvaluatedScene> shown_; // as the views draw it
    std::set<std::string> hidden_;
    int fontSize_ = kDefaultFontSize;
    bool popups_ = true;
    QString lastMessage_;
};

} // namespace viewpipe::gui
