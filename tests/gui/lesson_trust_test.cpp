// A lesson used in front of a class: nothing the user typed is lost, whichever
// way a prompt is answered, and nothing on screen gives a question's answer
// (or a later one's) away before it is answered.

#include <QAbstractButton>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSlider>
#include <QTemporaryDir>
#include <QTextDocumentFragment>
#include <QtTest>

#include <vtkRenderWindow.h>
#include <vtkRendererCollection.h>

#include <cmath>

#include "build_paths.h"
#include "drawn_texts.h"
#include "app/LessonPanel.h"
#include "app/MainWindow.h"
#include "app/ParameterPanel.h"
#include "app_window.h"
#include "viewpipe/format.hpp"
#include "viewpipe/lesson.hpp"

using namespace viewpipe;
using namespace viewpipe::gui;

namespace {

const QString kHouse = QString(viewpipe::build::dataDir) + "/scenes/house.json";
const QString kFoley = QString(viewpipe::build::dataDir) + "/lessons/foley-nper.json";
const QString kOpenGl = QString(viewpipe::build::dataDir) + "/lessons/opengl-perspective.json";
const QString kLetterF = QString(viewpipe::build::dataDir) + "/scenes/letter-f.json";

vtkRenderer* renderer(MainWindow& window, const char* view)
{
    return window.findChild<QVTKOpenGLNativeWidget*>(view)->renderWindow()->GetRenderers()->GetFirstRenderer();
}

// Every text the window shows or says: visible labels, buttons, fields and
// list entries, accessible names and descriptions, the window's title, and
// the texts drawn in both views.
QStringList shownTexts(MainWindow& w)
{
    w.renderNow();
    QStringList texts{w.windowTitle()};
    for (QWidget* widget : w.findChildren<QWidget*>()) {
        if (!widget->isVisibleTo(&w))
            continue;
        texts << widget->accessibleName() << widget->accessibleDescription();
        if (auto* label = qobject_cast<QLabel*>(widget))
            texts << QTextDocumentFragment::fromHtml(label->text()).toPlainText();
        else if (auto* button = qobject_cast<QAbstractButton*>(widget))
            texts << button->text();
        else if (auto* field = qobject_cast<QLineEdit*>(widget))
            texts << field->text();
        else if (auto* edit = qobject_cast<QPlainTextEdit*>(widget))
            texts << edit->toPlainText();
        else if (auto* list = qobject_cast<QListWidget*>(widget))
            for (int k = 0; k < list->count(); ++k)
                texts << list->item(k)->text() << list->item(k)->data(Qt::AccessibleTextRole).toString();
    }
    for (const char* view : {"worldView", "projectedView"})
        if (w.findChild<QVTKOpenGLNativeWidget*>(view)->isVisible())
            for (const DrawnText& text : drawnTexts(renderer(w, view)).texts)
                texts << QString::fromStdString(text.text);
    texts.removeAll(QString());
    return texts;
}

// A number as any panel may write it, cut to four significant digits (a
// panel rounds to four or more), its sign dropped (written − or -); nothing
// where that is too short to be told from other numbers (0.5, 2, 10).
std::optional<QString> telltale(double value)
{
    QString text = QString::fromStdString(formatSignificant(std::abs(value), 12));
    if (text.contains('e'))
        return std::nullopt;
    int digits = 0, cut = 0;
    bool significant = false;
    for (; cut < text.size() && digits < 4; ++cut) {
        significant = significant || (text[cut].isDigit() && text[cut] != '0');
        digits += significant && text[cut].isDigit();
    }
    text.truncate(cut);
    if (digits < 4 || !text.contains('.'))
        return std::nullopt;
    return text;
}

// The texts that would give a question's answer away, each a list of numbers
// that one text holds in this order to give it: a point's coordinates (not
// one of them alone: a matrix's entry may equal one), an entry; the verdict on
// the canonical volume for the point an inside question asks about (checked
// while that point is traced).
QList<QStringList> answerTexts(const Question& question, const std::optional<Vec3<double>>& traced)
{
    QStringList numbers;
    const auto add = [&numbers](double value) {
        if (const auto text = telltale(value))
            numbers << *text;
    };
    switch (question.kind) {
    case QuestionKind::Where:
        for (int k = 0; k < 3; ++k)
            add(question.where[k]);
        break;
    case QuestionKind::Entry:
        add(question.entry);
        break;
    case QuestionKind::Inside:
        if (traced == question.point)
            return {{"the canonical volume."}};
        break;
    default:
        break;
    }
    return numbers.isEmpty() ? QList<QStringList>{} : QList<QStringList>{numbers};
}

// Whether `text` holds `parts` in order.
bool holdsInOrder(const QString& text, const QStringList& parts)
{
    int from = 0;
    for (const QString& part : parts) {
        from = text.indexOf(part, from);
        if (from < 0)
            return false;
        from += part.size();
    }
    return true;
}

// The first of `texts` that holds an answer of questions `from` on, with the question's step.
QString givenAway(const Lesson& lesson, std::size_t from, const QStringList& texts, const std::optional<Vec3<double>>& traced)
{
    for (std::size_t j = from; j < lesson.steps.size(); ++j)
        if (lesson.steps[j].question)
            for (const QStringList& answer : answerTexts(*lesson.steps[j].question, traced))
                for (const QString& text : texts)
                    if (holdsInOrder(text, answer))
                        return QString("step %1's answer %2 in \"%3\"").arg(j + 1).arg(answer.join(", "), text.simplified());
    return {};
}

void typeInto(QWidget* field, const QString& text)
{
    field->setFocus();
    QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClick(field, Qt::Key_Backspace);
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

// Types a new VRP x in the parameter panel, as a person edits the scene.
void editVrpX(MainWindow& w, const QString& x)
{
    typeInto(w.parameters()->fields("view.vrp").at(0), x);
}

double vrpX(MainWindow& w)
{
    return std::get<foley::ViewSpec<double>>(w.document()->scene().camera).vrp.x();
}

// Ticks "Edit the lesson" with a click on its check box, where it is not ticked yet.
void openEditor(MainWindow& w)
{
    auto* editor = lessonChild<QGroupBox>(w, "lessonEditor");
    QVERIFY(QTest::qWaitFor([editor] { return editor->isVisible(); }));
    if (!editor->isChecked())
        QTest::mouseClick(editor, Qt::LeftButton, {}, QPoint(10, 10));
    QVERIFY(editor->isChecked());
}

// A new title typed in the lesson's editor, ticked open first.
void typeTitle(MainWindow& w, const QString& title)
{
    openEditor(w);
    typeInto(lessonChild<QLineEdit>(w, "titleEdit"), title);
}

QString lessonTitle(MainWindow& w)
{
    return QString::fromStdString(w.lessonFlow()->lesson()->lesson().title);
}

QByteArray fileBytes(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// A menu bar's menu clicked open, then its item clicked, as a person chooses it (names without the &).
void chooseFromMenu(MainWindow& w, const QString& menuName, const QString& itemName)
{
    QMenuBar* bar = w.menuBar();
    QAction* menuAction = nullptr;
    for (QAction* action : bar->actions())
        if (action->text().remove('&') == menuName)
            menuAction = action;
    QVERIFY2(menuAction && menuAction->menu(), qPrintable("no menu " + menuName));
    QMenu* menu = menuAction->menu();
    QTest::mouseClick(bar, Qt::LeftButton, {}, bar->actionGeometry(menuAction).center());
    QVERIFY2(QTest::qWaitFor([menu] { return menu->isVisible(); }), qPrintable(menuName + " did not open"));
    for (QAction* action : menu->actions())
        if (action->text().remove('&') == itemName) {
            QVERIFY(action->isEnabled());
            return QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(action).center());
        }
    QFAIL(qPrintable("no item " + itemName + " in " + menuName));
}

// The keys of File ▸ Quit, Open… and Lesson ▸ Open Lesson…, pressed in the window, active again
// after a dialog (a shortcut acts in the active window only).
void pressKeys(MainWindow& w, Qt::Key key)
{
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    QTest::keyClick(&w, key, Qt::ControlModifier);
}

} // namespace

class LessonTrustTest : public QObject {
    Q_OBJECT
private slots:
    void init() { window_ = openWindow(kHouse, {1280, 800}); }
    void cleanup()
    {
        cancelAnswers();
        if (window_)
            window_->lessonFlow()->lesson()->undoStack()->setClean();
        closeWindow(window_);
    }

