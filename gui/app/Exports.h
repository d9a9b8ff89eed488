#pragma once

// What the window exports (File and Edit menus): the stages as pictures, the
// scene as a web page, the CAD sheet, the matrix as LaTeX and the view as an
// image. Long exports show progress and can be cancelled; failures are shown,
// not thrown, and leave nothing half written.

#include <QObject>
#include <QString>

#include <filesystem>
#include <vector>

class QWidget;

#include "export/Exporter.h"

namespace viewpipe::gui {

class ActionRegistry;
class Document;
class LessonFlow;
class Messages;
class Stepper;
class ViewDeck;

class Exports : public QObject {
    Q_OBJECT
public:
    // The document's scene at the stepper's stage, as `views` show it; dialogs and progress over
    // `dialogParent`, which owns the role.
    Exports(Document* document, const Stepper* stepper, ViewDeck* views, const LessonFlow* lesson, Messages& messages,
            QWidget* dialogParent);

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

    Document* document_;
    const Stepper* stepper_;
    ViewDeck* views_;
    const LessonFlow* lesson_;
    Messages& messages_;
    QWidget* dialogParent_;
};

} // namespace viewpipe::gui
