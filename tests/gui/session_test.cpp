// The app as a person uses it for an afternoon: menus and keys, scene after
// scene, themes after every panel has run, a small screen with larger text,
// and a crash that must not lose the unsaved edits.

#include <QAbstractButton>
#include <QApplication>
#include <QDirIterator>
#include <QDockWidget>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QMessageBox>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QSlider>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTabBar>
#include <QTableWidget>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include <chrono>
#include <csignal>
#include <functional>
#include <thread>

#include "build_paths.h"
#include "evaluation_count.h"
#include "app/MathText.h"
#include "app_window.h"
#include "files.h"
#include "app/AccuracyPanel.h"
#include "app/Autosave.h"
#include "app/LessonDocument.h"
#include "app/LessonFlow.h"
#include "app/MainWindow.h"
#include "app/MatrixPanel.h"
#include "app/ParameterPanel.h"

using namespace viewpipe;
using namespace viewpipe::gui;

namespace {

const QString kHouse = QString(viewpipe::build::dataDir) + "/scenes/house.json";
const QString kCorridor = QString(viewpipe::build::dataDir) + "/scenes/depth-corridor.json";

QAction* actionNamed(QWidget& window, const QString& text)
{
    for (QAction* action : window.findChildren<QAction*>())
        if (action->text().remove('&') == text)
            return action;
    qFatal("no action \"%s\"", qPrintable(text));
}

// What the world view's title says of the stage shown: "World coordinates" or "After SYMBOL".
// The world view's title: the caption's first line (the second says what the stage achieved).
QString shownTitle(MainWindow& window)
{
    return QString::fromStdString(window.painter()->worldCaption()).section('\n', 0, 0);
}

QString expectedCaption(MainWindow& window, int stage)
{
    if (stage == 0)
        return "World coordinates";
    return "After $" + QString::fromStdString(symbolMath(window.document()->pipeline().stages[std::size_t(stage - 1)].symbol())) + "$";
}

QImage worldPicture(MainWindow& window)
{
    window.renderNow();
    return window.findChild<QVTKOpenGLNativeWidget*>("worldView")->grabFramebuffer();
}

// A camera edit through the document, as the parameter panel makes it.
void moveBackPlane(MainWindow& window, double back)
{
    auto view = std::get<foley::ViewSpec<double>>(window.document()->scene().camera);
    view.back = back;
    window.document()->setCamera(view, "Edit view.back");
}

// Run in a child process: edits the house, lets autosave write it, then dies
// as a crash would (SIGKILL: no destructor, no clean-up).
[[noreturn]] void editThenCrash()
{
    MainWindow window;
    window.show();
    if (!window.sceneFiles()->openScene(kHouse))
        std::_Exit(3);
    moveBackPlane(window, -25);
    window.sceneFiles()->autosave()->saveNow();
    std::raise(SIGKILL);
    std::_Exit(4);
}

} // namespace

