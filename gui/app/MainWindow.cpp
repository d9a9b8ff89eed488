#include "MainWindow.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QResizeEvent>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTabBar>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>


#include "AccuracyPanel.h"
#include "ActionRegistry.h"
#include "Autosave.h"
#include "ClassicalDialog.h"
#include "CodePanel.h"
#include "DepthPanel.h"
#include "EffectsMenu.h"
#include "ExportDialog.h"
#include "Exports.h"
#include "GuideDialog.h"
#include "LessonDocument.h"
#include "LessonFlow.h"
#include "LessonPanel.h"
#include "MatrixPanel.h"
#include "ParameterPanel.h"
#include "PresentMode.h"
#include "SceneFiles.h"
#include "StagePair.h"
#include "StagePanel.h"
#include "Stepper.h"
#include "StoryboardView.h"
#include "Theme.h"
#include "ViewDeck.h"

namespace viewpipe::gui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), document_(new Document(this)), actions_(new ActionRegistry(this))
{
    setObjectName("ViewPipeMainWindow");
    setAcceptDrops(true);
    buildViews();
    stepper_ = new Stepper(document_, painter(), this);
    sceneFiles_ = new SceneFiles(document_, *this, this);
    lessonFlow_ = new LessonFlow(document_, stepper_, views_, sceneFiles_, *this, this);
    // The views draw the document's scene as the lesson step shown leaves it.
    views_->setSceneSource([this] { return lessonFlow_->asShown(document_->evaluated()); });
    exports_ = new Exports(document_, stepper_, views_, lessonFlow_, *this, this);
    presentMode_ = new PresentMode(this, *this, views_, lessonPanel());
    effectsMenu_ = new EffectsMenu(document_, this);
    buildDocks();
    addActions();
    buildMenus();

