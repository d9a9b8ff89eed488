#pragma once

// One animated step between neighbouring stages, as a function of progress
// s in [0, 1]: the camera first widens to take in the whole motion, the
// picture then moves with the interpolated cumulative matrix under a still
// camera (so the motion reads against the screen), and the camera finally
// closes in on the result. Nothing jumps: every phase starts where the last
// one ended.

#include <optional>
#include <vector>

#include "ScenePainter.h"

namespace viewpipe::gui {

class StageTransition {
public:
    StageTransition(ScenePainter& painter, const std::vector<Stage<double>>& stages, int from, int to);

    void apply(double s);
    int to() const { return to_; }

    // Ease in and out: 0 at 0, 1 at 1, flat at both ends (u clamped to [0, 1]).
    static double smooth(double u);

    // The canonical outline fades in while the last stage is reached.
    static double canonicalOpacity(double position, std::size_t stageCount);
    // Shows a stage at rest, framed with the stages that keep its sizes.
    static void showStage(ScenePainter& painter, const std::vector<Stage<double>>& stages, int stage);
    // The framing of a stage: one for all the stages framed together with it
    // (translations and rotations between them are seen moving, rotations'
    // sweeps included).
    static ScenePainter::Framing framingAt(const ScenePainter& painter, const std::vector<Stage<double>>& stages,
                                           int stage);

private:
    ScenePainter& painter_;
    std::vector<Stage<double>> stages_;
    int from_, to_;
    ScenePainter::Framing start_, sweep_, end_;
    std::optional<Mat4<double>> ghost_;
};

} // namespace viewpipe::gui
