#pragma once

// The scene being edited: the last valid state, its file, and the undo stack.
// Widgets forward user intent here; every accepted edit is one undoable
// command, and an edit the core refuses changes nothing.

#include <QObject>
#include <QString>
#include <QUndoStack>

#include "viewpipe/scene.hpp"

namespace viewpipe::gui {

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    // Silent: the undo stack's clearing must not reach a window being destroyed.
    ~Document() override;

    const Scene& scene() const { return scene_; }
    const Pipeline<double>& pipeline() const { return pipeline_; }
    QUndoStack* undoStack() { return &undo_; }
    QString filePath() const { return filePath_; }
    bool isModified() const { return !undo_.isClean(); }

    // A scene read from `path` replaces the current one (no undo across it).
    // Throws InputError for a camera the core refuses, changing nothing.
    void load(const Scene& scene, const QString& path);
    // Throws InputError when the file cannot be written.
    void save(const QString& path);

    // Validates with the core; on success pushes an undoable edit and returns
    // true, otherwise throws InputError and changes nothing.
    void setCamera(const CameraSpec<double>& camera, const QString& description);
    void addObject(const SceneObject& object, const QString& description);
    void setEffects(const EffectList& effects, const QString& description);

    // After a crash: the loaded scene becomes one undoable edit away from
    // `saved` (the file as it was), so it shows as unsaved changes.
    void markRecovered(const Scene& saved);

    // Replaces the state without validation; only for undo and redo of states
    // that were valid when they were pushed.
    void restore(const Scene& scene);

signals:
    void changed();
    void fileChanged();

private:
    void replace(Scene next, const QString& description);

    Scene scene_;
    Pipeline<double> pipeline_;
    QString filePath_;
    QUndoStack undo_;
};

} // namespace viewpipe::gui
