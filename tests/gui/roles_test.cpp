// The window's roles with no window: each is given the document, the stepper,
// the views and a recorder of what it tells the user, and does its work there.

#include <QApplication>
#include <QClipboard>
#include <QFileInfo>
#include <QMenu>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QVBoxLayout>
#include <QtTest>

#include "build_paths.h"
#include "app_window.h"
#include "app/Document.h"
#include "app/Exports.h"
#include "app/LessonDocument.h"
#include "app/LessonFlow.h"
#include "app/Messages.h"
#include "app/SceneFiles.h"
#include "app/StagePair.h"
#include "app/StageViews.h"
#include "app/Stepper.h"
#include "app/ViewDeck.h"

using namespace viewpipe;
using namespace viewpipe::gui;

namespace {

const QString kHouse = QString(viewpipe::build::dataDir) + "/scenes/house.json";

// What the roles tell the user, kept in order.
class RecordedMessages : public Messages {
public:
    void showMessage(const QString& text) override { errors << text; }
    QString lastMessage() const override { return errors.isEmpty() ? QString() : errors.last(); }
    void showNote(const QString& text, int) override { notes << text; }
    QStringList errors, notes;
};

// A widget standing in for the window: the dialogs' parent and the views' place on screen.
struct Roles {
    Roles()
    {
        auto* layout = new QVBoxLayout(&parent);
        layout->addWidget(views);
        layout->addWidget(lesson.panel()); // the window's dock would own it
        files.setMenus(&presets, &recent);
        parent.resize(900, 600);
        parent.show();
    }
    QWidget parent;
    QMenu presets, recent;
    RecordedMessages messages;
    Document document;
    ViewDeck* views = new ViewDeck;
    Stepper stepper{&document, views->pair()->painter()};
    SceneFiles files{&document, messages, &parent};
    LessonFlow lesson{&document, &stepper, views, &files, messages, &parent};
    Exports exports{&document, &stepper, views, &lesson, messages, &parent};
};

} // namespace

class RolesTest : public QObject {
    Q_OBJECT

private slots:
    void sceneFilesOpenAndSaveIntoTheDocumentAndSayWhy()
    {
        Roles roles;
        QSignalSpy opened(&roles.files, &SceneFiles::sceneOpened);
        QTemporaryDir dir;
        QVERIFY(!roles.files.openScene(dir.filePath("missing.json")));
        QCOMPARE(opened.count(), 0);
        QCOMPARE(roles.messages.errors.size(), 1);
        QVERIFY2(roles.messages.errors.last().startsWith("Cannot open " + dir.filePath("missing.json")),
                 qPrintable(roles.messages.errors.last()));

        QVERIFY(roles.files.openScene(kHouse));
        QCOMPARE(opened.count(), 1);
        QCOMPARE(roles.recent.actions().front()->text(), QFileInfo(kHouse).absoluteFilePath());
        QCOMPARE(roles.document.filePath(), kHouse);
        QVERIFY(roles.document.scene() == loadScene(kHouse.toStdString()));

        const QString copy = dir.filePath("copy.json");
        QVERIFY(roles.files.saveScene(copy));
        QCOMPARE(roles.messages.notes, QStringList{"Saved " + copy});
        QVERIFY(loadScene(copy.toStdString()) == roles.document.scene());
    }

    // A lesson's steps reach the document, the stepper and the views it is given; a step made from the
    // view reads them back; the exports hold the matrices back while a question waits.
    void aLessonShowsItsStepsInTheViewsItIsGiven()
    {
        Roles roles;
        roles.views->setSceneSource([&] { return roles.lesson.asShown(roles.document.evaluated()); });
        QSignalSpy opened(&roles.lesson, &LessonFlow::sceneOpened);
        QSignalSpy shown(&roles.lesson, &LessonFlow::lessonShown);
        QSignalSpy panel(&roles.lesson, &LessonFlow::panelWanted);

        LessonStep first;
        first.scene = loadScene(kHouse.toStdString());
        first.stage = 2;
        first.trace = Vec3<double>(16, 10, 54);
        first.yaw = 30;
        first.pitch = 10;
        first.zoom = 1.5;
        first.storyboard = true;
        LessonStep second = first;
        second.stage = 4;
        second.trace.reset();
        second.storyboard = false;
        second.panel = "matrices";
        second.question = Question{};
        second.question->prompt = "Which?";
        second.question->choices = {"This", "That"};
        QVERIFY(roles.lesson.openLesson(Lesson{"Two steps", {first, second}}, QString()));

        QCOMPARE(opened.count(), 1);
        QCOMPARE(shown.last().at(0).toBool(), true);
        QVERIFY(roles.document.scene() == first.scene);
        QCOMPARE(roles.stepper.stage(), 2);
        QVERIFY(roles.views->shownScene());
        QCOMPARE(roles.views->traced(), first.trace);
        QVERIFY(roles.views->storyboardShown());
        // The step made from the view is the step shown.
        roles.lesson.addLessonStepFromView();
        const LessonStep& made = roles.lesson.lesson()->currentStep();
        QCOMPARE(made.stage, 2);
        QCOMPARE(made.trace, first.trace);
        QCOMPARE(made.yaw, 30.0);
        QCOMPARE(made.pitch, 10.0);
        QCOMPARE(made.zoom, 1.5);
        QVERIFY(made.storyboard);

        roles.lesson.lesson()->goTo(2); // the question
        QCOMPARE(roles.stepper.stage(), 4);
        QCOMPARE(panel.last().at(0).toString(), QString("matrices"));
        QVERIFY(!roles.views->storyboardShown());
        QVERIFY(roles.lesson.hidesAnswers());
        QApplication::clipboard()->setText("before");
        roles.exports.copyMatrixAsLatex();
        QCOMPARE(QApplication::clipboard()->text(), QString("before"));
        QCOMPARE(roles.messages.lastMessage(), QString("The matrices follow the answer to the lesson's question."));

        roles.lesson.advance(1); // reveals the answer
        QVERIFY(!roles.lesson.hidesAnswers());
        roles.exports.copyMatrixAsLatex();
        QVERIFY2(QApplication::clipboard()->text().startsWith("\\mathit{SH}_{\\mathrm{per}} =\n\\begin{bmatrix}"),
                 qPrintable(QApplication::clipboard()->text()));
        QCOMPARE(roles.messages.notes.last(), QString("Copied the matrix as LaTeX"));

        roles.lesson.lesson()->close();
        QCOMPARE(shown.last().at(0).toBool(), false);
    }
};

int main(int argc, char** argv)
{
    return runAppTests<RolesTest>(argc, argv);
}

#include "roles_test.moc"
