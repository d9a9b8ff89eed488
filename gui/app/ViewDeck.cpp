#include "ViewDeck.h"

#include "StagePair.h"
#include "StoryboardView.h"
#include "viewpipe/lesson.hpp"

namespace viewpipe::gui {

ViewDeck::ViewDeck(QWidget* parent) : QStackedWidget(parent)
{
    // Every view draws a mesh from one copy of its poly data.
    const auto meshes = std::make_shared<MeshDetails>();
    pair_ = new StagePair(meshes);
    storyboard_ = new StoryboardView(meshes);
    for (StageViews* layout : {static_cast<StageViews*>(pair_), static_cast<StageViews*>(storyboard_)}) {
        addWidget(layout);
        connect(layout, &StageViews::vertexPicked, this, &ViewDeck::traceVertex);
    }
}

std::vector<StageViews*> ViewDeck::layouts() const
{
    std::vector<StageViews*> all;
    for (int k = 0; k < count(); ++k)
        all.push_back(static_cast<StageViews*>(widget(k)));
    return all;
}

StageViews* ViewDeck::shown() const
{
    return static_cast<StageViews*>(currentWidget());
}

void ViewDeck::setSceneSource(std::function<std::shared_ptr<const EvaluatedScene>()> source)
{
    source_ = std::move(source);
}

void ViewDeck::drawScene()
{
    shown_ = withoutHidden(source_(), hidden_);
    for (StageViews* layout : layouts())
        layout->setScene(shown_);
}

void ViewDeck::setHidden(const std::set<std::string>& hidden)
{
    hidden_ = hidden;
    for (StageViews* layout : layouts())
        layout->setTicksAndNotesShown(!hidden_.count("ticks"), !hidden_.count("notes"));
    if (shown_)
        drawScene();
}

void ViewDeck::traceVertex(const std::optional<Vec3<double>>& point)
{
    traced_ = point;
    for (StageViews* layout : layouts())
        layout->setTraced(traced_);
    emit tracedChanged();
    renderNow();
}

void ViewDeck::orbit(double yaw, double pitch, double zoom)
{
    for (StageViews* layout : layouts())
        layout->orbit(yaw, pitch, zoom);
}

void ViewDeck::resetView()
{
    for (StageViews* layout : layouts())
        layout->resetView();
}

void ViewDeck::setStoryboardShown(bool shown)
{
    if (shown == storyboardShown() || (shown && !shown_)) // no scene yet: nothing to lay out
        return;
    setCurrentWidget(shown ? static_cast<StageViews*>(storyboard_) : pair_);
    renderNow();
}

bool ViewDeck::storyboardShown() const
{
    return currentWidget() == storyboard_;
}

void ViewDeck::setTheme(report::Theme theme)
{
    for (StageViews* layout : layouts())
        layout->setTheme(theme);
}

report::Theme ViewDeck::theme() const
{
    return pair_->painter()->theme();
}

void ViewDeck::setTextScale(double scale)
{
    for (StageViews* layout : layouts())
        layout->setTextScale(scale);
}

void ViewDeck::renderNow()
{
    renderWanted_ = renderHolds_ > 0;
    if (renderWanted_)
        return;
    shown()->renderNow(); // the layouts hidden are drawn once shown
}

ViewDeck::RenderHold::RenderHold(ViewDeck& deck) : deck_(deck)
{
    ++deck_.renderHolds_;
}

ViewDeck::RenderHold::~RenderHold()
{
    if (--deck_.renderHolds_ == 0 && deck_.renderWanted_)
        deck_.renderNow();
}

} // namespace viewpipe::gui
