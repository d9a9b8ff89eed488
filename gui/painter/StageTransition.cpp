#include "StageTransition.h"

#include <algorithm>

#include "viewpipe/animation.hpp"

namespace viewpipe::gui {
namespace {

constexpr double kWiden = 0.2;   // share of the step spent widening the view
constexpr double kSettle = 0.2;  // and closing in at the end
constexpr int kSweepSamples = 8; // positions sampled to frame a rotation's sweep

ScenePainter::Framing blend(const ScenePainter::Framing& a, const ScenePainter::Framing& b, double u)
{
    return {a.center + u * (b.center - a.center), a.radius + u * (b.radius - a.radius)};
}

} // namespace

double StageTransition::smooth(double u)
{
    u = std::clamp(u, 0.0, 1.0);
    return u * u * (3 - 2 * u);
}

double StageTransition::canonicalOpacity(double position, std::size_t stageCount)
{
    return std::clamp(position - (double(stageCount) - 1), 0.0, 1.0);
}

void StageTransition::showStage(ScenePainter& painter, const std::vector<Stage<double>>& stages, int stage)
{
    painter.show(drawnAt(stages, stage), canonicalOpacity(stage, stages.size()));
    painter.setGhost(ghostAt(stages, stage));
    painter.frameOn(framingAt(painter, stages, stage));
}

ScenePainter::Framing StageTransition::framingAt(const ScenePainter& painter, const std::vector<Stage<double>>& stages,
                                                 int stage)
{
    const auto [first, last] = framedTogether(stages, stage);
    std::vector<Mat4<double>> positions;
    for (int k = first * kSweepSamples; k <= last * kSweepSamples; ++k)
        positions.push_back(drawnAt(stages, double(k) / kSweepSamples));
    return painter.framingOf(positions, canonicalOpacity(stage, stages.size()) > 0);
}

StageTransition::StageTransition(ScenePainter& painter, const std::vector<Stage<double>>& stages, int from, int to)
    : painter_(painter), stages_(stages), from_(from), to_(to)
{
    ghost_ = to == from + 1 ? ghostAt(stages, to) : std::nullopt; // where it starts, while it moves
    start_ = framingAt(painter, stages, from);
    end_ = framingAt(painter, stages, to);
    if (framedTogether(stages, from) == framedTogether(stages, to)) {
        sweep_ = start_; // one framing: the motion is seen against it
        return;
    }
    const bool canonicalAtStart = canonicalOpacity(from, stages.size()) > 0;
    const bool canonicalAtEnd = canonicalOpacity(to, stages.size()) > 0;
    std::vector<Mat4<double>> sweep;
    for (int k = 0; k <= kSweepSamples; ++k)
        sweep.push_back(drawnAt(stages, from + (to - from) * double(k) / kSweepSamples));
    sweep_ = painter.framingOf(sweep, canonicalAtStart || canonicalAtEnd);
}

void StageTransition::apply(double s)
{
    const double motion = smooth((s - kWiden) / (1 - kWiden - kSettle));
    const double position = from_ + (to_ - from_) * motion;
    painter_.show(drawnAt(stages_, position), canonicalOpacity(position, stages_.size()));
    painter_.setGhost(ghost_);
    if (s < kWiden)
        painter_.frameOn(blend(start_, sweep_, smooth(s / kWiden)));
    else if (s <= 1 - kSettle)
        painter_.frameOn(sweep_);
    else
        painter_.frameOn(blend(sweep_, end_, smooth((s - (1 - kSettle)) / kSettle)));
}

} // namespace viewpipe::gui
