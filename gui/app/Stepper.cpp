#include "Stepper.h"

#include <QSignalBlocker>
#include <QVariantAnimation>

#include <algorithm>

#include "Document.h"
#include "painter/ScenePainter.h"
#include "viewpipe/report/world_view.hpp"

namespace viewpipe::gui {

Stepper::Stepper(const Document* document, ScenePainter* painter, QObject* parent)
    : QObject(parent), document_(document), painter_(painter), animation_(new QVariantAnimation(this)),
      stepMilliseconds_(report::kStepMilliseconds)
{
    steady_.start();
    animation_->setStartValue(0.0);
    animation_->setEndValue(1.0);
    connect(animation_, &QVariantAnimation::valueChanged, this, [this](const QVariant& v) {
        if (transition_) {
            painter_->showMoment(transition_->at(v.toDouble()));
            emit frameChanged();
        }
    });
    connect(animation_, &QVariantAnimation::finished, this, [this] {
        stage_ = transition_->to();
        transition_.reset();
        painter_->setMoving(stage_ != target_); // playing on: the next step starts from this frame
        emit rested();
        if (stage_ != target_)
            startStep(true);
        else
            playing_ = false;
        emit moved();
    });
}

int Stepper::stageCount() const
{
    return int(document_->pipeline().stages.size());
}

bool Stepper::isAnimating() const
{
    return animation_->state() == QAbstractAnimation::Running;
}

void Stepper::setLastStage(std::optional<int> stage)
{
    lastStage_ = stage;
    if (target_ > lastStage())
        goToStage(lastStage(), false);
    emit moved();
}

int Stepper::lastStage() const
{
    return std::clamp(lastStage_.value_or(stageCount()), 0, stageCount());
}

int Stepper::shownStage() const
{
    return transition_ ? transition_->to() : stage_;
}

void Stepper::goToStage(int stage, bool animate)
{
    target_ = std::clamp(stage, 0, lastStage());
    if (!animate) {
        animation_->stop();
        transition_.reset();
        stage_ = target_;
        playing_ = false;
        rest();
        emit moved();
        return;
    }
    stepMilliseconds_ = std::abs(target_ - stage_) > 1 ? report::kSkipMilliseconds : report::kStepMilliseconds;
    if (!isAnimating() && target_ != stage_)
        startStep(false);
    emit moved();
}

void Stepper::play()
{
    if (stage_ >= lastStage())
        goToStage(0, false);
    if (lastStage() == 0)
        return;
    target_ = lastStage();
    stepMilliseconds_ = report::kStepMilliseconds;
    playing_ = true;
    startStep(false);
    emit moved();
}

void Stepper::stop()
{
    goToStage(shownStage(), false);
}

void Stepper::restart()
{
    animation_->stop();
    transition_.reset();
    playing_ = false;
    stage_ = target_ = std::min(stage_, lastStage());
    rest();
    emit moved();
}

void Stepper::setClock(std::function<qint64()> clock)
{
    clock_ = std::move(clock);
    stepEnds_ = now(); // a step following one timed on the old clock starts at once
}

qint64 Stepper::now() const
{
    return clock_ ? clock_() : steady_.elapsed();
}

void Stepper::startStep(bool follows)
{
    const int next = stage_ + (target_ > stage_ ? 1 : -1);
    transition_.emplace(*document_->evaluated(), stage_, next);
    painter_->setMoving(true);
    emit stepStarted();
    animation_->setDuration(stepMilliseconds_);
    // By the clock: a step that follows another starts when that one was due to
    // end, so the time the stage at rest took on the way (its matrices, both views
    // drawn) is made up by dropping frames, not added to Play. However late, the
    // step still shows its last frame moving.
    const qint64 started = now();
    const qint64 late = follows ? std::clamp<qint64>(started - stepEnds_, 0, stepMilliseconds_ - 1) : 0;
    stepEnds_ = started - late + stepMilliseconds_;
    if (late == 0) {
        animation_->start();
        return;
    }
    {
        const QSignalBlocker quiet(animation_); // no frame drawn at the step's start, only where it is due
        animation_->start();
    }
    animation_->setCurrentTime(int(late));
}

void Stepper::rest()
{
    painter_->setMoving(false);
    painter_->showMoment(report::stageAtRest(*document_->evaluated(), stage_));
    emit rested();
}

} // namespace viewpipe::gui
