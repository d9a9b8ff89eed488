#include "Document.h"

#include <QUndoCommand>

namespace viewpipe::gui {
namespace {

class SceneEdit : public QUndoCommand {
public:
    using State = std::shared_ptr<const EvaluatedScene>;
    SceneEdit(Document* document, State before, State after, const QString& text, int gesture)
        : QUndoCommand(text), document_(document), before_(std::move(before)), after_(std::move(after)),
          gesture_(gesture)
    {
    }
    void undo() override { document_->restore(before_); }
    void redo() override { document_->restore(after_); }
    int id() const override { return gesture_; }
    // The same gesture goes on: one edit from where it started to where it is now.
    bool mergeWith(const QUndoCommand* other) override
    {
        after_ = static_cast<const SceneEdit*>(other)->after_;
        return true;
    }

private:
    Document* document_;
    State before_;
    State after_;
    int gesture_;
};

} // namespace

Document::Document(QObject* parent) : QObject(parent), evaluated_(std::make_shared<const EvaluatedScene>())
{
    connect(&undo_, &QUndoStack::cleanChanged, this, &Document::fileChanged);
}

const Pipeline<Exact>* Document::exactPipeline() const
{
    if (exactOf_ != evaluated_) {
        exactOf_ = evaluated_;
        try {
            exact_ = viewpipe::exactPipeline(evaluated_->scene);
        } catch (const std::exception&) { // refused exactly (an up vector exactly parallel): the doubles stand
            exact_.reset();
        }
    }
    return exact_ ? &*exact_ : nullptr;
}

Document::~Document()
{
    undo_.blockSignals(true);
}

void Document::load(std::shared_ptr<const EvaluatedScene> evaluated, const QString& path)
{
    evaluated_ = std::move(evaluated);
    filePath_ = path;
    undo_.clear();
    emit fileChanged();
    emit changed();
}

void Document::save(const QString& path)
{
    saveScene(scene(), path.toStdString());
    filePath_ = path;
    undo_.setClean();
    emit fileChanged();
}

void Document::setCamera(const CameraSpec<double>& camera, const QString& description, int gesture)
{
    Scene next = scene();
    next.camera = camera;
    replace(std::move(next), description, gesture);
}

void Document::setCamera(const CameraSpec<double>& camera, const std::map<std::string, std::string>& typed,
                         const QString& description)
{
    Scene next = scene();
    next.camera = camera;
    next.typedExpressions = typed;
    replace(std::move(next), description);
}

void Document::setEffects(const EffectList& effects, const QString& description)
{
    Scene next = scene();
    next.effects = effects;
    replace(std::move(next), description);
}

std::shared_ptr<const EvaluatedScene> Document::evaluate(const Scene& scene)
{
    const std::lock_guard<std::mutex> one(evaluating_);
    return evaluator_.evaluate(scene);
}

void Document::edit(std::shared_ptr<const EvaluatedScene> after, const QString& description)
{
    undo_.push(new SceneEdit(this, evaluated_, std::move(after), description, -1));
}

void Document::markRecovered(const Scene& saved)
{
    undo_.push(new SceneEdit(this, evaluate(saved), evaluated_, tr("Recover unsaved changes"), -1));
}

void Document::replace(Scene next, const QString& description, int gesture)
{
    next.typedExpressions = heldExpressions(next); // an expression whose field was edited since is gone
    std::shared_ptr<const EvaluatedScene> after = evaluate(next); // throws InputError: nothing changes
    undo_.push(new SceneEdit(this, evaluated_, std::move(after), description, gesture));
}

void Document::restore(std::shared_ptr<const EvaluatedScene> state)
{
    evaluated_ = std::move(state);
    emit changed();
}

} // namespace viewpipe::gui
