// The desktop app under Xvfb: the stepper, refused edits, undo and redo,
// open and save, and the Eigen-VTK adapter.

#include <QApplication>
#include <QClipboard>
#include <QDockWidget>
#include <QAnimationDriver>
#include <QFileDialog>
#include <QMenuBar>
#include <QProgressDialog>
#include <QTableWidget>
#include <QTimer>
#include <QScreen>
#include <QWindow>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QSettings>
#include <QtTest>

#include <atomic>
#include <functional>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkWindowToImageFilter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include "build_paths.h"
#include "app_window.h"
#include "faces_drawn.h"
#include "files.h"
#include "sheet_mesh.h"
#include "app/AccuracyPanel.h"
#include "app/ClassicalDialog.h"
#include "app/DepthPanel.h"
#include "app/MainWindow.h"
#include "viewpipe/animation.hpp"
#include "app/MatrixPanel.h"
#include "app/ParameterPanel.h"
#include "app/Stepper.h"
#include "painter/EigenVtk.h"
#include "painter/VtkGeometry.h"

using namespace viewpipe;
using namespace viewpipe::gui;

namespace {

const QString kHouse = QString(viewpipe::build::dataDir) + "/scenes/house.json";

QImage worldPicture(MainWindow& window)
{
    window.renderNow();
    return window.findChild<QVTKOpenGLNativeWidget*>("worldView")->grabFramebuffer();
}

// The action of a menu (by object name) whose text, without the mnemonic, is `text`.
QAction* menuAction(MainWindow& window, const QString& menu, const QString& text)
{
    for (QAction* action : window.findChild<QMenu*>(menu)->actions())
        if (action->text().remove('&') == text)
            return action;
    qFatal("no action \"%s\" in %s", qPrintable(text), qPrintable(menu));
}

// Pixels of the projected view in a band color of the depth effect: strongly
// yellow or green, which no other element of the dark theme uses.
int bandPixels(MainWindow& window)
{
    window.renderNow();
    const QImage image =
        window.findChild<QVTKOpenGLNativeWidget*>("projectedView")->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb c = image.pixel(x, y);
            count += qGreen(c) > 120 && qBlue(c) < 90 && qGreen(c) > qBlue(c) + 80;
        }
    return count;
}

// The faces the world view's visible actors draw.
vtkIdType worldFacesDrawn(MainWindow& window)
{
    return facesDrawn(window.findChild<QVTKOpenGLNativeWidget*>("worldView")->renderWindow()->GetRenderers()->GetFirstRenderer());
}

// A mouse event on the world view (Qt 5's QTest cannot drag with a button held).
void sendMouse(MainWindow& window, QEvent::Type type, QPoint at, Qt::MouseButtons held,
               Qt::MouseButton button = Qt::LeftButton)
{
    auto* view = window.findChild<QVTKOpenGLNativeWidget*>("worldView");
    QMouseEvent event(type, at, view->mapToGlobal(at), type == QEvent::MouseMove ? Qt::NoButton : button, held,
                      Qt::NoModifier);
    QApplication::sendEvent(view, &event);
}

void waitForRest(MainWindow& window)
{
    QTRY_VERIFY_WITH_TIMEOUT(!window.stepper()->isAnimating(), 20000);
}

// Clicks the world view where a world point is drawn at the stage shown.
void clickWhereDrawn(MainWindow& window, const Vec3<double>& world)
{
    auto* view = window.findChild<QVTKOpenGLNativeWidget*>("worldView");
    vtkRenderer* renderer = view->renderWindow()->GetRenderers()->GetFirstRenderer();
    const Vec4<double> h = cumulativeAt(window.document()->pipeline().stages, window.stepper()->stage()) * world.homogeneous();
    renderer->SetWorldPoint(h.x() / h.w(), h.y() / h.w(), h.z() / h.w(), 1);
    renderer->WorldToDisplay();
    double display[3];
    renderer->GetDisplayPoint(display);
    const double ratio = view->devicePixelRatioF();
    const QPoint at(int(std::lround(display[0] / ratio)), int(std::lround(view->height() - display[1] / ratio)));
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, at);
}

// A clock the test owns: Qt's animations (through their driver) and the stepper read it, and it
// moves only when the test ticks it, so that no test waits on the machine's speed.
class TestClock : public QAnimationDriver {
public:
    static constexpr qint64 kTick = 16; // ms: a 60 Hz screen's frame
    explicit TestClock(viewpipe::gui::Stepper& stepper) : stepper_(stepper)
    {
        install();
        stepper_.setClock([this] { return now; });
    }
    ~TestClock() override
    {
        uninstall();
        stepper_.setClock({});
    }
    qint64 elapsed() const override { return now; }
    // Ticks until `running` is false, handling events between ticks; false if it never stops (a minute).
    bool runWhile(const std::function<bool()>& running)
    {
        for (int ticks = 0; running(); ++ticks) {
            if (ticks > 60000 / kTick)
                return false;
            now += kTick;
            advance();
            QCoreApplication::processEvents();
        }
        return true;
    }
    qint64 now = 0;

private:
    viewpipe::gui::Stepper& stepper_;
};

} // namespace

