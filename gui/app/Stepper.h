#pragma once

// The stepper: the stage the world view is at and the stage it heads for. A
// step is a transition of the world view, timed by the clock; Play steps on to
// the last stage. Stage 0 is the world; stage k is after the k-th matrix.

#include <QElapsedTimer>
#include <QObject>

#include <functional>
#include <optional>

#include "viewpipe/report/world_view.hpp"

class QVariantAnimation;

namespace viewpipe::gui {

class Document;
class ScenePainter;

class Stepper : public QObject {
    Q_OBJECT
public:
    Stepper(const Document* document, ScenePainter* painter, QObject* parent = nullptr);

    // With animate = false the picture jumps there (screenshots, tests); else a
    // running step carries on, then heads for the new target.
    void goToStage(int stage, bool animate = true);
    void stepBy(int by) { goToStage(target_ + by); }
    // Plays every stage from the current one (from the world at the end).
    void play();
    // Holds the stage the running step heads for.
    void stop();
    int stage() const { return stage_; }
    int target() const { return target_; }
    // The stage the picture is at or moving to.
    int shownStage() const;
    int stageCount() const;
    // The highest stage the stepper goes to (a lesson's question holds it before the stage it asks
    // about, stepShows); the last stage by default. A step beyond it goes no further.
    void setLastStage(std::optional<int> stage);
    int lastStage() const;
    bool isAnimating() const;
    bool isPlaying() const { return playing_; }
    // After the document's scene changed: the picture at rest at the same stage, or the last one.
    void restart();
    // The clock steps keep to, in milliseconds: a steady clock (none given) unless a test drives its own
    // (with the animations' driver, QAnimationDriver, on the same time).
    void setClock(std::function<qint64()> clock);

signals:
    // A transition's frame is on the painter: the world view needs drawing.
    void frameChanged();
    // A step toward shownStage() begins: captions and matrices name it while it moves.
    void stepStarted();
    // The picture rests at stage(): captions, matrices and both views follow.
    void rested();
    // The stage, the target or Play changed: the widgets follow.
    void moved();

private:
    // `follows`: the step follows one that just ended, and keeps to its time.
    void startStep(bool follows);
    void rest();
    qint64 now() const; // on the clock steps keep to

    const Document* document_;
    ScenePainter* painter_;
    QVariantAnimation* animation_;
    int stage_ = 0;  // where the picture is, or where the running step started
    int target_ = 0; // where the stepper is going
    std::optional<int> lastStage_;
    int stepMilliseconds_;
    bool playing_ = false;
    std::optional<report::StageMotion> transition_;
    QElapsedTimer steady_;
    std::function<qint64()> clock_; // none: steady_
    qint64 stepEnds_ = 0; // on clock_: when the running step is due to end
};

} // namespace viewpipe::gui