    // Before each question of every built-in lesson is answered, nothing the
    // window shows or says holds its answer or a later one; ▶, the slider and
    // Play hold before the stage a question asks about.
    void nothingShownGivesAnAnswerAway()
    {
        MainWindow& w = *window_;
        int looks = 0;
        const QFileInfoList files = QDir(QString(viewpipe::build::dataDir) + "/lessons").entryInfoList({"*.json"}, QDir::Files, QDir::Name);
        QVERIFY(files.size() >= 5);
        for (const QFileInfo& file : files) {
            const Lesson lesson = loadLesson(file.absoluteFilePath().toStdString());
            QVERIFY(w.lessonFlow()->openLesson(file.absoluteFilePath()));
            LessonDocument* document = w.lessonFlow()->lesson();
            for (int k = 0; k < int(lesson.steps.size()); ++k) {
                const QString where = file.fileName() + QString(", step %1").arg(k + 1);
                document->goTo(k);
                settle(w);
                if (lesson.steps[std::size_t(k)].question) {
                    const QString early = givenAway(lesson, std::size_t(k), shownTexts(w), w.views()->traced());
                    QVERIFY2(early.isEmpty(), qPrintable(where + ", asking: " + early));
                    // An inside question's point is not marked: where it lies against the volume is the answer.
                    const Question& asked = *lesson.steps[std::size_t(k)].question;
                    if (asked.kind == QuestionKind::Inside)
                        QVERIFY2(w.views()->traced() != asked.point, qPrintable(where));
                    // The stepper holds: ▶, the slider and Play go no further than the stage the step waits at.
                    const int holds = w.stepper()->target();
                    QCOMPARE(holds, askingStage(lesson.steps[std::size_t(k)]));
                    click(w.stagePanel()->findChild<QPushButton*>("nextButton"), false);
                    w.stepper()->stepBy(1);
                    QCOMPARE(w.stepper()->target(), holds);
                    w.stagePanel()->findChild<QSlider*>("stageSlider")->setValue(holds + 1);
                    QCOMPARE(w.stepper()->target(), holds);
                    click(w.stagePanel()->findChild<QPushButton*>("playButton"), holds > 0);
                    QCOMPARE(w.stepper()->target(), holds);
                    settle(w);
                    QCOMPARE(w.stepper()->shownStage(), holds);
                    const QString pressed = givenAway(lesson, std::size_t(k), shownTexts(w), w.views()->traced());
                    QVERIFY2(pressed.isEmpty(), qPrintable(where + ", asking, after ▶ and Play: " + pressed));
                    document->reveal();
                    settle(w);
                    ++looks;
                }
                const QString later = givenAway(lesson, std::size_t(k) + 1, shownTexts(w), w.views()->traced());
                QVERIFY2(later.isEmpty(), qPrintable(where + ", answered: " + later));
                ++looks;
            }
            document->close();
        }
        QVERIFY(looks > 60);
    }

