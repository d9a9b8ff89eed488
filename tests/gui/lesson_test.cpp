// Lessons in the app, driven as a student and a lecturer use them: questions
// answered with clicks and typing, then revealed with the stage's transition;
// the answers saved; a lesson presented with a clicker's keys; a lesson made
// from the views on screen, edited and saved.

#include <QAbstractButton>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QWindow>
#include <QtTest>
#include <QVTKOpenGLNativeWidget.h>

#include "build_paths.h"
#include "evaluation_count.h"
#include "app/LessonDocument.h"
#include "app/LessonPanel.h"
#include "app/MathText.h"
#include "app/MainWindow.h"
#include "app/MatrixPanel.h"
#include "app_window.h"

using namespace viewpipe;
using namespace viewpipe::gui;

namespace {

const QString kHouse = QString(viewpipe::build::dataDir) + "/scenes/house.json";
const QString kFoley = QString(viewpipe::build::dataDir) + "/lessons/foley-nper.json";

// A click where a person clicks: a button's middle, a radio button's circle.
void click(QWidget* widget)
{
    QVERIFY(widget && widget->isEnabled());
    // A widget just shown is laid out by the event loop.
    QVERIFY(QTest::qWaitFor([widget] { return widget->isVisible() && widget->width() > 4 && widget->height() > 4; }));
    const bool radio = qobject_cast<QRadioButton*>(widget);
    QTest::mouseClick(widget, Qt::LeftButton, {}, radio ? QPoint(8, widget->height() / 2) : widget->rect().center());
}

QImage worldPicture(MainWindow& w)
{
    w.renderNow();
    return w.findChild<QVTKOpenGLNativeWidget*>("worldView")->grabFramebuffer();
}

// Share of pixels that differ by more than a little between two pictures of one size.
double differingShare(const QImage& a, const QImage& b)
{
    if (a.size() != b.size())
        return 1;
    const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
    qint64 differing = 0;
    for (int row = 0; row < x.height(); ++row)
        for (int col = 0; col < x.width(); ++col) {
            const QRgb p = x.pixel(col, row), q = y.pixel(col, row);
            differing += std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)), std::abs(qBlue(p) - qBlue(q))}) > 40;
        }
    return double(differing) / (double(x.width()) * x.height());
}

QString feedback(MainWindow& w)
{
    return lessonChild<QLabel>(w, "feedback")->text();
}

// The step's view has settled: no transition running.
bool settled(MainWindow& w)
{
    return !w.stepper()->isAnimating();
}

} // namespace

class LessonTest : public QObject {
    Q_OBJECT
private slots:
    void init() { window_ = openWindow(kHouse, {1280, 800}); }
    void cleanup()
    {
        if (window_)
            window_->lessonFlow()->lesson()->undoStack()->setClean();
        closeWindow(window_);
    }

    void aStudentAnswersWithClicksAndTyping()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        QTRY_VERIFY(w.findChild<QDockWidget*>("lessonDock")->isVisible());
        QCOMPARE(lessonChild<QLabel>(w, "lessonStep")->text(), QString("Step 1 of 9"));

