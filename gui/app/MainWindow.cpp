#include "MainWindow.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QClipboard>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QGroupBox>
#include <QRegularExpression>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QPushButton>
#include <QResizeEvent>
#include <QScreen>
#include <QWindow>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QShortcut>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QStyle>
#include <QTabBar>
#include <QTimer>
#include <QVariantAnimation>
#include <QVBoxLayout>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include <map>

#include "AccuracyPanel.h"
#include "AppPaths.h"
#include "Autosave.h"
#include "ClassicalDialog.h"
#include "ClickStyle.h"
#include "DepthPanel.h"
#include "ExportDialog.h"
#include "GuideDialog.h"
#include "LessonDocument.h"
#include "LessonPanel.h"
#include "MathText.h"
#include "viewpipe/report/latex.hpp"
#include "MatrixPanel.h"
#include "CodePanel.h"
#include "ParameterPanel.h"
#include "Theme.h"

namespace viewpipe::gui {
namespace {

constexpr int kStepMilliseconds = 1000;
constexpr int kMaxRecent = 8;

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), document_(new Document(this)), autosave_(new Autosave(document_, this)),
      lesson_(new LessonDocument(this))
{
    setObjectName("ViewPipeMainWindow");
    setAcceptDrops(true);
    buildViews();
    buildDocks();
    buildMenus();

    animation_ = new QVariantAnimation(this);
    animation_->setStartValue(0.0);
    animation_->setEndValue(1.0);
    connect(animation_, &QVariantAnimation::valueChanged, this, [this](const QVariant& v) {
        if (transition_) {
            painter_->showMoment(transition_->at(v.toDouble()));
            // Only the world view moves; the projected view is the same picture at every stage.
            worldWindow_->Render();
            worldWidget_->update();
        }
    });
    connect(animation_, &QVariantAnimation::finished, this, [this] {
        stage_ = transition_->to();
        transition_.reset();
        painter_->setMoving(stage_ != target_); // playing on: the next step starts from this frame
        updateCaptions();
        renderNow();
        if (stage_ != target_)
            startStep();
        else
            playButton_->setText(tr("Play"));
        updateStageWidgets();
    });

    connect(document_, &Document::changed, this, &MainWindow::onDocumentChanged);
    connect(document_, &Document::fileChanged, this, &MainWindow::updateTitle);
    connect(lesson_, &LessonDocument::lessonChanged, this, &MainWindow::updateTitle);
    connect(lesson_, &LessonDocument::stepChanged, this, &MainWindow::showLessonStep);
    connect(parameters_, &ParameterPanel::cameraEdited, this, &MainWindow::onCameraEdited);
    connect(code_, &CodePanel::cameraEdited, this,
            [this](const CameraSpec<double>& camera, const QString& field, int gesture) {
                try {
                    document_->setCamera(camera, tr("Edit %1").arg(field), gesture);
                } catch (const InputError& e) {
                    code_->showError(QString::fromUtf8(e.what())); // the last valid camera stays
                }
            });
    fitToScreen();
}

void MainWindow::fitToScreen()
{
    QSize size(1600, 950);
    if (const QScreen* screen = QGuiApplication::primaryScreen())
        size = size.boundedTo(screen->availableGeometry().size() * 0.95);
    resize(size);
    fitDocksToText();
}

MainWindow::~MainWindow() = default;

void MainWindow::buildViews()
{
    auto makeView = [](QVTKOpenGLNativeWidget*& widget, vtkGenericOpenGLRenderWindow*& window, vtkRenderer*& renderer) {
        widget = new QVTKOpenGLNativeWidget;
        auto renderWindow = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
        widget->setRenderWindow(renderWindow);
        auto r = vtkSmartPointer<vtkRenderer>::New();
        renderWindow->AddRenderer(r);
        window = renderWindow;
        renderer = r;
    };
    makeView(worldWidget_, worldWindow_, worldRenderer_);
    makeView(projectedWidget_, projectedWindow_, projectedRenderer_);
    worldWidget_->setObjectName("worldView");
    projectedWidget_->setObjectName("projectedView");
    worldWidget_->setToolTip(tr("The world view: every element through the stages' matrices so far. "
                                "Drag to turn, wheel to zoom, click a vertex to trace it"));
    projectedWidget_->setToolTip(tr("What the camera sees: the scene projected onto the view plane"));
    worldWidget_->setMinimumSize(260, 260);
    projectedWidget_->setMinimumSize(160, 160);

    // A click picks a vertex to trace; a camera move is kept by later framing.
    auto style = vtkSmartPointer<ClickStyle>::New();
    style->onClick = [this](int x, int y) { pickAt(x, y); };
    style->onCameraMoved = [this] { painter_->rememberUserCamera(); };
    worldWindow_->GetInteractor()->SetInteractorStyle(style);
    // The projected view is a fixed picture: no camera interaction.
    projectedWindow_->GetInteractor()->SetInteractorStyle(nullptr);

    painter_ = std::make_unique<ScenePainter>(worldRenderer_, projectedRenderer_);

    auto* splitter = new QSplitter(Qt::Horizontal);
    splitter->addWidget(worldWidget_);
    splitter->addWidget(projectedWidget_);
    splitter->setStretchFactor(0, 5);
    splitter->setStretchFactor(1, 3);
    splitter->setSizes({500, 300});
    setCentralWidget(splitter);
}

void MainWindow::buildDocks()
{
    auto* stepper = new QWidget;
    auto* v = new QVBoxLayout(stepper);
    stageList_ = new QListWidget;
    stageList_->setObjectName("stageList");
    stageList_->setWordWrap(true);
    stageList_->setItemDelegate(new MathItemDelegate(stageList_));
    stageList_->setToolTip(tr("The stages of the normalizing transformation: pick one to see the scene after its matrix"));
    v->addWidget(stageList_);
    stagesWait_ = new QLabel(tr("<i>The stages' names follow the answer to the lesson's question.</i>"));
    stagesWait_->setObjectName("stagesWait");
    stagesWait_->setWordWrap(true);
    stagesWait_->hide();
    v->addWidget(stagesWait_);
    slider_ = new QSlider(Qt::Horizontal);
    slider_->setObjectName("stageSlider");
    slider_->setPageStep(1);
    slider_->setToolTip(tr("Stage: 0 is the world, k is after the k-th matrix"));
    v->addWidget(slider_);
    auto* buttons = new QHBoxLayout;
    // Short labels: the row fits the dock at any text size.
    auto* previous = new QPushButton(tr("◀"));
    playButton_ = new QPushButton(tr("Play"));
    auto* next = new QPushButton(tr("▶"));
    previous->setObjectName("previousButton");
    playButton_->setObjectName("playButton");
    next->setObjectName("nextButton");
    playButton_->setToolTip(tr("Play every stage from here, one transition a second; Stop holds the stage reached"));
    previous->setToolTip(tr("Previous stage (Left arrow)"));
    next->setToolTip(tr("Next stage (Right arrow)"));
    buttons->addWidget(previous);
    buttons->addWidget(playButton_);
    buttons->addWidget(next);
    v->addLayout(buttons);

    connect(stageList_, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0 && row != target_)
            goToStage(row);
    });
    connect(slider_, &QSlider::valueChanged, this, [this](int value) {
        if (value != target_)
            goToStage(value);
    });
    connect(previous, &QPushButton::clicked, this, [this] { goToStage(target_ - 1); });
    connect(next, &QPushButton::clicked, this, [this] { goToStage(target_ + 1); });
    connect(playButton_, &QPushButton::clicked, this, [this] {
        if (isAnimating())
            goToStage(transition_->to(), false);
        else
            play();
    });
    auto* left = new QShortcut(QKeySequence(Qt::Key_Left), this);
    auto* right = new QShortcut(QKeySequence(Qt::Key_Right), this);
    connect(left, &QShortcut::activated, this, [this] { goToStage(target_ - 1); });
    connect(right, &QShortcut::activated, this, [this] { goToStage(target_ + 1); });
    // A presenter's clicker sends Page Down and Page Up; they step anywhere. Space,
    // Backspace and B would get in the way of typing: only while presenting.
    for (const auto& [key, step] : {std::pair{Qt::Key_PageDown, 1}, std::pair{Qt::Key_PageUp, -1}}) {
        auto* shortcut = new QShortcut(QKeySequence(key), this);
        connect(shortcut, &QShortcut::activated, this, [this, step = step] { advance(step); });
    }
    for (const auto& [key, step] : {std::pair{Qt::Key_Space, 1}, std::pair{Qt::Key_Backspace, -1}}) {
        auto* shortcut = new QShortcut(QKeySequence(key), this);
        connect(shortcut, &QShortcut::activated, this, [this, step = step] { advance(step); });
        presentingKeys_.append(shortcut);
    }
    auto* black = new QShortcut(QKeySequence(Qt::Key_B), this);
    connect(black, &QShortcut::activated, this, [this] {
        blackout_->setGeometry(rect());
        blackout_->raise();
        blackout_->setVisible(!blackout_->isVisible());
    });
    auto* leave = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    connect(leave, &QShortcut::activated, this, [this] { setPresenting(false); });
    presentingKeys_ << black << leave;
    for (QShortcut* shortcut : presentingKeys_)
        shortcut->setEnabled(false);
    blackout_ = new QWidget(this);
    blackout_->setObjectName("blackout");
    blackout_->setStyleSheet("background: black");
    blackout_->setAttribute(Qt::WA_StyledBackground);
    blackout_->hide();

    auto dock = [this](const QString& title, const QString& name, QWidget* content, Qt::DockWidgetArea area) {
        auto* scroll = new QScrollArea;
        // Texts wrap to the dock's width rather than run off to the side.
        scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        scroll->setWidget(content);
        scroll->setWidgetResizable(true);
        auto* d = new QDockWidget(title, this);
        d->setObjectName(name);
        d->setWidget(scroll);
        addDockWidget(area, d);
        return d;
    };
    dock(tr("Stages"), "stagesDock", stepper, Qt::LeftDockWidgetArea);
    matrices_ = new MatrixPanel;
    QDockWidget* matrixDock = dock(tr("Matrices"), "matricesDock", matrices_, Qt::RightDockWidgetArea);
    // The camera's numbers, and below them the same camera as code: two ways to edit one camera, one tab.
    parameters_ = new ParameterPanel;
    code_ = new CodePanel;
    auto* camera = new QWidget;
    auto* cameraLayout = new QVBoxLayout(camera);
    cameraLayout->setContentsMargins(0, 0, 0, 0);
    cameraLayout->addWidget(parameters_);
    auto* codeHeading = new QLabel(tr("<b>The camera as code</b>"));
    codeHeading->setObjectName("codeHeading");
    cameraLayout->addWidget(codeHeading);
    cameraLayout->addWidget(code_);
    QDockWidget* parametersDock = dock(tr("Parameters"), "parametersDock", camera, Qt::RightDockWidgetArea);
    accuracy_ = new AccuracyPanel;
    accuracy_->setSceneSource([this] { return document_->evaluated(); });
    QDockWidget* accuracyDock = dock(tr("Accuracy"), "accuracyDock", accuracy_, Qt::RightDockWidgetArea);
    depth_ = new DepthPanel;
    QDockWidget* depthDock = dock(tr("Depth"), "depthDock", depth_, Qt::RightDockWidgetArea);
    // The 3D view gets the room: parameters and accuracy share the right side with the matrices.
    tabifyDockWidget(matrixDock, parametersDock);
    tabifyDockWidget(matrixDock, accuracyDock);
    tabifyDockWidget(matrixDock, depthDock);
    matrixDock->raise();
    // The lesson under the stages, shown while a lesson is open.
    lessonPanel_ = new LessonPanel(lesson_);
    QDockWidget* lessonDock = dock(tr("Lesson"), "lessonDock", lessonPanel_, Qt::LeftDockWidgetArea);
    lessonDock->hide();
    connect(lessonPanel_, &LessonPanel::addStepRequested, this, &MainWindow::addLessonStepFromView);
    connect(lessonPanel_, &LessonPanel::message, this, &MainWindow::showMessage);
    connect(lessonPanel_, &LessonPanel::saveResultsRequested, this, [this] {
        const QString path = chooseFileToSave(this, tr("Save my answers"), "lesson-results.json", tr("Results (*.json)"));
        if (!path.isEmpty())
            saveLessonResults(path);
    });
    fitDocksToText();
}