class SessionTest : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        window_ = openWindow(kHouse);
        QVERIFY(window_);
    }

    void cleanup()
    {
        cancelAnswers();
        closeWindow(window_);
    }

    // Found: Accuracy, measure, then a theme: std::bad_alloc, the app gone (a
    // redraw replaced the result it was reading).
    void themeAfterAccuracyKeepsTheResults()
    {
        MainWindow& w = *window_;
        QSignalSpy done(w.accuracy(), &AccuracyPanel::finished);
        w.accuracy()->measure(*w.document()->evaluated(), 2000);
        QVERIFY(done.wait(120000));
        const QString doubleRow = w.accuracy()->table()->item(1, 5)->text();
        for (const QString theme : {"Light Theme (slides, print)", "Dark Theme (screen)", "Light Theme (slides, print)"})
            actionNamed(w, theme)->trigger();
        QCOMPARE(w.accuracy()->table()->rowCount(), 7); // six tiers and the exact end
        QCOMPARE(w.accuracy()->table()->item(1, 5)->text(), doubleRow);
    }

    // Each theme after each panel has shown something.
    void everyThemeAfterEveryPanel()
    {
        MainWindow& w = *window_;
        QVERIFY(w.sceneFiles()->openScene(kCorridor));
        QSignalSpy done(w.accuracy(), &AccuracyPanel::finished);
        w.accuracy()->measure(*w.document()->evaluated(), 2000);
        QVERIFY(done.wait(120000));
        w.stepper()->goToStage(2, false);
        for (const QString panel : {"stages", "matrices", "parameters", "accuracy", "depth"}) {
            w.showPanel(panel);
            for (const QString theme : {"Light Theme (slides, print)", "Dark Theme (screen)"}) {
                actionNamed(w, theme)->trigger();
                QApplication::processEvents();
            }
        }
        QCOMPARE(w.stepper()->stage(), 2);
        QCOMPARE(w.accuracy()->table()->rowCount(), 7); // six tiers and the exact end
    }

    // Scene after scene, every built-in one: each opens at the world stage with its own title.
    void everyPresetAfterAnother()
    {
        MainWindow& w = *window_;
        QDirIterator files(QString(viewpipe::build::dataDir) + "/scenes", {"*.json"}, QDir::Files,
                           QDirIterator::Subdirectories);
        int opened = 0;
        while (files.hasNext()) {
            const QString path = files.next();
            w.stepper()->goToStage(w.stepper()->stageCount(), false);
            QVERIFY2(w.sceneFiles()->openScene(path), qPrintable(path + ": " + w.lastMessage()));
            QCOMPARE(w.stepper()->stage(), 0);
            QCOMPARE(w.stagePanel()->stageList()->count(), w.stepper()->stageCount() + 1);
            QVERIFY2(w.windowTitle().startsWith(QFileInfo(path).fileName() + " "), qPrintable(w.windowTitle()));
            QCOMPARE(shownTitle(w), expectedCaption(w, 0));
            ++opened;
        }
        QVERIFY(opened >= 20);
    }

    // Found: after opening a scene while on stage k, and after Stop during
    // Play, the title named another stage than the list and the matrices.
    void titleNamesTheStageShown()
    {
        MainWindow& w = *window_;
        w.stepper()->goToStage(3, false);
        QCOMPARE(shownTitle(w), expectedCaption(w, 3));
        QVERIFY(w.sceneFiles()->openScene(kCorridor));
        QCOMPARE(w.stagePanel()->stageList()->currentRow(), 0);
        QCOMPARE(shownTitle(w), expectedCaption(w, 0));

        w.stepper()->play();
        // Found: the list and the slider went to the last stage at once, the picture still at the world.
        QCOMPARE(w.stagePanel()->stageList()->currentRow(), 1);
        QCOMPARE(w.findChild<QSlider*>("stageSlider")->value(), 1);
        QTRY_VERIFY_WITH_TIMEOUT(w.stepper()->stage() >= 1, 10000);
        QVERIFY(w.stagePanel()->stageList()->currentRow() <= w.stepper()->stage() + 1);
        w.findChild<QAbstractButton*>("playButton")->click(); // Stop
        QVERIFY(!w.stepper()->isAnimating());
        QCOMPARE(w.stagePanel()->stageList()->currentRow(), w.stepper()->stage());
        QCOMPARE(shownTitle(w), expectedCaption(w, w.stepper()->stage()));
        QVERIFY(w.matrices()->stageText().contains(
            mathHtml("$" + symbolMath(w.document()->pipeline().stages[std::size_t(w.stepper()->stage() - 1)].symbol()) + "$")));
    }

    // Found: a traced vertex and the Accuracy results carried into the next scene.
    void nextSceneKeepsNothingOfThePrevious()
    {
        MainWindow& w = *window_;
        QSignalSpy done(w.accuracy(), &AccuracyPanel::finished);
        w.accuracy()->measure(*w.document()->evaluated(), 2000);
        QVERIFY(done.wait(120000));
        const QImage untraced = worldPicture(w);
        w.views()->traceVertex(Vec3<double>(16, 10, 54));
        QVERIFY(w.matrices()->traceText().contains("Traced vertex"));
        QVERIFY2(worldPicture(w) != untraced, "the traced vertex is marked in the world view");
        w.stepper()->goToStage(3, false);
        QVERIFY(w.matrices()->traceText().contains("Traced vertex"));
        w.stepper()->goToStage(0, false);

        QVERIFY(w.sceneFiles()->openScene(kHouse));
        QVERIFY(!w.matrices()->traceText().contains("Traced vertex"));
        QCOMPARE(worldPicture(w), untraced);
        QVERIFY(!w.accuracy()->hasResult());
        QCOMPARE(w.accuracy()->table()->rowCount(), 0);

        // A measurement still running when the scene changes is abandoned, not shown.
        w.accuracy()->measure(*w.document()->evaluated(), 2000);
        QVERIFY(w.sceneFiles()->openScene(kHouse));
        QCoreApplication::processEvents(); // a result sent before the abandon would arrive now
        QVERIFY(!w.accuracy()->hasResult());
        QVERIFY(!w.accuracy()->isRunning());
    }

    // One edit typed into a field is one evaluation of the scene (the
    // pipeline built once) and reads no mesh; undo, redo and stepping
    // through the stages evaluate nothing.
    void oneEditIsOneEvaluationAndNoMeshRead()
    {
        MainWindow& w = *window_;
        const QString scene = writeMeshScene();
        QVERIFY(!scene.isEmpty());
        viewpipe::test::EvaluationCount count;
        const ListeningToEvaluations listening(count);
        QVERIFY(w.sceneFiles()->openScene(scene));
        QCOMPARE(w.document()->scene().objects.size(), std::size_t(2));
        const long evaluations = count.evaluations, reads = count.meshReads;
        QCOMPARE(reads, 1L);

        QLineEdit* back = w.parameters()->fields("view.back").front();
        back->selectAll();
        QTest::keyClicks(back, "20");
        QTest::keyClick(back, Qt::Key_Return);
        QCOMPARE(std::get<foley::ViewSpec<double>>(w.document()->scene().camera).back, 20.0);
        QCOMPARE(count.evaluations, evaluations + 1);
        QCOMPARE(count.meshReads, reads);

        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QTest::keyClick(&w, Qt::Key_Y, Qt::ControlModifier);
        for (int stage = 1; stage <= w.stepper()->stageCount(); ++stage)
            w.stepper()->goToStage(stage, false);
        QCOMPARE(count.evaluations, evaluations + 1);
        QCOMPARE(count.meshReads, reads);
    }

    // Opening a scene whose mesh is slow to read (a listener here makes the
    // read take a second): a dialog names the file being opened, and it is
    // gone once the scene is shown.
    void openingASlowSceneSaysWhatIsOpening()
    {
        MainWindow& w = *window_;
        const QString scene = writeMeshScene();
        QVERIFY(!scene.isEmpty());
        SlowReads slow;
        QString announced;
        QVERIFY(readSlowly(w, slow, announced, [&] { return w.sceneFiles()->openScene(scene); }));
        QCOMPARE(announced, QString("Opening viewpipe-session-mesh.json…"));
        QCOMPARE(w.document()->scene().objects.size(), std::size_t(2));
        QVERIFY(!w.findChild<QProgressDialog*>("waitingProgress"));
    }

    // Importing a mesh that is slow to read: read off the GUI thread, a dialog
    // names the file, one undoable edit; found, the window froze while it read.
    void importingASlowMeshSaysWhatIsImported()
    {
        MainWindow& w = *window_;
        QVERIFY(!writeMeshScene().isEmpty()); // writes the mesh beside it
        const std::size_t objects = w.document()->scene().objects.size();
        SlowReads slow;
        QString announced;
        QVERIFY(readSlowly(w, slow, announced,
                           [&] { return w.sceneFiles()->importMesh(QDir::temp().filePath("viewpipe-session-tetrahedron.obj")); }));
        QCOMPARE(announced, QString("Importing viewpipe-session-tetrahedron.obj…"));
        QVERIFY(slow.reader != std::thread::id()); // read,
        QVERIFY(slow.reader != std::this_thread::get_id()); // and not here
        QCOMPARE(w.document()->scene().objects.size(), objects + 1);
        QVERIFY(!w.findChild<QProgressDialog*>("waitingProgress"));
        QTRY_VERIFY(QApplication::activeWindow() == &w); // keys reach the window again
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(w.document()->scene().objects.size(), objects);
    }

    // Importing a mesh that is slow to read, cancelled from its dialog (its button, or Escape): the
    // reading stops, the scene is as it was and says why, nothing to undo; imported afterwards, the
    // mesh reads whole.
    void cancellingASlowImportKeepsTheScene()
    {
        MainWindow& w = *window_;
        QVERIFY(!writeMeshScene().isEmpty()); // writes the mesh beside it
        const QString mesh = QDir::temp().filePath("viewpipe-session-tetrahedron.obj");
        const std::size_t objects = w.document()->scene().objects.size();
        const int edits = w.document()->undoStack()->count();
        SlowReads slow;
        const ListeningToEvaluations listening(slow);
        for (const bool byKey : {false, true}) {
            bool cancelled = false;
            QTimer press; // as soon as the dialog shows
            QObject::connect(&press, &QTimer::timeout, [&] {
                auto* dialog = w.findChild<QProgressDialog*>("waitingProgress");
                if (cancelled || !dialog || !dialog->isVisible())
                    return;
                cancelled = true;
                auto* button = dialog->findChild<QPushButton*>();
                QVERIFY(button);
                QCOMPARE(button->text(), QString("Cancel"));
                if (byKey)
                    QTest::keyClick(dialog, Qt::Key_Escape);
                else
                    QTest::mouseClick(button, Qt::LeftButton);
            });
            press.start(50);
            QVERIFY(!w.sceneFiles()->importMesh(mesh));
            QVERIFY(cancelled);
            QVERIFY2(w.lastMessage().endsWith("reading was stopped"), qPrintable(w.lastMessage()));
            QCOMPARE(w.document()->scene().objects.size(), objects);
            QCOMPARE(w.document()->undoStack()->count(), edits);
        }
        QVERIFY(w.sceneFiles()->importMesh(mesh));
        QCOMPARE(w.document()->scene().objects.size(), objects + 1);
    }

    // Opening a lesson whose step shows a scene with a slow mesh: every step's
    // scene is read off the GUI thread (it was read on it, the window frozen),
    // and a dialog names the lesson meanwhile.
    void openingASlowLessonSaysWhatIsOpening()
    {
        MainWindow& w = *window_;
        QVERIFY(!writeMeshScene().isEmpty());
        const QString lesson = QDir::temp().filePath("viewpipe-session-lesson.json");
        QVERIFY(writeFile(lesson, R"({"title": "A slow mesh", "steps": [{"scene": "viewpipe-session-mesh.json",
                                     "stage": 0, "caption": "The house and a tetrahedron."}]})"));
        SlowReads slow;
        QString announced;
        QVERIFY(readSlowly(w, slow, announced, [&] { return w.lessonFlow()->openLesson(lesson); }));
        QCOMPARE(announced, QString("Opening viewpipe-session-lesson.json…"));
        QVERIFY(slow.reader != std::thread::id());
        QVERIFY(slow.reader != std::this_thread::get_id());
        QCOMPARE(w.document()->scene().objects.size(), std::size_t(2)); // the step's scene shown
        QVERIFY(!w.findChild<QProgressDialog*>("waitingProgress"));
        w.lessonFlow()->lesson()->close();
    }

    // Making a lesson of a view with a slow mesh, and adding a step that shows
    // another: the lesson reads each off the GUI thread (an edit read on it,
    // the window frozen), and a dialog says what is under way.
    void lessonEditsReadSlowMeshesOffTheGuiThread()
    {
        MainWindow& w = *window_;
        const QString scene = writeMeshScene();
        QVERIFY(!scene.isEmpty());
        QVERIFY(w.sceneFiles()->openScene(scene));
        SlowReads slow;
        QString announced;
        QVERIFY(readSlowly(w, slow, announced, [&] {
            w.lessonFlow()->addLessonStepFromView(); // no lesson open: a new one of this view
            return w.lessonFlow()->lesson()->isOpen();
        }));
        QCOMPARE(announced, QString("Making the lesson…"));
        QVERIFY(slow.reader != std::thread::id());
        QVERIFY(slow.reader != std::this_thread::get_id());

        const QString other = QDir::temp().filePath("viewpipe-session-other.obj");
        QVERIFY(QFile::remove(other) || !QFile::exists(other));
        QVERIFY(QFile::copy(QDir::temp().filePath("viewpipe-session-tetrahedron.obj"), other));
        QVERIFY(w.sceneFiles()->importMesh(other));
        slow = SlowReads{};
        announced.clear();
        QVERIFY(readSlowly(w, slow, announced, [&] {
            w.lessonFlow()->addLessonStepFromView();
            return w.lessonFlow()->lesson()->lesson().steps.size() == 2;
        }));
        QCOMPARE(announced, QString("Updating the lesson…"));
        QVERIFY(slow.reader != std::thread::id());
        QVERIFY(slow.reader != std::this_thread::get_id());
        QVERIFY(!w.findChild<QProgressDialog*>("waitingProgress"));
        QCOMPARE(w.lessonFlow()->lesson()->stepScene(1)->meshes.size(), std::size_t(3));
        w.lessonFlow()->lesson()->close();
    }

    // Found: Ctrl+Y did nothing.
    void undoAndRedoByKeyboard()
    {
        MainWindow& w = *window_;
        const double back = std::get<foley::ViewSpec<double>>(w.document()->scene().camera).back;
        moveBackPlane(w, -25);
        auto currentBack = [&w] { return std::get<foley::ViewSpec<double>>(w.document()->scene().camera).back; };
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(currentBack(), back);
        QTest::keyClick(&w, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(currentBack(), -25.0);
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(currentBack(), -25.0);
    }

    // Found: at 1280x720 the stepper's buttons, the Matrices dock and the
    // tabs were off screen, and Larger Text cut texts and buttons.
    void everyControlFitsAt1280x720WithLargerText()
    {
        MainWindow& w = *window_;
        w.resize(1280, 720);
        const QFont normal = QApplication::font();
        for (int i = 0; i < 3; ++i)
            QTest::keyClick(&w, Qt::Key_Plus, Qt::ControlModifier);
        QVERIFY(QApplication::font().pointSize() >= normal.pointSize() + 6);
        QTRY_VERIFY(w.width() <= 1280 && w.height() <= 720);
        // The docks take their new widths once the font has reached every widget: wait for that.
        QListWidget* stages = w.stagePanel()->stageList();
        auto stagesWrap = [stages] {
            for (int i = 0; i < stages->count(); ++i)
                if (stages->visualItemRect(stages->item(i)).right() > stages->viewport()->width())
                    return false;
            return true;
        };
        int tabs = 0;
        QTRY_VERIFY_WITH_TIMEOUT(stagesWrap() && cutDockTabTitle(w, tabs).isEmpty() && tabs == 4, 10000);
        auto restore = qScopeGuard([&w, normal] { w.setFontSize(normal.pointSize()); });
        QVERIFY(w.width() <= 1280 && w.height() <= 720);
        const QRect inside = w.rect();
        auto check = [&](QWidget* widget) {
            if (!widget->isVisible())
                return;
            const QString name = widget->objectName() + " " + widget->metaObject()->className();
            const QRect box(widget->mapTo(&w, QPoint(0, 0)), widget->size());
            QVERIFY2(inside.contains(box), qPrintable(name));
            // Not cut by a scroll area or a splitter: all of it can be seen.
            QVERIFY2(widget->visibleRegion().boundingRect() == widget->rect(), qPrintable(name + " is cut"));
            QVERIFY2(widget->width() >= widget->minimumSizeHint().width(), qPrintable(name + " is narrower than its text"));
        };
        for (QAbstractButton* button : w.findChildren<QAbstractButton*>("playButton"))
            check(button);
        for (const char* name : {"previousButton", "nextButton", "stageSlider"})
            check(w.findChild<QWidget*>(name));
        for (QTabBar* bar : w.findChildren<QTabBar*>())
            check(bar);
        for (QDockWidget* dock : w.findChildren<QDockWidget*>())
            if (!dock->isFloating() && !dock->visibleRegion().isEmpty())
                check(dock);
    }

    // Found: malformed meshes crashed the app on import and on drop.
    void hostileMeshesAreRefusedOnImportAndDrop()
    {
        MainWindow& w = *window_;
        const QString truncated = QDir::temp().filePath("viewpipe-session-truncated.ply");
        QVERIFY(writeFile(truncated, "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty float x\n"
                                     "property float y\nproperty float z\nelement face 6\n"
                                     "property list uchar int vertex_indices\nend_header\n\x01\x02"));
        const QString outOfRange = QDir::temp().filePath("viewpipe-session-out-of-range.obj");
        QVERIFY(writeFile(outOfRange, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"));
        const std::string before = sceneToJson(w.document()->scene());
        QVERIFY(!w.sceneFiles()->importMesh(truncated));
        QVERIFY2(w.lastMessage().contains("too short"), qPrintable(w.lastMessage()));
        QMimeData dropped;
        dropped.setUrls({QUrl::fromLocalFile(outOfRange)});
        // As a drag arrives: it enters the window, then drops.
        QDragEnterEvent enter(QPoint(100, 100), Qt::CopyAction, &dropped, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(100, 100), Qt::CopyAction, &dropped, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &drop);
        QVERIFY2(w.lastMessage().contains("out of range"), qPrintable(w.lastMessage()));
        QCOMPARE(sceneToJson(w.document()->scene()), before);
        QCOMPARE(w.document()->undoStack()->count(), 0);
    }

    // Nothing lost: edits survive a killed process and are offered at the next start.
    void editsSurviveACrash()
    {
        for (const AutosavedScene& orphan : Autosave::orphans())
            Autosave::discard(orphan);
        QProcess child;
        child.start(QCoreApplication::applicationFilePath(), {"--edit-then-crash"});
        QVERIFY(child.waitForFinished(60000));
        QCOMPARE(child.exitStatus(), QProcess::CrashExit);

        const std::vector<AutosavedScene> orphans = Autosave::orphans();
        QCOMPARE(int(orphans.size()), 1);
        QCOMPARE(orphans.front().sourcePath, kHouse);

        MainWindow& w = *window_;
        answerNextQuestion("Recover");
        QVERIFY(w.sceneFiles()->offerRecovery());
        QCOMPARE(std::get<foley::ViewSpec<double>>(w.document()->scene().camera).back, -25.0);
        QCOMPARE(w.document()->filePath(), kHouse);
        QVERIFY(w.document()->isModified());
        QVERIFY(w.windowTitle().contains("*"));
        w.document()->undoStack()->undo(); // back to the file as saved
        QCOMPARE(std::get<foley::ViewSpec<double>>(w.document()->scene().camera).back,
                 std::get<foley::ViewSpec<double>>(loadScene(kHouse.toStdString()).camera).back);
        QVERIFY(Autosave::orphans().empty());
    }

    // A running session's autosave is not offered to another; a saved or closed one leaves nothing.
    void autosaveFollowsTheDocument()
    {
        MainWindow& w = *window_;
        moveBackPlane(w, -30);
        w.sceneFiles()->autosave()->saveNow();
        const QString autosaved = w.sceneFiles()->autosave()->scenePath();
        QVERIFY(QFile::exists(autosaved));
        QCOMPARE(std::get<foley::ViewSpec<double>>(loadScene(autosaved.toStdString()).camera).back, -30.0);
        QVERIFY(Autosave::orphans().empty());
        w.document()->undoStack()->undo(); // back to the saved state: nothing to recover
        QVERIFY(!QFile::exists(autosaved));
        moveBackPlane(w, -31);
        w.sceneFiles()->autosave()->saveNow();
        QVERIFY(QFile::exists(w.sceneFiles()->autosave()->scenePath()));
        const QString second = w.sceneFiles()->autosave()->scenePath();
        window_.reset(); // closed with unsaved changes, as after "Discard"
        QVERIFY(!QFile::exists(second));
        window_ = std::make_unique<MainWindow>();
    }

private:
    // A scene of the house and a tetrahedron read from an OBJ file, in the
    // temporary folder; empty if it cannot be written.
    // A mesh read made to take a second, noting the thread that reads it.
    struct SlowReads : EvaluationListener {
        std::thread::id reader;
        void readingMesh(const std::filesystem::path&) override
        {
            reader = std::this_thread::get_id();
            std::this_thread::sleep_for(std::chrono::seconds(1));
        }
    };

    // Runs `read` with `slow` listening (to the scene's reads and the lesson's), noting what the waiting dialog says meanwhile.
    static bool readSlowly(MainWindow& w, SlowReads& slow, QString& announced, const std::function<bool()>& read)
    {
        const ListeningToEvaluations listening(slow);
        QTimer look;
        QObject::connect(&look, &QTimer::timeout, [&] {
            if (auto* dialog = w.findChild<QProgressDialog*>("waitingProgress"); dialog && dialog->isVisible())
                announced = dialog->labelText();
        });
        look.start(50);
        return read();
    }

    static QString writeMeshScene()
    {
        const QDir dir = QDir::temp();
        const QString scene = dir.filePath("viewpipe-session-mesh.json");
        QString text = QString::fromStdString(sceneToJson(loadScene(kHouse.toStdString())));
        text.replace(R"("objects": [)", R"("objects": [{"type": "mesh", "path": "viewpipe-session-tetrahedron.obj"}, )");
        const bool written = writeFile(dir.filePath("viewpipe-session-tetrahedron.obj"),
                                       "v 0 0 30\nv 16 0 30\nv 8 16 30\nv 8 6 50\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n") &&
                             writeFile(scene, text.toUtf8());
        return written ? scene : QString();
    }

    std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv)
{
    return runAppTests<SessionTest>(argc, argv, [&] {
        if (argc > 1 && QString(argv[1]) == "--edit-then-crash")
            editThenCrash();
    });
}

#include "session_test.moc"
