#pragma once
// The exports' offscreen drawing: a window with the scene painter in it, and
// a stage at rest as its picture shows it.
#include <memory>
#include <optional>
#include <string>

#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "painter/ScenePainter.h"

namespace viewpipe::gui {

// An offscreen window and the scene painter in it, sized and styled as the
// export draws: text sized by the picture's width (exportLabelSize; textScale
// enlarges it, 1 is 100 %), lines by `scale`.
struct OffscreenPainter {
    OffscreenPainter(const std::shared_ptr<const EvaluatedScene>& scene, int width, int height, int scale, report::Theme theme,
                     bool transparent, double textScale = 1);
    vtkNew<vtkRenderWindow> window;
    vtkNew<vtkRenderer> renderer;
    std::unique_ptr<ScenePainter> painter;
};

// Stage k at rest as its picture shows it (the ghost of the stage before,
// the caption, its framing or the fixed one), rendered; the stage as shown.
report::StageShown showStageAtRest(const OffscreenPainter& offscreen, const EvaluatedScene& scene, int k,
                           const std::string& caption, const report::StageFramings& framings);

// A storyboard's cell, in the app and every export alike: labels `labelSize`
// pixels high and never shrunk, no legend or caption (the storyboard's headers
// and footers speak for the cells), the notice of labels left out for room where
// `notes` (an exported storyboard says what it leaves out, as a stage's picture does), `traced` marked.
void styleStoryboardCell(ScenePainter& painter, double labelSize, bool ticks, bool notes, const Vec3<double>& traced);

} // namespace viewpipe::gui
