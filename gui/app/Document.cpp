#include "Document.h"

#include <QUndoCommand>

namespace viewpipe::gui {
namespace {

class SceneEdit : public QUndoCommand {
public:
    SceneEdit(Document* document, Scene before, Scene after, const QString& text)
        : QUndoCommand(text), document_(document), before_(std::move(before)), after_(std::move(after))
    {
    }
    void undo() override { document_->restore(before_); }
    void redo() override { document_->restore(after_); }

private:
    Document* document_;
    Scene before_;
    Scene after_;
};

} // namespace

Document::Document(QObject* parent) : QObject(parent)
{
    connect(&undo_, &QUndoStack::cleanChanged, this, &Document::fileChanged);
}

Document::~Document()
{
    undo_.blockSignals(true);
}

void Document::load(const Scene& scene, const QString& path)
{
    Pipeline<double> pipeline = buildPipeline(scene.camera, scene.effects);
    scene_ = scene;
    pipeline_ = std::move(pipeline);
    filePath_ = path;
    undo_.clear();
    emit fileChanged();
    emit changed();
}

void Document::save(const QString& path)
{
    saveScene(scene_, path.toStdString());
    filePath_ = path;
    scene_.file = path.toStdString();
    undo_.setClean();
    emit fileChanged();
}

void Document::setCamera(const CameraSpec<double>& camera, const QString& description)
{
    Scene next = scene_;
    next.camera = camera;
    replace(std::move(next), description);
}

void Document::setEffects(const EffectList& effects, const QString& description)
{
    Scene next = scene_;
    next.effects = effects;
    replace(std::move(next), description);
}

void Document::addObject(const SceneObject& object, const QString& description)
{
    Scene next = scene_;
    next.objects.push_back(object);
    replace(std::move(next), description);
}

void Document::markRecovered(const Scene& saved)
{
    undo_.push(new SceneEdit(this, saved, scene_, tr("Recover unsaved changes")));
}

void Document::replace(Scene next, const QString& description)
{
    buildPipeline(next.camera); // throws InputError: nothing changes
    undo_.push(new SceneEdit(this, scene_, std::move(next), description));
}

void Document::restore(const Scene& scene)
{
    pipeline_ = buildPipeline(scene.camera, scene.effects);
    scene_ = scene;
    emit changed();
}

} // namespace viewpipe::gui
