#pragma once

// The scene being edited: the last valid state evaluated (the pipeline, every
// element, the effects' outcomes: built once per accepted edit, meshes read
// once through the evaluator's cache), its file, and the undo stack. Widgets
// forward user intent here; every accepted edit is one undoable command, and
// an edit the core refuses changes nothing. Undo and redo return to states
// already evaluated.

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <mutex>

#include <memory>
#include <optional>

#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/exact.hpp"

namespace viewpipe::gui {

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    // Silent: the undo stack's clearing must not reach a window being destroyed.
    ~Document() override;

    const Scene& scene() const { return evaluated_->scene; }
    const Pipeline<double>& pipeline() const { return evaluated_->pipeline; }
    // The same pipeline computed exactly, for the numbers people read; once per
    // evaluation, when first asked. Null where exact arithmetic refuses the scene.
    const Pipeline<Exact>* exactPipeline() const;
    // What every picture, panel and export of the scene reads.
    const std::shared_ptr<const EvaluatedScene>& evaluated() const { return evaluated_; }
    QUndoStack* undoStack() { return &undo_; }
    QString filePath() const { return filePath_; }
    bool isModified() const { return !undo_.isClean(); }

    // A scene evaluated through this document's cache, for load() and edit():
    // safe off the GUI thread (one evaluation at a time: an edit on the GUI
    // thread meanwhile waits for it). Throws InputError for a scene the core
    // refuses.
    std::shared_ptr<const EvaluatedScene> evaluate(const Scene& scene);
    // An evaluated scene (a file's, a lesson step's) read from `path`
    // replaces the current one (no undo across it).
    void load(std::shared_ptr<const EvaluatedScene> evaluated, const QString& path);
    // Throws InputError when the file cannot be written.
    void save(const QString& path);

    // Validates with the core; on success pushes an undoable edit, otherwise
    // throws InputError and changes nothing. Consecutive edits with the same
    // `gesture` (>= 0: one drag of a number) make one undoable edit.
    void setCamera(const CameraSpec<double>& camera, const QString& description, int gesture = -1);
    // The same, with the scene's expressions typed (Scene::typedExpressions) replaced by `typed`.
    void setCamera(const CameraSpec<double>& camera, const std::map<std::string, std::string>& typed,
                   const QString& description);
    void setEffects(const EffectList& effects, const QString& description);
    // A scene already evaluated (by evaluate(), off the GUI thread: an object
    // added) becomes the current state, as one undoable edit.
    void edit(std::shared_ptr<const EvaluatedScene> after, const QString& description);

    // After a crash: the loaded scene becomes one undoable edit away from
    // `saved` (the file as it was), so it shows as unsaved changes.
    void markRecovered(const Scene& saved);

    // Replaces the state; only for undo and redo of evaluated states.
    void restore(std::shared_ptr<const EvaluatedScene> state);

signals:
    void changed();
    void fileChanged();

private:
    mutable std::shared_ptr<const EvaluatedScene> exactOf_; // the evaluation exact_ was computed for
    mutable std::optional<Pipeline<Exact>> exact_;
    // Keeps the expressions typed whose field still holds their value (heldExpressions).
    void replace(Scene next, const QString& description, int gesture = -1);

    SceneEvaluator evaluator_;
    std::mutex evaluating_; // the evaluator's mesh cache is not thread-safe
    std::shared_ptr<const EvaluatedScene> evaluated_;
    QString filePath_;
    QUndoStack undo_;
};

} // namespace viewpipe::gui
