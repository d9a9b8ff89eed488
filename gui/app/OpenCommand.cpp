#include "OpenCommand.h"

#include <QApplication>
#include <QBuffer>
#include <QFile>
#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QImage>
#include <QSettings>
#include <QSurfaceFormat>

#include <QVTKOpenGLNativeWidget.h>

#include <filesystem>
#include <iostream>
#include <optional>

#include "AccuracyPanel.h"
#include "LessonDocument.h"
#include "LessonFlow.h"
#include "MainWindow.h"
#include "PresentMode.h"
#include "SceneFiles.h"
#include "Stepper.h"
#include "export/VirtualDisplay.h"
#include "viewpipe/lesson.hpp"
#include "viewpipe/scene.hpp"

namespace viewpipe::gui {

int runOpen(int argc, char** argv, const OpenOptions& options)
{
    const QString scenePath = QString::fromStdString(options.scene);
    // Validate before any window appears: bad input is exit 2 with the core's message.
    const Scene scene = loadScene(scenePath.toStdString());
    const int stages = int(evaluateScene(scene)->pipeline.stages.size()); // reads the meshes
    if (options.stage < 0 || options.stage > stages)
        throw InputError("--stage", "must lie between 0 and " + std::to_string(stages) + " (got " +
                                        std::to_string(options.stage) + ")");

    std::optional<Lesson> lesson; // read once: checked here, opened below
    if (!options.lesson.empty()) {
        try {
            lesson = loadLesson(options.lesson);
        } catch (const InputError& e) { // named by its file: the message's prefix is the scene's
            throw InputError("--lesson", options.lesson + ": " + e.what());
        }
        if (options.step < 1 || options.step > int(lesson->steps.size()))
            throw InputError("--step", "must lie between 1 and " + std::to_string(lesson->steps.size()) + " (got " +
                                           std::to_string(options.step) + ")");
    }

    const bool screenshot = !options.screenshot.empty();
    // A screenshot needs no screen: a private one is started, as export starts it. A window without
    // a display is refused here, where Qt would abort.
    std::optional<VirtualDisplay> display;
    if (screenshot)
        display.emplace();
    else if (qEnvironmentVariableIsEmpty("DISPLAY"))
        throw InputError("DISPLAY", "is not set: the window needs an X display (--screenshot starts a virtual one; "
                                    "`viewpipe export` saves the stages without one)");
    else if (!displayReachable())
        throw InputError("DISPLAY", "is " + qEnvironmentVariable("DISPLAY").toStdString() +
                                        ", which does not answer: the window needs an X display (--screenshot starts a "
                                        "virtual one; `viewpipe export` saves the stages without one)");
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication::setOrganizationName("ViewPipe");
    QApplication::setApplicationName("ViewPipe");
    QApplication app(argc, argv);

    QSettings settings;
    const QString themeName =
        options.theme ? QString::fromStdString(*options.theme) : (screenshot ? "dark" : settings.value("theme", "dark").toString());
    const report::Theme theme = themeName == "light" ? report::Theme::Light : report::Theme::Dark;

    MainWindow window;
    window.setPopupsEnabled(!screenshot); // a screenshot run reports in the status bar and its exit code
    window.setTheme(theme);
    if (options.width > 0)
        window.resize(options.width, options.height);
    else if (screenshot)
        window.resize(1600, 950);
    else
        window.fitToScreen();
    // Fits the docks to the window too.
    if (options.textScale > 0) // for this run only
        window.setFontSize(int(std::lround(MainWindow::kDefaultFontSize * options.textScale / 100.0)), false);
    else
        window.setFontSize(screenshot ? MainWindow::kDefaultFontSize : settings.value("fontSize", MainWindow::kDefaultFontSize).toInt(),
                           !screenshot);
    window.show();
    if (!window.sceneFiles()->openScene(scene, scenePath)) {
        std::cerr << window.lastMessage().toStdString() << "\n";
        return 2;
    }
    if (!screenshot)
        window.sceneFiles()->offerRecovery();
    window.stepper()->goToStage(options.stage, false);
    if (lesson) {
        if (!window.lessonFlow()->openLesson(std::move(*lesson), QString::fromStdString(options.lesson))) {
            std::cerr << window.lastMessage().toStdString() << "\n";
            return 2;
        }
        window.lessonFlow()->lesson()->goTo(options.step - 1);
        if (options.reveal)
            window.lessonFlow()->lesson()->reveal();
    }
    if (options.layout == "storyboard")
        window.setStoryboardShown(true);
    if (options.present)
        window.presentMode()->setPresenting(true);
    if (!options.panel.empty())
        window.showPanel(QString::fromStdString(options.panel));
    if (!screenshot)
        return app.exec();
    if (options.panel == "accuracy") {
        QEventLoop wait;
        QObject::connect(window.accuracy(), &AccuracyPanel::finished, &wait, &QEventLoop::quit);
        window.accuracy()->measure(*window.document()->evaluated());
        wait.exec();
    }

    // Let the window reach its size, a step's transition end and the GL views draw their frames.
    while (window.stepper()->isAnimating())
        app.processEvents(QEventLoop::WaitForMoreEvents, 50);
    for (int i = 0; i < 5; ++i) {
        app.processEvents();
        window.renderNow();
    }
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!window.grab().toImage().save(&buffer, "PNG"))
        throw InputError("--screenshot", "cannot encode the window's picture");
    try {
        writeFileAtomically(options.screenshot, png.toStdString());
    } catch (const InputError& e) {
        throw InputError("--screenshot", e.reason());
    }
    return 0;
}

} // namespace viewpipe::gui
