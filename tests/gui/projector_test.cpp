// A lecturer at a 1280x720 projector: Larger Text pressed four times, then
// View > Present (F5). Every built-in scene at every stage, in the world view
// and in what the camera sees: every text inside its view, none on another
// or on the legend, and the legend on no part of the subject. Run on a screen
// of that size (tests/CMakeLists.txt).

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAction>
#include <QComboBox>
#include <QLineEdit>
#include <QDockWidget>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRendererCollection.h>

#include "build_paths.h"
#include "app/LessonDocument.h"
#include "app/LessonFlow.h"
#include "app_window.h"
#include "drawn_texts.h"
#include "viewpipe/report/world_view.hpp"

using namespace viewpipe::gui;

namespace {

const QString kScenes = QString(viewpipe::build::dataDir) + "/scenes";

vtkRenderer* renderer(MainWindow& window, const char* view)
{
    return window.findChild<QVTKOpenGLNativeWidget*>(view)->renderWindow()->GetRenderers()->GetFirstRenderer();
}

// Whether the world view's legend covers a point of the subject (the objects and the view volume, their
// vertices and points along their edges) as the view draws the stage shown.
bool legendCoversTheSubject(MainWindow& window, std::string& where)
{
    const DrawnTexts drawn = drawnTexts(renderer(window, "worldView"));
    if (!drawn.legend)
        return false;
    const viewpipe::report::FigureView view = window.painter()->figureView();
    const auto [x0, x1, y0, y1] = *drawn.legend; // viewport pixels, y up
    const viewpipe::report::Box2 legend{{x0, view.height - y1}, {x1, view.height - y0}};
    const auto& scene = *window.document()->evaluated();
    const viewpipe::report::StageShown stage = viewpipe::report::stageShown(scene, viewpipe::report::stageAtRest(scene, window.stepper()->stage()));
    using viewpipe::Element;
    for (const viewpipe::Primitive& p : scene.primitives) {
        if (!stage.draws(p) || !(p.element == Element::Objects || p.element == Element::Volume ||
                                 p.element == Element::FrontPlane || p.element == Element::BackPlane))
            continue;
        std::vector<viewpipe::Vec3<double>> points = p.kind == viewpipe::PrimitiveKind::Lines ? p.segments : p.faces->vertices;
        if (p.kind == viewpipe::PrimitiveKind::Lines)
            for (std::size_t k = 0; k + 1 < p.segments.size(); k += 2)
                for (int t = 1; t < 16; ++t)
                    points.push_back(p.segments[k] + t / 16.0 * (p.segments[k + 1] - p.segments[k]));
        for (const viewpipe::Vec3<double>& world : points)
            if (stage.shows(world))
                if (const auto q = viewpipe::projectPoint(stage.matrixOf(p), world))
                    if (const auto px = view.pixel(*q); px && legend.contains({px->head<2>(), px->head<2>()})) {
                        where = "(" + std::to_string(px->x()) + ", " + std::to_string(px->y()) + ")";
                        return true;
                    }
    }
    return false;
}

} // namespace

class ProjectorTest : public QObject {
    Q_OBJECT

private slots:
    // Each test starts with the system's font, not the last test's Larger Text.
    void initTestCase() { systemFont_ = QApplication::font(); }
    void init() { QApplication::setFont(systemFont_); }

    void presentingWithLargerTextEveryStageReads()
    {
        QCOMPARE(QGuiApplication::primaryScreen()->size(), QSize(1280, 720));
        auto window = openWindow(kScenes + "/house.json", {1280, 720});
        QVERIFY(window);
        QAction* larger = nullptr;
        for (QAction* action : window->findChildren<QAction*>())
            if (action->shortcut() == QKeySequence(QKeySequence::ZoomIn))
                larger = action;
        QVERIFY(larger);
        for (int k = 0; k < 4; ++k)
            larger->trigger();
        QTest::keyClick(window.get(), Qt::Key_F5);
        QTRY_VERIFY(window->presentMode()->isPresenting());
        QTRY_COMPARE(window->size(), QSize(1280, 720));
        settle(*window);

        const int pictures = showEveryBuiltInStage(*window, [&](const QString& where) {
            for (const char* view : {"worldView", "projectedView"}) {
                const std::string trouble = textTrouble(renderer(*window, view));
                QVERIFY2(trouble.empty(), qPrintable(where + ", " + view + ": " + QString::fromStdString(trouble)));
            }
            std::string covered;
            QVERIFY2(!legendCoversTheSubject(*window, covered),
                     qPrintable(where + ": the legend covers the subject at " + QString::fromStdString(covered)));
        });
        QVERIFY(pictures > 100);
        closeWindow(window);
    }

