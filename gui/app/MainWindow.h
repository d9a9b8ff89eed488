#pragma once

// The main window: the world view and the projected view, the stage stepper,
// the matrix panel and the parameter panel. Slots forward user intent to the
// Document or the stepper and re-render; the math is in core.

#include <QFont>
#include <QMainWindow>
#include <QPointer>

#include <functional>
#include <memory>
#include <optional>

#include "Document.h"
#include "viewpipe/lesson.hpp"
#include "export/Exporter.h"
#include "painter/ScenePainter.h"

class QAction;
class QActionGroup;
class QLabel;
class QListWidget;
class QMenu;
class QPushButton;
class QScreen;
class QShortcut;
class QSlider;
class QVariantAnimation;
class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;
class vtkRenderer;

namespace viewpipe::gui {

class AccuracyPanel;
class Autosave;
class LessonDocument;
class LessonPanel;
class DepthPanel;
class MatrixPanel;
class CodePanel;
class ParameterPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a scene file; on failure shows the reason and keeps the current scene.
    bool openScene(const QString& path);
    // The same for a scene already read from `path`; `remember` lists it under Open Recent.
    bool openScene(const Scene& scene, const QString& path, bool remember = true);
    bool saveScene(const QString& path);
    // At start: offers the newest scene autosaved by a session that crashed;
    // returns true when it was recovered (open, with its changes unsaved).
    bool offerRecovery();
    Autosave* autosave() { return autosave_; }

    // Stage 0 is the world; stage k is after the k-th matrix. With
    // animate = false the picture jumps there (screenshots, tests).
    void goToStage(int stage, bool animate = true);
    // Plays every stage from the current one (from the world at the end).
    void play();
    int stage() const { return stage_; }
    int stageCount() const;
    bool isAnimating() const;

    // Adds a mesh (OBJ, PLY, STL) to the scene as one undoable edit; a file
    // VTK cannot read is refused with its reason and changes nothing.
    bool importMesh(const QString& path);

    // Writes the scene as one web page; failures are shown, not thrown.
    void exportWebPage(const QString& path);
    // Exports with a progress dialog that can cancel; returns the files written
    // (none when cancelled or failed, with the reason shown).
    std::vector<std::filesystem::path> exportStages(const ExportOptions& options);
    // Edit > Copy Matrix as LaTeX: the current stage's matrix (all of them at stage 0).
    void copyMatrixAsLatex();
    // Edit > Copy View as Image: the world view as it is on screen.
    void copyViewAsImage();
    // View > Classical Projection: a class of seed 001 for the scene's objects, one undoable edit.
    void chooseClassicalProjection();

    // Follows a world point through the stages in the Matrices panel (a click on a vertex does this).
    void traceVertex(const std::optional<Vec3<double>>& point);

    // Lessons (Lesson menu): opening one shows its first step, each step its
    // scene, stage and world view; a question waits at the stage before the
    // one it asks about, with the stage names, matrices and captions hidden,
    // until it is answered or revealed. Failures are shown, not thrown.
    bool openLesson(const QString& path);
    // The same for a lesson already read from `path`.
    bool openLesson(Lesson lesson, const QString& path);
    bool saveLesson(const QString& path);
    bool saveLessonResults(const QString& path);
    // A new lesson whose first step is the current view.
    void newLessonFromView();
    // The current view as a step after the one shown.
    void addLessonStepFromView();
    // The clicker: with a lesson open, the next step (a question not answered
    // yet is revealed first) or the one before; otherwise the next or previous stage.
    void advance(int by);
    LessonDocument* lesson() { return lesson_; }
    LessonPanel* lessonPanel() { return lessonPanel_; }

    // Whether errors also open a message box (besides the status bar).
    void setPopupsEnabled(bool enabled) { popups_ = enabled; }
    void setTheme(Theme theme);
    // The text's size in points; 100 % of `open --text-scale` is kDefaultFontSize.
    static constexpr int kDefaultFontSize = 11;
    // `remember`: kept in the user's settings for the next start.
    void setFontSize(int points, bool remember = true);
    // View > Present (F5): the two views alone, full screen on `screen` (the
    // window's own by default), with the projector theme (light, text half as
    // large again). PageDown, Space and Right step on; PageUp, Backspace and
    // Left step back (a presenter's clicker sends these); B blacks the screen
    // out and back; Esc or F5 leaves, restoring the window as it was.
    void setPresenting(bool on, QScreen* screen = nullptr);
    bool isPresenting() const { return presentation_.has_value(); }
    bool isBlackedOut() const;
    void setProjectedViewVisible(bool visible);
    // Effects menu: turns an effect on or off (with its parameters) as one
    // undoable edit of the scene's effect list.
    void editEffects(const QString& description, const std::function<EffectList(EffectList)>& edit);