class AppTest : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        window_ = openWindow(kHouse);
        QVERIFY(window_);
        window_->setPopupsEnabled(true);
    }

    void cleanup() { closeWindow(window_); }

    // While Play runs and while the view is turned, a large mesh is drawn from
    // its decimated copy; at rest every face is drawn.
    void largeMeshMovesFromItsDecimatedCopy()
    {
        QTemporaryDir folder;
        viewpipe::bench::writeSheetMesh(folder.filePath("sheet.ply").toStdString(), 200'000);
        QFile house(kHouse);
        QVERIFY(house.open(QIODevice::ReadOnly));
        QVERIFY(writeFile(folder.filePath("scene.json"),
                          house.readAll().replace(R"("objects": [)", R"("objects": [ { "type": "mesh", "path": "sheet.ply" },)")));
        MainWindow& w = *window_;
        QVERIFY(w.sceneFiles()->openScene(folder.filePath("scene.json")));
        w.renderNow();
        const vtkIdType full = worldFacesDrawn(w);
        QVERIFY2(full > 190'000, qPrintable(QString::number(full))); // the sheet's 2 · 316² triangles and the house's faces

        // Playing (again from the start until the copy, made off the GUI thread, is there).
        vtkIdType whilePlaying = full;
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                if (!w.stepper()->isAnimating())
                    w.stepper()->play();
                whilePlaying = worldFacesDrawn(w);
                return w.stepper()->isAnimating() && whilePlaying < full / 4;
            }(),
            60000);
        QVERIFY2(whilePlaying > full / 100, qPrintable(QString::number(whilePlaying))); // a copy, not nothing
        w.stepper()->goToStage(1, false);
        QCOMPARE(worldFacesDrawn(w), full);

        // Turning the view with the mouse: the copy while the button is held, every face once it is let go.
        auto* view = w.findChild<QVTKOpenGLNativeWidget*>("worldView");
        const QPoint center = view->rect().center();
        sendMouse(w, QEvent::MouseButtonPress, center, Qt::LeftButton);
        sendMouse(w, QEvent::MouseMove, center + QPoint(40, 10), Qt::LeftButton);
        w.renderNow();
        QCOMPARE(worldFacesDrawn(w), whilePlaying);
        sendMouse(w, QEvent::MouseButtonRelease, center + QPoint(40, 10), Qt::NoButton);
        w.renderNow();
        QCOMPARE(worldFacesDrawn(w), full);
    }

    // The wheel and the right button zoom the world view, the middle button
    // pans it, and the next stage keeps the zoom.
    void wheelAndButtonsZoomAndPan()
    {
        MainWindow& w = *window_;
        auto* view = w.findChild<QVTKOpenGLNativeWidget*>("worldView");
        vtkCamera* camera = view->renderWindow()->GetRenderers()->GetFirstRenderer()->GetActiveCamera();
        const QPoint center = view->rect().center();
        const double distance = camera->GetDistance();
        QWheelEvent wheel(center, view->mapToGlobal(center), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(view, &wheel);
        QVERIFY2(camera->GetDistance() < 0.95 * distance, qPrintable(QString::number(camera->GetDistance())));
        const double zoom = w.painter()->orbitAngles().zoom;
        QVERIFY2(zoom > 1.05, qPrintable(QString::number(zoom)));

        // Dragging up with the right button zooms in further.
        sendMouse(w, QEvent::MouseButtonPress, center, Qt::RightButton, Qt::RightButton);
        sendMouse(w, QEvent::MouseMove, center - QPoint(0, 40), Qt::RightButton);
        sendMouse(w, QEvent::MouseButtonRelease, center - QPoint(0, 40), Qt::NoButton, Qt::RightButton);
        const double dollied = w.painter()->orbitAngles().zoom;
        QVERIFY2(dollied > 1.05 * zoom, qPrintable(QString::number(dollied)));
        // The text stays where it was laid out: the layout allows for a step's or an export's zoom, not the
        // wheel's (found: a notch moved the legend beside the stage and reframed it).
        QCOMPARE(w.painter()->figureView().zoom, 1.0);

        // Dragging with the middle button moves the focal point across the view, not along it.
        Vec3<double> before, after, direction;
        camera->GetFocalPoint(before.data());
        camera->GetDirectionOfProjection(direction.data());
        sendMouse(w, QEvent::MouseButtonPress, center, Qt::MiddleButton, Qt::MiddleButton);
        sendMouse(w, QEvent::MouseMove, center + QPoint(60, 0), Qt::MiddleButton);
        sendMouse(w, QEvent::MouseButtonRelease, center + QPoint(60, 0), Qt::NoButton, Qt::MiddleButton);
        camera->GetFocalPoint(after.data());
        QVERIFY((after - before).norm() > 1);
        QVERIFY(std::abs((after - before).normalized().dot(direction)) < 1e-6);

        w.stepper()->goToStage(1, false);
        waitForRest(w);
        QCOMPARE(w.painter()->orbitAngles().zoom, dollied);
    }

    // Reset View (R) brings back the view a scene opens with at a stage: its
    // viewpoint and framing, the user's turn and zoom undone (it framed what
    // the stage shows alone, tighter than the stage at rest is framed).
    void resetViewReturnsToTheOpeningView()
    {
        MainWindow& w = *window_;
        auto* view = w.findChild<QVTKOpenGLNativeWidget*>("worldView");
        vtkCamera* camera = view->renderWindow()->GetRenderers()->GetFirstRenderer()->GetActiveCamera();
        w.stepper()->goToStage(3, false);
        w.painter()->orbit(30, -15, 1.5); // left behind by opening another scene
        QVERIFY(w.sceneFiles()->openScene(QString(viewpipe::build::dataDir) + "/scenes/house-corner.json"));
        w.renderNow();
        Vec3<double> opened, reset;
        camera->GetPosition(opened.data());
        w.painter()->orbit(40, 20, 2);
        w.renderNow();
        QTest::keyClick(&w, Qt::Key_R);
        camera->GetPosition(reset.data());
        QVERIFY2((opened - reset).norm() < 1e-9 * opened.norm(),
                 qPrintable(QString("%1 %2 %3 against %4 %5 %6").arg(reset.x()).arg(reset.y()).arg(reset.z())
                                .arg(opened.x()).arg(opened.y()).arg(opened.z())));
    }

    // While a step moves, the caption and the matrices name the stage it moves
    // to, as the stage list does (they named the stage it left: "the identity
    // here: nothing moves" over a moving picture).
    void aMovingStepIsNamedAsItMoves()
    {
        MainWindow& w = *window_;
        w.stepper()->goToStage(3, false);
        const std::string caption = w.painter()->worldCaption();
        const QString matrices = w.matrices()->stageText();
        w.stepper()->goToStage(2, false);
        QVERIFY(w.painter()->worldCaption() != caption);
        w.stepper()->goToStage(3);
        QVERIFY(w.stepper()->isAnimating());
        QCOMPARE(w.painter()->worldCaption(), caption);
        QCOMPARE(w.matrices()->stageText(), matrices);
        waitForRest(w);
        QCOMPARE(w.painter()->worldCaption(), caption);
    }

    // A mesh is drawn from one float copy of its vertices where VTK draws them
    // unshifted (from doubles it packs a float copy of its own for each view, and
    // keeps it); from its own doubles, not a copy, where VTK shifts and scales
    // them first, and for what computes with them (Exact).
    void meshVerticesAsVtkGetsThem()
    {
        using viewpipe::gui::Coordinates;
        using viewpipe::gui::facesData;
        const auto near = std::make_shared<const PolygonMesh>(boxMesh({0.1, -2, 30}, {16.3, 10, 54}));
        const vtkSmartPointer<vtkPolyData> drawnData = facesData(near, Coordinates::Drawn);
        vtkDataArray* drawn = drawnData->GetPoints()->GetData();
        QCOMPARE(drawn->GetDataType(), VTK_FLOAT);
        QCOMPARE(drawn->GetNumberOfTuples(), vtkIdType(near->vertices.size()));
        for (std::size_t k = 0; k < near->vertices.size(); ++k)
            for (int c = 0; c < 3; ++c)
                QCOMPARE(drawn->GetComponent(vtkIdType(k), c), double(float(near->vertices[k][c])));
        const vtkSmartPointer<vtkPolyData> exactData = facesData(near, Coordinates::Exact);
        vtkDataArray* exact = exactData->GetPoints()->GetData();
        QCOMPARE(exact->GetDataType(), VTK_DOUBLE);
        QCOMPARE(exact->GetVoidPointer(0), static_cast<const void*>(near->vertices.data()->data())); // not a copy

        // Where VTK shifts and scales: far from the origin for its size (float would round these
        // vertices to a unit), and large (10^3 across).
        const auto far = std::make_shared<const PolygonMesh>(boxMesh({1e7, 1e7, 0}, {1e7 + 1e4, 1e7 + 1e4, 1e4}));
        QCOMPARE(facesData(far, Coordinates::Drawn)->GetPoints()->GetDataType(), VTK_DOUBLE);
        const auto large = std::make_shared<const PolygonMesh>(boxMesh({-500, -500, -500}, {500, 500, 500}));
        QCOMPARE(facesData(large, Coordinates::Drawn)->GetPoints()->GetDataType(), VTK_DOUBLE);
    }

    void stepperWalksThroughTheStages()
    {
        MainWindow& w = *window_;
        QCOMPARE(w.stepper()->stageCount(), 5);
        QCOMPARE(w.stepper()->stage(), 0);
        const QImage world = worldPicture(w);

        QTest::keyClick(&w, Qt::Key_Right);
        QVERIFY(w.stepper()->isAnimating());
        waitForRest(w);
        QCOMPARE(w.stepper()->stage(), 1);
        QVERIFY(w.matrices()->stageText().contains("<i>T</i>(−<i>VRP</i>)")); // set as math

        // Through the slider to the last stage: each step animates.
        w.findChild<QSlider*>("stageSlider")->setValue(5);
        waitForRest(w);
        QCOMPARE(w.stepper()->stage(), 5);
        QVERIFY(w.matrices()->stageText().contains("<i>S</i><sub>per</sub>")); // S_per, set as math
        QCOMPARE(w.stagePanel()->stageList()->currentRow(), 5);
        QVERIFY(worldPicture(w) != world);

        QTest::keyClick(&w, Qt::Key_Left);
        waitForRest(w);
        QCOMPARE(w.stepper()->stage(), 4);
        w.stepper()->goToStage(0, false);
        QCOMPARE(w.stepper()->stage(), 0);
    }

    // Behaviour only: how fast the frames come is measured in bench/, not asserted here. On the test's
    // clock (a tick every 16 ms, as a 60 Hz screen's), a step of a second shows a frame each tick.
    void transitionsProduceFramesAndEndOnTheTarget()
    {
        MainWindow& w = *window_;
        TestClock clock(*w.stepper());
        int frames = 0;
        QVariantAnimation* animation = w.stepper()->findChild<QVariantAnimation*>();
        QVERIFY(animation);
        connect(animation, &QVariantAnimation::valueChanged, this, [&frames] { ++frames; });
        w.stepper()->goToStage(1);
        QVERIFY(w.stepper()->isAnimating());
        QVERIFY(clock.runWhile([&] { return w.stepper()->isAnimating(); }));
        QVERIFY2(std::abs(frames - 1000 / TestClock::kTick) <= 2, qPrintable(QString::number(frames)));
        QCOMPARE(w.stepper()->stage(), 1);
        QCOMPARE(w.stagePanel()->stageList()->currentRow(), 1);
        w.stepper()->goToStage(0, false);
    }

    // Found: on a busy machine a step of Play took about 2 s, not the promised
    // second, as each stage at rest on the way (matrices, both views drawn) came
    // on top. Here each rest takes 400 ms of the test's clock; each following step
    // starts as far along its second as the rest before it lasted (to the tick),
    // making the time up by dropping frames. The last rest takes longer than a
    // step: that step still starts at its last moving frame.
    void playKeepsToTheClockWhenRestingIsSlow()
    {
        MainWindow& w = *window_;
        TestClock clock(*w.stepper());
        w.stepper()->goToStage(0, false);
        QVariantAnimation* animation = w.stepper()->findChild<QVariantAnimation*>();
        QVERIFY(animation);
        QList<qint64> rested; // how long each rest before a following step lasted, in ms
        const auto busy = connect(w.stepper(), &Stepper::rested, this, [&] {
            const qint64 resting = w.stepper()->stage() == 4 ? 1200 : 400;
            clock.now += resting;
            if (w.stepper()->stage() >= 1 && w.stepper()->stage() <= 4)
                rested << resting;
        });
        QList<int> startedAt; // each following step's time, in ms, as it starts
        const auto started = connect(w.stepper(), &Stepper::moved, this, [&] {
            if (w.stepper()->isAnimating() && w.stepper()->stage() > 0)
                startedAt << animation->currentTime();
        });
        w.stepper()->play();
        QVERIFY(clock.runWhile([&] { return w.stepper()->isPlaying(); }));
        disconnect(busy);
        disconnect(started);
        QCOMPARE(w.stepper()->stage(), 5);
        QCOMPARE(startedAt.size(), 4); // steps 2 to 5 each follow a rest
        QCOMPARE(rested.size(), 4);
        for (int k = 0; k < 3; ++k) // late by the rest, and by at most the tick in which the step before ended
            QVERIFY2(startedAt[k] >= rested[k] && startedAt[k] <= rested[k] + TestClock::kTick,
                     qPrintable(QString("step %1 started %2 ms along after a rest of %3 ms").arg(k + 2).arg(startedAt[k]).arg(rested[k])));
        QCOMPARE(startedAt.last(), animation->duration() - 1); // later than the step lasts: its last frame
        w.stepper()->goToStage(0, false);
    }

    void refusedEditKeepsThePicture()
    {
        MainWindow& w = *window_;
        w.stepper()->goToStage(3, false);
        const QImage before = worldPicture(w);
        const QString sceneBefore = QString::fromStdString(sceneToJson(w.document()->scene()));

        QLineEdit* front = w.parameters()->fields("view.front").first();
        front->setText("10"); // F = 10 < B = 25
        emit front->editingFinished();
        QVERIFY(w.parameters()->errorText("view.front").contains("F (10) must be greater than B (25)"));
        QCOMPARE(QString::fromStdString(sceneToJson(w.document()->scene())), sceneBefore);
        QCOMPARE(worldPicture(w), before);
        QVERIFY(!w.document()->undoStack()->canUndo());

        QLineEdit* vupY = w.parameters()->fields("view.vup")[1];
        vupY->setText("0"); // VUP = 0
        emit vupY->editingFinished();
        QVERIFY(w.parameters()->errorText("view.vup").contains("zero vector"));
        QCOMPARE(worldPicture(w), before);

        vupY->setText("1"); // valid again: the message goes, the edit is taken
        emit vupY->editingFinished();
        QVERIFY(w.parameters()->errorText("view.vup").isEmpty());
    }

    void undoAndRedoEveryEdit()
    {
        MainWindow& w = *window_;
        QLineEdit* vrpX = w.parameters()->fields("view.vrp").first();
        vrpX->setText("5");
        emit vrpX->editingFinished();
        auto vrpOf = [&w] { return std::get<foley::ViewSpec<double>>(w.document()->scene().camera).vrp.x(); };
        QCOMPARE(vrpOf(), 5.0);
        QVERIFY(w.document()->isModified());
        w.document()->undoStack()->undo();
        QCOMPARE(vrpOf(), 0.0);
        QCOMPARE(w.parameters()->fields("view.vrp").first()->text(), QString("0"));
        w.document()->undoStack()->redo();
        QCOMPARE(vrpOf(), 5.0);
        QCOMPARE(w.parameters()->fields("view.vrp").first()->text(), QString("5"));
    }

    void openAndSaveRoundTrip()
    {
        MainWindow& w = *window_;
        QLineEdit* prpN = w.parameters()->fields("view.prp").last();
        prpN->setText("90");
        emit prpN->editingFinished();
        QTemporaryDir dir;
        const QString file = dir.filePath("saved.json");
        QVERIFY(w.sceneFiles()->saveScene(file));
        QVERIFY(!w.document()->isModified());
        const std::string saved = sceneToJson(w.document()->scene());
        QVERIFY(QDir(dir.path()).entryList(QDir::Files) == QStringList{"saved.json"});

        MainWindow other;
        QVERIFY(other.sceneFiles()->openScene(file));
        QCOMPARE(sceneToJson(other.document()->scene()), saved);
        QCOMPARE(std::get<foley::ViewSpec<double>>(other.document()->scene().camera).prp.z(), 90.0);

        // A file that does not parse is refused and the open scene stays.
        const QString broken = dir.filePath("broken.json");
        QVERIFY(writeFile(broken, "{\"view\": 3}"));
        QVERIFY(!other.sceneFiles()->openScene(broken));
        QCOMPARE(sceneToJson(other.document()->scene()), saved);
    }

    void importMeshIsUndoableAndRefusesUnreadableFiles()
    {
        MainWindow& w = *window_;
        QTemporaryDir dir;
        const QString obj = dir.filePath("tetra.obj");
        QVERIFY(writeFile(obj, "v 0 0 30\nv 10 0 30\nv 0 10 30\nv 0 0 40\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n"));
        QVERIFY(w.sceneFiles()->importMesh(obj));
        QCOMPARE(w.document()->scene().objects.size(), std::size_t(2));
        QCOMPARE(w.document()->scene().objects[1].type, ObjectType::Mesh);

        // Saved elsewhere, the mesh path is written relative to the scene file.
        const QString saved = dir.filePath("scene.json");
        QVERIFY(w.sceneFiles()->saveScene(saved));
        QVERIFY(QString::fromStdString(sceneToJson(loadScene(saved.toStdString()))).contains("\"path\": \"tetra.obj\""));

        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->scene().objects.size(), std::size_t(1));

        const QString junk = dir.filePath("junk.stl");
        QVERIFY(writeFile(junk, "this is not a mesh"));
        QVERIFY(!w.sceneFiles()->importMesh(junk));
        QCOMPARE(w.document()->scene().objects.size(), std::size_t(1));
    }

    void clickTracesAVertex()
    {
        MainWindow& w = *window_;
        w.stepper()->goToStage(3, false);
        clickWhereDrawn(w, Vec3<double>(16, 10, 54));
        QTRY_VERIFY(w.matrices()->traceText().contains("Traced vertex"));
        // After T(-PRP) the vertex is (16 - 8, 10 - 6, 54 - 84) = (8, 4, -30).
        QVERIFY2(w.matrices()->traceText().contains("<td align='right'>&nbsp;8</td><td align='right'>&nbsp;4</td>"
                                                    "<td align='right'>&nbsp;−30</td>"),
                 qPrintable(w.matrices()->traceText()));
    }

    // Under a projective stage matrix (gluPerspective's), where VTK's own
    // pickers would not look: the click finds the vertex drawn there.
    void clickTracesAVertexThroughAProjectiveStage()
    {
        MainWindow& w = *window_;
        QVERIFY(w.sceneFiles()->openScene(QString(viewpipe::build::dataDir) + "/scenes/opengl-perspective.json"));
        const int last = w.stepper()->stageCount();
        w.stepper()->goToStage(last, false);
        const double w4 = (cumulativeAt(w.document()->pipeline().stages, last) * Vec4<double>(16, 10, 54, 1)).w();
        QVERIFY(w4 > 0 && std::abs(w4 - 1) > 0.1); // projective: the divide moves the point
        clickWhereDrawn(w, Vec3<double>(16, 10, 54));
        QTRY_VERIFY(w.matrices()->traceText().contains("Traced vertex"));
        QVERIFY2(w.matrices()->traceText().contains("<td align='right'>&nbsp;16</td><td align='right'>&nbsp;10</td>"
                                                    "<td align='right'>&nbsp;54</td>"),
                 qPrintable(w.matrices()->traceText()));
    }

    void copiesMatrixAndViewToTheClipboard()
    {
        MainWindow& w = *window_;
        w.stepper()->goToStage(4, false);
        w.exports()->copyMatrixAsLatex();
        const QString latex = QApplication::clipboard()->text();
        QVERIFY2(latex.startsWith("\\mathit{SH}_{\\mathrm{per}} =\n\\begin{bmatrix}"), qPrintable(latex));
        QVERIFY(latex.contains("1 & 0 & -\\frac{2}{21} & 0"));
        w.exports()->copyViewAsImage();
        const QImage image = QApplication::clipboard()->image();
        QCOMPARE(image.size(), w.findChild<QVTKOpenGLNativeWidget*>("worldView")->size());
    }

    void exportsFromTheAppAndCancels()
    {
        MainWindow& w = *window_;
        QTemporaryDir dir;
        ExportOptions options;
        options.out = dir.filePath("slides").toStdString();
        options.width = 320;
        options.height = 180;
        options.stages = {0, 5};
        const auto files = w.exports()->exportStages(options);
        QCOMPARE(files.size(), std::size_t(4)); // two pictures, matrices.tex, matrices.json
        QVERIFY(QFile::exists(dir.filePath("slides/05-s-per.png")));

        // Cancel as soon as the progress dialog shows: nothing is left behind.
        QTimer::singleShot(0, [&w] {
            if (auto* progress = w.findChild<QProgressDialog*>())
                progress->cancel();
        });
        options.out = dir.filePath("cancelled").toStdString();
        options.stages = {};
        options.animate = true;
        QVERIFY(w.exports()->exportStages(options).empty());
        QVERIFY(!QDir(dir.filePath("cancelled")).exists());
    }

    void exportsTheSceneAsAWebPage()
    {
        MainWindow& w = *window_;
        QAction* action = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->text() == "Export as &Web Page…")
                action = a;
        QVERIFY2(action, "File has Export as Web Page");
        QTemporaryDir dir;
        QDir(dir.path()).mkpath("lecture");
        const QString page = dir.filePath("lecture/house.html");
        // Through the menu: the save dialog (Qt's own under the tests) answered with the file name.
        QTimer::singleShot(0, [page] {
            for (QWidget* top : QApplication::topLevelWidgets())
                if (auto* dialog = qobject_cast<QFileDialog*>(top)) {
                    dialog->selectFile(page);
                    QMetaObject::invokeMethod(dialog, "accept"); // as the Save button does
                }
        });
        action->trigger();
        QFile file(page);
        QVERIFY2(file.open(QIODevice::ReadOnly), "the page was written where the dialog said");
        const QByteArray html = file.readAll();
        QVERIFY(html.startsWith("<!DOCTYPE html>"));
        QVERIFY(html.contains("<title>Foley's house · ViewPipe</title>"));
        QVERIFY(html.contains("\"transitions\""));
        QCOMPARE(QDir(dir.filePath("lecture")).entryList(QDir::Files | QDir::Hidden).size(), 1); // nothing left beside it

        // Cancel clicked as the last step reports (the progress dialog's events run then): the page stays as it was.
        file.close();
        QVERIFY(QFile::resize(page, 0));
        std::atomic<bool> cancel{false};
        exportWebPage(w.document()->evaluated(), page.toStdString(), report::Theme::Light,
                      [&cancel](int, int, const std::string& what) { cancel = what == "scene.html"; }, cancel);
        QVERIFY(cancel);
        QCOMPARE(QFileInfo(page).size(), 0);
    }

    void presentsFullScreenWithAClickersKeys()
    {
        MainWindow& w = *window_;
        w.stepper()->goToStage(0, false);
        QSettings().setValue("fontSize", MainWindow::kDefaultFontSize);
        w.setFontSize(MainWindow::kDefaultFontSize + 2, false); // one run's size (open --text-scale)
        const int fontBefore = QApplication::font().pointSize();
        const report::Theme themeBefore = w.painter()->theme();
        QTest::keyClick(&w, Qt::Key_F5);
        QVERIFY(w.presentMode()->isPresenting());
        QTRY_VERIFY(w.isFullScreen());
        QTRY_COMPARE(w.frameGeometry().size(), w.windowHandle()->screen()->geometry().size()); // no window manager here
        QVERIFY(!w.menuBar()->isVisible());
        for (QDockWidget* dock : w.findChildren<QDockWidget*>())
            QVERIFY2(!dock->isVisible(), qPrintable(dock->objectName()));
        QCOMPARE(w.painter()->theme(), report::Theme::Light);
        QVERIFY(QApplication::font().pointSize() >= std::max(16, fontBefore));
        // The world view fills the screen and its caption fits in it.
        auto* world = w.findChild<QVTKOpenGLNativeWidget*>("worldView");
        QTRY_VERIFY(world->width() > w.width() / 2);

        // The clicker: Page Down and Space on, Page Up and Backspace back, through the transitions.
        QTest::keyClick(&w, Qt::Key_PageDown);
        QTRY_VERIFY(!w.stepper()->isAnimating() && w.stepper()->stage() == 1);
        QTest::keyClick(&w, Qt::Key_Space);
        QTRY_VERIFY(!w.stepper()->isAnimating() && w.stepper()->stage() == 2);
        QTest::keyClick(&w, Qt::Key_Backspace);
        QTRY_VERIFY(!w.stepper()->isAnimating() && w.stepper()->stage() == 1);
        QTest::keyClick(&w, Qt::Key_PageUp);
        QTRY_VERIFY(!w.stepper()->isAnimating() && w.stepper()->stage() == 0);
        QVERIFY(w.painter()->worldCaption().find("World") != std::string::npos);

        // B blacks the screen out and back.
        QTest::keyClick(&w, Qt::Key_B);
        QVERIFY(w.presentMode()->isBlackedOut());
        QVERIFY(w.findChild<QWidget*>("blackout")->geometry().contains(world->geometry()));
        QTest::keyClick(&w, Qt::Key_B);
        QVERIFY(!w.presentMode()->isBlackedOut());

        // Esc leaves, as the window was.
        QTest::keyClick(&w, Qt::Key_Escape);
        QVERIFY(!w.presentMode()->isPresenting());
        QTRY_VERIFY(!w.isFullScreen());
        QVERIFY(w.menuBar()->isVisible());
        QTRY_VERIFY(w.findChild<QDockWidget*>("stagesDock")->isVisible());
        QCOMPARE(QApplication::font().pointSize(), fontBefore);
        QCOMPARE(QSettings().value("fontSize").toInt(), MainWindow::kDefaultFontSize); // found: the run's size kept
        QCOMPARE(w.painter()->theme(), themeBefore);
        // Outside present mode B and Space are the keys they always were.
        QTest::keyClick(&w, Qt::Key_B);
        QVERIFY(!w.presentMode()->isBlackedOut());
    }

    void accuracyPanelMeasuresInTheBackground()
    {
        MainWindow& w = *window_;
        QSignalSpy done(w.accuracy(), &AccuracyPanel::finished);
        w.accuracy()->measure(*w.document()->evaluated(), 20000);
        QVERIFY(w.accuracy()->isRunning());
        // The window keeps handling events while the worker measures.
        QTest::keyClick(&w, Qt::Key_Right);
        QVERIFY(w.stepper()->isAnimating() || w.stepper()->stage() == 1);
        QVERIFY(done.wait(120000));
        QCOMPARE(w.accuracy()->table()->rowCount(), 7); // six tiers and the exact end
        QCOMPARE(w.accuracy()->table()->item(1, 0)->text(), QString("double"));
        QVERIFY(w.accuracy()->table()->item(1, 5)->text().contains("e-16"));
    }

    // Found: the Vulkan preset with its far plane at infinity was refused
    // ("camera.projection.far: is infinite"); what can be measured is.
    void accuracyMeasuresAVolumeWithoutAFarFace()
    {
        MainWindow& w = *window_;
        QVERIFY(w.sceneFiles()->openScene(QString(viewpipe::build::dataDir) + "/scenes/apis/vulkan-reversed-infinite.json"));
        QSignalSpy done(w.accuracy(), &AccuracyPanel::finished);
        w.accuracy()->measure(*w.document()->evaluated(), 2000);
        QVERIFY(done.wait(120000));
        QCOMPARE(w.accuracy()->table()->rowCount(), 7); // six tiers and the exact end
        QVERIFY(w.accuracy()->table()->item(1, 5)->text().contains("e-16")); // double's corners
        const QList<QLabel*> labels = w.accuracy()->findChildren<QLabel*>();
        QVERIFY(std::any_of(labels.begin(), labels.end(), [](const QLabel* label) {
            return label->text().contains("up to far = 1000 × near (its far plane is infinite)");
        }));
    }

    // Before any measurement the Accuracy panel's plot area is the theme's
    // background: dark in the dark theme, not a white box; light in the light.
    void accuracyPlotAreaTakesTheThemeBeforeAMeasurement()
    {
        MainWindow& w = *window_;
        w.showPanel("accuracy");
        auto* charts = w.accuracy()->findChild<QVTKOpenGLNativeWidget*>();
        QVERIFY(charts);
        QTRY_VERIFY(charts->isVisible() && charts->height() > 100);
        for (const report::Theme theme : {report::Theme::Dark, report::Theme::Light, report::Theme::Dark}) {
            w.setTheme(theme);
            const QImage image = charts->grabFramebuffer();
            const int lightness = image.pixelColor(image.width() / 2, image.height() / 2).lightness();
            QVERIFY2(theme == report::Theme::Dark ? lightness < 60 : lightness > 200, qPrintable(QString::number(lightness)));
        }
    }

    void classicalProjectionIsOneUndoableEdit()
    {
        MainWindow& w = *window_;
        QTimer::singleShot(0, [&w] {
            auto* dialog = w.findChild<ClassicalDialog*>();
            QVERIFY(dialog);
            dialog->setKind(ClassicalKind::Cabinet);
            dialog->accept();
        });
        w.chooseClassicalProjection();
        const auto& spec = std::get<foley::ViewSpec<double>>(w.document()->scene().camera);
        QCOMPARE(classify(CameraSpec<double>(spec)).kind, std::string("cabinet"));
        QCOMPARE(w.stepper()->stageCount(), 5);
        QCOMPARE(w.document()->pipeline().stages[2].symbol(), std::string("SH_par"));
        w.document()->undoStack()->undo();
        QCOMPARE(std::get<foley::ViewSpec<double>>(w.document()->scene().camera).prp, Vec3<double>(8, 6, 84));
    }

    // The raster effect at full size against VTK's own render of the same
    // scene (a gluPerspective camera, which VTK's camera reproduces): the
    // object seen at each pixel agrees but for a sliver along the edges.
    void rasterMatchesVtk()
    {
        const int width = 320, height = 240;
        Scene scene = loadScene((QString(viewpipe::build::dataDir) + "/scenes/opengl-perspective.json").toStdString());
        auto& camera = std::get<gl::Camera<double>>(scene.camera);
        auto& perspective = std::get<gl::Perspective<double>>(camera.projection);
        perspective.aspect = double(width) / height;
        std::vector<PolygonMesh> meshes;
        for (const auto& mesh : objectMeshes(scene))
            meshes.push_back(*mesh);
        const RasterOutcome raster = rasterize(buildPipeline(scene.camera), meshes, RasterOptions{width, height});

        vtkNew<vtkRenderWindow> window;
        window->SetOffScreenRendering(1);
        window->SetSize(width, height);
        window->SetMultiSamples(0);
        vtkNew<vtkRenderer> renderer;
        window->AddRenderer(renderer);
        for (std::size_t o = 0; o < meshes.size(); ++o) {
            vtkNew<vtkPoints> points;
            for (const Vec3<double>& v : meshes[o].vertices)
                points->InsertNextPoint(v.data());
            vtkNew<vtkCellArray> polys;
            for (const auto& face : meshes[o].faces) {
                std::vector<vtkIdType> ids(face.begin(), face.end());
                polys->InsertNextCell(vtkIdType(ids.size()), ids.data());
            }
            vtkNew<vtkPolyData> data;
            data->SetPoints(points);
            data->SetPolys(polys);
            vtkNew<vtkPolyDataMapper> mapper;
            mapper->SetInputData(data);
            vtkNew<vtkActor> actor;
            actor->SetMapper(mapper);
            actor->GetProperty()->LightingOff();
            actor->GetProperty()->SetColor(o == 0 ? 1 : 0, o == 1 ? 1 : 0, 0);
            renderer->AddActor(actor);
        }
        vtkCamera* c = renderer->GetActiveCamera();
        c->SetPosition(camera.lookAt.eye.data());
        c->SetFocalPoint(camera.lookAt.center.data());
        c->SetViewUp(camera.lookAt.up.data());
        c->SetViewAngle(perspective.fovyDegrees);
        c->SetClippingRange(perspective.zNear, perspective.zFar);
        window->Render();
        vtkNew<vtkWindowToImageFilter> grab;
        grab->SetInput(window);
        grab->ReadFrontBufferOff();
        grab->Update();
        vtkImageData* image = grab->GetOutput();
        int differing = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
                const int vtk = rgb[0] > 127 ? 0 : rgb[1] > 127 ? 1 : -1;
                differing += vtk != raster.object[std::size_t(y * width + x)];
            }
        const double share = double(differing) / (width * height);
        qInfo("raster against VTK: %d of %d pixels differ (%.2f%%), %d covered", differing, width * height,
              100 * share, raster.covered);
        QVERIFY(raster.covered > width * height / 20);
        QVERIFY(share < 0.01);
    }

    // The Effects menu edits the scene's list, one undoable step each; the
    // stepper, the note under the world view and the Depth panel follow, and
    // a saved scene keeps the list.
    void effectsMenuTogglesEffectsUndoably()
    {
        MainWindow& w = *window_;
        // The document's scene is replaced by each edit: read it afresh.
        auto effects = [&]() -> const EffectList& { return w.document()->scene().effects; };
        QUndoStack* undo = w.document()->undoStack();
        const int stages = w.stepper()->stageCount();
        QAction* divide = menuAction(w, "effectsMenu", "Divide (stage M)");
        divide->trigger();
        QCOMPARE(w.stepper()->stageCount(), stages + 1);
        QCOMPARE(w.document()->pipeline().stages.back().symbol(), std::string("M"));
        QCOMPARE(w.stagePanel()->stageList()->count(), stages + 2);
        QVERIFY(divide->isChecked());
        undo->undo();
        QCOMPARE(w.stepper()->stageCount(), stages);
        QVERIFY(!divide->isChecked());

        menuAction(w, "depthMenu", "16-bit Fixed Point")->trigger();
        QVERIFY(effects().depth && effects().depth->bits == 16 && !effects().depth->floating);
        QVERIFY(w.depth()->summary().contains("16-bit fixed point"));
        QVERIFY(w.document()->evaluated()->effectsNote.find("depth: 16-bit fixed point; each band") != std::string::npos);
        QAction* reversed = menuAction(w, "depthMenu", "Reversed Z (near 1, far 0)");
        QVERIFY(reversed->isEnabled());
        reversed->trigger();
        QVERIFY(effects().depth->reversed && effects().depth->bits == 16);
        menuAction(w, "depthMenu", "32-bit Float")->trigger(); // keeps reversed
        QVERIFY(effects().depth->floating && effects().depth->bits == 32 && effects().depth->reversed);
        undo->undo();
        undo->undo();
        QVERIFY(effects().depth && !effects().depth->reversed && !effects().depth->floating);
        QVERIFY(menuAction(w, "depthMenu", "16-bit Fixed Point")->isChecked());
        menuAction(w, "depthMenu", "Off")->trigger();
        QVERIFY(!effects().depth);
        QVERIFY(!reversed->isEnabled());
        QVERIFY(w.depth()->summary().contains("does not simulate"));

        menuAction(w, "rasterMenu", "32 × 24 Pixels")->trigger();
        QVERIFY(effects().raster && effects().raster->width == 32 && effects().raster->height == 24);
        QVERIFY(w.document()->evaluated()->effectsNote.find("raster: 32 x 24") != std::string::npos);
        menuAction(w, "effectsMenu", "Clip to the View Volume")->trigger();
        QVERIFY(effects().listed == (std::vector<EffectKind>{EffectKind::Raster, EffectKind::Clip}));
        QCOMPARE(undo->undoText(), QString("Turn on Clip to the View Volume"));

        // Choosing what is already chosen is no edit.
        const int edits = undo->count();
        menuAction(w, "rasterMenu", "32 × 24 Pixels")->trigger();
        QCOMPARE(undo->count(), edits);

        QTemporaryDir dir;
        const QString path = dir.filePath("effects.json");
        QVERIFY(w.sceneFiles()->saveScene(path));
        QVERIFY(loadScene(path.toStdString()).effects.listed == effects().listed);
    }

    // Depth bands color the corridor's posts in the projected view; without
    // the effect no band color appears.
    void depthBandsColorTheScene()
    {
        MainWindow& w = *window_;
        QVERIFY(w.sceneFiles()->openScene(QString(viewpipe::build::dataDir) + "/scenes/depth-corridor.json"));
        w.showPanel("depth");
        const int banded = bandPixels(w);
        QVERIFY2(banded > 2000, qPrintable(QString::number(banded)));
        QVERIFY(w.depth()->summary().contains("z-fight"));
        w.effectsMenu()->editEffects("Turn off the depth buffer", [](EffectList list) { return withEffect(std::move(list), "depth", false); });
        QVERIFY(!w.document()->scene().effects.depth);
        QCOMPARE(bandPixels(w), 0);
        w.document()->undoStack()->undo();
        QCOMPARE(bandPixels(w), banded);
    }

    void eigenVtkAdapterKeepsRowsAndColumns()
    {
        Mat4<double> m;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                m(r, c) = 10 * r + c;
        const auto v = toVtk(m);
        QCOMPARE(v->GetElement(1, 3), 13.0);
        QCOMPARE(v->GetElement(3, 1), 31.0);
        double p[4] = {1, 2, 3, 1}, q[4];
        v->MultiplyPoint(p, q);
        const Vec4<double> expected = m * Vec4<double>(1, 2, 3, 1);
        for (int i = 0; i < 4; ++i)
            QCOMPARE(q[i], expected[i]);
        QVERIFY(fromVtk(v) == m);
    }

private:
    std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv)
{
    return runAppTests<AppTest>(argc, argv);
}

#include "app_test.moc"