    // Present (F5), two steps on (Page Down), leave (Esc): the window and the
    // world view as large as before, the view framed for that size (as the
    // stage shown afresh frames it), every text inside it.
    void leavingPresentShowsTheWorldViewAsBefore()
    {
        auto window = openWindow(kScenes + "/house.json", {1000, 600});
        QVERIFY(window);
        settle(*window);
        QWidget* world = window->findChild<QWidget*>("worldView");
        const QSize windowBefore = window->size(), worldBefore = world->size();

        QTest::keyClick(window.get(), Qt::Key_F5);
        QTRY_VERIFY(window->presentMode()->isPresenting());
        QTRY_COMPARE(window->size(), QSize(1280, 720));
        settle(*window);
        QTest::keyClick(window.get(), Qt::Key_PageDown);
        QTest::keyClick(window.get(), Qt::Key_PageDown);
        QTRY_COMPARE(window->stepper()->stage(), 2);
        QTest::keyClick(window.get(), Qt::Key_Escape);
        QTRY_VERIFY(!window->presentMode()->isPresenting());
        QTRY_COMPARE_WITH_TIMEOUT(window->size(), windowBefore, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(world->size(), worldBefore, 10000); // found: a status bar shrank it
        settle(*window);

        vtkCamera* camera = renderer(*window, "worldView")->GetActiveCamera();
        const auto where = [camera] {
            std::array<double, 6> at{};
            camera->GetPosition(at.data());
            camera->GetFocalPoint(at.data() + 3);
            return at;
        };
        const std::array<double, 6> shown = where();
        window->stepper()->goToStage(2, false);
        window->renderNow();
        const std::array<double, 6> fresh = where();
        for (int k = 0; k < 6; ++k)
            QVERIFY2(std::abs(shown[k] - fresh[k]) < 1e-6 * (1 + std::abs(fresh[k])),
                     qPrintable(QString("camera coordinate %1: %2 after presenting, %3 shown afresh").arg(k).arg(shown[k]).arg(fresh[k])));
        const std::string trouble = textTrouble(renderer(*window, "worldView"));
        QVERIFY2(trouble.empty(), trouble.c_str());
        closeWindow(window);
    }

    // A lesson presented on the 1280x720 projector with text at 150 %: the question reads whole, its fields in
    // sight (found: the lesson's dock a quarter of the screen, "Where is the hou…", the z field off it).
    void aLessonPresentedReadsWhole()
    {
        auto window = openWindow(kScenes + "/house.json", {1280, 720});
        QVERIFY(window);
        window->setFontSize(MainWindow::kDefaultFontSize * 3 / 2, false);
        QVERIFY(window->lessonFlow()->openLesson(QString(viewpipe::build::dataDir) + "/lessons/foley-nper.json"));
        window->lessonFlow()->lesson()->goTo(6); // step 7: where is (16, 10, 30) after S_per?
        QTest::keyClick(window.get(), Qt::Key_F5);
        QTRY_VERIFY(window->presentMode()->isPresenting());
        QTRY_COMPARE(window->size(), QSize(1280, 720));
        settle(*window);
        auto* scroll = qobject_cast<QScrollArea*>(window->findChild<QDockWidget*>("lessonDock")->widget());
        QTRY_COMPARE(scroll->horizontalScrollBar()->maximum(), 0);
        QVERIFY2(100 * window->centralWidget()->width() >= 55 * window->width(),
                 qPrintable(QString("the views %1 px of %2").arg(window->centralWidget()->width()).arg(window->width())));
        closeWindow(window);
    }

    // Text at 200 % in a window filling the 1280x720 screen: found, the docks' contents made the
    // window 1395 px wide, a sixth of it off the screen. The window fits; the views' texts read.
    void largeTextKeepsTheWindowOnTheScreen()
    {
        auto window = openWindow(kScenes + "/house-corner.json", {1280, 720});
        QVERIFY(window);
        window->stepper()->goToStage(5, false); // its matrices panel the widest, with S_per's formulas
        window->setFontSize(2 * MainWindow::kDefaultFontSize, false);
        QTest::qWait(100); // the docks fit to the text once the widgets have taken it
        settle(*window);
        const QRect screen = window->screen()->availableGeometry();
        QVERIFY2(window->frameGeometry().width() <= screen.width(),
                 qPrintable(QString("the window is %1 px wide on a %2 px screen").arg(window->frameGeometry().width()).arg(screen.width())));
        window->renderNow();
        for (const char* view : {"worldView", "projectedView"}) {
            const std::string trouble = textTrouble(renderer(*window, view));
            QVERIFY2(trouble.empty(), qPrintable(QString(view) + ": " + QString::fromStdString(trouble)));
        }
        // No text larger than the caption, which the narrow view sets smaller (found: labels of 40 px under a
        // 17 px caption, covering the stage); the other view's title no larger either.
        const DrawnTexts world = drawnTexts(renderer(*window, "worldView"));
        QVERIFY(world.texts.size() > 5);
        const DrawnText caption = *std::max_element(world.texts.begin(), world.texts.end(),
                                                    [](const DrawnText& a, const DrawnText& b) { return a.box[3] < b.box[3]; });
        for (const DrawnText& t : world.texts)
            QVERIFY2(t.fontSize <= caption.fontSize, qPrintable(QString("\"%1\" at %2 px, the caption \"%3\" at %4 px")
                                                              .arg(QString::fromStdString(t.text)).arg(t.fontSize)
                                                              .arg(QString::fromStdString(caption.text)).arg(caption.fontSize)));
        for (const DrawnText& t : drawnTexts(renderer(*window, "projectedView")).texts)
            QVERIFY2(t.fontSize <= caption.fontSize, qPrintable(QString::fromStdString(t.text)));
        // The views keep 40 % of the window (found: 33 %); the docks' tabs show their titles whole (found: "Matri…").
        QVERIFY2(100 * window->centralWidget()->width() >= 40 * window->width(),
                 qPrintable(QString("the views are %1 px of %2, the docks %3 and %4").arg(window->centralWidget()->width()).arg(window->width()).arg(window->findChild<QDockWidget*>("stagesDock")->width()).arg(window->findChild<QDockWidget*>("matricesDock")->width())));
        int tabs = 0;
        const QString cut = cutDockTabTitle(*window, tabs);
        QVERIFY2(cut.isEmpty(), qPrintable(cut + " is cut"));
        QCOMPARE(tabs, 4);
        // A dock's content wider than the dock can be scrolled to, not cut.
        for (const QScrollArea* scroll : window->findChildren<QScrollArea*>())
            if (scroll->isVisible() && scroll->widget() && scroll->widget()->width() > scroll->viewport()->width())
                QVERIFY2(scroll->horizontalScrollBar()->isVisible(), qPrintable(scroll->parentWidget()->objectName()));
        closeWindow(window);
    }

    // Text at 200 %: the Parameters dock (the camera's fields and its code) fits the dock's width (found:
    // the longest option of a list widened the panel past the dock, the window's fourth value and the Copy
    // button out of sight), and each list opens as wide as its longest option.
    void largeTextParametersFitTheirDock()
    {
        for (const char* scene : {"/house-corner.json", "/apis/direct3d.json"}) {
            auto window = openWindow(kScenes + scene, {1280, 720});
            QVERIFY(window);
            window->setFontSize(2 * MainWindow::kDefaultFontSize, false);
            window->showPanel("parameters");
            QTest::qWait(100); // the docks fit to the text once the widgets have taken it
            settle(*window);
            auto* scroll = qobject_cast<QScrollArea*>(window->findChild<QDockWidget*>("parametersDock")->widget());
            QVERIFY(scroll && scroll->widget());
            QTRY_COMPARE(scroll->horizontalScrollBar()->maximum(), 0);
            int fields = 0;
            for (QWidget* field : scroll->widget()->findChildren<QWidget*>()) {
                if (!field->isVisible() ||
                    !(qobject_cast<QLineEdit*>(field) || qobject_cast<QComboBox*>(field) || qobject_cast<QAbstractButton*>(field)))
                    continue;
                const int left = field->mapTo(scroll->viewport(), QPoint(0, 0)).x();
                QVERIFY2(left >= 0 && left + field->width() <= scroll->viewport()->width(),
                         qPrintable(QString("%1: %2 %3 spans %4 to %5 px of %6").arg(scene, field->metaObject()->className(), field->objectName())
                                        .arg(left).arg(left + field->width()).arg(scroll->viewport()->width())));
                ++fields;
            }
            QVERIFY(fields > 12);
            int lists = 0;
            for (QComboBox* combo : scroll->widget()->findChildren<QComboBox*>()) {
                if (!combo->isVisible())
                    continue;
                combo->showPopup();
                QTRY_VERIFY(combo->view()->isVisible());
                QVERIFY2(combo->view()->viewport()->width() >= combo->view()->sizeHintForColumn(0),
                         qPrintable(QString("%1: the list of %2 is %3 px wide, its longest option %4")
                                        .arg(scene, combo->objectName()).arg(combo->view()->viewport()->width())
                                        .arg(combo->view()->sizeHintForColumn(0))));
                combo->hidePopup();
                ++lists;
            }
            QVERIFY(lists >= 2);
            closeWindow(window);
        }
    }

private:
    QFont systemFont_;

    // Until the views have their sizes (the layout settles over a few events).
    static void settle(MainWindow& window)
    {
        const auto sizes = [&window] {
            return std::pair{window.findChild<QWidget*>("worldView")->size(), window.findChild<QWidget*>("projectedView")->size()};
        };
        for (std::pair<QSize, QSize> last; sizes() != last;) {
            last = sizes();
            QTest::qWait(100);
        }
    }
};

int main(int argc, char** argv)
{
    return runAppTests<ProjectorTest>(argc, argv);
}

#include "projector_test.moc"
