#include "Offscreen.h"


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
                           const std::string& caption, const StageFramings& framings)
{
    const WorldMoment moment = stageAtRest(scene, k, framings);
    ScenePainter& painter = *offscreen.painter;
    painter.setCaptions(caption, "");
    painter.showMoment(moment);
    offscreen.window->Render();
    return stageShown(scene, moment);
}

void styleStoryboardCell(ScenePainter& painter, double labelSize, bool ticks, const Vec3<double>& traced)
{
    painter.setFontSize(int(labelSize), int(labelSize));
    painter.setLegendPlace(LegendPlace::None);
    painter.setTicksAndNotesShown(ticks, false);
    painter.setCaptions("", "");
    painter.markTraced(traced);
}

} // namespace viewpipe::gui
