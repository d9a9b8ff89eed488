#pragma once

// Error against time, log-log, with VTK's charts: one panel for pushing
// vertices (NDC error against ns per vertex), one for building the matrices
// (largest relative error of N's entries against ns per build); one point
// per precision, named in the legend.

#include <filesystem>

#include "viewpipe/precision_ladder.hpp"
#include "viewpipe/report/style.hpp"

class vtkChartMatrix;

namespace viewpipe::gui {

// Fills a chart matrix (made by the caller, shown by a context view): the
// two panels side by side, or stacked for a narrow panel.
void drawAccuracyCharts(vtkChartMatrix* charts, const BenchResult& result, report::Theme theme, bool stacked);

// Renders the charts offscreen to a PNG (needs a display; see VirtualDisplay).
void writeAccuracyPlot(const BenchResult& result, const std::filesystem::path& file, report::Theme theme);

} // namespace viewpipe::gui
