#include "Exports.h"

#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QFileInfo>
#include <QProgressDialog>
#include <QRegularExpression>

#include <atomic>

#include "ActionRegistry.h"
#include "AppPaths.h"
#include "Document.h"
#include "ExportDialog.h"
#include "LessonFlow.h"
#include "Messages.h"
#include "StageViews.h"
#include "ViewDeck.h"
#include "Stepper.h"
#include "viewpipe/report/latex.hpp"

namespace viewpipe::gui {
namespace {

// Reports an export's progress in `dialog`; keeps the window alive and Cancel clickable.
ExportProgress progressIn(QProgressDialog& dialog, std::atomic<bool>& cancel)
{
    return [&dialog, &cancel](int done, int total, const std::string& what) {
        dialog.setMaximum(total);
        dialog.setValue(done);
        dialog.setLabelText(QString::fromStdString(what));
        QApplication::processEvents();
        cancel = dialog.wasCanceled();
    };
}

} // namespace

Exports::Exports(Document* document, const Stepper* stepper, ViewDeck* views, const LessonFlow* lesson,
                 Messages& messages, QWidget* dialogParent)
    : QObject(dialogParent), document_(document), stepper_(stepper), views_(views), lesson_(lesson), messages_(messages),
      dialogParent_(dialogParent)
{
}

void Exports::addActions(ActionRegistry& actions)
{
    actions.add("file.exportStages", tr("&Export Stages…"), [this] { chooseAndExportStages(); },
                QKeySequence(Qt::CTRL | Qt::Key_E));
    actions.add("file.exportWebPage", tr("Export as &Web Page…"), [this] { chooseAndExportWebPage(); });
    actions.add("file.exportSheet", tr("Export CAD &Sheet…"), [this] { chooseAndExportSheet(); });
    actions.add("edit.copyLatex", tr("Copy Matrix as &LaTeX"), [this] { copyMatrixAsLatex(); },
                QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
    actions.add("edit.copyImage", tr("Copy View as &Image"), [this] { copyViewAsImage(); },
                QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_I));
}

void Exports::chooseAndExportStages()
{
    ExportDialog dialog(stepper_->stageCount(), views_->theme(), dialogParent_);
    dialog.startFrom(views_->hidden(), views_->storyboardShown());
    if (dialog.exec() != QDialog::Accepted)
        return;
    try {
        const auto files = exportStages(dialog.options());
        if (!files.empty())
            messages_.showNote(tr("Exported %1 files to %2")
                                   .arg(files.size())
                                   .arg(QString::fromStdString(files.front().parent_path().string())),
                               8000);
    } catch (const InputError& e) {
        messages_.showMessage(QString::fromStdString(e.what()));
    }
}

void Exports::chooseAndExportWebPage()
{
    QString name = QString::fromStdString(document_->scene().name).toLower();
    name = name.replace(QRegularExpression("[^a-z0-9]+"), "-").remove(QRegularExpression("^-+|-+$"));
    const QString path = chooseFileToSave(dialogParent_, tr("Export as a web page"), (name.isEmpty() ? "scene" : name) + ".html",
                                          tr("Web pages (*.html)"));
    if (!path.isEmpty())
        exportWebPage(path);
}

void Exports::chooseAndExportSheet()
{
    const QString path = chooseFileToSave(dialogParent_, tr("Export the CAD sheet"), "sheet.png", tr("PNG images (*.png)"));
    if (path.isEmpty())
        return;
    try {
        exportSheet(*document_->evaluated(), path.toStdString(), 1600, 1200, views_->theme());
        messages_.showNote(tr("Exported %1").arg(path), 6000);
    } catch (const InputError& e) {
        messages_.showMessage(QString::fromStdString(e.what()));
    }
}

std::vector<std::filesystem::path> Exports::exportStages(const ExportOptions& options)
{
    QProgressDialog progress(tr("Exporting stages…"), tr("Cancel"), 0, 100, dialogParent_);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(0);
    std::atomic<bool> cancel{false};
    try {
        auto files = gui::exportStages(document_->evaluated(), options, progressIn(progress, cancel), cancel);
        progress.setValue(progress.maximum());
        return files;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        messages_.showMessage(tr("Export failed; nothing was written: %1").arg(e.what()));
        return {};
    }
}

void Exports::exportWebPage(const QString& path)
{
    QProgressDialog progress(tr("Exporting the web page…"), tr("Cancel"), 0, 100, dialogParent_);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(0);
    std::atomic<bool> cancel{false};
    try {
        QDir().mkpath(QFileInfo(path).absolutePath());
        gui::exportWebPage(document_->evaluated(), path.toStdString(), views_->theme(),
                           progressIn(progress, cancel), cancel);
        progress.setValue(progress.maximum());
        if (!cancel)
            messages_.showNote(tr("Exported %1: open it in any browser").arg(path), 8000);
    } catch (const std::exception& e) {
        messages_.showMessage(tr("Export failed; nothing was written: %1").arg(e.what()));
    }
}

void Exports::copyMatrixAsLatex()
{
    if (lesson_->hidesAnswers()) {
        messages_.showMessage(tr("The matrices follow the answer to the lesson's question."));
        return;
    }
    const Scene& scene = document_->scene();
    const int stage = stepper_->stage();
    const std::string latex = stage == 0 ? report::matricesLatex(scene, 4) : report::stageLatex(scene, stage, 4);
    QApplication::clipboard()->setText(QString::fromStdString(latex));
    messages_.showNote(tr("Copied the matrix as LaTeX"), 4000);
}

void Exports::copyViewAsImage()
{
    views_->renderNow();
    QApplication::clipboard()->setImage(views_->shown()->image());
    messages_.showNote(tr("Copied the view as an image"), 4000);
}

} // namespace viewpipe::gui
