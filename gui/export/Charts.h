#pragma once

// What the charts (accuracy, depth resolution) share: axes in powers of ten,
// chart titles and legends styled for a theme, and writing a chart as a PNG.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "viewpipe/report/style.hpp"

class vtkAxis;
class vtkChart;
class vtkContextView;

namespace viewpipe::gui {

// A chart's text sizes: as the app's panels set them (points on a screen), or
// for an exported picture by its width (chartTextFor), as its pictures are.
// For an exported chart, also the room its text leaves the plot (0: not known).
struct ChartText {
    double title = 18, axisTitle = 16, labels = 13, legend = 14;
    double plotWidth = 0, plotHeight = 0;
};
ChartText chartTextFor(int width, double textScale);

// What a chart says, for fitChartText to measure.
struct ChartWords {
    std::string title, bottomTitle, leftTitle, widestLeftLabel;
    std::vector<std::string> legend; // a row each, below the plot
};
// The text of a chart exported at width x height: at `textScale` where the
// picture has room for it; where it has not (200 % at 800x450), at the
// largest scale, down to 100 %, at which the title, the axes' titles and the
// legend fit beside a plot at least a third of the picture high. Measured in
// the figures' font, which the chart's styles set.
ChartText fitChartText(int width, int height, double textScale, const ChartWords& words);

// VTK's charts hold points in single precision, where tiny errors (1e-50)
// underflow: values are plotted as log10 on a linear axis, labelled in powers
// of ten, from below `low` (and half a label's step more, which keeps its
// number off the corner) to above `high`, at most `maxLabels` labels (fewer on
// a short axis, where they would run together). The room beyond `low` and
// `high`, a decade or an eighth of their span, keeps a 14 px marker there
// whole on a plot about 80 px long or more, however many decades it spans.
void styleLogAxis(vtkAxis* axis, const std::string& title, report::Theme theme, double low, double high, int maxLabels = 12,
                  const ChartText& text = {});

// A linear axis: title and labels in the theme's colors.
void styleAxis(vtkAxis* axis, const std::string& title, report::Theme theme, const ChartText& text = {});
// A linear axis from `low` to `high` labelled at round steps (1, 2 or 5 times
// a power of ten), as many as fit along `length` pixels with room between them.
void styleLinearAxis(vtkAxis* axis, const std::string& title, report::Theme theme, double low, double high, double length,
                     const ChartText& text);

// The chart's title and legend in the theme's colors.
void styleChart(vtkChart* chart, const std::string& title, report::Theme theme, const ChartText& text = {});

// Renders what `draw` puts into an offscreen context view of the given size
// and writes it as a PNG, atomically (temporary file, then rename); throws
// InputError naming `field` when it cannot be written. Needs a display.
void writeChartPng(const std::function<void(vtkContextView*)>& draw, int width, int height, report::Theme theme,
                   const std::filesystem::path& file, const std::string& field);

} // namespace viewpipe::gui
