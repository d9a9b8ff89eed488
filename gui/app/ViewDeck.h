#pragma once

// The middle of the window: its layouts of stage views (the world and
// projected views, the storyboard), one shown, and what every layout is told:
// the scene as shown, the point traced, what View > Leave Out leaves out, the
// look. The roles draw through it, not through the window.

#include <QStackedWidget>

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "painter/ScenePainter.h"

namespace viewpipe::gui {

class StagePair;
class StageViews;
class StoryboardView;

class ViewDeck : public QStackedWidget {
    Q_OBJECT
public:
    explicit ViewDeck(QWidget* parent = nullptr);

    StagePair* pair() const { return pair_; }
    StoryboardView* storyboard() const { return storyboard_; }
    std::vector<StageViews*> layouts() const;
    // The layout shown: the world and projected views, or the storyboard.
    StageViews* shown() const;

    // The scene before View > Leave Out: the document's, as the lesson step shown leaves it.
    void setSceneSource(std::function<std::shared_ptr<const EvaluatedScene>()> source);
    // Draws the source's scene in every layout, without what View > Leave Out names.
    void drawScene();
    // The scene every layout draws, as drawScene left it (none before the first).
    const std::shared_ptr<const EvaluatedScene>& shownScene() const { return shown_; }
    // View > Leave Out: what every layout leaves out, by the names export --hide takes.
    void setHidden(const std::set<std::string>& hidden);
    const std::set<std::string>& hidden() const { return hidden_; }
    // Follows a world point through the stages in every layout (a click on a vertex does this).
    void traceVertex(const std::optional<Vec3<double>>& point);
    const std::optional<Vec3<double>>& traced() const { return traced_; }

    // Every layout framed as at first, then turned and zoomed (a lesson step's turn).
    void orbit(double yaw, double pitch, double zoom);
    void resetView();
    // The storyboard in place of the world and projected views (not before a scene is drawn), or those again.
    void setStoryboardShown(bool shown);
    bool storyboardShown() const;
    void setTheme(report::Theme theme);
    report::Theme theme() const;
    void setTextScale(double scale);

    // Draws the layout shown, or once the last RenderHold ends if one is held.
    void renderNow();
    // Held through an operation that changes several things (opening a
    // scene, entering Present): the views are drawn once, at its end.
    class RenderHold {
    public:
        explicit RenderHold(ViewDeck& deck);
        ~RenderHold();
        RenderHold(const RenderHold&) = delete;
        RenderHold& operator=(const RenderHold&) = delete;

    private:
        ViewDeck& deck_;
    };

signals:
    // After traceVertex, before the views are drawn: the panels that follow the point catch up.
    void tracedChanged();

private:
    StagePair* pair_;
    StoryboardView* storyboard_;
    std::function<std::shared_ptr<const EvaluatedScene>()> source_;
    std::shared_ptr<const EvaluatedScene> shown_;
    std::set<std::string> hidden_;
    std::optional<Vec3<double>> traced_;
    int renderHolds_ = 0;
    bool renderWanted_ = false; // asked for while held
};

} // namespace viewpipe::gui
