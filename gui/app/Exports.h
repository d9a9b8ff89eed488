#pragma once

// What the window exports (File and Edit menus): the stages as pictures, the
// scene as a web page, the CAD sheet, the matrix as LaTeX and the view as an
// image. Long exports show progress and can be cancelled; failures are shown,
// not thrown, and leave nothing half written.

#include <QObject>
#include <QString>

#include <filesystem>
#include <vector>

#include "export/Exporter.h"

namespace viewpipe::gui {

class ActionRegistry;
class MainWindow;

class Exports : public QObject {
    Q_OBJECT
public:
    explicit Exports(MainWindow* window);

    // Exports with a progress dialog that can cancel; returns the files written
    // (none when cancelled or failed, with the reason shown). Options the
    // exporter refuses throw InputError.
    std::vector<std::filesystem::path> exportStages(const ExportOptions& options);
    // Writes the scene as one web page.
    void exportWebPage(const QString& path);
    // Edit > Copy Matrix as LaTeX: the current stage's matrix (all of them at stage 0).
    void copyMatrixAsLatex();
    // Edit > Copy View as Image: the world view as it is on screen.
    void copyViewAsImage();

    // "file.exportStages", "file.exportWebPage", "file.exportSheet", "edit.copyLatex", "edit.copyImage".
    void addActions(ActionRegistry& actions);

private:
    void chooseAndExportStages();
    void chooseAndExportWebPage();
    void chooseAndExportSheet();

    MainWindow* window_;
};

} // namespace viewpipe::gui
