// The storyboard in the app (View > Storyboard): every stage at once, driven
// by keys and the mouse as a person drives it; one copy of a mesh however
// many views draw it.

#include <QAction>
#include <QClipboard>
#include <QFile>
#include <QLineEdit>
#include <QRegularExpression>
#include <QWheelEvent>
#include <QTemporaryDir>
#include <QStackedWidget>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include <set>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include "app_window.h"
#include "drawn_texts.h"
#include "app/ParameterPanel.h"
#include "app/StoryboardView.h"
#include "viewpipe/report/world_view.hpp"

using namespace viewpipe;
using namespace viewpipe::gui;

namespace {

const QString kHouse = QString(viewpipe::build::dataDir) + "/scenes/house.json";
const QString kLetterF = QString(viewpipe::build::dataDir) + "/scenes/letter-f.json";
const QString kFoley = QString(viewpipe::build::dataDir) + "/lessons/foley-nper.json";

QImage cellPicture(MainWindow& window, int k)
{
    window.renderNow();
    return window.views()->storyboard()->cellWidget(k)->grabFramebuffer();
}

// The share of a picture's pixels that are not its background (its corner's color).
double drawnShare(const QImage& image)
{
    const QRgb background = image.pixel(0, 0);
    long drawn = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            drawn += image.pixel(x, y) != background;
    return double(drawn) / (double(image.width()) * image.height());
}

// Where cell k draws a world point, in the cell widget's pixels (y down).
QPoint drawnAt(MainWindow& window, int k, const Vec3<double>& world)
{
    const EvaluatedScene& scene = *window.document()->evaluated();
    const report::FigureView view = window.views()->storyboard()->cellPainter(k).figureView();
    const Mat4<double> drawn = report::stageAtRest(scene, k, report::stageFramings(scene, report::FramingMode::Together)).drawn;
    const Vec4<double> clip = view.camera * drawn * world.homogeneous();
    const Vec3<double> ndc = clip.head<3>() / clip.w();
    return QPoint(int(std::lround((ndc.x() + 1) / 2 * view.width)), int(std::lround((1 - ndc.y()) / 2 * view.height)));
}

// A left-button drag across a widget, as the mouse sends it (QTest's moves carry no button).
void drag(QWidget* widget, QPoint from, QPoint to)
{
    QTest::mousePress(widget, Qt::LeftButton, {}, from);
    for (int step = 1; step <= 10; ++step) {
        const QPoint at = from + (to - from) * step / 10;
        QMouseEvent move(QEvent::MouseMove, at, widget->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(widget, &move);
    }
    QTest::mouseRelease(widget, Qt::LeftButton, {}, to);
}

} // namespace

class StoryboardAppTest : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> window_;

private slots:
    void init()
    {
        window_ = openWindow(kHouse);
        QVERIFY(window_);
    }

    void cleanup()
    {
        if (window_ && window_->lessonFlow()->lesson()->isOpen())
            window_->lessonFlow()->lesson()->undoStack()->setClean();
        closeWindow(window_);
    }

    // S shows every stage at once in place of the two views, each cell its stage's picture
    // side by side in reading order; S again brings the two views back.
    void theKeyShowsEveryStage()
    {
        MainWindow& w = *window_;
        QTest::keyClick(&w, Qt::Key_S);
        QVERIFY(w.views()->storyboardShown());
        QVERIFY(w.actions()->action("view.storyboard")->isChecked());
        StoryboardView& board = *w.views()->storyboard();
        QTRY_VERIFY(board.isVisible());
        QVERIFY(!w.findChild<QVTKOpenGLNativeWidget*>("worldView")->isVisible());
        const int stages = int(w.document()->pipeline().stages.size());
        QCOMPARE(board.cellCount(), stages + 1);
        QRect before;
        std::vector<QImage> pictures;
        for (int k = 0; k < board.cellCount(); ++k) {
            QCOMPARE(board.cellStage(k), k);
            QWidget* cell = board.cellWidget(k);
            QVERIFY2(cell->isVisible(), qPrintable(QString("stage %1 is not shown").arg(k)));
            const QRect box = cell->geometry();
            QVERIFY(board.rect().contains(box));
            QVERIFY(box.width() >= 160 && box.height() >= 90);
            // Reading order: each cell right of the one before in its row, or in a row below.
            if (k > 0)
                QVERIFY2(box.left() > before.right() || box.top() > before.bottom(), qPrintable(QString("stage %1").arg(k)));
            before = box;
            pictures.push_back(cellPicture(w, k));
            QVERIFY2(drawnShare(pictures.back()) > 0.1, qPrintable(QString("stage %1 is nearly blank").arg(k)));
        }
        QVERIFY(pictures.front() != pictures.back()); // the world is not the canonical volume
        // The shown stage is the stepper's: stepping outlines another cell, the pictures stay.
        QTest::keyClick(&w, Qt::Key_Right);
        QTRY_COMPARE(w.stepper()->shownStage(), 1);
        QTest::keyClick(&w, Qt::Key_S);
        QVERIFY(!w.views()->storyboardShown());
        QTRY_VERIFY(w.findChild<QVTKOpenGLNativeWidget*>("worldView")->isVisible());
    }

