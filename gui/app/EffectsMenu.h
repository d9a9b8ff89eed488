#pragma once

// The Effects menu: clipping, the divide, culling, a depth buffer and a raster,
// each turned on or off (with its parameters) as one undoable edit of the
// scene's effect list; its checks follow the scene.

#include <QMenu>

#include <functional>

#include "viewpipe/effects.hpp"

class QActionGroup;

namespace viewpipe::gui {

class Document;

class EffectsMenu : public QMenu {
    Q_OBJECT
public:
    EffectsMenu(Document* document, QWidget* parent);

    // `edit` applied to the scene's effects as one undoable edit named `description`.
    void editEffects(const QString& description, const std::function<EffectList(EffectList)>& edit);
    // The checks as the scene's effects are.
    void follow();

signals:
    // A refused edit's reason.
    void message(const QString& text);

private:
    void addToggles();
    void addDepthMenu();
    void addRasterMenu();

    Document* document_;
    QAction* clip_ = nullptr;
    QAction* divide_ = nullptr;
    QAction* cull_ = nullptr;
    QAction* reversed_ = nullptr;
    QActionGroup* depthFormats_ = nullptr; // off, or a format: data "bits,float"
    QActionGroup* rasterSizes_ = nullptr;  // off, or a size: data QSize
};

} // namespace viewpipe::gui
