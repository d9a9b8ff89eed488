#pragma once

// What the app's GUI tests share: a main window shown, active and on a scene,
// closed without the "save changes?" prompt, and the test program's main().

#include <QApplication>
#include <QDirIterator>
#include <QAbstractButton>
#include <QFileDialog>
#include <QFileInfo>
#include <QLineEdit>
#include <QMessageBox>
#include <QPointer>
#include <QTimer>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTabBar>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include <functional>
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif
#include <memory>

#include "build_paths.h"
#include "app/ActionRegistry.h"
#include "app/Autosave.h"
#include "app/EffectsMenu.h"
#include "app/Exports.h"
#include "app/LessonDocument.h"
#include "app/LessonFlow.h"
#include "app/LessonPanel.h"
#include "app/MainWindow.h"
#include "app/PresentMode.h"
#include "app/SceneFiles.h"
#include "app/StagePanel.h"
#include "app/Stepper.h"
#include "app/ViewDeck.h"

// A window of the given size, shown and active, with `scene` open; null (and
// the test failed) when any of that did not happen.
inline std::unique_ptr<viewpipe::gui::MainWindow> openWindow(const QString& scene, QSize size = {1280, 800})
{
    auto window = std::make_unique<viewpipe::gui::MainWindow>();
    window->setPopupsEnabled(false);
    window->resize(size);
    window->show();
    window->activateWindow();
    if (!QTest::qWaitForWindowActive(window.get()) || !window->sceneFiles()->openScene(scene)) {
        QTest::qFail(qPrintable("cannot open a window on " + scene), __FILE__, __LINE__);
        return nullptr;
    }
    return window;
}

// A widget of the Lesson panel by its object name; a warning, and null, where there is none.
template <class T> T* lessonChild(viewpipe::gui::MainWindow& window, const QString& name)
{
    T* found = window.lessonPanel()->findChild<T*>(name);
    if (!found)
        qWarning("no %s", qPrintable(name));
    return found;
}

// Closes a window as a test ends, without asking about unsaved changes.
inline void closeWindow(std::unique_ptr<viewpipe::gui::MainWindow>& window)
{
    if (window)
        window->document()->undoStack()->setClean();
    window.reset();
}

// The first of the window's dock tabs whose title is cut short (elided), "" when every title is
// whole; tabs that do not all fit are scrolled with arrows, not shortened. `tabs`: how many were seen.
inline QString cutDockTabTitle(const viewpipe::gui::MainWindow& window, int& tabs)
{
    tabs = 0;
    for (const QTabBar* bar : window.findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly))
        for (int k = 0; bar->isVisible() && k < bar->count(); ++k, ++tabs)
            if (bar->elideMode() != Qt::ElideNone || bar->tabRect(k).width() < bar->fontMetrics().horizontalAdvance(bar->tabText(k)))
                return bar->tabText(k);
    return {};
}

// Every built-in scene (data/scenes) at every stage in `window`, rendered,
// then `check(where)` with `where` naming the scene's file and the stage.
// Stops at a scene that does not open or a failed check; returns the number of stages shown.
inline int showEveryBuiltInStage(viewpipe::gui::MainWindow& window, const std::function<void(const QString& where)>& check)
{
    QDirIterator scenes(QString(viewpipe::build::dataDir) + "/scenes", {"*.json"}, QDir::Files, QDirIterator::Subdirectories);
    int shown = 0;
    while (scenes.hasNext()) {
        const QString scene = scenes.next();
        if (!window.sceneFiles()->openScene(scene)) {
            QTest::qFail(qPrintable("cannot open " + scene), __FILE__, __LINE__);
            return shown;
        }
        const int stages = int(window.document()->pipeline().stages.size());
        for (int k = 0; k <= stages; ++k) {
            window.stepper()->goToStage(k, false);
            window.renderNow();
            check(QFileInfo(scene).fileName() + " stage " + QString::number(k));
            if (QTest::currentTestFailed())
                return shown;
            ++shown;
        }
    }
    return shown;
}

// The dialog of type T on screen (a window that is not active has no active modal widget), or null.
template <class T> T* shownDialog()
{
    for (QWidget* widget : QApplication::topLevelWidgets())
        if (auto* dialog = qobject_cast<T*>(widget); dialog && dialog->isVisible())
            return dialog;
    return nullptr;
}

// The context of the timers that answer dialogs: cancelAnswers() (a test's
// cleanup) deletes it, so that no answer waits on into the next test.
inline QObject*& answerContext()
{
    static QObject* context = nullptr;
    if (!context)
        context = new QObject;
    return context;
}
inline void cancelAnswers()
{
    QObject*& context = answerContext();
    delete context;
    context = nullptr;
}

// Answers the next modal question boxes in turn, each by clicking the button
// with its text; `asked`, where given, gets the last question's text.
inline void answerNextQuestions(const QStringList& texts, QString* asked = nullptr, int triesLeft = 100)
{
    if (texts.isEmpty())
        return;
    QTimer::singleShot(100, answerContext(), [texts, asked, triesLeft] {
        auto* box = shownDialog<QMessageBox>();
        if (!box) {
            if (triesLeft > 0)
                answerNextQuestions(texts, asked, triesLeft - 1); // not up yet
            return;
        }
        if (asked)
            *asked = box->text();
        for (QAbstractButton* button : box->buttons())
            if (button->text() == texts.front()) {
                button->click();
                return answerNextQuestions(texts.mid(1), asked);
            }
        qFatal("no button \"%s\"", qPrintable(texts.front()));
    });
}

inline void answerNextQuestion(const QString& text, QString* asked = nullptr, int triesLeft = 100)
{
    answerNextQuestions({text}, asked, triesLeft);
}

// Answers the next file dialogs in turn, each with its path; a dialog is
// answered once (the next answer waits for another dialog to show).
inline void answerNextFileDialogs(const QStringList& paths, QPointer<QFileDialog> answered = nullptr, int triesLeft = 100)
{
    if (paths.isEmpty())
        return;
    QTimer::singleShot(100, answerContext(), [paths, answered, triesLeft] {
        auto* dialog = shownDialog<QFileDialog>();
        if (!dialog || dialog == answered) {
            if (triesLeft > 0)
                answerNextFileDialogs(paths, answered, triesLeft - 1);
            return;
        }
        // Typed into the file name, as a person types a whole path, then accepted.
        auto* name = dialog->findChild<QLineEdit*>("fileNameEdit");
        if (!name)
            qFatal("the file dialog has no file name field");
        name->setText(paths.front());
        QMetaObject::invokeMethod(dialog, "accept", Qt::QueuedConnection);
        answerNextFileDialogs(paths.mid(1), dialog);
    });
}

// Answers the next file dialog with `path`.
inline void answerNextFileDialog(const QString& path)
{
    answerNextFileDialogs({path});
}

// The body of a GUI test's main(): VTK's OpenGL format, settings and data
// apart from the user's; `first` runs once the application exists.
template <class Test> int runAppTests(int argc, char** argv, const std::function<void()>& first = {})
{
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    if (first)
        first();
    Test test;
    const int failed = QTest::qExec(&test, argc, argv);
#if defined(__SANITIZE_ADDRESS__)
    // Leaks are checked here, while every library is loaded: at exit, VTK's
    // are reported from unloaded modules that tests/sanitizers/lsan.supp cannot name.
    if (__lsan_do_recoverable_leak_check())
        return 1;
#endif
    return failed;
}
