#include "Offscreen.h"


namespace viewpipe::gui {

OffscreenPainter::OffscreenPainter(const std::shared_ptr<const EvaluatedScene>& scene, int width, int height, int scale,
                                   report::Theme theme, bool transparent, double textScale)
{
    window->SetOffScreenRendering(1);
    window->SetSize(width * scale, height * scale);
    window->SetAlphaBitPlanes(transparent ? 1 : 0);
    window->SetMultiSamples(0);
    renderer->UseFXAAOn();
    window->AddRenderer(renderer);
    painter = std::make_unique<ScenePainter>(renderer, nullptr);
    painter->setTheme(theme);
    painter->setFontSize(int(report::exportLabelSize(width * scale, textScale)), int(report::exportLabelSize(width * scale, 1)));
    painter->setLineScale(scale);
    painter->setScene(scene);
    if (transparent)
        renderer->SetBackgroundAlpha(0);
    window->Render(); // sizes the renderer before framing
    painter->resetView();
}

report::StageShown showStageAtRest(const OffscreenPainter& offscreen, const EvaluatedScene& scene, int k,
                           const std::string& caption, const report::StageFramings& framings)
{
    const report::WorldMoment moment = report::stageAtRest(scene, k, framings);
    ScenePainter& painter = *offscreen.painter;
    painter.setCaptions(caption, "");
    painter.showMoment(moment);
    offscreen.window->Render();
    return report::stageShown(scene, moment);
}

void styleStoryboardCell(ScenePainter& painter, double labelSize, bool ticks, bool notes, const Vec3<double>& traced)
{
    painter.setFontSize(int(labelSize), int(labelSize));
    painter.setLegendPlace(report::LegendPlace::None);
    painter.setTicksAndNotesShown(ticks, notes);
    painter.setCaptions("", "");
    painter.markTraced(traced);
}

} // namespace viewpipe::gui
