// The camera as code under Xvfb, driven with the mouse and the keyboard as a
// student does: dragging a number changes that parameter in steps and is one
// undoable edit, a number typed over is the double typed, Up and Down step the
// selected number, pasted calls set the camera, bad code is refused beside
// the code with the camera kept, Copy copies what is shown, and the
// Parameters panel's API choice adds the stage to the API's volume.

#include <QClipboard>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>

#include "build_paths.h"
#include "app_window.h"
#include "app/CodePanel.h"
#include "app/ParameterPanel.h"

using namespace viewpipe;
using namespace viewpipe::gui;

namespace {

QString scenePath(const QString& name)
{
    return QString(viewpipe::build::dataDir) + "/scenes/" + name;
}

const gl::Camera<double>& cameraOf(MainWindow& window)
{
    return std::get<gl::Camera<double>>(window.document()->scene().camera);
}

double fovyOf(MainWindow& window)
{
    return std::get<gl::Perspective<double>>(cameraOf(window).projection).fovyDegrees;
}

std::size_t numberFor(CodeView* view, const std::string& field)
{
    const auto& numbers = view->code().numbers;
    for (std::size_t k = 0; k < numbers.size(); ++k)
        if (numbers[k].field == field)
            return k;
    return numbers.size();
}

// A number's center, where it is drawn (the code wraps: every number is in view).
QPoint showNumber(CodeView* view, std::size_t index)
{
    return view->numberRect(index).center();
}

} // namespace

