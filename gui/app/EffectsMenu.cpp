#include "EffectsMenu.h"

#include <QActionGroup>
#include <QSize>

#include <variant>

#include "Document.h"

namespace viewpipe::gui {

EffectsMenu::EffectsMenu(Document* document, QWidget* parent) : QMenu(tr("E&ffects"), parent), document_(document)
{
    setObjectName("effectsMenu");
    setToolTipsVisible(true);
    addToggles();
    addDepthMenu();
    addRasterMenu();
}

void EffectsMenu::addToggles()
{
    auto toggle = [this](const QString& text, EffectKind effect, const QString& tip) {
        QAction* action = addAction(text);
        action->setCheckable(true);
        action->setToolTip(tip);
        connect(action, &QAction::triggered, this, [this, effect, text](bool on) {
            editEffects((on ? tr("Turn on %1") : tr("Turn off %1")).arg(QString(text).remove('&')),
                        [effect, on](EffectList list) { return withEffect(std::move(list), effect, on); });
        });
        return action;
    };
    clip_ = toggle(tr("&Clip to the View Volume"), EffectKind::Clip,
                   tr("Clip edges and faces in homogeneous coordinates; clipped-away parts are ghosted"));
    divide_ = toggle(tr("&Divide (stage M)"), EffectKind::Divide,
                     tr("Append Foley's M (OpenGL: the divide into NDC) as a stage"));
    cull_ = toggle(tr("Back-Face C&ulling"), EffectKind::Cull, tr("Ghost the faces turned away from the viewer"));
}

void EffectsMenu::addDepthMenu()
{
    QMenu* depth = addMenu(tr("Depth &Buffer"));
    depth->setObjectName("depthMenu");
    depthFormats_ = new QActionGroup(this);
    depthFormats_->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    const std::vector<std::pair<QString, QString>> formats = {{tr("Off"), ""},
                                                              {tr("16-bit Fixed Point"), "16,0"},
                                                              {tr("24-bit Fixed Point"), "24,0"},
                                                              {tr("32-bit Fixed Point"), "32,0"},
                                                              {tr("32-bit Float"), "32,1"}};
    for (const auto& [text, data] : formats) {
        QAction* action = depth->addAction(text);
        action->setCheckable(true);
        action->setData(data);
        depthFormats_->addAction(action);
        connect(action, &QAction::triggered, this, [this, text = text, data = data] {
            editEffects(data.isEmpty() ? tr("Turn off the depth buffer") : tr("Depth buffer: %1").arg(text),
                        [data](EffectList list) {
                            if (data.isEmpty())
                                return withEffect(std::move(list), EffectKind::Depth, false);
                            const bool reversed = list.depth && list.depth->reversed;
                            list.depth = DepthOptions{data.section(',', 0, 0).toInt(), data.endsWith('1'), reversed};
                            return withEffect(std::move(list), EffectKind::Depth, true);
                        });
        });
    }
    depth->addSeparator();
    reversed_ = depth->addAction(tr("&Reversed Z (near 1, far 0)"));
    reversed_->setCheckable(true);
    connect(reversed_, &QAction::triggered, this, [this](bool on) {
        editEffects(on ? tr("Reverse the depth buffer") : tr("Unreverse the depth buffer"), [on](EffectList list) {
            list.depth = list.depth.value_or(DepthOptions{});
            list.depth->reversed = on;
            return withEffect(std::move(list), EffectKind::Depth, true);
        });
    });
}

void EffectsMenu::addRasterMenu()
{
    QMenu* raster = addMenu(tr("&Raster"));
    raster->setObjectName("rasterMenu");
    rasterSizes_ = new QActionGroup(this);
    rasterSizes_->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    for (const QSize& size : {QSize(), QSize(16, 12), QSize(32, 24), QSize(64, 48), QSize(128, 96)}) {
        const QString text = size.isValid() ? tr("%1 × %2 Pixels").arg(size.width()).arg(size.height()) : tr("Off");
        QAction* action = raster->addAction(text);
        action->setCheckable(true);
        action->setData(size);
        rasterSizes_->addAction(action);
        connect(action, &QAction::triggered, this, [this, size, text] {
            editEffects(size.isValid() ? tr("Raster: %1").arg(text) : tr("Turn off the raster"),
                        [size](EffectList list) {
                            if (!size.isValid())
                                return withEffect(std::move(list), EffectKind::Raster, false);
                            list.raster = RasterOptions{size.width(), size.height()};
                            return withEffect(std::move(list), EffectKind::Raster, true);
                        });
        });
    }
}

void EffectsMenu::editEffects(const QString& description, const std::function<EffectList(EffectList)>& edit)
{
    try {
        const EffectList next = edit(document_->scene().effects);
        if (!(next == document_->scene().effects))
            document_->setEffects(next, description);
    } catch (const InputError& e) {
        emit message(QString::fromStdString(e.what()));
    }
    follow(); // a refused edit leaves the menu as the scene is
}

void EffectsMenu::follow()
{
    const EffectList& effects = document_->scene().effects;
    clip_->setChecked(effects.has(EffectKind::Clip));
    divide_->setChecked(effects.has(EffectKind::Divide));
    cull_->setChecked(effects.has(EffectKind::Cull));
    const QString format =
        effects.depth ? QString("%1,%2").arg(effects.depth->bits).arg(effects.depth->floating ? 1 : 0) : QString();
    for (QAction* action : depthFormats_->actions())
        action->setChecked(action->data().toString() == format);
    // A camera with reversed depth reverses the buffer itself (Parameters ▸ Depth).
    const auto* camera = std::get_if<gl::Camera<double>>(&document_->scene().camera);
    const bool cameraReversed = camera && camera->depth == gl::DepthMode::Reversed;
    reversed_->setChecked(effects.depth && (effects.depth->reversed || cameraReversed));
    reversed_->setEnabled(effects.depth.has_value() && !cameraReversed);
    // A size from the scene file that the menu does not offer leaves all unchecked.
    const QSize size = effects.raster ? QSize(effects.raster->width, effects.raster->height) : QSize();
    for (QAction* action : rasterSizes_->actions())
        action->setChecked(action->data().toSize() == size);
}

} // namespace viewpipe::gui