    // A click on a vertex in any cell traces it in every cell, and in the Matrices panel.
    void aClickTracesAVertexInEveryCell()
    {
        MainWindow& w = *window_;
        w.setStoryboardShown(true);
        StoryboardView& board = *w.views()->storyboard();
        QTRY_VERIFY(board.cellWidget(3)->isVisible());
        w.renderNow();
        const Vec3<double> vertex(16, 10, 30);
        QVERIFY(board.traced() != vertex);
        QTest::mouseClick(board.cellWidget(3), Qt::LeftButton, {}, drawnAt(w, 3, vertex));
        QVERIFY(w.views()->traced());
        QCOMPARE(*w.views()->traced(), vertex);
        QCOMPARE(board.traced(), vertex);
    }

    // Edit > Copy Image copies what is shown: with the storyboard, every cell as drawn with its headers
    // (it copied the world view hidden behind it); with the two views, the world view.
    void copyImageCopiesTheStoryboardShown()
    {
        MainWindow& w = *window_;
        w.setStoryboardShown(true);
        StoryboardView& board = *w.views()->storyboard();
        QTRY_VERIFY(board.cellWidget(3)->isVisible());
        w.actions()->action("edit.copyImage")->trigger();
        const QImage copied = QApplication::clipboard()->image();
        const double ratio = board.devicePixelRatioF();
        QCOMPARE(copied.size(), (QSizeF(board.size()) * ratio).toSize());
        for (int k = 0; k < board.cellCount(); ++k) { // each cell's picture where the cell is
            const QRect cell = board.cellWidget(k)->geometry();
            const QImage part = copied.copy(QRectF(QPointF(cell.topLeft()) * ratio, QSizeF(cell.size()) * ratio).toRect());
            QVERIFY2(drawnShare(part) > 0.1, qPrintable(QString("stage %1 is nearly blank in the copy").arg(k)));
            const QImage picture = cellPicture(w, k).convertToFormat(QImage::Format_RGB32);
            QVERIFY2(part.convertToFormat(QImage::Format_RGB32).scaled(picture.size()) == picture,
                     qPrintable(QString("stage %1 is not its cell's picture").arg(k)));
        }
        QTest::keyClick(&w, Qt::Key_S);
        QTRY_VERIFY(w.findChild<QVTKOpenGLNativeWidget*>("worldView")->isVisible());
        w.actions()->action("edit.copyImage")->trigger();
        QCOMPARE(QApplication::clipboard()->image().size(), w.findChild<QVTKOpenGLNativeWidget*>("worldView")->grabFramebuffer().size());
    }

    // Turning one cell turns them all, and each keeps its own stage's framing.
    void turningOneCellTurnsAll()
    {
        MainWindow& w = *window_;
        w.setStoryboardShown(true);
        StoryboardView& board = *w.views()->storyboard();
        QTRY_VERIFY(board.cellWidget(1)->isVisible());
        w.renderNow();
        const QImage before = cellPicture(w, 4);
        QWidget* cell = board.cellWidget(1);
        drag(cell, cell->rect().center(), cell->rect().center() + QPoint(cell->width() / 4, 0));
        const ScenePainter::Orbit turned = board.cellPainter(1).orbitAngles();
        QVERIFY2(std::abs(turned.yaw) > 5, qPrintable(QString("yaw %1").arg(turned.yaw)));
        for (int k = 0; k < board.cellCount(); ++k) {
            const ScenePainter::Orbit orbit = board.cellPainter(k).orbitAngles();
            QVERIFY2(std::abs(orbit.yaw - turned.yaw) < 1e-6 && std::abs(orbit.pitch - turned.pitch) < 1e-6,
                     qPrintable(QString("stage %1: yaw %2, pitch %3").arg(k).arg(orbit.yaw).arg(orbit.pitch)));
        }
        QVERIFY(cellPicture(w, 4) != before);
        // View > Reset View turns them all back.
        QTest::keyClick(&w, Qt::Key_R);
        for (int k = 0; k < board.cellCount(); ++k) {
            const ScenePainter::Orbit orbit = board.cellPainter(k).orbitAngles();
            QVERIFY2(std::abs(orbit.yaw) < 1e-6 && std::abs(orbit.pitch) < 1e-6,
                     qPrintable(QString("stage %1: yaw %2, pitch %3").arg(k).arg(orbit.yaw).arg(orbit.pitch)));
        }
    }