    // The answers themselves are found where they are shown: the check above can fail.
    void anAnswerShownIsFound()
    {
        MainWindow& w = *window_;
        const Lesson lesson = loadLesson(kFoley.toStdString());
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        w.lessonFlow()->lesson()->goTo(6); // step 7: where is (16, 10, 30) after S_per?
        w.lessonFlow()->lesson()->reveal();
        settle(w);
        QVERIFY(!givenAway(lesson, 6, shownTexts(w), w.views()->traced()).isEmpty());
    }

    // The reported loss: a scene edit, then a title typed in the lesson's editor.
    void aTitleTypedAfterASceneEditIsKept()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        openEditor(w);
        editVrpX(w, "3");
        QCOMPARE(vrpX(w), 3.0);
        QString asked;
        answerNextQuestion("Cancel", &asked, 5); // were anything asked within half a second: the safe answer
        QVERIFY(w.lessonFlow()->lesson()->isRevealed(0)); // the editor shows the answers
        typeInto(lessonChild<QLineEdit>(w, "titleEdit"), "Foley, revised");
        QTest::qWait(800);
        QCOMPARE(asked, QString()); // nothing to ask: the view stays as the user left it
        QVERIFY(w.lessonFlow()->lesson()->isOpen());
        QCOMPARE(w.lessonFlow()->lesson()->lesson().title, std::string("Foley, revised"));
        QCOMPARE(vrpX(w), 3.0);
        QVERIFY(w.findChild<QDockWidget*>("lessonDock")->isVisible());
        QCOMPARE(lessonChild<QLineEdit>(w, "titleEdit")->text(), QString("Foley, revised"));
        QCOMPARE(w.lessonFlow()->lesson()->undoStack()->count(), 1);
        // Quit asks about the lesson (not about answers: the editor's showing them is no student's answer);
        // Cancel keeps the window, the lesson and the scene as they are.
        QVERIFY(!w.lessonFlow()->lesson()->hasUnsavedAnswers());
        answerNextQuestion("Cancel", &asked);
        QVERIFY(!w.close());
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QVERIFY(w.lessonFlow()->lesson()->isOpen());
        QCOMPARE(w.lessonFlow()->lesson()->lesson().title, std::string("Foley, revised"));
        QCOMPARE(vrpX(w), 3.0);
    }

