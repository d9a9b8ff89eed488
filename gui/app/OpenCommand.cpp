#include "OpenCommand.h"

#include <QApplication>
#include <QFile>
#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QImage>
#include <QSettings>
#include <QSurfaceFormat>

#include <QVTKOpenGLNativeWidget.h>

#include <filesystem>

#include "AccuracyPanel.h"
#include "AppPaths.h"
#include "MainWindow.h"
#include "viewpipe/scene.hpp"

namespace viewpipe::gui {

int runOpen(int argc, char** argv, const OpenOptions& options)
{
    const QString scenePath = options.scene.empty() ? scenesDirectory() + "/house.json"
                                                    : QString::fromStdString(options.scene);
    // Validate before any window appears: bad input is exit 2 with the core's message.
    const Scene scene = loadScene(scenePath.toStdString());
    const int stages = int(buildPipeline(scene.camera, scene.effects).stages.size());
    if (options.stage < 0 || options.stage > stages)
        throw InputError("--stage", "must lie between 0 and " + std::to_string(stages) + " (got " +
                                        std::to_string(options.stage) + ")");

    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication::setOrganizationName("ViewPipe");
    QApplication::setApplicationName("ViewPipe");
    QApplication app(argc, argv);
    const bool screenshot = !options.screenshot.empty();

    QSettings settings;
    const QString themeName =
        options.theme ? QString::fromStdString(*options.theme) : (screenshot ? "dark" : settings.value("theme", "dark").toString());
    const Theme theme = themeName == "light" ? Theme::Light : Theme::Dark;

    MainWindow window;
    window.setPopupsEnabled(!screenshot); // a screenshot run reports in the status bar and its exit code
    window.setTheme(theme);
    window.setFontSize(screenshot ? 11 : settings.value("fontSize", 11).toInt());
    window.resize(options.width, options.height);
    window.show();
    if (!window.openScene(scene, scenePath))
        return 2;
    window.goToStage(options.stage, false);
    if (!options.panel.empty())
        window.showPanel(QString::fromStdString(options.panel));
    if (!screenshot)
        return app.exec();
    if (options.panel == "accuracy") {
        QEventLoop wait;
        QObject::connect(window.accuracy(), &AccuracyPanel::finished, &wait, &QEventLoop::quit);
        window.accuracy()->measure(window.document()->scene());
        wait.exec();
    }

    // Let the window reach its size and the GL views their first frames.
    for (int i = 0; i < 5; ++i) {
        app.processEvents();
        window.renderNow();
    }
    const QImage image = window.grab().toImage();
    const QString target = QString::fromStdString(options.screenshot);
    const QString temporary = target + ".tmp.png";
    if (image.isNull() || !image.save(temporary, "PNG"))
        throw InputError("--screenshot", "cannot write \"" + options.screenshot + "\"");
    std::error_code error;
    std::filesystem::rename(temporary.toStdString(), options.screenshot, error); // atomic replace
    if (error) {
        QFile::remove(temporary);
        throw InputError("--screenshot", "cannot replace \"" + options.screenshot + "\": " + error.message());
    }
    return 0;
}

} // namespace viewpipe::gui
