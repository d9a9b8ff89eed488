#include "Offscreen.h"

#include "painter/StageTransition.h"
#include "viewpipe/animation.hpp"

namespace viewpipe::gui {

OffscreenPainter::OffscreenPainter(const std::shared_ptr<const EvaluatedScene>& scene, int width, int height, int scale,
                                   Theme theme, bool transparent, double textScale)
{
    window->SetOffScreenRendering(1);
    window->SetSize(width * scale, height * scale);
    window->SetAlphaBitPlanes(transparent ? 1 : 0);
    window->SetMultiSamples(0);
    renderer->UseFXAAOn();
    window->AddRenderer(renderer);
    painter = std::make_unique<ScenePainter>(renderer, nullptr);
    painter->setTheme(theme);
    painter->setFontSize(int(exportLabelSize(width * scale, textScale)), int(exportLabelSize(width * scale, 1)));
    painter->setLineScale(scale);
    painter->setScene(scene);
    if (transparent)
        renderer->SetBackgroundAlpha(0);
    window->Render(); // sizes the renderer before framing
    painter->resetView();
}

StageShown showStageAtRest(const OffscreenPainter& offscreen, const EvaluatedScene& scene, int k,
                           const std::string& caption, const std::optional<ScenePainter::Framing>& fixedFraming)
{
    const std::vector<Stage<double>>& stages = scene.pipeline.stages;
    StageShown shown(scene, drawnAt(stages, k), StageTransition::canonicalOpacity(k, stages.size()));
    shown.ghost = ghostAt(stages, k);
    ScenePainter& painter = *offscreen.painter;
    painter.show(shown.cumulative, shown.canonicalOpacity);
    painter.setGhost(shown.ghost);
    painter.setCaptions(caption, "");
    painter.frameOn(fixedFraming ? *fixedFraming : StageTransition::framingAt(painter, stages, k));
    offscreen.window->Render();
    return shown;
}

std::optional<ScenePainter::Framing> fixedFramingOf(const ScenePainter& painter, const std::vector<Stage<double>>& stages,
                                                    bool fixed)
{
    if (!fixed)
        return std::nullopt;
    std::vector<Mat4<double>> all;
    for (std::size_t k = 0; k <= stages.size(); ++k)
        all.push_back(drawnAt(stages, double(k)));
    return painter.framingOf(all, true);
}

} // namespace viewpipe::gui