    // Leaving the editor applies what was typed.
    void leavingTheEditorKeepsWhatWasTyped()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        openEditor(w);
        auto* title = lessonChild<QLineEdit>(w, "titleEdit");
        title->setFocus();
        QTest::keyClick(title, Qt::Key_End);
        QTest::keyClicks(title, " (draft)");
        QTest::mouseClick(lessonChild<QGroupBox>(w, "lessonEditor"), Qt::LeftButton, {}, QPoint(10, 10));
        QVERIFY(!lessonChild<QGroupBox>(w, "lessonEditor")->isChecked());
        QVERIFY(QString::fromStdString(w.lessonFlow()->lesson()->lesson().title).endsWith(" (draft)"));
        // A refused edit (an empty title) opens the editor again with the reason, and keeps the text.
        openEditor(w);
        title->setFocus();
        QTest::keyClick(title, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClick(title, Qt::Key_Backspace);
        QTest::mouseClick(lessonChild<QGroupBox>(w, "lessonEditor"), Qt::LeftButton, {}, QPoint(10, 10));
        QTRY_VERIFY(lessonChild<QGroupBox>(w, "lessonEditor")->isChecked());
        QVERIFY(lessonChild<QLabel>(w, "editError")->text().contains("title"));
        QVERIFY(QString::fromStdString(w.lessonFlow()->lesson()->lesson().title).endsWith(" (draft)"));
    }

