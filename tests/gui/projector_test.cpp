// A lecturer at a 1280x720 projector: Larger Text pressed four times, then
// View > Present (F5). Every built-in scene at every stage, in the world view
// and in what the camera sees: every text inside its view, none on another
// or on the legend. Run on a screen of that size (tests/CMakeLists.txt).

#include <QAction>
#include <QScreen>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include <vtkRenderWindow.h>
#include <vtkRendererCollection.h>

#include "build_paths.h"
#include "app_window.h"
#include "drawn_texts.h"

using namespace viewpipe::gui;

namespace {

const QString kScenes = QString(viewpipe::build::dataDir) + "/scenes";

vtkRenderer* renderer(MainWindow& window, const char* view)
{
    return window.findChild<QVTKOpenGLNativeWidget*>(view)->renderWindow()->GetRenderers()->GetFirstRenderer();
}

} // namespace

class ProjectorTest : public QObject {
    Q_OBJECT

private slots:
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
        // Until the views have their full-screen sizes (the layout settles over a few events).
        QWidget* projected = window->findChild<QWidget*>("projectedView");
        for (QSize last; projected->size() != last;) {
            last = projected->size();
            QTest::qWait(100);
        }

        const int pictures = showEveryBuiltInStage(*window, [&](const QString& where) {
            for (const char* view : {"worldView", "projectedView"}) {
                const std::string trouble = textTrouble(renderer(*window, view));
                QVERIFY2(trouble.empty(), qPrintable(where + ", " + view + ": " + QString::fromStdString(trouble)));
            }
        });
        QVERIFY(pictures > 100);
        closeWindow(window);
    }
};

int main(int argc, char** argv)
{
    return runAppTests<ProjectorTest>(argc, argv);
}

#include "projector_test.moc"