    // Brings a dock to the front: "stages", "matrices", "parameters", "accuracy" or "depth".
    void showPanel(const QString& name);
    void renderNow();
    // 1600x950, or less where the screen is smaller: every control stays on screen.
    void fitToScreen();
    // The last error or warning shown (status bar and message box).
    QString lastMessage() const { return lastMessage_; }

    Document* document() { return document_; }
    ParameterPanel* parameters() { return parameters_; }
    CodePanel* codePanel() { return code_; }
    MatrixPanel* matrices() { return matrices_; }
    AccuracyPanel* accuracy() { return accuracy_; }
    DepthPanel* depth() { return depth_; }
    ScenePainter* painter() { return painter_.get(); }
    QListWidget* stageList() { return stageList_; }

protected:
    void closeEvent(QCloseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void buildViews();
    void buildDocks();
    void buildMenus();
    void buildEffectsMenu();
    void fitDocksToText();
    void updateEffectsMenu();
    void onDocumentChanged();
    // The stepper, panels, menus and title from the document, the picture being drawn.
    void refreshWidgets();
    void onCameraEdited(const CameraSpec<double>& camera, const QString& field);
    void startStep();
    void showRestingStage();
    void updateStageWidgets();
    void updateCaptions();
    void updateTitle();
    void showMessage(const QString& text);
    bool confirmDiscard();
    // Saves to the scene's file, asking for a name when it has none (or when asked to).
    bool saveSceneAs(bool askForName = false);
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    void rebuildPresetMenu();
    void pickAt(int x, int y);
    void showLessonStep();
    // The scene just loaded into the document shown: widgets, view and stage anew.
    void showOpenedScene(const QString& path, bool remember);
    // The scene, stage and world view now, as a lesson step.
    LessonStep stepFromView() const;
    bool confirmDiscardLesson();
    bool saveLessonAs(bool askForName = false);
    // While a lesson's question waits: no stage names, matrices or captions.
    bool hidesAnswers() const;

    Document* document_;
    Autosave* autosave_;
    LessonDocument* lesson_;
    LessonPanel* lessonPanel_ = nullptr;
    int shownLessonStep_ = -1; // the step whose view is set up
    int shownGeneration_ = -1; // of the lesson it was in
    bool keepLessonView_ = false; // the step about to be shown is the view on screen
    std::unique_ptr<ScenePainter> painter_;
    QVTKOpenGLNativeWidget* worldWidget_ = nullptr;
    QVTKOpenGLNativeWidget* projectedWidget_ = nullptr;
    vtkGenericOpenGLRenderWindow* worldWindow_ = nullptr;
    vtkGenericOpenGLRenderWindow* projectedWindow_ = nullptr;
    vtkRenderer* worldRenderer_ = nullptr;
    vtkRenderer* projectedRenderer_ = nullptr;

    QListWidget* stageList_ = nullptr;
    QLabel* stagesWait_ = nullptr; // in the list's place while a lesson's question waits
    QSlider* slider_ = nullptr;
    QPushButton* playButton_ = nullptr;
    MatrixPanel* matrices_ = nullptr;
    AccuracyPanel* accuracy_ = nullptr;
    DepthPanel* depth_ = nullptr;
    ParameterPanel* parameters_ = nullptr;
    CodePanel* code_ = nullptr;
    QVariantAnimation* animation_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QMenu* presetMenu_ = nullptr;
    QAction* projectedAction_ = nullptr;
    QAction* clipAction_ = nullptr;
    QAction* divideAction_ = nullptr;
    QAction* cullAction_ = nullptr;
    QAction* reversedAction_ = nullptr;
    QActionGroup* depthGroup_ = nullptr;  // off, or a format: data "bits,float"
    QActionGroup* rasterGroup_ = nullptr; // off, or a size: data QSize

    int stage_ = 0;  // where the picture is, or where the running step started
    int target_ = 0; // where the stepper is going
    int stepMilliseconds_ = 1000;
    std::optional<StageMotion> transition_;
    std::optional<Vec3<double>> traced_;
    int fontSize_ = kDefaultFontSize;
    // What presenting changed, to be restored.
    struct Presentation {
        QByteArray docks, geometry;
        Qt::WindowStates states;
        Theme theme;
        int fontSize;
        QFont appFont; // the widgets' (before any Larger Text, the system's)
    };
    std::optional<Presentation> presentation_;
    QWidget* blackout_ = nullptr;
    QList<QShortcut*> presentingKeys_; // active only while presenting
    bool popups_ = true;
    QString lastMessage_;
};

} // namespace viewpipe::gui