    // Only the world view moves; the projected view is the same picture at every stage.
    connect(stepper_, &Stepper::frameChanged, views_->pair(), &StagePair::renderWorldView);
    // The captions and matrices name the step under way, then the stage at rest; the stage panel
    // follows the stepper itself.
    connect(stepper_, &Stepper::stepStarted, this, [this] {
        updateCaptions();
        updateMatrices();
    });
    connect(stepper_, &Stepper::rested, this, &MainWindow::showStageDetails);
    connect(stepper_, &Stepper::rested, this, [this] { views_->storyboard()->setCurrentStage(stepper_->shownStage()); });
    connect(views_, &ViewDeck::currentChanged, this, [this] {
        if (views_->storyboardShown())
            views_->storyboard()->setCurrentStage(stepper_->shownStage());
        actions_->action("view.storyboard")->setChecked(views_->storyboardShown());
    });
    connect(views_, &ViewDeck::tracedChanged, this, &MainWindow::updateTrace);
    connect(sceneFiles_, &SceneFiles::sceneOpened, this, &MainWindow::showOpenedScene);
    connect(lessonFlow_, &LessonFlow::sceneOpened, this, &MainWindow::showOpenedScene);
    connect(lessonFlow_, &LessonFlow::stepShown, this, &MainWindow::showStageDetails);
    connect(lessonFlow_, &LessonFlow::panelWanted, this, &MainWindow::showPanel);
    connect(lessonFlow_, &LessonFlow::lessonShown, this, &MainWindow::showLessonDock);
    connect(presentMode_, &PresentMode::stepRequested, lessonFlow_, &LessonFlow::advance);
    connect(effectsMenu_, &EffectsMenu::message, this, &MainWindow::showMessage);
    connect(document_, &Document::changed, this, &MainWindow::onDocumentChanged);
    connect(document_, &Document::fileChanged, this, &MainWindow::updateTitle);
    connect(lessonFlow_->lesson(), &LessonDocument::lessonChanged, this, &MainWindow::updateTitle);
    connect(lessonPanel(), &LessonPanel::message, this, &MainWindow::showMessage);
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

MainWindow::~MainWindow()
{
    // Hidden as the window goes, the dock would call a window already half gone.
    disconnect(findChild<QDockWidget*>("matricesDock"), nullptr, this, nullptr);
}

LessonPanel* MainWindow::lessonPanel()
{
    return lessonFlow_->panel();
}

void MainWindow::fitToScreen()
{
    QSize size(1600, 950);
    if (const QScreen* screen = QGuiApplication::primaryScreen())
        size = size.boundedTo(screen->availableGeometry().size() * 0.95);
    resize(size);
    fitDocksToText();
}

void MainWindow::buildViews()
{
    views_ = new ViewDeck;
    setCentralWidget(views_);
    // From the start: a bar appearing with the first message (or after presenting) would shrink the views.
    statusBar();
}

ScenePainter* MainWindow::painter()
{
    return views_->pair()->painter();
}

void MainWindow::buildDocks()
{
    auto dock = [this](const QString& title, const QString& name, QWidget* content, Qt::DockWidgetArea area) {
        auto* scroll = new QScrollArea;
        // Texts wrap to the dock's width; only content wider than a dock may be (fitDocksToText) scrolls sideways.
        scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
        scroll->setWidget(content);
        scroll->setWidgetResizable(true);
        auto* d = new QDockWidget(title, this);
        d->setObjectName(name);
        d->setWidget(scroll);
        addDockWidget(area, d);
        return d;
    };
    stagePanel_ = new StagePanel(stepper_);
    dock(tr("Stages"), "stagesDock", stagePanel_, Qt::LeftDockWidgetArea);
    matrices_ = new MatrixPanel;
    QDockWidget* matrixDock = dock(tr("Matrices"), "matricesDock", matrices_, Qt::RightDockWidgetArea);
    connect(matrixDock, &QDockWidget::visibilityChanged, this, &MainWindow::updateRoomWhileAsking);
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
    dock(tr("Lesson"), "lessonDock", lessonPanel(), Qt::LeftDockWidgetArea)->hide();
    fitDocksToText();
}

bool MainWindow::event(QEvent* event)
{
    // The docks' tab bars, made by Qt as docks are tabbed (also later: docked again, a layout restored),
    // never shorten a title: arrows scroll the tabs that do not fit.
    if (event->type() == QEvent::ChildPolished)
        if (auto* bar = qobject_cast<QTabBar*>(static_cast<QChildEvent*>(event)->child())) {
            bar->setElideMode(Qt::ElideNone);
            bar->setUsesScrollButtons(true);
        }
    return QMainWindow::event(event);
}

void MainWindow::fitDocksToText()
{
    // Widths in units of the text's average character, the views keeping at least 40 % of the window.
    // A dock is as wide as its content where the screen has room (its scroll area would cut it, not
    // shrink it); with large text on a small screen, each at most a quarter of the screen, the content
    // scrolling sideways, so that the window fits the screen and the views keep their share.
    fitDockMinimumWidths();
    const int em = QFontMetrics(QApplication::font()).averageCharWidth();
    QDockWidget* stages = findChild<QDockWidget*>("stagesDock");
    const int separators = 2 * style()->pixelMetric(QStyle::PM_DockWidgetSeparatorExtent, nullptr, this);
    const int docks = std::min(em * (40 + 60), width() * 60 / 100 - separators);
    // The right docks' tabs keep their titles whole: the right dock as wide as its tabs where the left
    // dock can give it the room (the left keeping its minimum), else arrows scroll them.
    int tabs = 0;
    for (const QTabBar* bar : findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly))
        tabs = std::max(tabs, bar->sizeHint().width() + 2 * em);
    const int left = std::max({1, stages->minimumSizeHint().width(), std::min(docks * 40 / 100, docks - tabs)});
    int right = std::max(1, docks - left);
    if (matricesAside_) { // the room the answer gives back
        matricesWidth_ = right;
        right = asideMatricesWidth();
    }
    resizeDocks({stages, findChild<QDockWidget*>("matricesDock")}, {left, right},
                Qt::Horizontal);
}