    // A step on another scene, with the scene edited: each choice of the prompt.
    void movingToAStepOnAnotherSceneAsksFirst()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        LessonDocument* lesson = w.lessonFlow()->lesson();
        lesson->goTo(2);
        w.lessonFlow()->lesson()->reveal();
        editVrpX(w, "3");
        // Step 4 shows another scene: Cancel stays at step 3 with the edit.
        QString asked;
        answerNextQuestion("Cancel", &asked);
        click(lessonChild<QPushButton>(w, "lessonNext"));
        QTRY_VERIFY(asked.contains("scene has unsaved changes"));
        QCOMPARE(lesson->step(), 2);
        QCOMPARE(vrpX(w), 3.0);
        QVERIFY(w.document()->isModified());
        // Discard goes on to step 4, its scene as the lesson has it.
        asked.clear();
        answerNextQuestion("Discard", &asked);
        click(lessonChild<QPushButton>(w, "lessonNext"));
        QTRY_COMPARE(lesson->step(), 3);
        QVERIFY(asked.contains("scene has unsaved changes"));
        QVERIFY(w.document()->scene() == lesson->currentStep().scene);
        QVERIFY(!w.document()->isModified());
        // Save writes the edited scene first, then goes on.
        lesson->goTo(2);
        QVERIFY(w.document()->scene() == lesson->currentStep().scene);
        editVrpX(w, "4");
        QTemporaryDir folder;
        const QString saved = folder.filePath("edited-house.json");
        answerNextQuestion("Save");
        answerNextFileDialog(saved);
        click(lessonChild<QPushButton>(w, "lessonNext"));
        QTRY_COMPARE(lesson->step(), 3);
        QVERIFY(QFile::exists(saved));
        QCOMPARE(std::get<foley::ViewSpec<double>>(loadScene(kHouse.toStdString()).camera).vrp.x(), 0.0); // the preset untouched
        const Scene written = loadScene(saved.toStdString());
        QCOMPARE(std::get<foley::ViewSpec<double>>(written.camera).vrp.x(), 4.0);
    }

    // Opening another lesson over an edited scene: Cancel keeps the lesson open and the edit.
    void openingAnotherLessonAsksFirst()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        w.lessonFlow()->lesson()->goTo(2);
        editVrpX(w, "3");
        QString asked;
        answerNextQuestion("Cancel", &asked);
        QVERIFY(!w.lessonFlow()->openLesson(kOpenGl));
        QVERIFY(asked.contains("scene has unsaved changes"));
        QCOMPARE(QFileInfo(w.lessonFlow()->lesson()->filePath()).fileName(), QString("foley-nper.json"));
        QCOMPARE(w.lessonFlow()->lesson()->step(), 2);
        QCOMPARE(vrpX(w), 3.0);
        answerNextQuestion("Discard");
        QVERIFY(w.lessonFlow()->openLesson(kOpenGl));
        QCOMPARE(QFileInfo(w.lessonFlow()->lesson()->filePath()).fileName(), QString("opengl-perspective.json"));
        QVERIFY(w.document()->scene() == w.lessonFlow()->lesson()->currentStep().scene);
    }

    // Closing a lesson with an edit, or with answers not saved: each choice.
    void closingALessonAsksAboutEditsAndAnswers()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        LessonDocument* lesson = w.lessonFlow()->lesson();
        lesson->reveal(); // shown unanswered: the results say so, and are not saved
        QVERIFY(lesson->hasUnsavedAnswers());
        QAction* close = w.actions()->action("lesson.close");
        QString asked;
        answerNextQuestion("Cancel", &asked);
        close->trigger();
        QVERIFY(asked.contains("answers"));
        QVERIFY(lesson->isOpen());
        QTemporaryDir folder;
        const QString results = folder.filePath("lesson-results.json");
        answerNextQuestion("Save");
        answerNextFileDialog(results);
        close->trigger();
        QTRY_VERIFY(!lesson->isOpen());
        QVERIFY(QFile::exists(results));

        // An edit: Cancel keeps it, Save writes it, Discard drops it. (An edit asks the questions afresh:
        // no answers to ask about.)
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        openEditor(w);
        typeInto(lessonChild<QLineEdit>(w, "titleEdit"), "Kept");
        answerNextQuestion("Cancel", &asked);
        close->trigger();
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QVERIFY(lesson->isOpen());
        QCOMPARE(lesson->lesson().title, std::string("Kept"));
        const QString file = folder.filePath("kept.json");
        answerNextQuestion("Save");
        answerNextFileDialog(file);
        close->trigger();
        QTRY_VERIFY(!lesson->isOpen());
        QCOMPARE(loadLesson(file.toStdString()).title, std::string("Kept"));
        QVERIFY(w.lessonFlow()->openLesson(file));
        openEditor(w);
        typeInto(lessonChild<QLineEdit>(w, "titleEdit"), "Dropped");
        answerNextQuestion("Discard");
        close->trigger();
        QTRY_VERIFY(!lesson->isOpen());
        QCOMPARE(loadLesson(file.toStdString()).title, std::string("Kept"));
    }

    // File ▸ Quit (its keys) with the lesson edited: Cancel changes nothing; Save writes the edit where
    // the user chooses (a built-in lesson is not overwritten), then the window closes.
    void quittingWithLessonEditsAsksFirst()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        LessonDocument* lesson = w.lessonFlow()->lesson();
        typeTitle(w, "Foley, before the bell");
        QVERIFY(lesson->isModified());
        const QByteArray builtIn = fileBytes(kFoley);
        QString asked;
        answerNextQuestion("Cancel", &asked);
        pressKeys(w, Qt::Key_Q);
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QVERIFY(w.isVisible());
        QVERIFY(lesson->isOpen());
        QVERIFY(lesson->isModified());
        QCOMPARE(lesson->filePath(), kFoley);
        QCOMPARE(lessonTitle(w), QString("Foley, before the bell"));
        QCOMPARE(lessonChild<QLineEdit>(w, "titleEdit")->text(), QString("Foley, before the bell"));

        QTemporaryDir folder;
        const QString saved = folder.filePath("before-the-bell.json");
        asked.clear();
        answerNextQuestion("Save", &asked);
        answerNextFileDialog(saved);
        pressKeys(w, Qt::Key_Q);
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QVERIFY(!w.isVisible());
        QCOMPARE(QString::fromStdString(loadLesson(saved.toStdString()).title), QString("Foley, before the bell"));
        QCOMPARE(fileBytes(kFoley), builtIn);
    }

    // File ▸ Quit with a lesson of the user's own edited, the edit discarded: the window closes, the file as it was.
    void quittingAndDiscardingLeavesTheLessonFile()
    {
        MainWindow& w = *window_;
        QTemporaryDir folder;
        const QString file = folder.filePath("mine.json");
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        QVERIFY(w.lessonFlow()->saveLesson(file));
        QCOMPARE(w.lessonFlow()->lesson()->filePath(), file);
        const QByteArray before = fileBytes(file);
        QVERIFY(!before.isEmpty());
        typeTitle(w, "Not kept");
        QVERIFY(w.lessonFlow()->lesson()->isModified());
        QString asked;
        answerNextQuestion("Discard", &asked);
        pressKeys(w, Qt::Key_Q);
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QVERIFY(!w.isVisible());
        QCOMPARE(fileBytes(file), before);
    }

    // Lesson ▸ New Lesson From View (clicked) over an edited lesson: each choice.
    void aNewLessonFromViewAsksAboutTheEditedOne()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        LessonDocument* lesson = w.lessonFlow()->lesson();
        const std::size_t steps = lesson->lesson().steps.size();
        QVERIFY(steps > 1);
        typeTitle(w, "Foley, my notes");
        // Cancel: the lesson stays, with its edit.
        QString asked;
        answerNextQuestion("Cancel", &asked);
        chooseFromMenu(w, "Lesson", "New Lesson From View");
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QCOMPARE(lesson->filePath(), kFoley);
        QCOMPARE(lesson->lesson().steps.size(), steps);
        QCOMPARE(lessonTitle(w), QString("Foley, my notes"));
        QVERIFY(lesson->isModified());
        // Save: the edit written where the user chooses, then a lesson of the view.
        QTemporaryDir folder;
        const QString saved = folder.filePath("my-notes.json");
        asked.clear();
        answerNextQuestion("Save", &asked);
        answerNextFileDialog(saved);
        chooseFromMenu(w, "Lesson", "New Lesson From View");
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QTRY_COMPARE(lesson->lesson().steps.size(), std::size_t(1));
        QCOMPARE(lesson->filePath(), QString());
        QCOMPARE(QString::fromStdString(loadLesson(saved.toStdString()).title), QString("Foley, my notes"));
        // Discard, over the lesson saved and edited again: a lesson of the view; the file as it was.
        QVERIFY(w.lessonFlow()->openLesson(saved));
        const QByteArray before = fileBytes(saved);
        typeTitle(w, "Not kept");
        asked.clear();
        answerNextQuestion("Discard", &asked);
        chooseFromMenu(w, "Lesson", "New Lesson From View");
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QTRY_COMPARE(lesson->lesson().steps.size(), std::size_t(1));
        QCOMPARE(lesson->filePath(), QString());
        QCOMPARE(fileBytes(saved), before);
    }

    // File ▸ Open… (its keys), a scene, over an edited lesson and an edited scene: the prompt is the
    // scene's, each choice keeps the lesson open with its edit (another scene replaces no lesson).
    void openingASceneKeepsTheEditedLesson()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        LessonDocument* lesson = w.lessonFlow()->lesson();
        typeTitle(w, "Foley, kept");
        editVrpX(w, "3");
        const QString stepScene = w.document()->filePath();
        // Cancel: the scene and its edit stay, no file is asked for.
        QString asked;
        answerNextQuestion("Cancel", &asked);
        pressKeys(w, Qt::Key_O);
        QVERIFY2(asked.contains("scene has unsaved changes"), qPrintable(asked));
        QVERIFY(!shownDialog<QFileDialog>());
        QCOMPARE(w.document()->filePath(), stepScene);
        QCOMPARE(vrpX(w), 3.0);
        QVERIFY(w.document()->isModified());
        QCOMPARE(lessonTitle(w), QString("Foley, kept"));
        QVERIFY(lesson->isModified());
        // Discard: the other scene opened; the lesson open with its edit.
        answerNextQuestion("Discard");
        answerNextFileDialog(kLetterF);
        pressKeys(w, Qt::Key_O);
        QCOMPARE(QFileInfo(w.document()->filePath()).fileName(), QString("letter-f.json"));
        QVERIFY(!w.document()->isModified());
        QVERIFY(lesson->isOpen());
        QCOMPARE(lessonTitle(w), QString("Foley, kept"));
        QVERIFY(lesson->isModified());
        // Save: the edited scene written where the user chooses (a preset is not overwritten), then the other opened.
        editVrpX(w, "4");
        QTemporaryDir folder;
        const QString saved = folder.filePath("edited-letter-f.json");
        answerNextQuestion("Save");
        answerNextFileDialogs({saved, kHouse});
        pressKeys(w, Qt::Key_O);
        QCOMPARE(QFileInfo(w.document()->filePath()).fileName(), QString("house.json"));
        QCOMPARE(std::get<foley::ViewSpec<double>>(loadScene(saved.toStdString()).camera).vrp.x(), 4.0);
        QCOMPARE(std::get<foley::ViewSpec<double>>(loadScene(kLetterF.toStdString()).camera).vrp.x(), 0.0);
        QCOMPARE(lessonTitle(w), QString("Foley, kept"));
        QVERIFY(lesson->isModified());
        // The lesson's edit is still asked about as the window closes.
        answerNextQuestion("Cancel", &asked);
        pressKeys(w, Qt::Key_Q);
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QVERIFY(w.isVisible());
    }

    // Lesson ▸ Open Lesson… (its keys) over an edited lesson: each choice.
    void openingAnotherLessonAsksAboutTheEditedOne()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        LessonDocument* lesson = w.lessonFlow()->lesson();
        typeTitle(w, "Foley, mine");
        // Cancel: nothing changes, no file is asked for.
        QString asked;
        answerNextQuestion("Cancel", &asked);
        pressKeys(w, Qt::Key_L);
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QVERIFY(!shownDialog<QFileDialog>());
        QCOMPARE(lesson->filePath(), kFoley);
        QCOMPARE(lessonTitle(w), QString("Foley, mine"));
        QVERIFY(lesson->isModified());
        // Save: the edit written where the user chooses, then the lesson chosen opened.
        QTemporaryDir folder;
        const QString saved = folder.filePath("mine.json");
        asked.clear();
        answerNextQuestion("Save", &asked);
        answerNextFileDialogs({saved, kOpenGl});
        pressKeys(w, Qt::Key_L);
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QCOMPARE(QFileInfo(lesson->filePath()).fileName(), QString("opengl-perspective.json"));
        QVERIFY(!lesson->isModified());
        QCOMPARE(QString::fromStdString(loadLesson(saved.toStdString()).title), QString("Foley, mine"));
        // Discard, over the lesson saved and edited again: the lesson chosen opened; the file as it was.
        QVERIFY(w.lessonFlow()->openLesson(saved));
        const QByteArray before = fileBytes(saved);
        typeTitle(w, "Not kept");
        asked.clear();
        answerNextQuestion("Discard", &asked);
        answerNextFileDialog(kOpenGl);
        pressKeys(w, Qt::Key_L);
        QVERIFY2(asked.contains("lesson has unsaved changes"), qPrintable(asked));
        QCOMPARE(QFileInfo(lesson->filePath()).fileName(), QString("opengl-perspective.json"));
        QCOMPARE(fileBytes(saved), before);
    }

    // File ▸ Pack Lesson… gathers the lesson as edited, with its scenes and meshes, into the folder chosen.
    void aLessonIsPackedToTravel()
    {
        MainWindow& w = *window_;
        QVERIFY(w.lessonFlow()->openLesson(kFoley));
        openEditor(w);
        typeInto(lessonChild<QLineEdit>(w, "titleEdit"), "Foley, to take home");
        QTemporaryDir folder;
        answerNextFileDialog(folder.path());
        w.actions()->action("lesson.pack")->trigger();
        const QString packed = folder.filePath("foley-nper.json");
        QTRY_VERIFY(QFile::exists(packed));
        const Lesson lesson = loadLesson(packed.toStdString());
        QCOMPARE(lesson.title, std::string("Foley, to take home"));
        for (const LessonStep& step : lesson.steps)
            QVERIFY2(QString::fromStdString(step.scene.file.string()).startsWith(folder.filePath("scenes/")),
                     step.scene.file.c_str());
        evaluateLesson(lesson); // its scenes read from the pack
    }

private:
    // A click where a person clicks, on a button that is (or is not) enabled: a disabled one does nothing.
    static void click(QWidget* widget, bool enabled = true)
    {
        QVERIFY(widget);
        QCOMPARE(widget->isEnabled(), enabled);
        QVERIFY(QTest::qWaitFor([widget] { return widget->isVisible() && widget->width() > 4; }));
        QTest::mouseClick(widget, Qt::LeftButton, {}, widget->rect().center());
    }

    // The picture at rest where the stepper is going (a test's own pace, not the clock's).
    static void settle(MainWindow& w) { w.stepper()->goToStage(w.stepper()->target(), false); }

    std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv)
{
    return runAppTests<LessonTrustTest>(argc, argv);
}

#include "lesson_trust_test.moc"