    // A wheel zoom in one cell zooms them all, and the zoomed cell keeps it when the cells are laid
    // out again (a click tracing a vertex): a first version forgot it there.
    void zoomingOneCellZoomsAll()
    {
        MainWindow& w = *window_;
        w.setStoryboardShown(true);
        StoryboardView& board = *w.views()->storyboard();
        QTRY_VERIFY(board.cellWidget(2)->isVisible());
        w.renderNow();
        QWidget* cell = board.cellWidget(2);
        const QPoint at = cell->rect().center();
        for (int notch = 0; notch < 3; ++notch) {
            QWheelEvent wheel(at, cell->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                              Qt::NoScrollPhase, false);
            QApplication::sendEvent(cell, &wheel);
        }
        const double zoom = board.cellPainter(2).orbitAngles().zoom;
        QVERIFY2(std::abs(zoom - 1) > 0.05, qPrintable(QString("zoom %1").arg(zoom)));
        for (int k = 0; k < board.cellCount(); ++k)
            QVERIFY2(std::abs(board.cellPainter(k).orbitAngles().zoom - zoom) < 1e-9, qPrintable(QString("stage %1").arg(k)));
        board.setTraced(Vec3<double>(16, 10, 30));
        QVERIFY2(std::abs(board.cellPainter(2).orbitAngles().zoom - zoom) < 1e-9,
                 qPrintable(QString("zoom %1 after laying out").arg(board.cellPainter(2).orbitAngles().zoom)));
    }

    // View > Leave Out > ticks leaves the fixed axes' numbers out of every cell, as export --hide ticks does.
    void theCellsLeaveOutTicksAsTheViewsDo()
    {
        MainWindow& w = *window_;
        w.setStoryboardShown(true);
        StoryboardView& board = *w.views()->storyboard();
        QTRY_VERIFY(board.cellWidget(3)->isVisible());
        auto tickNumbers = [&] {
            w.renderNow();
            int numbers = 0;
            for (const DrawnText& text : drawnTexts(board.cellWidget(3)->renderWindow()->GetRenderers()->GetFirstRenderer()).texts)
                numbers += QRegularExpression(R"(^\$-?[0-9.]+\$$)").match(QString::fromStdString(text.text)).hasMatch();
            return numbers;
        };
        QVERIFY(tickNumbers() > 2);
        w.actions()->action("view.hide.ticks")->trigger();
        QCOMPARE(tickNumbers(), 0);
        w.actions()->action("view.hide.ticks")->trigger();
        QVERIFY(tickNumbers() > 2);
    }

    // An edit redraws every cell.
    void anEditRedrawsEveryCell()
    {
        MainWindow& w = *window_;
        w.setStoryboardShown(true);
        StoryboardView& board = *w.views()->storyboard();
        QTRY_VERIFY(board.cellWidget(0)->isVisible());
        std::vector<QImage> before;
        for (int k = 0; k < board.cellCount(); ++k)
            before.push_back(cellPicture(w, k));
        QLineEdit* prpN = w.parameters()->fields("view.prp").last();
        prpN->setText("120");
        emit prpN->editingFinished();
        QCOMPARE(std::get<foley::ViewSpec<double>>(w.document()->scene().camera).prp.z(), 120.0);
        for (int k = 0; k < board.cellCount(); ++k)
            QVERIFY2(cellPicture(w, k) != before[std::size_t(k)], qPrintable(QString("stage %1 stayed").arg(k)));
    }

    // While a lesson's question waits, the storyboard (which names every stage and traces the
    // point) is not shown: asked for, it says why; shown, it gives way to the two views.
    void aWaitingQuestionKeepsTheStoryboardAway()
    {
        MainWindow& w = *window_;
        w.setStoryboardShown(true);
        QVERIFY(w.views()->storyboardShown());
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        QVERIFY(w.lessonFlow()->hidesAnswers());
        QVERIFY(!w.views()->storyboardShown());
        QTest::keyClick(&w, Qt::Key_S);
        QVERIFY(!w.views()->storyboardShown());
        QVERIFY(!w.actions()->action("view.storyboard")->isChecked());
        QVERIFY2(w.lastMessage().contains("storyboard"), qPrintable(w.lastMessage()));
    }