void MainWindow::fitDocksToText()
{
    // Widths in units of the text's average character, the views keeping at least 40 % of the window.
    // A dock is never narrower than its content: a scroll area would cut it, not shrink it.
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        if (auto* scroll = qobject_cast<QScrollArea*>(dock->widget()))
            scroll->setMinimumWidth(scroll->widget()->minimumSizeHint().width() +
                                    scroll->verticalScrollBar()->sizeHint().width() + 2 * scroll->frameWidth());
    const QFontMetrics metrics(QApplication::font());
    const int em = metrics.averageCharWidth();
    const double share = std::min(1.0, 0.6 * width() / double(em * (40 + 60)));
    // The right docks' tabs need their titles in full.
    int tabs = 0;
    for (const QTabBar* bar : findChildren<QTabBar*>())
        tabs = std::max(tabs, bar->sizeHint().width() + 2 * em);
    const int right = std::max(int(em * 60 * share), tabs);
    const int left = std::max(int(em * 40 * share), std::min(int(em * 40), int(0.6 * width()) - right));
    resizeDocks({findChild<QDockWidget*>("stagesDock"), findChild<QDockWidget*>("matricesDock")}, {left, right},
                Qt::Horizontal);
}

void MainWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Open…"), this, [this] {
        if (!confirmDiscard())
            return;
        const QString path = chooseFileToOpen(this, tr("Open scene"), tr("Scenes (*.json)"));
        if (!path.isEmpty())
            openScene(path);
    }, QKeySequence::Open);
    presetMenu_ = file->addMenu(tr("&Presets"));
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    file->addAction(tr("&Save"), this, [this] { saveSceneAs(); }, QKeySequence::Save);
    file->addAction(tr("Save &As…"), this, [this] { saveSceneAs(true); }, QKeySequence::SaveAs);
    file->addSeparator();
    file->addAction(tr("&Import Mesh…"), this, [this] {
        const QString path = chooseFileToOpen(this, tr("Import mesh"), tr("Meshes (*.obj *.ply *.stl)"));
        if (!path.isEmpty())
            importMesh(path);
    });
    file->addAction(tr("&Export Stages…"), this, [this] {
        ExportDialog dialog(stageCount(), painter_->theme(), this);
        if (dialog.exec() != QDialog::Accepted)
            return;
        try {
            const auto files = exportStages(dialog.options());
            if (!files.empty())
                statusBar()->showMessage(tr("Exported %1 files to %2")
                                             .arg(files.size())
                                             .arg(QString::fromStdString(files.front().parent_path().string())),
                                         8000);
        } catch (const InputError& e) {
            showMessage(QString::fromStdString(e.what()));
        }
    }, QKeySequence(Qt::CTRL | Qt::Key_E));
    file->addAction(tr("Export as &Web Page…"), this, [this] {
        QString name = QString::fromStdString(document_->scene().name).toLower();
        name = name.replace(QRegularExpression("[^a-z0-9]+"), "-").remove(QRegularExpression("^-+|-+$"));
        const QString path = chooseFileToSave(this, tr("Export as a web page"), (name.isEmpty() ? "scene" : name) + ".html",
                                              tr("Web pages (*.html)"));
        if (!path.isEmpty())
            exportWebPage(path);
    });
    file->addAction(tr("Export CAD &Sheet…"), this, [this] {
        const QString path = chooseFileToSave(this, tr("Export the CAD sheet"), "sheet.png", tr("PNG images (*.png)"));
        if (path.isEmpty())
            return;
        try {
            exportSheet(*document_->evaluated(), path.toStdString(), 1600, 1200, painter_->theme());
            statusBar()->showMessage(tr("Exported %1").arg(path), 6000);
        } catch (const InputError& e) {
            showMessage(QString::fromStdString(e.what()));
        }
    });
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);
    addAction(quit); // also while presenting, the menu bar hidden
    rebuildPresetMenu();
    rebuildRecentMenu();

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcuts({QKeySequence(QKeySequence::Redo), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    edit->addAction(tr("Copy Matrix as &LaTeX"), this, &MainWindow::copyMatrixAsLatex, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
    edit->addAction(tr("Copy View as &Image"), this, &MainWindow::copyViewAsImage, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_I));

    QMenu* view = menuBar()->addMenu(tr("&View"));
    projectedAction_ = view->addAction(tr("&Projected View"), this, &MainWindow::setProjectedViewVisible);
    projectedAction_->setCheckable(true);
    projectedAction_->setChecked(true);
    projectedAction_->setShortcut(QKeySequence(Qt::Key_P));
    view->addAction(tr("&Reset View"), this, [this] {
        painter_->resetView();
        renderNow();
    }, QKeySequence(Qt::Key_R));
    view->addAction(tr("&Classical Projection…"), this, &MainWindow::chooseClassicalProjection,
                    QKeySequence(Qt::CTRL | Qt::Key_K));
    view->addSeparator();
    auto* themes = new QActionGroup(this);
    QAction* dark = view->addAction(tr("&Dark Theme (screen)"), this, [this] { setTheme(Theme::Dark); });
    QAction* light = view->addAction(tr("&Light Theme (slides, print)"), this, [this] { setTheme(Theme::Light); });
    for (QAction* a : {dark, light}) {
        a->setCheckable(true);
        themes->addAction(a);
    }
    dark->setChecked(true);
    view->addSeparator();
    QAction* present = view->addAction(tr("&Present"), this, [this] { setPresenting(!isPresenting()); },
                                       QKeySequence(Qt::Key_F5));
    present->setObjectName("presentAction");
    // Present mode stays reachable with the menu bar hidden.
    addAction(present);
    QMenu* presentOn = view->addMenu(tr("Present &On"));
    connect(presentOn, &QMenu::aboutToShow, this, [this, presentOn] {
        presentOn->clear();
        for (QScreen* screen : QGuiApplication::screens())
            presentOn->addAction(QString("%1 (%2 x %3)").arg(screen->name()).arg(screen->size().width()).arg(screen->size().height()),
                                 this, [this, screen] { setPresenting(true, screen); });
    });
    view->addSeparator();
    view->addAction(tr("&Larger Text"), this, [this] { setFontSize(fontSize_ + 2); }, QKeySequence::ZoomIn);
    view->addAction(tr("&Smaller Text"), this, [this] { setFontSize(fontSize_ - 2); }, QKeySequence::ZoomOut);

    buildEffectsMenu();

    QMenu* lessonMenu = menuBar()->addMenu(tr("&Lesson"));
    lessonMenu->addAction(tr("&Open Lesson…"), this, [this] {
        if (!confirmDiscardLesson())
            return;
        const QString path = QFileDialog::getOpenFileName(this, tr("Open lesson"), lessonsDirectory(), tr("Lessons (*.json)"));
        if (!path.isEmpty())
            openLesson(path);
    }, QKeySequence(Qt::CTRL | Qt::Key_L));
    QMenu* builtIn = lessonMenu->addMenu(tr("&Built-in Lessons"));
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
    lessonMenu->addAction(tr("&New Lesson From View"), this, [this] {
        if (confirmDiscardLesson())
            newLessonFromView();
    });
    lessonMenu->addSeparator();
    // These need a lesson open.
    const QList<QAction*> withLesson = {
        lessonMenu->addAction(tr("&Save Lesson"), this, [this] { saveLessonAs(); }),
        lessonMenu->addAction(tr("Save Lesson &As…"), this, [this] { saveLessonAs(true); }),
        lessonMenu->addAction(tr("Add Step From &View"), this, &MainWindow::addLessonStepFromView),
        lessonMenu->addAction(tr("Save My &Answers…"), lessonPanel_, &LessonPanel::saveResultsRequested),
        lessonMenu->addAction(tr("&Close Lesson"), this, [this] {
            if (confirmDiscardLesson())
                lesson_->close();
        })};
    connect(lessonMenu, &QMenu::aboutToShow, this, [this, withLesson] {
        for (QAction* action : withLesson)
            action->setEnabled(lesson_->isOpen());
    });

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&Guide"), this, [this] { GuideDialog::showFor(this); }, QKeySequence::HelpContents);
    help->addAction(tr("&About ViewPipe"), this, [this] {
        QMessageBox::about(this, tr("About ViewPipe"),
                           tr("<b>ViewPipe</b><p>Step through the 3D viewing pipeline: Foley &amp; van Dam's "
                              "normalizing transformation and the OpenGL forms.</p>"));
    });
}

void MainWindow::buildEffectsMenu()
{
    QMenu* effects = menuBar()->addMenu(tr("E&ffects"));
    effects->setObjectName("effectsMenu");
    effects->setToolTipsVisible(true);
    auto toggle = [this, effects](const QString& text, EffectKind effect, const QString& tip) {
        QAction* action = effects->addAction(text);
        action->setCheckable(true);
        action->setToolTip(tip);
        connect(action, &QAction::triggered, this, [this, effect, text](bool on) {
            editEffects((on ? tr("Turn on %1") : tr("Turn off %1")).arg(QString(text).remove('&')),
                        [effect, on](EffectList list) { return withEffect(std::move(list), effect, on); });
        });
        return action;
    };
    clipAction_ = toggle(tr("&Clip to the View Volume"), EffectKind::Clip,
                         tr("Clip edges and faces in homogeneous coordinates; clipped-away parts are ghosted"));
    divideAction_ = toggle(tr("&Divide (stage M)"), EffectKind::Divide,
                           tr("Append Foley's M (OpenGL: the divide into NDC) as a stage"));
    cullAction_ =
        toggle(tr("Back-Face C&ulling"), EffectKind::Cull, tr("Ghost the faces turned away from the viewer"));

    QMenu* depth = effects->addMenu(tr("Depth &Buffer"));
    depth->setObjectName("depthMenu");
    depthGroup_ = new QActionGroup(this);
    depthGroup_->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    const std::vector<std::pair<QString, QString>> formats = {{tr("Off"), ""},
                                                              {tr("16-bit Fixed Point"), "16,0"},
                                                              {tr("24-bit Fixed Point"), "24,0"},
                                                              {tr("32-bit Fixed Point"), "32,0"},
                                                              {tr("32-bit Float"), "32,1"}};
    for (const auto& [text, data] : formats) {
        QAction* action = depth->addAction(text);
        action->setCheckable(true);
        action->setData(data);
        depthGroup_->addAction(action);
        connect(action, &QAction::triggered, this, [this, text = text, data = data] {
            editEffects(data.isEmpty() ? tr("Turn off the depth buffer") : tr("Depth buffer: %1").arg(text),
                        [data](EffectList list) {
                            if (data.isEmpty())
                                return withEffect(std::move(list), EffectKind::Depth, false);
                            const bool reversed = list.depth && list.depth->reversed;
                            list.depth = DepthOptions{data.section(',', 0, 0).toInt(), data.endsWith('1'), reversed};
                            return withEffect(std::move(list), EffectKind::Depth, true);
                        });
        });
    }
    depth->addSeparator();
    reversedAction_ = depth->addAction(tr("&Reversed Z (near 1, far 0)"));
    reversedAction_->setCheckable(true);
    connect(reversedAction_, &QAction::triggered, this, [this](bool on) {
        editEffects(on ? tr("Reverse the depth buffer") : tr("Unreverse the depth buffer"), [on](EffectList list) {
            list.depth = list.depth.value_or(DepthOptions{});
            list.depth->reversed = on;
            return withEffect(std::move(list), EffectKind::Depth, true);
        });
    });

    QMenu* raster = effects->addMenu(tr("&Raster"));
    raster->setObjectName("rasterMenu");
    rasterGroup_ = new QActionGroup(this);
    rasterGroup_->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    for (const QSize& size : {QSize(), QSize(16, 12), QSize(32, 24), QSize(64, 48), QSize(128, 96)}) {
        const QString text = size.isValid() ? tr("%1 × %2 Pixels").arg(size.width()).arg(size.height()) : tr("Off");
        QAction* action = raster->addAction(text);
        action->setCheckable(true);
        action->setData(size);
        rasterGroup_->addAction(action);
        connect(action, &QAction::triggered, this, [this, size, text] {
            editEffects(size.isValid() ? tr("Raster: %1").arg(text) : tr("Turn off the raster"),
                        [size](EffectList list) {
                            if (!size.isValid())
                                return withEffect(std::move(list), EffectKind::Raster, false);
                            list.raster = RasterOptions{size.width(), size.height()};
                            return withEffect(std::move(list), EffectKind::Raster, true);
                        });
        });
    }
    effects->addSeparator();
    effects->addAction(tr("Show the &Depth Panel"), this, [this] { showPanel("depth"); });
}

void MainWindow::editEffects(const QString& description, const std::function<EffectList(EffectList)>& edit)
{
    try {
        const EffectList next = edit(document_->scene().effects);
        if (!(next == document_->scene().effects))
            document_->setEffects(next, description);
    } catch (const InputError& e) {
        showMessage(QString::fromStdString(e.what()));
    }
    updateEffectsMenu(); // a refused edit leaves the menu as the scene is
}

void MainWindow::updateEffectsMenu()
{
    const EffectList& effects = document_->scene().effects;
    clipAction_->setChecked(effects.has(EffectKind::Clip));
    divideAction_->setChecked(effects.has(EffectKind::Divide));
    cullAction_->setChecked(effects.has(EffectKind::Cull));
    const QString format =
        effects.depth ? QString("%1,%2").arg(effects.depth->bits).arg(effects.depth->floating ? 1 : 0) : QString();
    for (QAction* action : depthGroup_->actions())
        action->setChecked(action->data().toString() == format);
    // A camera with reversed depth reverses the buffer itself (Parameters ▸ Depth).
    const auto* camera = std::get_if<gl::Camera<double>>(&document_->scene().camera);
    const bool cameraReversed = camera && camera->depth == gl::DepthMode::Reversed;
    reversedAction_->setChecked(effects.depth && (effects.depth->reversed || cameraReversed));
    reversedAction_->setEnabled(effects.depth.has_value() && !cameraReversed);
    // A size from the scene file that the menu does not offer leaves all unchecked.
    const QSize size = effects.raster ? QSize(effects.raster->width, effects.raster->height) : QSize();
    for (QAction* action : rasterGroup_->actions())
        action->setChecked(action->data().toSize() == size);
}

bool MainWindow::openScene(const QString& path)
{
    Scene scene;
    try {
        scene = loadScene(path.toStdString());
    } catch (const InputError& e) {
        showMessage(tr("Cannot open %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    return openScene(scene, path);
}

bool MainWindow::openScene(const Scene& scene, const QString& path, bool remember)
{
    try {
        const QSignalBlocker drawn(document_); // the picture is made once, when shown
        document_->load(scene, path);          // a scene the core refuses is not opened
    } catch (const InputError& e) {
        showMessage(tr("Cannot open %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    showOpenedScene(path, remember);
    return true;
}

void MainWindow::showOpenedScene(const QString& path, bool remember)
{
    painter_->setScene(document_->evaluated());
    autosave_->saveNow(); // the previous scene's unsaved edits are not this one's to recover
    // Nothing of the previous scene stays: its traced vertex and measurements are not this one's.
    traceVertex(std::nullopt);
    accuracy_->clear();
    refreshWidgets();
    if (remember && !path.isEmpty())
        addRecent(QFileInfo(path).absoluteFilePath());
    painter_->resetView();
    goToStage(0, false);
}

bool MainWindow::saveSceneAs(bool askForName)
{
    QString path = document_->filePath();
    if (askForName || path.isEmpty())
        path = chooseFileToSave(this, tr("Save scene"), path.isEmpty() ? "scene.json" : path, tr("Scenes (*.json)"));
    return !path.isEmpty() && saveScene(path);
}

bool MainWindow::offerRecovery()
{
    const std::vector<AutosavedScene> orphans = Autosave::orphans();
    if (orphans.empty())
        return false;
    const AutosavedScene& newest = orphans.front();
    const QString name = newest.sourcePath.isEmpty() ? tr("an untitled scene") : newest.sourcePath;
    QMessageBox question(QMessageBox::Question, tr("Recover unsaved changes"),
                         tr("ViewPipe ended unexpectedly while %1 had unsaved changes. Recover them?").arg(name),
                         QMessageBox::Yes | QMessageBox::No, this);
    question.setObjectName("recoveryQuestion");
    question.button(QMessageBox::Yes)->setText(tr("Recover"));
    question.button(QMessageBox::No)->setText(tr("Discard"));
    if (question.exec() != QMessageBox::Yes) {
        Autosave::discard(newest);
        return false;
    }
    try {
        const Scene recovered = loadScene(newest.scenePath.toStdString());
        Scene saved = recovered;
        try {
            if (!newest.sourcePath.isEmpty())
                saved = loadScene(newest.sourcePath.toStdString());
        } catch (const InputError&) {
            // The file is gone or broken: the recovered scene is all there is.
        }
        if (!openScene(recovered, newest.sourcePath))
            return false;
        document_->markRecovered(saved);
        Autosave::discard(newest);
        return true;
    } catch (const std::exception& e) {
        showMessage(tr("Cannot recover %1: %2").arg(name, QString::fromStdString(e.what())));
        return false;
    }
}

bool MainWindow::saveScene(const QString& path)
{
    try {
        document_->save(path);
        addRecent(QFileInfo(path).absoluteFilePath());
        statusBar()->showMessage(tr("Saved %1").arg(path), 4000);
        return true;
    } catch (const std::exception& e) {
        showMessage(tr("Cannot save: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
}

void MainWindow::onDocumentChanged()
{
    painter_->setScene(document_->evaluated());
    painter_->markTraced(traced_);
    refreshWidgets();
}

void MainWindow::refreshWidgets()
{
    parameters_->setCamera(document_->scene().camera);
    code_->setCamera(document_->scene().camera);
    updateEffectsMenu();
    depth_->showDepth(document_->pipeline(), document_->evaluated()->outcomes.depth, painter_->theme());
    const auto& stages = document_->pipeline().stages;
    const QSignalBlocker blockList(stageList_);
    const QSignalBlocker blockSlider(slider_);
    stageList_->clear();
    for (std::size_t k = 0; k <= stages.size(); ++k)
    {
        const std::string entry = stageText(stages, k, StageText::ListEntry);
        auto* item = new QListWidgetItem(QString::fromStdString(mathPlainText(entry)));
        item->setData(MathItemDelegate::kMathRole, QString::fromStdString(entry));
        item->setData(Qt::AccessibleTextRole, QString::fromStdString(mathSpokenText(entry))); // "S sub per", not "S_per"
        stageList_->addItem(item);
    }
    slider_->setRange(0, stageCount());
    animation_->stop();
    transition_.reset();
    stage_ = target_ = std::min(stage_, stageCount());
    showRestingStage();
    updateStageWidgets();
    updateTitle();
}

void MainWindow::onCameraEdited(const CameraSpec<double>& camera, const QString& field)
{
    try {
        document_->setCamera(camera, tr("Edit %1").arg(field));
        parameters_->clearErrors();
    } catch (const InputError& e) {
        // The last valid picture stays; the reason goes next to the field.
        parameters_->showError(QString::fromStdString(e.field()), QString::fromStdString(e.reason()));
    }
}

int MainWindow::stageCount() const
{
    return int(document_->pipeline().stages.size());
}

bool MainWindow::isAnimating() const
{
    return animation_->state() == QAbstractAnimation::Running;
}

void MainWindow::goToStage(int stage, bool animate)
{
    target_ = std::clamp(stage, 0, stageCount());
    if (!animate) {
        animation_->stop();
        transition_.reset();
        stage_ = target_;
        playButton_->setText(tr("Play"));
        showRestingStage();
        updateStageWidgets();
        return;
    }
    stepMilliseconds_ = std::abs(target_ - stage_) > 1 ? 600 : kStepMilliseconds;
    if (!isAnimating() && target_ != stage_)
        startStep(); // a running step carries on, then heads for the new target
    updateStageWidgets();
}

void MainWindow::play()
{
    if (stage_ >= stageCount())
        goToStage(0, false);
    target_ = stageCount();
    stepMilliseconds_ = kStepMilliseconds;
    playButton_->setText(tr("Stop"));
    startStep();
    updateStageWidgets();
}

void MainWindow::startStep()
{
    const int next = stage_ + (target_ > stage_ ? 1 : -1);
    transition_.emplace(*document_->evaluated(), stage_, next);
    painter_->setMoving(true);
    animation_->setDuration(stepMilliseconds_);
    animation_->start();
}

void MainWindow::showRestingStage()
{
    painter_->setMoving(false);
    painter_->showMoment(stageAtRest(*document_->evaluated(), stage_));
    updateCaptions();
    renderNow();
}

void MainWindow::updateCaptions()
{
    painter_->setCaptions(hidesAnswers() ? std::string()
                                         : stageCaption(*document_->evaluated(), std::size_t(stage_), StageText::Caption),
                          tr("What the camera sees").toStdString());
}

void MainWindow::updateStageWidgets()
{
    const QSignalBlocker blockList(stageList_);
    const QSignalBlocker blockSlider(slider_);
    // The stage the picture is at or moving to: Play's last stage waits until the picture gets there.
    const int shown = transition_ ? transition_->to() : stage_;
    stageList_->setCurrentRow(shown);
    if (!slider_->isSliderDown())
        slider_->setValue(shown);
    // A question waits: the stages' names and matrices would answer it.
    const bool waiting = hidesAnswers();
    stageList_->setVisible(!waiting);
    stagesWait_->setVisible(waiting);
    if (waiting) {
        matrices_->showWaiting(tr("<i>The matrices follow the answer to the lesson's question.</i>"));
        return;
    }
    // A lesson step's highlighted entries, while its stage is shown.
    const bool stepShown = lesson_->isOpen() && shownLessonStep_ == lesson_->step() &&
                           stage_ == revealedStage(lesson_->currentStep());
    matrices_->showStage(document_->pipeline(), stage_,
                         stepShown ? lesson_->currentStep().entries : std::vector<std::array<int, 2>>{});
    matrices_->showTrace(document_->pipeline(), traced_, stage_);
}

void MainWindow::renderNow()
{
    worldWindow_->Render();
    if (projectedWidget_->isVisible())
        projectedWindow_->Render();
    worldWidget_->update();
    projectedWidget_->update();
}

void MainWindow::setTheme(Theme theme)
{
    painter_->setTheme(theme);
    accuracy_->setTheme(theme);
    depth_->showDepth(document_->pipeline(), document_->evaluated()->outcomes.depth, theme);
    applyTheme(theme);
    if (!isPresenting()) // the projector's look is not the user's setting
        QSettings().setValue("theme", theme == Theme::Light ? "light" : "dark");
    renderNow();
}

void MainWindow::setPresenting(bool on, QScreen* screen)
{
    if (on == isPresenting())
        return;
    if (on) {
        presentation_ =
            Presentation{saveState(), saveGeometry(), windowState(), painter_->theme(), fontSize_, QApplication::font()};
        for (QDockWidget* dock : findChildren<QDockWidget*>())
            if (dock->objectName() != "lessonDock") // a lesson's caption and questions stay in view
                dock->hide();
        menuBar()->hide();
        statusBar()->hide();
        setTheme(Theme::Light); // black on white carries best on a projector
        setFontSize(std::max(fontSize_ * 3 / 2, 16));
        if (screen && windowHandle())
            windowHandle()->setScreen(screen);
        // The whole screen even where no window manager enlarges a full-screen window.
        if (const QScreen* target = screen ? screen : (windowHandle() ? windowHandle()->screen() : nullptr))
            setGeometry(target->geometry());
        showFullScreen();
    } else {
        const Presentation before = *presentation_;
        presentation_.reset();
        blackout_->hide();
        menuBar()->show();
        statusBar()->show();
        setTheme(before.theme);
        setFontSize(before.fontSize);
        QApplication::setFont(before.appFont);
        setWindowState(before.states);
        restoreGeometry(before.geometry);
        restoreState(before.docks);
    }
    for (QShortcut* shortcut : presentingKeys_)
        shortcut->setEnabled(on);
    // A class sees the lesson, not its editing.
    lessonPanel_->setEditorAvailable(!on);
    renderNow();
}

bool MainWindow::isBlackedOut() const
{
    return blackout_->isVisible();
}

void MainWindow::resizeEvent(QResizeEvent* event)
{
    QMainWindow::resizeEvent(event);
    blackout_->setGeometry(rect());
    blackout_->raise();
}

void MainWindow::setFontSize(int points, bool remember)
{
    fontSize_ = std::clamp(points, 7, 40);
    QFont font = QApplication::font();
    font.setPointSize(fontSize_);
    QApplication::setFont(font);
    // Where the text leaves too little room, the caption and legend may shrink back to the default size.
    painter_->setFontSize(int(std::lround(fontSize_ * 1.6)), int(std::lround(kDefaultFontSize * 1.6)));
    if (remember && !isPresenting())
        QSettings().setValue("fontSize", fontSize_);
    // Once the widgets have taken the new font: the tabs' size hints follow it.
    QTimer::singleShot(0, this, &MainWindow::fitDocksToText);
    renderNow();
}

void MainWindow::showPanel(const QString& name)
{
    const bool code = name == "code"; // below the parameters, in their dock
    if (auto* dock = findChild<QDockWidget*>(code ? QString("parametersDock") : name + "Dock"))
        dock->raise();
    if (code) // once the raised dock is laid out
        QTimer::singleShot(0, this, [this] {
            if (auto* scroll = qobject_cast<QScrollArea*>(findChild<QDockWidget*>("parametersDock")->widget()))
                scroll->ensureWidgetVisible(code_, 0, 0);
        });
}

void MainWindow::setProjectedViewVisible(bool visible)
{
    projectedWidget_->setVisible(visible);
    projectedAction_->setChecked(visible);
    renderNow();
}

void MainWindow::updateTitle()
{
    const QString name = document_->filePath().isEmpty() ? tr("untitled") : QFileInfo(document_->filePath()).fileName();
    QString lesson;
    if (lesson_->isOpen())
        lesson = tr("lesson %1%2 — ")
                     .arg(lesson_->filePath().isEmpty() ? tr("untitled") : QFileInfo(lesson_->filePath()).fileName(),
                          lesson_->isModified() ? "*" : "");
    setWindowTitle(QString("%1%2 — %3ViewPipe").arg(name, document_->isModified() ? "*" : "", lesson));
}

void MainWindow::showMessage(const QString& text)
{
    lastMessage_ = text;
    statusBar()->showMessage(text, 10000);
    if (!isVisible() || !popups_)
        return;
    // Window-modal, not blocking: the event loop (and the picture) carry on.
    auto* box = new QMessageBox(QMessageBox::Warning, tr("ViewPipe"), text, QMessageBox::Ok, this);
    box->setObjectName("errorMessage");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

bool MainWindow::confirmDiscard()
{
    if (!document_->isModified())
        return true;
    const auto answer = QMessageBox::question(this, tr("Unsaved changes"),
                                              tr("The scene has unsaved changes. Save them first?"),
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveSceneAs();
    return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (confirmDiscardLesson() && confirmDiscard())
        event->accept();
    else
        event->ignore();
}

bool MainWindow::importMesh(const QString& path)
{
    SceneObject object;
    object.type = ObjectType::Mesh;
    object.resolvedPath = QFileInfo(path).absoluteFilePath().toStdString();
    object.path = object.resolvedPath.string();
    try {
        document_->addObject(object, tr("Import %1").arg(QFileInfo(path).fileName()));
        return true;
    } catch (const InputError& e) {
        showMessage(tr("Cannot import %1: %2").arg(path, QString::fromStdString(e.reason())));
        return false;
    }
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (event->mimeData()->hasUrls())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    for (const QUrl& url : event->mimeData()->urls()) {
        const QString path = url.toLocalFile();
        const QString suffix = QFileInfo(path).suffix().toLower();
        if (suffix == "json") {
            if (confirmDiscard())
                openScene(path);
        } else if (suffix == "obj" || suffix == "ply" || suffix == "stl") {
            importMesh(path);
        }
    }
}

void MainWindow::addRecent(const QString& path)
{
    QSettings settings;
    QStringList recent = settings.value("recentFiles").toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    settings.setValue("recentFiles", recent);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu()
{
    recentMenu_->clear();
    const QStringList recent = QSettings().value("recentFiles").toStringList();
    for (const QString& path : recent)
        recentMenu_->addAction(path, this, [this, path] {
            if (confirmDiscard())
                openScene(path);
        });
    recentMenu_->setEnabled(!recent.isEmpty());
}

void MainWindow::rebuildPresetMenu()
{
    presetMenu_->clear();
    std::map<std::string, QMenu*> menus = {{"", presetMenu_}};
    for (const Preset& preset : presetScenes(scenesDirectory().toStdString())) {
        QMenu*& menu = menus[preset.group];
        if (!menu)
            menu = presetMenu_->addMenu(QString::fromStdString(preset.group));
        const QString path = QString::fromStdString(preset.scene.file.string());
        menu->addAction(QString::fromStdString(preset.scene.name), this, [this, path] {
            if (confirmDiscard())
                openScene(path);
        });
    }
}

void MainWindow::chooseClassicalProjection()
{
    Eigen::AlignedBox<double, 3> box = document_->evaluated()->objectBounds();
    if (box.isEmpty())
        box = Eigen::AlignedBox<double, 3>(Vec3<double>(-1, -1, -1), Vec3<double>(1, 1, 1));
    ClassicalDialog dialog(box.min(), box.max(), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    try {
        document_->setCamera(dialog.view(), tr("Classical projection: %1").arg(dialog.kindName()));
    } catch (const InputError& e) {
        showMessage(QString::fromStdString(e.what()));
    }
}

std::vector<std::filesystem::path> MainWindow::exportStages(const ExportOptions& options)
{
    QProgressDialog progress(tr("Exporting stages…"), tr("Cancel"), 0, 100, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(0);
    std::atomic<bool> cancel{false};
    try {
        auto files = gui::exportStages(
            document_->evaluated(), options,
            [&progress, &cancel](int done, int total, const std::string& what) {
                progress.setMaximum(total);
                progress.setValue(done);
                progress.setLabelText(QString::fromStdString(what));
                QApplication::processEvents(); // keeps the window alive and Cancel clickable
                cancel = progress.wasCanceled();
            },
            cancel);
        progress.setValue(progress.maximum());
        return files;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        showMessage(tr("Export failed; nothing was written: %1").arg(e.what()));
        return {};
    }
}

void MainWindow::exportWebPage(const QString& path)
{
    QProgressDialog progress(tr("Exporting the web page…"), tr("Cancel"), 0, 100, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(0);
    std::atomic<bool> cancel{false};
    try {
        QDir().mkpath(QFileInfo(path).absolutePath());
        gui::exportWebPage(
            document_->evaluated(), path.toStdString(), painter_->theme(),
            [&progress, &cancel](int done, int total, const std::string& what) {
                progress.setMaximum(total);
                progress.setValue(done);
                progress.setLabelText(QString::fromStdString(what));
                QApplication::processEvents();
                cancel = progress.wasCanceled();
            },
            cancel);
        progress.setValue(progress.maximum());
        if (!cancel)
            statusBar()->showMessage(tr("Exported %1: open it in any browser").arg(path), 8000);
    } catch (const std::exception& e) {
        showMessage(tr("Export failed; nothing was written: %1").arg(e.what()));
    }
}

void MainWindow::copyMatrixAsLatex()
{
    if (hidesAnswers()) {
        showMessage(tr("The matrices follow the answer to the lesson's question."));
        return;
    }
    const std::string latex = stage_ == 0 ? cli::matricesLatex(document_->scene(), 4)
                                          : cli::stageLatex(document_->scene(), stage_, 4);
    QApplication::clipboard()->setText(QString::fromStdString(latex));
    statusBar()->showMessage(tr("Copied the matrix as LaTeX"), 4000);
}

void MainWindow::copyViewAsImage()
{
    renderNow();
    QApplication::clipboard()->setImage(worldWidget_->grabFramebuffer());
    statusBar()->showMessage(tr("Copied the view as an image"), 4000);
}

void MainWindow::pickAt(int x, int y)
{
    traceVertex(painter_->pickVertex(x, y));
}

void MainWindow::traceVertex(const std::optional<Vec3<double>>& point)
{
    traced_ = point;
    painter_->markTraced(traced_);
    matrices_->showTrace(document_->pipeline(), traced_, stage_);
    renderNow();
}

} // namespace viewpipe::gui

namespace viewpipe::gui {

bool MainWindow::hidesAnswers() const
{
    return lesson_->isAsking();
}

bool MainWindow::openLesson(const QString& path)
{
    try {
        return openLesson(loadLesson(path.toStdString()), path);
    } catch (const InputError& e) {
        showMessage(tr("Cannot open the lesson %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
}

bool MainWindow::openLesson(Lesson lesson, const QString& path)
{
    try {
        // Every step's scene is evaluated now (its meshes read): a step that cannot be shown stops nothing later.
        lesson_->open(std::move(lesson), path);
    } catch (const InputError& e) {
        showMessage(tr("Cannot open the lesson %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    return true;
}

void MainWindow::showLessonStep()
{
    auto* dock = findChild<QDockWidget*>("lessonDock");
    if (!lesson_->isOpen()) {
        shownLessonStep_ = -1;
        dock->hide();
        updateStageWidgets();
        updateCaptions();
        renderNow();
        return;
    }
    if (!dock->isVisible() && !isPresenting()) {
        dock->show();
        // The lesson's text and questions get the room; the stage list needs little.
        resizeDocks({findChild<QDockWidget*>("stagesDock"), dock}, {height() / 3, 2 * height() / 3}, Qt::Vertical);
    }
    dock->show();
    dock->raise();
    const int k = lesson_->step();
    const LessonStep& step = lesson_->currentStep();
    // Otherwise the step shown was just answered or revealed, or is the view on screen just added.
    const bool newStep = !keepLessonView_ && (k != shownLessonStep_ || lesson_->generation() != shownGeneration_);
    keepLessonView_ = false;
    const bool sameScene = step.scene == document_->scene();
    if (!sameScene && !confirmDiscard()) {
        // The lesson and the view must agree: back to the step shown, or no lesson at all.
        if (shownLessonStep_ >= 0 && shownGeneration_ == lesson_->generation() && shownLessonStep_ != k)
            lesson_->goTo(shownLessonStep_);
        else if (shownLessonStep_ < 0 || shownGeneration_ != lesson_->generation())
            lesson_->close();
        return;
    }
    if (!sameScene) { // the step's scene as the lesson evaluated it
        const QString file = QString::fromStdString(step.scene.file.string());
        {
            const QSignalBlocker drawn(document_);
            document_->load(lesson_->stepScene(k), file);
        }
        showOpenedScene(file, false);
    }
    shownLessonStep_ = k;
    shownGeneration_ = lesson_->generation();
    if (newStep || !sameScene) {
        if (isAnimating())
            goToStage(target_, false);
        // What the step hides is not drawn, what it highlights is drawn wider; the picture stays at its stage.
        painter_->setScene(shownAtStep(document_->evaluated(), step));
        if (!step.panel.empty())
            showPanel(QString::fromStdString(step.panel));
        painter_->resetView();
        painter_->orbit(step.yaw, step.pitch, step.zoom);
        showRestingStage();
    }
    const bool revealed = !step.question || lesson_->isRevealed(k);
    traceVertex(tracedAt(step)); // the point asked about, followed through the stages once answered
    const int stage = revealed ? revealedStage(step) : askingStage(step);
    // The answer comes with the transition to the stage asked about; a step to the next stage plays it too.
    goToStage(stage, sameScene && (!newStep || std::abs(stage - target_) == 1));
    updateStageWidgets();
    updateCaptions();
    renderNow();
}

LessonStep MainWindow::stepFromView() const
{
    LessonStep step;
    step.scene = document_->scene();
    // A scene with unsaved changes goes into the lesson itself, not as its file.
    step.scene.file = document_->isModified() || document_->filePath().isEmpty()
                          ? std::filesystem::path()
                          : std::filesystem::path(QFileInfo(document_->filePath()).absoluteFilePath().toStdString());
    step.stage = target_;
    const ScenePainter::Orbit orbit = painter_->orbitAngles();
    // Readable numbers in the file: a tenth of a degree, a thousandth of the zoom.
    step.yaw = std::clamp(std::round(orbit.yaw * 10) / 10, -180.0, 180.0);
    step.pitch = std::clamp(std::round(orbit.pitch * 10) / 10, -89.0, 89.0);
    step.zoom = std::clamp(std::round(orbit.zoom * 1000) / 1000, 0.1, 20.0);
    // The stage's name, for the author to go on from; not the picture's notes on framing and ghosts.
    step.caption = stageText(document_->pipeline().stages, std::size_t(target_), StageText::Caption);
    step.trace = traced_;
    return step;
}

void MainWindow::newLessonFromView()
{
    try {
        keepLessonView_ = true;
        lesson_->create(tr("A new lesson").toStdString(), stepFromView());
        lessonPanel_->openEditor();
    } catch (const InputError& e) {
        showMessage(tr("Cannot make a lesson of this view: %1").arg(QString::fromStdString(e.what())));
    }
    keepLessonView_ = false;
}

void MainWindow::addLessonStepFromView()
{
    if (!lesson_->isOpen())
        return newLessonFromView();
    try {
        keepLessonView_ = true; // the new step's view is the one on screen
        lesson_->insertStep(lesson_->step() + 1, stepFromView());
    } catch (const InputError& e) {
        showMessage(tr("Cannot add the step: %1").arg(QString::fromStdString(e.what())));
    }
    keepLessonView_ = false;
}

bool MainWindow::saveLesson(const QString& path)
{
    try {
        lesson_->save(path);
        statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
        return true;
    } catch (const InputError& e) {
        showMessage(tr("Cannot save the lesson: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
}

bool MainWindow::saveLessonAs(bool askForName)
{
    if (!lessonPanel_->applyPendingEdits())
        return false;
    QString path = lesson_->filePath();
    // A built-in lesson is a copy's starting point, not a file to overwrite.
    if (askForName || path.isEmpty() || QFileInfo(path).absolutePath() == QDir(lessonsDirectory()).absolutePath())
        path = chooseFileToSave(this, tr("Save lesson"), path.isEmpty() ? "lesson.json" : path, tr("Lessons (*.json)"));
    return !path.isEmpty() && saveLesson(path);
}

bool MainWindow::saveLessonResults(const QString& path)
{
    try {
        lesson_->saveResults(path);
        statusBar()->showMessage(tr("Saved your answers to %1").arg(path), 5000);
        return true;
    } catch (const InputError& e) {
        showMessage(tr("Cannot save the answers: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
}

bool MainWindow::confirmDiscardLesson()
{
    if (!lessonPanel_->applyPendingEdits()) {
        const auto answer = QMessageBox::question(this, tr("Edits not applied"),
                                                  tr("%1\n\nDiscard the step's edits?").arg(lastMessage_),
                                                  QMessageBox::Discard | QMessageBox::Cancel);
        if (answer != QMessageBox::Discard)
            return false;
        lessonPanel_->discardPendingEdits();
    }
    if (lesson_->hasUnsavedAnswers()) {
        const auto answer = QMessageBox::question(this, tr("Unsaved answers"),
                                                  tr("Your answers to the lesson's questions are not saved. Save them first?"),
                                                  QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
        if (answer == QMessageBox::Cancel)
            return false;
        if (answer == QMessageBox::Save) {
            const QString path = chooseFileToSave(this, tr("Save my answers"), "lesson-results.json", tr("Results (*.json)"));
            if (path.isEmpty() || !saveLessonResults(path))
                return false;
        }
    }
    if (!lesson_->isModified())
        return true;
    const auto answer = QMessageBox::question(this, tr("Unsaved lesson"), tr("The lesson has unsaved changes. Save them first?"),
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveLessonAs();
    return answer == QMessageBox::Discard;
}

void MainWindow::advance(int by)
{
    if (!lesson_->isOpen())
        return goToStage(target_ + by);
    if (!lessonPanel_->applyPendingEdits())
        return;
    if (by > 0 && lesson_->isAsking())
        return lesson_->reveal();
    lesson_->goTo(lesson_->step() + by);
}

} // namespace viewpipe::gui
