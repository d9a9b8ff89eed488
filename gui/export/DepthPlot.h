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

void drawDepthChart(vtkChartXY* chart, const Pipeline<double>& pipeline, const DepthOptions& options, Theme theme,
                    const ChartText& text = {});

// Renders the chart offscreen to a PNG, atomically (needs a display).
// At the export's size, its text sized as its pictures' (chartTextFor).
void writeDepthPlot(const Pipeline<double>& pipeline, const DepthOptions& options, const std::filesystem::path& file,
                    Theme theme, int width, int height, double textScale);

} // namespace viewpipe::gui
