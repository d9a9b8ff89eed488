#pragma once

// The scene's files (File menu): open (a dialog, a preset, a recent file or a
// dropped one), save, import a mesh, and recover what a crashed session left
// unsaved. Failures are shown, not thrown; a scene that cannot be opened
// leaves the current one as it is.

#include <QObject>
#include <QString>

#include "viewpipe/scene.hpp"

class QMenu;
class QWidget;

namespace viewpipe::gui {

class ActionRegistry;
class Autosave;
class Document;
class Messages;

class SceneFiles : public QObject {
    Q_OBJECT
public:
    // Dialogs and progress are shown over `dialogParent`, which owns the role.
    SceneFiles(Document* document, Messages& messages, QWidget* dialogParent);

    Autosave* autosave() { return autosave_; }

    bool openScene(const QString& path);
    // The same for a scene already read from `path`; `remember` lists it under Open Recent.
    bool openScene(const Scene& scene, const QString& path, bool remember = true);
    bool saveScene(const QString& path);
    // Saves to the scene's file, asking for a name when it has none (or when asked to).
    bool saveSceneAs(bool askForName = false);
    // Adds a mesh (OBJ, PLY, STL) to the scene as one undoable edit; a file
    // VTK cannot read is refused with its reason and changes nothing.
    bool importMesh(const QString& path);
    // A file dropped on the window: a scene is opened, a mesh imported.
    void openDropped(const QString& path);
    // At start: offers the newest scene autosaved by a session that crashed;
    // returns true when it was recovered (open, with its changes unsaved).
    bool offerRecovery();
    // Asks about the scene's unsaved changes; false: stay.
    bool confirmDiscard();

    // The File menu's actions ("file.open", …); the Presets and Open Recent menus.
    void addActions(ActionRegistry& actions);
    void setMenus(QMenu* presets, QMenu* recent);

signals:
    // A scene was loaded into the document without drawing it (opened, recovered): the window shows it anew.
    void sceneOpened();

private:
    // While a scene opens or a mesh is imported (read off the GUI thread,
    // the window waiting), a drop, another open or import is refused, said
    // in the status bar.
    bool refusedWhileOpening(const QString& path);
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    void rebuildPresetMenu();

    Document* document_;
    Messages& messages_;
    QWidget* dialogParent_;
    Autosave* autosave_;
    QMenu* presetMenu_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    bool opening_ = false;
};

} // namespace viewpipe::gui