class CodePanelTest : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        window_ = openWindow(scenePath("apis/opengl.json"), {1600, 950});
        QVERIFY(window_);
        window_->showPanel("code");
        panel_ = window_->codePanel();
        panel_->setDialect(report::Dialect::OpenGL);
        view_ = panel_->codeView();
        QTRY_VERIFY(view_->isVisible());
    }

    void cleanup() { closeWindow(window_); }

    void longLinesWrapAndEveryNumberShows()
    {
        for (const report::Dialect dialect : report::kDialects) {
            panel_->setDialect(dialect);
            QVERIFY(view_->isVisible());
            // Once laid out (the panel's layout follows the view's height for its width in a posted event).
            QTRY_VERIFY2(view_->height() >= view_->heightForWidth(view_->width()),
                         qPrintable(QString("%1 px high, %2 needed").arg(view_->height()).arg(view_->heightForWidth(view_->width()))));
            for (std::size_t k = 0; k < view_->code().numbers.size(); ++k)
                QVERIFY2(view_->rect().contains(view_->numberRect(k)),
                         qPrintable(QString("%1: number %2 outside a %3 px wide view")
                                        .arg(QString::fromStdString(report::dialectTitle(dialect)))
                                        .arg(k)
                                        .arg(view_->width())));
        }
        // Narrower, the lines wrap more: the view grows taller rather than cutting them.
        QVERIFY(view_->heightForWidth(300) > view_->heightForWidth(1200));
    }

    void draggingANumberIsOneEdit()
    {
        MainWindow& w = *window_;
        const std::size_t fovy = numberFor(view_, "camera.projection.fovy_deg");
        QVERIFY(fovy < view_->code().numbers.size());
        QCOMPARE(fovyOf(w), 40.0);
        const QPoint start = showNumber(view_, fovy);
        QTest::mousePress(view_, Qt::LeftButton, {}, start);
        for (int dx = 10; dx <= 50; dx += 10) {
            QMouseEvent move(QEvent::MouseMove, start + QPoint(dx, 0), Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(view_, &move);
        }
        QTest::mouseRelease(view_, Qt::LeftButton, {}, start + QPoint(50, 0));
        // 40 moves by 0.1 a pixel: 50 pixels make 45, exactly, and the picture followed on the way.
        QCOMPARE(report::stepFor(40), 0.1);
        QCOMPARE(fovyOf(w), 45.0);
        QCOMPARE(w.document()->undoStack()->count(), 1);
        QVERIFY(QString::fromStdString(view_->code().text).contains("gluPerspective(45, 1.5, 30, 110)"));
        w.document()->undoStack()->undo();
        QCOMPARE(fovyOf(w), 40.0);
        QVERIFY(QString::fromStdString(view_->code().text).contains("gluPerspective(40, 1.5, 30, 110)"));
    }

    void aNumberTypedOverIsTheDoubleTyped()
    {
        MainWindow& w = *window_;
        const std::size_t aspect = numberFor(view_, "camera.projection.aspect");
        QTest::mouseDClick(view_, Qt::LeftButton, {}, showNumber(view_, aspect));
        QLineEdit* editor = view_->editor();
        QVERIFY(editor);
        QCOMPARE(editor->text(), QString("1.5"));
        editor->selectAll();
        QTest::keyClicks(editor, "1.7777777777777777");
        QTest::keyClick(editor, Qt::Key_Return);
        QCOMPARE(std::get<gl::Perspective<double>>(cameraOf(w).projection).aspect, 1.7777777777777777);
        QCOMPARE(w.document()->undoStack()->count(), 1);
        QVERIFY(!view_->editor()); // Enter closed it
        // Escape leaves the camera as it is.
        QTest::mouseDClick(view_, Qt::LeftButton, {}, showNumber(view_, aspect));
        QTest::keyClicks(view_->editor(), "3");
        QTest::keyClick(view_->editor(), Qt::Key_Escape);
        QCOMPARE(w.document()->undoStack()->count(), 1);
        QVERIFY(!view_->editor());
    }

    void keysStepTheSelectedNumber()
    {
        MainWindow& w = *window_;
        view_->setFocus();
        QTRY_VERIFY(view_->hasFocus());
        const std::size_t fovy = numberFor(view_, "camera.projection.fovy_deg");
        for (std::size_t k = 0; k <= fovy; ++k)
            QTest::keyClick(view_, Qt::Key_Tab);
        QCOMPARE(view_->selected().value_or(999), fovy);
        QTest::keyClick(view_, Qt::Key_Up);
        QTest::keyClick(view_, Qt::Key_Up);
        QCOMPARE(fovyOf(w), 40.2);
        QTest::keyClick(view_, Qt::Key_Down);
        QCOMPARE(fovyOf(w), 40.1);
        QCOMPARE(w.document()->undoStack()->count(), 3); // each press its own edit
    }

    void pastedCallsSetTheCamera()
    {
        MainWindow& w = *window_;
        QApplication::clipboard()->setText("gluPerspective(45, 1.333, 0.1, 100);");
        view_->setFocus();
        QTest::keySequence(view_, QKeySequence::Paste);
        const auto& p = std::get<gl::Perspective<double>>(cameraOf(w).projection);
        QCOMPARE(p.fovyDegrees, 45.0);
        QCOMPARE(p.aspect, 1.333);
        QCOMPARE(p.zNear, 0.1);
        QCOMPARE(p.zFar, 100.0);
        QCOMPARE(w.document()->undoStack()->count(), 1);

        QPlainTextEdit* paste = panel_->pasteBox();
        paste->setPlainText("XMMatrixPerspectiveFovLH(XM_PIDIV4, 16.f/9.f, 0.1f, 100.f)");
        QTest::mouseClick(panel_->findChild<QPushButton*>("codeApply"), Qt::LeftButton);
        const auto& d3d = std::get<gl::Perspective<double>>(cameraOf(w).projection);
        QCOMPARE(d3d.fovyDegrees, 45.0);
        QCOMPARE(d3d.aspect, 16.0 / 9.0);
        QCOMPARE(cameraOf(w).handedness, gl::Handedness::Left);
        QCOMPARE(w.document()->undoStack()->count(), 2);
    }

    void badCodeIsRefusedAndTheCameraKept()
    {
        MainWindow& w = *window_;
        const std::string before = sceneToJson(w.document()->scene());
        panel_->pasteBox()->setPlainText("gluPerspective(0, 1.5, 30, 110)");
        QTest::mouseClick(panel_->findChild<QPushButton*>("codeApply"), Qt::LeftButton);
        auto* error = panel_->findChild<QLabel*>("codeError");
        QTRY_VERIFY(error->isVisible());
        QVERIFY2(error->text().contains("fovy"), qPrintable(error->text()));
        QCOMPARE(sceneToJson(w.document()->scene()), before);
        QCOMPARE(w.document()->undoStack()->count(), 0);

        panel_->pasteBox()->setPlainText("hello");
        QTest::mouseClick(panel_->findChild<QPushButton*>("codeApply"), Qt::LeftButton);
        QVERIFY2(error->text().contains("no camera call"), qPrintable(error->text()));
        QCOMPARE(sceneToJson(w.document()->scene()), before);
    }

    void copyPutsTheCodeShownOnTheClipboard()
    {
        for (const report::Dialect dialect : report::kDialects) {
            panel_->setDialect(dialect);
            QApplication::clipboard()->clear();
            QTest::mouseClick(panel_->findChild<QPushButton*>("codeCopy"), Qt::LeftButton);
            QCOMPARE(QApplication::clipboard()->text(), QString::fromStdString(view_->code().text));
            QVERIFY(!view_->code().numbers.empty());
        }
    }

    void aFoleyViewHasNoCode()
    {
        QVERIFY(window_->sceneFiles()->openScene(scenePath("house.json")));
        QTRY_VERIFY(!view_->isVisible());
        QVERIFY(view_->code().text.empty());
    }

    void theApiChoiceAddsTheStageToItsVolume()
    {
        MainWindow& w = *window_;
        w.showPanel("parameters");
        auto* api = w.parameters()->findChild<QComboBox*>("camera.api");
        QVERIFY(api);
        const std::size_t stages = w.document()->pipeline().stages.size();
        api->setCurrentIndex(int(gl::Api::Vulkan));
        QCOMPARE(cameraOf(w).api, gl::Api::Vulkan);
        QCOMPARE(w.document()->pipeline().stages.size(), stages + 1);
        QCOMPARE(QString::fromStdString(w.document()->pipeline().stages.back().symbol()), QString("NDC_vulkan"));
        // Its projection is no longer named by OpenGL's call.
        auto* projection = w.parameters()->findChild<QComboBox*>("camera.projection.type");
        QVERIFY(projection);
        QCOMPARE(projection->currentText(), QString("perspective (field of view)"));
        // The code follows the camera.
        w.showPanel("code");
        panel_->setDialect(report::Dialect::Glm);
        QVERIFY(QString::fromStdString(view_->code().text).contains("perspectiveRH_ZO"));
        w.document()->undoStack()->undo();
        QCOMPARE(cameraOf(w).api, gl::Api::OpenGL);
        QCOMPARE(api->currentIndex(), int(gl::Api::OpenGL));
        QCOMPARE(projection->currentText(), QString("gluPerspective"));
    }

private:
    std::unique_ptr<MainWindow> window_;
    CodePanel* panel_ = nullptr;
    CodeView* view_ = nullptr;
};

int main(int argc, char** argv)
{
    return runAppTests<CodePanelTest>(argc, argv);
}

#include "code_panel_test.moc"