void MainWindow::fitDockMinimumWidths()
{
    // While the matrices step aside for a question, the panels tabbed with them ask no room either.
    auto* matrices = findChild<QDockWidget*>("matricesDock");
    QList<QDockWidget*> aside;
    if (matricesAside_)
        aside = tabifiedDockWidgets(matrices) << matrices;
    const int screenWidth = screen() ? screen()->availableGeometry().width() : 1280;
    // Presenting, the lesson is the one dock: it may take two fifths of the screen (found: its question cut
    // at a quarter of a 1280 px projector).
    const int most = presentMode_->isPresenting() ? screenWidth * 2 / 5 : screenWidth / 4;
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        if (auto* scroll = qobject_cast<QScrollArea*>(dock->widget()))
            scroll->setMinimumWidth(aside.contains(dock)
                                        ? 0
                                        : std::min(most, scroll->widget()->minimumSizeHint().width() +
                                                                        scroll->verticalScrollBar()->sizeHint().width() +
                                                                        2 * scroll->frameWidth()));
}

int MainWindow::asideMatricesWidth()
{
    // While a question waits, the matrices are a note whose lines are some 16 characters long.
    return 16 * QFontMetrics(QApplication::font()).averageCharWidth();
}

void MainWindow::addActions()
{
    sceneFiles_->addActions(*actions_);
    exports_->addActions(*actions_);
    lessonFlow_->addActions(*actions_);
    actions_->add("file.quit", tr("&Quit"), [this] { close(); }, QKeySequence::Quit);

    actions_->add("stage.previous", tr("Previous Stage"), [this] { stepper_->stepBy(-1); }, QKeySequence(Qt::Key_Left));
    actions_->add("stage.next", tr("Next Stage"), [this] { stepper_->stepBy(1); }, QKeySequence(Qt::Key_Right));
    // A presenter's clicker sends Page Down and Page Up: the next lesson step, or stage.
    actions_->add("stage.advance", tr("Advance"), [this] { lessonFlow_->advance(1); }, QKeySequence(Qt::Key_PageDown));
    actions_->add("stage.goBack", tr("Go Back"), [this] { lessonFlow_->advance(-1); }, QKeySequence(Qt::Key_PageUp));

    QAction* projected = actions_->addToggle("view.projected", tr("&Projected View"),
                                             [this](bool on) { setProjectedViewVisible(on); }, QKeySequence(Qt::Key_P));
    projected->setChecked(true);
    actions_->addToggle("view.storyboard", tr("&Storyboard"), [this](bool on) { setStoryboardShown(on); },
                        QKeySequence(Qt::Key_S));
    actions_->add("view.reset", tr("&Reset View"), [this] {
        views_->resetView();
        renderNow();
    }, QKeySequence(Qt::Key_R));
    actions_->add("view.classical", tr("&Classical Projection…"), [this] { chooseClassicalProjection(); },
                  QKeySequence(Qt::CTRL | Qt::Key_K));
    auto* themes = new QActionGroup(this);
    for (auto [id, text, theme] : {std::tuple{"view.darkTheme", tr("&Dark Theme (screen)"), report::Theme::Dark},
                                   std::tuple{"view.lightTheme", tr("&Light Theme (slides, print)"), report::Theme::Light}})
        themes->addAction(actions_->addToggle(id, text, [this, theme = theme](bool) { setTheme(theme); }));
    actions_->action("view.darkTheme")->setChecked(true);
    actions_->add("view.present", tr("&Present"), [this] { presentMode_->setPresenting(!presentMode_->isPresenting()); },
                  QKeySequence(Qt::Key_F5));
    // Where each view's legend goes, kept for the next session.
    for (const char* view : {"world", "projected"}) {
        auto* places = new QActionGroup(this);
        const QString key = QString(view) + "Legend";
        const report::LegendPlace kept = report::legendPlaceNamed(QSettings().value(key, "best").toString().toStdString()).value_or(report::LegendPlace::Best);
        for (const auto& [place, text] : {std::pair{report::LegendPlace::Best, tr("Where It Costs Least")}, std::pair{report::LegendPlace::Beside, tr("Beside")},
                                          std::pair{report::LegendPlace::Below, tr("Below")}, std::pair{report::LegendPlace::Inside, tr("Inside, in a Free Corner")},
                                          std::pair{report::LegendPlace::None, tr("Hidden")}}) {
            const bool world = std::string(view) == "world";
            QAction* action = actions_->addToggle(std::string("view.") + view + "Legend." + legendPlaceName(place),
                                                  text, [this, world, key, place = place](bool on) {
                if (!on)
                    return;
                world ? painter()->setLegendPlace(place) : painter()->setProjectedLegendPlace(place);
                QSettings().setValue(key, legendPlaceName(place));
                renderNow();
            });
            places->addAction(action);
            if (place == kept) {
                action->setChecked(true);
                world ? painter()->setLegendPlace(place) : painter()->setProjectedLegendPlace(place);
            }
        }
    }
    // View > Leave Out: what export --hide names, left out of every view.
    for (const std::string& name : hideNames())
        actions_->addToggle("view.hide." + name, hideText(name), [this, name](bool on) {
            std::set<std::string> hidden = views_->hidden();
            on ? void(hidden.insert(name)) : void(hidden.erase(name));
            setHidden(hidden);
        });
    actions_->add("view.largerText", tr("&Larger Text"), [this] { setFontSize(fontSize_ + 2); }, QKeySequence::ZoomIn);
    actions_->add("view.smallerText", tr("&Smaller Text"), [this] { setFontSize(fontSize_ - 2); }, QKeySequence::ZoomOut);
    actions_->add("effects.depthPanel", tr("Show the &Depth Panel"), [this] { showPanel("depth"); });
    actions_->add("help.guide", tr("&Guide"), [this] { GuideDialog::showFor(this); }, QKeySequence::HelpContents);
    actions_->add("help.about", tr("&About ViewPipe"), [this] {
        QMessageBox::about(this, tr("About ViewPipe"),
                           tr("<b>ViewPipe</b><p>Step through the 3D viewing pipeline: Foley &amp; van Dam's "
                              "normalizing transformation and the OpenGL forms.</p>"));
    });
}

void MainWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    actions_->fill(file, {"file.open"});
    QMenu* presets = file->addMenu(tr("&Presets"));
    QMenu* recent = file->addMenu(tr("Open &Recent"));
    sceneFiles_->setMenus(presets, recent);
    actions_->fill(file, {"file.save", "file.saveAs", "-", "file.importMesh", "file.exportStages", "file.exportWebPage",
                          "file.exportSheet", "lesson.pack", "-", "file.quit"});
    connect(file, &QMenu::aboutToShow, this, [this] { actions_->action("lesson.pack")->setEnabled(lessonFlow_->lesson()->isOpen()); });

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcuts({QKeySequence(QKeySequence::Redo), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    actions_->fill(edit, {"edit.copyLatex", "edit.copyImage"});

    QMenu* view = menuBar()->addMenu(tr("&View"));
    actions_->fill(view, {"view.projected", "view.storyboard", "view.reset", "view.classical", "-", "view.darkTheme", "view.lightTheme", "-",
                          "view.present"});
    QMenu* presentOn = view->addMenu(tr("Present &On"));
    connect(presentOn, &QMenu::aboutToShow, this, [this, presentOn] {
        presentOn->clear();
        for (QScreen* screen : QGuiApplication::screens())
            presentOn->addAction(QString("%1 (%2 x %3)").arg(screen->name()).arg(screen->size().width()).arg(screen->size().height()),
                                 this, [this, screen] { presentMode_->setPresenting(true, screen); });
    });
    actions_->fill(view, {"-", "view.largerText", "view.smallerText"});
    QMenu* leaveOut = view->addMenu(tr("Leave &Out"));
    for (const std::string& name : hideNames())
        leaveOut->addAction(actions_->action("view.hide." + name));
    for (const char* which : {"world", "projected"}) {
        QMenu* legend = view->addMenu(std::string(which) == "world" ? tr("&World View Legend") : tr("&Camera View Legend"));
        for (const report::LegendPlace place : report::legendPlaces())
            legend->addAction(actions_->action(std::string("view.") + which + "Legend." + legendPlaceName(place)));
    }

    menuBar()->addMenu(effectsMenu_);
    actions_->fill(effectsMenu_, {"-", "effects.depthPanel"});
    lessonFlow_->fillMenu(menuBar()->addMenu(tr("&Lesson")), *actions_);
    actions_->fill(menuBar()->addMenu(tr("&Help")), {"help.guide", "help.about"});
}

void MainWindow::showOpenedScene()
{
    const ViewDeck::RenderHold once(*views_);
    views_->drawScene();
    sceneFiles_->autosave()->saveNow(); // the previous scene's unsaved edits are not this one's to recover
    views_->traceVertex(std::nullopt);
    accuracy_->clear();
    refreshWidgets();
    views_->resetView();
    stepper_->goToStage(0, false);
}

void MainWindow::showLessonDock(bool open)
{
    auto* dock = findChild<QDockWidget*>("lessonDock");
    if (!open)
        return dock->hide();
    if (!dock->isVisible() && !presentMode_->isPresenting()) {
        dock->show();
        // The lesson's text and questions get the room; the stage list needs little.
        resizeDocks({findChild<QDockWidget*>("stagesDock"), dock}, {height() / 3, 2 * height() / 3}, Qt::Vertical);
    }
    dock->show();
    dock->raise();
}

void MainWindow::onDocumentChanged()
{
    views_->drawScene();
    refreshWidgets();
}

void MainWindow::setHidden(const std::set<std::string>& hidden)
{
    for (const std::string& name : hideNames())
        actions_->action("view.hide." + name)->setChecked(hidden.count(name) > 0);
    views_->setHidden(hidden);
    stepper_->restart(); // the stage shown again, at rest, on the new props
    updateCaptions();
    renderNow();
}

void MainWindow::refreshWidgets()
{
    parameters_->setCamera(document_->scene().camera, document_->scene().typedExpressions);
    code_->setCamera(document_->scene().camera);
    effectsMenu_->follow();
    depth_->showDepth(document_->pipeline(), document_->evaluated()->outcomes.depth, painter()->theme());
    stagePanel_->setStages(document_->pipeline());
    stepper_->restart();
    updateTitle();
}

void MainWindow::onCameraEdited(const CameraSpec<double>& camera, const std::map<std::string, std::string>& typed,
                                const QString& field)
{
    try {
        document_->setCamera(camera, typed, tr("Edit %1").arg(field));
        parameters_->clearErrors();
    } catch (const InputError& e) {
        // The last valid picture stays; the reason goes next to the field.
        parameters_->showError(QString::fromStdString(e.field()), QString::fromStdString(e.reason()));
    }
}

void MainWindow::showStageDetails()
{
    updateCaptions();
    updateMatrices();
    renderNow();
}

void MainWindow::updateMatrices()
{
    // A question waits: the stages' names and matrices would answer it.
    const bool waiting = lessonFlow_->hidesAnswers();
    stagePanel_->setAnswersHidden(waiting);
    updateRoomWhileAsking();
    if (waiting && views_->storyboardShown())
        setStoryboardShown(false);
    if (waiting)
        return matrices_->showWaiting(tr("<i>The matrices follow the answer to the lesson's question.</i>"));
    const int stage = stepper_->shownStage();
    matrices_->showStage(document_->pipeline(), document_->exactPipeline(), stage, lessonFlow_->highlightedEntries(stage));
    updateTrace();
}

void MainWindow::updateRoomWhileAsking()
{
    // Another panel in front (the parameters, say) is the student's to use: it keeps its room.
    // (A dock behind another's tab stays "visible": what is seen of it tells.)
    // Moved elsewhere by the user, they stay as they are.
    auto* matrices = findChild<QDockWidget*>("matricesDock");
    const bool aside = lessonFlow_->hidesAnswers() && !matrices->isFloating() &&
                       dockWidgetArea(matrices) == Qt::RightDockWidgetArea && !matrices->visibleRegion().isEmpty();
    if (aside == matricesAside_)
        return;
    matricesAside_ = aside;
    if (aside)
        matricesWidth_ = matrices->width();
    fitDockMinimumWidths();
    // Once the lesson's dock and the minimums have taken their room; the other docks keep the widths the user gave.
    QTimer::singleShot(0, this, [this, matrices] {
        resizeDocks({matrices}, {matricesAside_ ? asideMatricesWidth() : matricesWidth_}, Qt::Horizontal);
    });
}

void MainWindow::updateTrace()
{
    if (lessonFlow_->hidesAnswers()) // a question waits: the trace follows its answer
        return;
    const int stage = stepper_->shownStage();
    matrices_->showTrace(document_->pipeline(), document_->exactPipeline(), views_->traced(), stage,
                         lessonFlow_->lastTracedStage(stage));
}

void MainWindow::updateCaptions()
{
    if (views_->hidden().count("caption"))
        return painter()->setCaptions("", "");
    painter()->setCaptions(lessonFlow_->hidesAnswers()
                              ? std::string()
                              : stageCaption(*document_->evaluated(), std::size_t(stepper_->shownStage()), StageText::Caption),
                          tr("What the camera sees").toStdString());
}

void MainWindow::renderNow()
{
    views_->renderNow();
}

report::Theme MainWindow::theme() const
{
    return views_->theme();
}

void MainWindow::setTheme(report::Theme theme)
{
    views_->setTheme(theme);
    accuracy_->setTheme(theme);
    depth_->showDepth(document_->pipeline(), document_->evaluated()->outcomes.depth, theme);
    applyTheme(theme);
    actions_->action(theme == report::Theme::Light ? "view.lightTheme" : "view.darkTheme")->setChecked(true);
    if (!presentMode_->isPresenting()) // the projector's look is not the user's setting
        QSettings().setValue("theme", theme == report::Theme::Light ? "light" : "dark");
    renderNow();
}

void MainWindow::setFontSize(int points, bool remember)
{
    // The range `open --text-scale` and the exports take.
    fontSize_ = std::clamp(points, (kDefaultFontSize * report::kMinTextScale + 99) / 100, kDefaultFontSize * report::kMaxTextScale / 100);
    QFont font = QApplication::font();
    font.setPointSize(fontSize_);
    QApplication::setFont(font);
    views_->setTextScale(double(fontSize_) / kDefaultFontSize);
    if (remember && !presentMode_->isPresenting())
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
    views_->pair()->setProjectedViewVisible(visible);
    actions_->action("view.projected")->setChecked(visible);
    renderNow();
}

void MainWindow::setStoryboardShown(bool shown)
{
    if (shown && lessonFlow_->hidesAnswers()) {
        shown = false;
        showMessage(tr("The storyboard follows the answer to the lesson's question: it names every stage"));
    }
    views_->setStoryboardShown(shown);
    actions_->action("view.storyboard")->setChecked(views_->storyboardShown()); // also where refused
}

void MainWindow::updateTitle()
{
    const QString name = document_->filePath().isEmpty() ? tr("untitled") : QFileInfo(document_->filePath()).fileName();
    const LessonDocument* lesson = lessonFlow_->lesson();
    QString lessonName;
    if (lesson->isOpen())
        lessonName = tr("lesson %1%2 — ")
                         .arg(lesson->filePath().isEmpty() ? tr("untitled") : QFileInfo(lesson->filePath()).fileName(),
                              lesson->isModified() ? "*" : "");
    setWindowTitle(QString("%1%2 — %3ViewPipe").arg(name, document_->isModified() ? "*" : "", lessonName));
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

void MainWindow::showNote(const QString& text, int milliseconds)
{
    statusBar()->showMessage(text, milliseconds);
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (lessonFlow_->confirmDiscardLesson() && sceneFiles_->confirmDiscard())
        event->accept();
    else
        event->ignore();
}

void MainWindow::resizeEvent(QResizeEvent* event)
{
    QMainWindow::resizeEvent(event);
    presentMode_->fitBlackout();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (event->mimeData()->hasUrls())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    for (const QUrl& url : event->mimeData()->urls())
        sceneFiles_->openDropped(url.toLocalFile());
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

} // namespace viewpipe::gui