        // Step 1 asks for the order of the stages: while it waits, nothing names them.
        QVERIFY(!w.stagePanel()->stageList()->isVisible());
        QVERIFY(w.findChild<QLabel*>("stagesWait")->isVisible());
        QVERIFY(w.matrices()->stageText().contains("follow the answer"));
        QCOMPARE(w.painter()->worldCaption(), std::string());
        QVERIFY(lessonChild<QLabel>(w, "lessonCaption")->text().contains("follows the answer"));
        // The stages offered sorted by name, which gives nothing away; put them in order with the mouse.
        auto* list = lessonChild<QListWidget>(w, "orderList");
        const QStringList order = {"T(-VRP)", "R", "T(-PRP)", "SH_per", "S_per"};
        QCOMPARE(list->item(0)->text(), QString("R"));
        for (int target = 0; target < order.size(); ++target) {
            int row = 0;
            while (list->item(row)->text() != order[target])
                ++row;
            QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(list->item(row)).center());
            QCOMPARE(list->currentRow(), row);
            for (; row > target; --row)
                click(lessonChild<QPushButton>(w, "orderUp"));
        }
        click(lessonChild<QPushButton>(w, "checkButton"));
        QVERIFY2(feedback(w).contains("Right."), qPrintable(feedback(w)));
        QVERIFY(w.stagePanel()->stageList()->isVisible());
        QVERIFY(w.matrices()->stageText().contains("World"));
        QVERIFY(lessonChild<QLabel>(w, "lessonCaption")->text().contains("The house in world coordinates"));
        QVERIFY(!lessonChild<QPushButton>(w, "checkButton")->isEnabled()); // right: the question is closed

        // Step 2, a multiple choice: a click on the answer, then Check.
        QTest::keyClick(&w, Qt::Key_PageDown);
        QCOMPARE(lessonChild<QLabel>(w, "lessonStep")->text(), QString("Step 2 of 9"));
        QVERIFY(!w.stagePanel()->stageList()->isVisible());
        click(lessonChild<QRadioButton>(w, "choice0"));
        click(lessonChild<QPushButton>(w, "checkButton"));
        QVERIFY2(feedback(w).contains("Right."), qPrintable(feedback(w)));

        // Step 4: which stage is this matrix? It shows R's numbers; pick R.
        w.lessonFlow()->lesson()->goTo(3);
        QTRY_VERIFY(settled(w));
        QVERIFY(lessonChild<QLabel>(w, "questionAbout")->text().contains("0.7071"));
        QCOMPARE(w.stepper()->stage(), 1); // waiting before the stage asked about
        for (QRadioButton* radio : w.lessonPanel()->findChildren<QRadioButton*>())
            if (radio->accessibleName() == "R")
                click(radio);
        click(lessonChild<QPushButton>(w, "checkButton"));
        QVERIFY2(feedback(w).contains("Right."), qPrintable(feedback(w)));
        QTRY_VERIFY(settled(w) && w.stepper()->stage() == 2); // the answer comes with R's transition

        // Step 5: where is the PRP after T(-PRP)? A wrong answer typed, and Enter.
        QTest::keyClick(&w, Qt::Key_PageDown);
        QTRY_VERIFY(settled(w));
        QCOMPARE(w.stepper()->stage(), 2);
        QTest::keyClicks(lessonChild<QLineEdit>(w, "answerX"), "1");
        QTest::keyClicks(lessonChild<QLineEdit>(w, "answerY"), "2");
        QTest::keyClick(lessonChild<QLineEdit>(w, "answerY"), Qt::Key_Return);
        QVERIFY2(feedback(w).startsWith("z: is empty: type a number"), qPrintable(feedback(w))); // nothing recorded yet
        QVERIFY(w.lessonFlow()->lesson()->isAsking());
        QTest::keyClicks(lessonChild<QLineEdit>(w, "answerZ"), "3");
        QTest::keyClick(lessonChild<QLineEdit>(w, "answerZ"), Qt::Key_Return);
        // Two tries (the default): the first wrong answer says so and keeps the answer back.
        QVERIFY2(feedback(w).contains("Not quite") && feedback(w).contains("one more try") && !feedback(w).contains("(0, 0, 0)"),
                 qPrintable(feedback(w)));
        QVERIFY(w.lessonFlow()->lesson()->isAsking());
        QVERIFY(lessonChild<QLabel>(w, "lessonCaption")->text().contains("follows the answer"));
        QCOMPARE(w.stepper()->stage(), 2);
        QTest::keyClick(lessonChild<QLineEdit>(w, "answerZ"), Qt::Key_Backspace);
        QTest::keyClicks(lessonChild<QLineEdit>(w, "answerZ"), "5");
        QTest::keyClick(lessonChild<QLineEdit>(w, "answerZ"), Qt::Key_Return);
        QVERIFY2(feedback(w).contains("Not quite") && feedback(w).contains("(0, 0, 0)"), qPrintable(feedback(w)));
        QTRY_VERIFY(settled(w) && w.stepper()->stage() == 3);
        QVERIFY(w.matrices()->traceText().contains("84")); // the PRP is followed through the stages

        // Step 6: an entry as a fraction with the typeset minus sign, after a text that is no number, which
        // is refused with the core's reason and costs no try.
        QTest::keyClick(&w, Qt::Key_PageDown);
        QTest::keyClicks(lessonChild<QLineEdit>(w, "answerEntry"), "2 +* 3");
        QTest::keyClick(lessonChild<QLineEdit>(w, "answerEntry"), Qt::Key_Return);
        QVERIFY2(feedback(w).startsWith("entry: expected a number, sqrt(...) or ( at character 4"), qPrintable(feedback(w)));
        QCOMPARE(w.lessonFlow()->lesson()->tries(w.lessonFlow()->lesson()->step()), 0);
        lessonChild<QLineEdit>(w, "answerEntry")->clear();
        // The minus as a keyboard layout with it sends it (keyClicks takes ASCII only).
        QTest::sendKeyEvent(QTest::Click, lessonChild<QLineEdit>(w, "answerEntry"), Qt::Key_unknown, QString::fromUtf8("\u2212"), {});
        QTest::keyClicks(lessonChild<QLineEdit>(w, "answerEntry"), "2/21");
        QTest::keyClick(lessonChild<QLineEdit>(w, "answerEntry"), Qt::Key_Return);
        QVERIFY2(feedback(w).contains("Right."), qPrintable(feedback(w)));
        // Revealed, SH_per's matrix marks the entries the step highlights: -2/21 and -1/14, and nothing else.
        QTRY_VERIFY(settled(w) && w.stepper()->stage() == 4);
        const QString tables = w.matrices()->matricesText();
        const QString shear = tables.mid(tables.indexOf("<b>" + mathHtml("$" + symbolMath("SH_per") + "$") + "</b>"));
        QCOMPARE(shear.left(shear.indexOf("</table>")).count("#8ecae6"), 2);
        QVERIFY(w.findChild<QDockWidget*>("matricesDock")->isVisible()); // the panel the step puts in front
        // The stage is drawn as the stepper draws it (a step that hides nothing nor moves once drew a blank view).
        const QImage revealed = worldPicture(w);
        w.stepper()->goToStage(3, false);
        w.stepper()->goToStage(4, false);
        QVERIFY2(differingShare(revealed, worldPicture(w)) < 0.01, "the revealed stage is not the stage as drawn");

        // The answers as the web page saves them.
        QTemporaryDir dir;
        const QString results = dir.filePath("lesson-results.json");
        QVERIFY(w.lessonFlow()->saveLessonResults(results));
        QFile file(results);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject saved = QJsonDocument::fromJson(file.readAll()).object();
        QCOMPARE(saved["lesson"].toString(), QString("Foley's perspective normalization, step by step"));
        const QJsonArray answers = saved["answers"].toArray();
        QCOMPARE(answers.size(), 5);
        QCOMPARE(answers[0].toObject()["kind"].toString(), QString("order"));
        QCOMPARE(answers[0].toObject()["answer"].toArray().first().toString(), QString("T(-VRP)"));
        QCOMPARE(answers[3].toObject()["answer"].toArray(), QJsonArray({1, 2, 5})); // the last answer checked
        QCOMPARE(answers[3].toObject()["correct"].toBool(), false);
        QCOMPARE(answers[3].toObject()["tries"].toInt(), 2);
        QCOMPARE(answers[3].toObject()["typed"].toArray(), QJsonArray({"1", "2", "5"})); // as typed, beside the numbers
        QCOMPARE(answers[4].toObject()["typed"].toString(), QString::fromUtf8("\u22122/21"));
        QVERIFY(!answers[0].toObject().contains("typed")); // an order is picked, not typed
        QCOMPARE(answers[4].toObject()["tries"].toInt(), 1);
        QCOMPARE(answers[4].toObject()["step"].toInt(), 6);
        QCOMPARE(answers[4].toObject()["correct"].toBool(), true);

        // Found: Show Answer before any answer left no trace in the results.
        w.lessonFlow()->lesson()->goTo(7);
        QVERIFY(w.lessonFlow()->lesson()->isAsking());
        click(lessonChild<QPushButton>(w, "revealButton"));
        QVERIFY(w.lessonFlow()->lesson()->hasUnsavedAnswers());
        QVERIFY(w.lessonFlow()->saveLessonResults(results));
        file.close();
        QVERIFY(file.open(QIODevice::ReadOnly)); // saved atomically: the file is a new one
        const QJsonArray again = QJsonDocument::fromJson(file.readAll()).object()["answers"].toArray();
        QCOMPARE(again.size(), 6);
        const QJsonObject shown = again[5].toObject();
        QCOMPARE(shown["step"].toInt(), 8);
        QVERIFY(shown["answer"].isNull() && !shown["correct"].toBool() && shown["revealed"].toBool());
    }

    void aLecturerPresentsALessonWithAClicker()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        w.lessonFlow()->lesson()->goTo(4); // step 5: where is the PRP after T(-PRP)?
        QTRY_VERIFY(settled(w));
        QTest::keyClick(&w, Qt::Key_F5);
        QVERIFY(w.presentMode()->isPresenting());
        QTRY_VERIFY(w.isFullScreen());
        QTRY_COMPARE(w.frameGeometry().size(), w.windowHandle()->screen()->geometry().size());
        // The lesson stays beside the views; nothing else does.
        for (QDockWidget* dock : w.findChildren<QDockWidget*>())
            QCOMPARE(dock->isVisible(), dock->objectName() == "lessonDock");
        // The clicker reveals the answer first, with its transition; then steps on.
        QVERIFY(w.lessonFlow()->lesson()->isAsking());
        QTest::keyClick(&w, Qt::Key_PageDown);
        QVERIFY(!w.lessonFlow()->lesson()->isAsking());
        QVERIFY2(feedback(w).contains("The answer: (0, 0, 0)"), qPrintable(feedback(w)));
        QTRY_VERIFY(settled(w) && w.stepper()->stage() == 3);
        QTest::keyClick(&w, Qt::Key_Space);
        QCOMPARE(w.lessonFlow()->lesson()->step(), 5);
        QTest::keyClick(&w, Qt::Key_Backspace);
        QCOMPARE(w.lessonFlow()->lesson()->step(), 4);
        // Nothing is cut off at 1920 x 1080: every step's text fits the lesson panel without scrolling.
        auto* scroll = qobject_cast<QScrollArea*>(w.findChild<QDockWidget*>("lessonDock")->widget());
        for (int k = 0; k < 9; ++k) {
            w.lessonFlow()->lesson()->goTo(k);
            w.lessonFlow()->lesson()->reveal(); // the answer and its explanation: the longest the panel gets
            QTRY_VERIFY(settled(w));
            QApplication::processEvents();
            QVERIFY2(!scroll->verticalScrollBar()->isVisible(), qPrintable(QString("step %1 scrolls").arg(k + 1)));
            QVERIFY2(scroll->widget()->width() <= scroll->viewport()->width(),
                     qPrintable(QString("%1 > %2").arg(scroll->widget()->width()).arg(scroll->viewport()->width())));
        }
        QTest::keyClick(&w, Qt::Key_Escape);
        QTRY_VERIFY(!w.isFullScreen());
        QVERIFY(w.findChild<QDockWidget*>("stagesDock")->isVisible());
    }

    // At a projector's size, a question's matrices (only a note while it waits) leave the views their room
    // (found: the note took 377 of 1280 px, the views 420); the answer gives the matrices their width back.
    // A panel the student chose in front keeps its width.
    void aQuestionLeavesTheViewsTheMatricesRoom()
    {
        MainWindow& w = *window_;
        w.setFontSize(MainWindow::kDefaultFontSize * 3 / 2, false);
        auto* matrices = w.findChild<QDockWidget*>("matricesDock");
        QTRY_VERIFY(matrices->isVisible());
        const auto stable = [](const std::function<int()>& width) { // the dock layout settles over a few events
            for (int last = -1, k = 0; k < 20 && width() != last; ++k) {
                last = width();
                QTest::qWait(50);
            }
            return width();
        };
        const int before = stable([matrices] { return matrices->width(); });
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        w.lessonFlow()->lesson()->goTo(2); // step 3 asks for R's rows
        QTRY_VERIFY(settled(w));
        QVERIFY(w.lessonFlow()->lesson()->isAsking());
        QTRY_VERIFY2(matrices->width() < before / 2, qPrintable(QString("%1 px while asking, %2 before").arg(matrices->width()).arg(before)));
        const int asking = stable([matrices] { return matrices->width(); });
        const int viewsAsking = w.centralWidget()->width();
        QVERIFY(w.matrices()->stageText().contains("follow the answer")); // the note reads whole: it wraps
        auto* note = matrices->findChild<QScrollArea*>();
        QCOMPARE(note->horizontalScrollBar()->maximum(), 0);
        w.lessonFlow()->lesson()->reveal();
        QTRY_VERIFY(settled(w));
        QTRY_VERIFY2(matrices->width() > 2 * asking, qPrintable(QString("%1 px after the answer, %2 while asking").arg(matrices->width()).arg(asking)));
        // The room the matrices left went to the views.
        const int answered = stable([matrices] { return matrices->width(); });
        QVERIFY2(viewsAsking - w.centralWidget()->width() >= (answered - asking) * 3 / 4,
                 qPrintable(QString("views %1 px while asking, %2 after, the matrices %3 and %4")
                                .arg(viewsAsking).arg(w.centralWidget()->width()).arg(asking).arg(answered)));
        // A width the user gave the matrices is the one the answer gives back (found: the default's).
        w.resizeDocks({matrices}, {matrices->width() + 40}, Qt::Horizontal);
        const int chosen = stable([matrices] { return matrices->width(); });
        w.lessonFlow()->lesson()->goTo(3);
        QTRY_VERIFY(settled(w));
        QVERIFY(w.lessonFlow()->lesson()->isAsking());
        QTRY_VERIFY(matrices->width() < chosen / 2);
        w.lessonFlow()->lesson()->reveal();
        QTRY_COMPARE(matrices->width(), chosen);
        // The parameters in front while the next question waits: they keep their width.
        w.showPanel("parameters");
        auto* parameters = w.findChild<QDockWidget*>("parametersDock");
        const int parametersWidth = stable([parameters] { return parameters->width(); });
        w.lessonFlow()->lesson()->goTo(4);
        QTRY_VERIFY(settled(w));
        QVERIFY(w.lessonFlow()->lesson()->isAsking());
        QCOMPARE(stable([parameters] { return parameters->width(); }), parametersWidth);
    }

    // Stepping through a lesson whose steps show two scenes: a step whose scene is not the one open opens it as the
    // lesson evaluated it when it was opened (the app evaluates nothing while stepping).
    void aLessonsScenesAreEvaluatedWhenItOpens()
    {
        MainWindow& w = *window_;
        QTemporaryDir folder;
        const QString scenes = QString(viewpipe::build::dataDir) + "/scenes/";
        QFile file(folder.filePath("two-scenes.json"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QString(R"({"title": "Two scenes", "steps": [
            {"scene": "%1house.json", "stage": 1, "caption": "The house."},
            {"scene": "%1opengl-perspective.json", "stage": 2, "caption": "A look-at camera."},
            {"scene": "%1house.json", "stage": 3, "caption": "The house again, without its projectors.", "hide": ["projectors"]}]})")
                       .arg(scenes)
                       .toUtf8());
        file.close();
        QVERIFY(w.lessonFlow()->openLesson(file.fileName()));
        QTRY_VERIFY(settled(w));
        viewpipe::test::EvaluationCount count;
        const viewpipe::ListeningToEvaluations listening(count);
        QTest::keyClick(&w, Qt::Key_PageDown);
        QTRY_VERIFY(settled(w));
        QVERIFY(std::holds_alternative<gl::Camera<double>>(w.document()->scene().camera));
        QTest::keyClick(&w, Qt::Key_PageDown);
        QTRY_VERIFY(settled(w));
        QCOMPARE(w.lessonFlow()->lesson()->step(), 2);
        QVERIFY(w.document()->scene() == w.lessonFlow()->lesson()->currentStep().scene);
        QCOMPARE(count.evaluations, 0L);
        QCOMPARE(w.document()->evaluated(), w.lessonFlow()->lesson()->stepScene(2));
        w.lessonFlow()->lesson()->close();
    }

    // What a step hides stays hidden through an edit of the camera (an edit drew the whole scene again,
    // the projectors a step left out among it); it goes with the step: a step removed, another scene
    // opened, the lesson closed.
    void aStepsHideHoldsThroughAnEditAndGoesWithTheStep()
    {
        MainWindow& w = *window_;
        QTemporaryDir folder;
        QFile file(folder.filePath("hidden.json"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QString(R"({"title": "Hidden", "steps": [{"scene": "%1", "stage": 2, "caption": "c", "hide": ["projectors", "labels"]},
                                                            {"scene": "%1", "stage": 2, "caption": "d"}]})")
                       .arg(kHouse)
                       .toUtf8());
        file.close();
        auto projectors = [](const EvaluatedScene& scene) {
            return std::count_if(scene.primitives.begin(), scene.primitives.end(),
                                 [](const Primitive& p) { return p.element == Element::Projectors; });
        };
        auto hidden = [&] { return projectors(*w.views()->shownScene()) == 0 && w.views()->shownScene()->labels.empty(); };
        auto whole = [&] { return projectors(*w.views()->shownScene()) > 0 && !w.views()->shownScene()->labels.empty(); };
        QVERIFY(w.lessonFlow()->openLesson(file.fileName()));
        QTRY_VERIFY(settled(w));
        QVERIFY(projectors(*w.document()->evaluated()) > 0);
        QVERIFY(hidden());
        // The step removed: the next, on the same scene, hides nothing; undone, the hide is back.
        w.lessonFlow()->lesson()->removeStep(0);
        QTRY_VERIFY(whole());
        w.lessonFlow()->lesson()->undoStack()->undo();
        QTRY_VERIFY(hidden());
        auto view = std::get<foley::ViewSpec<double>>(w.document()->scene().camera);
        view.back = 20;
        w.document()->setCamera(view, "Edit view.back");
        QCOMPARE(std::get<foley::ViewSpec<double>>(w.document()->scene().camera).back, 20.0);
        QVERIFY(hidden());
        w.document()->undoStack()->setClean(); // no question about the edit below
        // Another scene opened while the lesson is open is drawn whole.
        QVERIFY(w.sceneFiles()->openScene(QString(viewpipe::build::dataDir) + "/scenes/house-corner.json"));
        QVERIFY(whole());
        // The step's own scene file again: the step's, its hide holds.
        QVERIFY(w.sceneFiles()->openScene(kHouse));
        QVERIFY(hidden());
        // The lesson closed: whole at once.
        w.lessonFlow()->lesson()->close();
        QVERIFY(whole());
    }

    void aLessonIsMadeFromTheViewsOnScreen()
    {
        MainWindow& w = *window_;
        QTemporaryDir dir;
        w.stepper()->goToStage(3, false);
        w.painter()->orbit(30, -15, 1.5);
        w.lessonFlow()->newLessonFromView();
        QVERIFY(w.lessonFlow()->lesson()->isOpen());
        QVERIFY(lessonChild<QGroupBox>(w, "lessonEditor")->isChecked());
        const LessonStep first = w.lessonFlow()->lesson()->lesson().steps[0];
        QCOMPARE(first.stage, 3);
        QCOMPARE(first.yaw, 30.0);
        QCOMPARE(first.pitch, -15.0);
        QCOMPARE(first.zoom, 1.5);
        QCOMPARE(w.stepper()->stage(), 3); // the view stays as it was

        // A second step at stage 5, then its caption and a question, edited in the panel.
        w.stepper()->goToStage(5, false);
        click(lessonChild<QPushButton>(w, "addStepButton"));
        QCOMPARE(int(w.lessonFlow()->lesson()->lesson().steps.size()), 2);
        QCOMPARE(w.lessonFlow()->lesson()->step(), 1);
        QCOMPARE(w.stepper()->stage(), 5);
        // Found: a new step's caption carried the picture's note "(framed anew…)".
        QCOMPARE(w.lessonFlow()->lesson()->lesson().steps[1].caption, std::string("After $S_{\\mathrm{per}}$"));
        auto* caption = lessonChild<QPlainTextEdit>(w, "captionEdit");
        caption->setPlainText("After $S_{per}$ the volume is the canonical one.");
        auto* question = lessonChild<QPlainTextEdit>(w, "questionEdit");
        question->setPlainText(R"({"kind": "where", "prompt": "Where is the PRP?", "point": [8, 6, 84], "after": 9})");
        click(lessonChild<QPushButton>(w, "applyEditsButton"));
        // A bad question is refused with its field, and changes nothing.
        QVERIFY2(lessonChild<QLabel>(w, "editError")->text().contains("steps[1].question.after: must be a whole number from 1 to 5"),
                 qPrintable(lessonChild<QLabel>(w, "editError")->text()));
        QVERIFY(!w.lessonFlow()->lesson()->lesson().steps[1].question);
        question->setPlainText(R"({"kind": "where", "prompt": "Where is the PRP?", "point": [8, 6, 84], "after": 3})");
        click(lessonChild<QPushButton>(w, "applyEditsButton"));
        QVERIFY(lessonChild<QLabel>(w, "editError")->text().isEmpty());
        QVERIFY(w.lessonFlow()->lesson()->lesson().steps[1].question);
        QCOMPARE(w.lessonFlow()->lesson()->lesson().steps[1].caption, std::string("After $S_{per}$ the volume is the canonical one."));
        // The editor shows the question's answer: with it open, the step is answered too.
        QTRY_VERIFY(!w.lessonFlow()->lesson()->isAsking());
        QVERIFY(lessonChild<QLabel>(w, "lessonCaption")->text().contains("<i>S</i><sub><i>per</i></sub>"));

        // Reordered, undone and redone.
        click(lessonChild<QPushButton>(w, "moveUpButton"));
        QCOMPARE(w.lessonFlow()->lesson()->lesson().steps[0].stage, 5);
        click(lessonChild<QPushButton>(w, "lessonUndo"));
        QCOMPARE(w.lessonFlow()->lesson()->lesson().steps[0].stage, 3);
        click(lessonChild<QPushButton>(w, "lessonRedo"));
        QCOMPARE(w.lessonFlow()->lesson()->lesson().steps[0].stage, 5);

        // Saved atomically, and it reads back as the lesson it was.
        const QString path = dir.filePath("made.json");
        QVERIFY(w.lessonFlow()->saveLesson(path));
        // Saved away from its scene: the status bar names the file it uses from outside and the way to pack it.
        const QString saved = w.statusBar()->currentMessage();
        QVERIFY2(saved.contains("1 file from outside its folder") && saved.contains("house.json") &&
                     saved.contains("Pack Lesson"),
                 qPrintable(saved));
        QVERIFY(!w.lessonFlow()->lesson()->isModified());
        QVERIFY(w.windowTitle().contains("lesson made.json —"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList({"made.json"}));
        const Lesson read = loadLesson(path.toStdString());
        QCOMPARE(int(read.steps.size()), 2);
        QCOMPARE(read.steps[0].stage, 5);
        QVERIFY(read.steps[0].question && read.steps[0].question->where.norm() < 1e-12);
        QCOMPARE(read.steps[1].yaw, 30.0);
        QCOMPARE(std::filesystem::weakly_canonical(read.steps[1].scene.file),
                 std::filesystem::weakly_canonical(kHouse.toStdString()));
    }

    // The lessons' math in the panel: italics, scripts and signs as KaTeX sets them on the page.
    void mathIsSetWithScriptsAndSigns()
    {
        QCOMPARE(mathHtml("$\\mathit{SH}_\\mathit{par}$ costs \\$5"), QString("<i>SH</i><sub><i>par</i></sub> costs $5"));
        QCOMPARE(mathHtml("$\\sqrt{2/3} \\approx 0.8165$"), QString("√(2/3) ≈ 0.8165"));
        QCOMPARE(mathHtml("$\\sqrt{4872}$"), QString("√4872"));
        QCOMPARE(mathHtml("$-\\frac{2}{21}$"), QString("−2/21"));
        QCOMPARE(mathHtml("$45^\\circ$ and $x^2 < y$"), QString("45° and <i>x</i><sup>2</sup> &lt; <i>y</i>"));
        QCOMPARE(mathHtml("a <b> & $ unclosed"), QString("a &lt;b&gt; &amp; $ unclosed"));
        // What the core refuses (a hostile file's nesting) is shown as written, not followed down.
        const std::string deep = "$" + std::string(200000, '{') + "x" + std::string(200000, '}') + "$";
        QVERIFY(mathHtml(deep).contains("{{{x}}}"));
        std::string roots = "$";
        for (int k = 0; k < 100000; ++k)
            roots += "\\sqrt";
        QVERIFY(mathHtml(roots + "x$").contains("\\sqrt\\sqrtx"));
    }

private:
    std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv)
{
    return runAppTests<LessonTest>(argc, argv);
}

#include "lesson_test.moc"