    // A lesson step with "layout": "storyboard" shows every stage once its question is answered
    // (before, the two views: the storyboard would answer it); the next step, without it, the two views.
    void aLessonStepShowsTheStoryboardOnceAnswered()
    {
        MainWindow& w = *window_;
        QTemporaryDir dir;
        const QString lesson = dir.filePath("board.json");
        const QString step = QString(R"({"scene": "%1", "stage": 5, "caption": "c", "layout": "storyboard", "hide": ["projectors"],
            "question": {"kind": "choice", "prompt": "p", "choices": ["a", "b"], "answer": 0}})").arg(kHouse);
        QFile file(lesson);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QString(R"({"title": "t", "steps": [%1, {"scene": "%2", "caption": "d"}]})").arg(step, kHouse).toUtf8());
        file.close();
        QVERIFY(w.lessonFlow()->openLesson(lesson));
        QVERIFY(!w.views()->storyboardShown());
        w.lessonFlow()->lesson()->reveal();
        QTRY_VERIFY(w.views()->storyboardShown());
        // The step's hide holds in every cell: the projectors the scene has are not drawn.
        auto projectors = [](const EvaluatedScene& scene) {
            return std::count_if(scene.primitives.begin(), scene.primitives.end(),
                                 [](const Primitive& p) { return p.element == Element::Projectors; });
        };
        QVERIFY(projectors(*w.document()->evaluated()) > 0);
        QCOMPARE(projectors(*w.views()->storyboard()->scene()), 0);
        QTest::keyClick(&w, Qt::Key_PageDown);
        QTRY_VERIFY(!w.views()->storyboardShown());
    }

    // A storyboard step turned, on a scene of more stages than the one before: every cell is turned as the
    // step says (the cells made for the new scene came unturned).
    void aLessonStepTurnsTheStoryboardOfAnotherScene()
    {
        MainWindow& w = *window_;
        QTemporaryDir dir;
        const QString lesson = dir.filePath("turned.json");
        const QString opengl = QString(viewpipe::build::dataDir) + "/scenes/opengl-perspective.json";
        QFile file(lesson);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QString(R"({"title": "t", "steps": [{"scene": "%1", "caption": "c"},
            {"scene": "%2", "caption": "d", "layout": "storyboard", "camera": {"yaw": 30, "pitch": -20, "zoom": 1.5}}]})")
                       .arg(kHouse, opengl)
                       .toUtf8());
        file.close();
        QVERIFY(w.lessonFlow()->openLesson(lesson));
        const int houseCells = int(w.document()->pipeline().stages.size()) + 1;
        QTest::keyClick(&w, Qt::Key_PageDown);
        QTRY_VERIFY(w.views()->storyboardShown());
        StoryboardView& board = *w.views()->storyboard();
        QTRY_VERIFY(board.cellWidget(0)->isVisible());
        QVERIFY(board.cellCount() != houseCells);
        for (int k = 0; k < board.cellCount(); ++k) {
            const ScenePainter::Orbit turn = board.cellPainter(k).orbitAngles();
            QVERIFY2(std::abs(turn.yaw - 30) < 1e-6 && std::abs(turn.pitch + 20) < 1e-6 && std::abs(turn.zoom - 1.5) < 1e-6,
                     qPrintable(QString("stage %1 turned %2, %3, zoom %4").arg(k).arg(turn.yaw).arg(turn.pitch).arg(turn.zoom)));
        }
    }

    // A mesh is one copy of poly data however many views draw it: the world view, the
    // projected view and every cell of the storyboard draw the letter F from the same data.
    void everyViewDrawsAMeshFromOneCopy()
    {
        MainWindow& w = *window_;
        QVERIFY(w.sceneFiles()->openScene(kLetterF));
        w.setStoryboardShown(true);
        StoryboardView& board = *w.views()->storyboard();
        QVERIFY(board.cellCount() > 3);
        const PolygonMesh& mesh = *w.document()->evaluated()->meshes.front();
        std::vector<vtkRenderer*> renderers;
        for (const char* view : {"worldView", "projectedView"})
            renderers.push_back(w.findChild<QVTKOpenGLNativeWidget*>(view)->renderWindow()->GetRenderers()->GetFirstRenderer());
        for (int k = 0; k < board.cellCount(); ++k)
            renderers.push_back(board.cellWidget(k)->renderWindow()->GetRenderers()->GetFirstRenderer());
        std::set<vtkDataObject*> copies;
        int drawing = 0;
        for (vtkRenderer* renderer : renderers) {
            bool draws = false;
            vtkActorCollection* actors = renderer->GetActors();
            actors->InitTraversal();
            while (vtkActor* actor = actors->GetNextActor()) {
                auto* data = vtkPolyData::SafeDownCast(actor->GetMapper() ? actor->GetMapper()->GetInput() : nullptr);
                if (data && data->GetNumberOfPolys() > 0 && data->GetNumberOfPoints() == vtkIdType(mesh.vertices.size())) {
                    copies.insert(data);
                    draws = true;
                }
            }
            drawing += draws;
        }
        QCOMPARE(drawing, int(renderers.size()));
        QCOMPARE(int(copies.size()), 1);
    }
};

int main(int argc, char** argv)
{
    return runAppTests<StoryboardAppTest>(argc, argv);
}

#include "storyboard_app_test.moc"
