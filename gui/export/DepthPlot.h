#pragma once

// The depth buffer's resolution along the view, with VTK's charts: the
// smallest change of distance the buffer can tell apart (log scale) against
// the distance from the near (front) plane, for the scene's buffer (bold)
// and, for comparison, the usual formats.

#include <filesystem>

#include "Charts.h"
#include "viewpipe/report/style.hpp"

class vtkChartXY;

namespace viewpipe::gui {

// The chart with the app panel's text sizes (`text` as given), or as an
// export draws it (text fitted to the picture, fitChartText: as many
// numbers on the axes as fit).
void drawDepthChart(vtkChartXY* chart, const Pipeline<double>& pipeline, const DepthOptions& options, report::Theme theme,
                    const ChartText& text = {});
void drawDepthChart(vtkChartXY* chart, const Pipeline<double>& pipeline, const DepthOptions& options, report::Theme theme,
                    int width, int height, double textScale);

// Renders the export's chart offscreen to a PNG, atomically (needs a display).
void writeDepthPlot(const Pipeline<double>& pipeline, const DepthOptions& options, const std::filesystem::path& file,
                    report::Theme theme, int width, int height, double textScale);

} // namespace viewpipe::gui
