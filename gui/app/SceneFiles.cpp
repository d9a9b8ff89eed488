#include "SceneFiles.h"

#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QScopeGuard>
#include <QSettings>
#include <QSignalBlocker>

#include <algorithm>
#include <map>

#include "ActionRegistry.h"
#include "AppPaths.h"
#include "Autosave.h"
#include "Document.h"
#include "Messages.h"
#include "Waiting.h"

namespace viewpipe::gui {
namespace {

constexpr int kMaxRecent = 8;

} // namespace

SceneFiles::SceneFiles(Document* document, Messages& messages, QWidget* dialogParent)
    : QObject(dialogParent), document_(document), messages_(messages), dialogParent_(dialogParent),
      autosave_(new Autosave(document, this))
{
}

void SceneFiles::addActions(ActionRegistry& actions)
{
    actions.add("file.open", tr("&Open…"), [this] {
        if (!confirmDiscard())
            return;
        const QString path = chooseFileToOpen(dialogParent_, tr("Open scene"), tr("Scenes (*.json)"));
        if (!path.isEmpty())
            openScene(path);
    }, QKeySequence::Open);
    actions.add("file.save", tr("&Save"), [this] { saveSceneAs(); }, QKeySequence::Save);
    actions.add("file.saveAs", tr("Save &As…"), [this] { saveSceneAs(true); }, QKeySequence::SaveAs);
    actions.add("file.importMesh", tr("&Import Mesh…"), [this] {
        const QString path = chooseFileToOpen(dialogParent_, tr("Import mesh"), tr("Meshes (*.obj *.ply *.stl)"));
        if (!path.isEmpty())
            importMesh(path);
    });
}

void SceneFiles::setMenus(QMenu* presets, QMenu* recent)
{
    presetMenu_ = presets;
    recentMenu_ = recent;
    rebuildPresetMenu();
    rebuildRecentMenu();
}

bool SceneFiles::openScene(const QString& path)
{
    Scene scene;
    try {
        scene = loadScene(path.toStdString());
    } catch (const InputError& e) {
        messages_.showMessage(tr("Cannot open %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    return openScene(scene, path);
}

bool SceneFiles::refusedWhileOpening(const QString& path)
{
    if (opening_)
        messages_.showNote(tr("%1 not opened: another file is being read").arg(QFileInfo(path).fileName()), 4000);
    return opening_;
}

bool SceneFiles::openScene(const Scene& scene, const QString& path, bool remember)
{
    if (refusedWhileOpening(path))
        return false;
    opening_ = true;
    const auto opened = qScopeGuard([this] { opening_ = false; });
    try {
        // A mesh file can take a while to read: off the GUI thread, announced.
        std::shared_ptr<const EvaluatedScene> evaluated;
        const auto evaluate = [&] { evaluated = document_->evaluate(scene); };
        if (std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) { return o.type == ObjectType::Mesh; }))
            waitShowingProgress(dialogParent_, tr("Opening %1…").arg(path.isEmpty() ? tr("the scene") : QFileInfo(path).fileName()),
                                evaluate);
        else
            evaluate();
        const QSignalBlocker drawn(document_); // the picture is made once, when shown
        document_->load(std::move(evaluated), path);
    } catch (const InputError& e) { // a scene the core refuses is not opened
        messages_.showMessage(tr("Cannot open %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    emit sceneOpened();
    if (remember && !path.isEmpty())
        addRecent(QFileInfo(path).absoluteFilePath());
    return true;
}

bool SceneFiles::saveSceneAs(bool askForName)
{
    QString path = document_->filePath();
    if (askForName || path.isEmpty() || isBuiltInFile(path)) // a preset is a starting point, not a file to overwrite
        path = chooseFileToSave(dialogParent_, tr("Save scene"), path.isEmpty() ? "scene.json" : path, tr("Scenes (*.json)"));
    return !path.isEmpty() && saveScene(path);
}

bool SceneFiles::saveScene(const QString& path)
{
    try {
        document_->save(path);
        addRecent(QFileInfo(path).absoluteFilePath());
        messages_.showNote(tr("Saved %1").arg(path), 4000);
        return true;
    } catch (const std::exception& e) {
        messages_.showMessage(tr("Cannot save: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
}

bool SceneFiles::offerRecovery()
{
    const std::vector<AutosavedScene> orphans = Autosave::orphans();
    if (orphans.empty())
        return false;
    const AutosavedScene& newest = orphans.front();
    const QString name = newest.sourcePath.isEmpty() ? tr("an untitled scene") : newest.sourcePath;
    QMessageBox question(QMessageBox::Question, tr("Recover unsaved changes"),
                         tr("ViewPipe ended unexpectedly while %1 had unsaved changes. Recover them?").arg(name),
                         QMessageBox::Yes | QMessageBox::No, dialogParent_);
    question.setObjectName("recoveryQuestion");
    question.button(QMessageBox::Yes)->setText(tr("Recover"));
    question.button(QMessageBox::No)->setText(tr("Discard"));
    if (question.exec() != QMessageBox::Yes) {
        Autosave::discard(newest);
        return false;
    }
    try {
        const Scene recovered = loadScene(newest.scenePath.toStdString());
        Scene saved = recovered;
        try {
            if (!newest.sourcePath.isEmpty())
                saved = loadScene(newest.sourcePath.toStdString());
        } catch (const InputError&) {
            // The file is gone or broken: the recovered scene is all there is.
        }
        if (!openScene(recovered, newest.sourcePath))
            return false;
        document_->markRecovered(saved);
        Autosave::discard(newest);
        return true;
    } catch (const std::exception& e) {
        messages_.showMessage(tr("Cannot recover %1: %2").arg(name, QString::fromStdString(e.what())));
        return false;
    }
}

bool SceneFiles::confirmDiscard()
{
    if (!document_->isModified())
        return true;
    const auto answer = QMessageBox::question(dialogParent_, tr("Unsaved changes"),
                                              tr("The scene has unsaved changes. Save them first?"),
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveSceneAs();
    return answer == QMessageBox::Discard;
}

bool SceneFiles::importMesh(const QString& path)
{
    if (refusedWhileOpening(path))
        return false;
    opening_ = true;
    const auto opened = qScopeGuard([this] { opening_ = false; });
    SceneObject object;
    object.type = ObjectType::Mesh;
    object.resolvedPath = QFileInfo(path).absoluteFilePath().toStdString();
    object.path = object.resolvedPath.string();
    const auto withMesh = [&] {
        Scene next = document_->scene();
        next.objects.push_back(object);
        return next;
    };
    const std::shared_ptr<const EvaluatedScene> base = document_->evaluated();
    const QString name = QFileInfo(path).fileName();
    try {
        // Read off the GUI thread, announced, as opening a scene with meshes.
        std::shared_ptr<const EvaluatedScene> evaluated;
        waitShowingProgress(dialogParent_, tr("Importing %1…").arg(name), [&, next = withMesh()] { evaluated = document_->evaluate(next); });
        if (document_->evaluated() != base) // edited meanwhile (a field left by the dialog's focus): kept, the mesh read
            evaluated = document_->evaluate(withMesh());
        document_->edit(std::move(evaluated), tr("Import %1").arg(name));
        return true;
    } catch (const InputError& e) {
        messages_.showMessage(tr("Cannot import %1: %2").arg(path, QString::fromStdString(e.reason())));
        return false;
    }
}

void SceneFiles::openDropped(const QString& path)
{
    if (refusedWhileOpening(path))
        return;
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == "json") {
        if (confirmDiscard())
            openScene(path);
    } else if (suffix == "obj" || suffix == "ply" || suffix == "stl") {
        importMesh(path);
    }
}

void SceneFiles::addRecent(const QString& path)
{
    QSettings settings;
    QStringList recent = settings.value("recentFiles").toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    settings.setValue("recentFiles", recent);
    rebuildRecentMenu();
}

void SceneFiles::rebuildRecentMenu()
{
    recentMenu_->clear();
    const QStringList recent = QSettings().value("recentFiles").toStringList();
    for (const QString& path : recent)
        recentMenu_->addAction(path, this, [this, path] {
            if (confirmDiscard())
                openScene(path);
        });
    recentMenu_->setEnabled(!recent.isEmpty());
}

void SceneFiles::rebuildPresetMenu()
{
    presetMenu_->clear();
    std::map<std::string, QMenu*> menus = {{"", presetMenu_}};
    for (const Preset& preset : presetScenes(scenesDirectory().toStdString())) {
        QMenu*& menu = menus[preset.group];
        if (!menu)
            menu = presetMenu_->addMenu(QString::fromStdString(preset.group));
        const QString path = QString::fromStdString(preset.scene.file.string());
        menu->addAction(QString::fromStdString(preset.scene.name), this, [this, path] {
            if (confirmDiscard())
                openScene(path);
        });
    }
}

} // namespace viewpipe::gui
