#include "DepthPlot.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkTable.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "Charts.h"

namespace viewpipe::gui {
namespace {

// The usual formats, each in its Okabe-Ito color (the scene's in red), in
// drawing order. Float has a 24-bit significand: unreversed, its curve is
// 24-bit fixed point's, so it is drawn dashed over a wide 24-bit line, which
// shows between the dashes.
struct Format {
    DepthOptions options;
    unsigned char rgb[3];
    float width;
    int line;
    const char* note; // after the name in the legend
};
const Format kFormats[] = {
    {{16, false, false}, {230, 159, 0}, 2.5f, vtkPen::SOLID_LINE, ""},
    {{24, false, false}, {86, 180, 233}, 7.0f, vtkPen::SOLID_LINE, ""},
    {{32, false, false}, {0, 158, 115}, 2.5f, vtkPen::SOLID_LINE, ""},
    {{32, true, false}, {204, 121, 167}, 2.5f, vtkPen::DASH_LINE, " (= 24-bit fixed point without reversal)"},
    {{32, true, true}, {0, 114, 178}, 2.5f, vtkPen::DASH_DOT_LINE, ""},
};

// The usual formats and, if it is none of them, the scene's.
std::vector<Format> chartFormats(const DepthOptions& options)
{
    std::vector<Format> formats(std::begin(kFormats), std::end(kFormats));
    if (std::none_of(formats.begin(), formats.end(), [&](const Format& f) { return f.options == options; }))
        formats.push_back({options, {}, 2.5f, vtkPen::SOLID_LINE, ""}); // red, as the scene's
    return formats;
}

std::string legendEntry(const Format& format, const DepthOptions& options)
{
    return depthFormatName(format.options) + format.note + (format.options == options ? " (this scene)" : "");
}

ChartWords depthChartWords(const Pipeline<double>& pipeline, const DepthOptions& options)
{
    ChartWords words;
    words.title = "Depth resolution against distance";
    words.bottomTitle = pipeline.convention == Convention::Foley ? "distance from the front plane (F), along the view"
                                                                  : "distance from the near plane, along the view";
    words.leftTitle = "depth step\n(world units)"; // the labels, powers of ten, say the scale is logarithmic
    words.widestLeftLabel = "10⁻¹⁸"; // depth steps have two-digit exponents at most
    for (const Format& format : chartFormats(options))
        words.legend.push_back(legendEntry(format, options));
    return words;
}

} // namespace

void drawDepthChart(vtkChartXY* chart, const Pipeline<double>& pipeline, const DepthOptions& options, report::Theme theme,
                    const ChartText& text)
{
    chart->ClearPlots();
    const ChartWords words = depthChartWords(pipeline, options);
    styleChart(chart, words.title, theme, text);
    chart->SetShowLegend(true);
    // Below the plot, under the axis' title: inside, it would cover the curves' steep start.
    chart->GetLegend()->SetInline(false);
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::CENTER);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::BOTTOM);

    double low = 1e300, high = 0, reach = 0;
    for (const Format& format : chartFormats(options)) {
        const bool scene = format.options == options;
        const std::vector<DepthSample> curve = depthResolution(pipeline, format.options, 65);
        vtkNew<vtkTable> table;
        vtkNew<vtkDoubleArray> x, y;
        x->SetName("distance");
        y->SetName(legendEntry(format, options).c_str());
        for (const DepthSample& sample : curve) {
            if (sample.pastFar || !std::isfinite(sample.step) || !(sample.step > 0))
                continue; // a level cut short by the far plane is no measure of resolution
            x->InsertNextValue(sample.distance);
            y->InsertNextValue(std::log10(sample.step));
            low = std::min(low, sample.step), high = std::max(high, sample.step);
            reach = std::max(reach, sample.distance);
        }
        table->AddColumn(x);
        table->AddColumn(y);
        vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
        plot->SetInputData(table, 0, 1);
        // The scene's own format stands out: red, and wider.
        if (scene)
            plot->SetColor(228, 26, 28, 255);
        else
            plot->SetColor(format.rgb[0], format.rgb[1], format.rgb[2], 255);
        plot->SetWidth(format.width + (scene ? 2.0f : 0.0f));
        plot->GetPen()->SetLineType(format.line);
    }
    if (!(low <= high && reach > 0)) // no curve: VTK's axes would search forever for ticks over no range
        low = 1e-3, high = 1, reach = 1;
    vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
    // An export knows the room its plot has (fitChartText): as many numbers as fit. The app's panel lets VTK choose.
    if (text.plotWidth > 0) {
        styleLinearAxis(bottom, words.bottomTitle, theme, 0, reach, text.plotWidth, text);
    } else {
        styleAxis(bottom, words.bottomTitle, theme, text);
        bottom->SetBehavior(vtkAxis::FIXED);
        bottom->SetRange(0, reach);
    }
    const int leftLabels = text.plotHeight > 0 ? std::max(2, int(text.plotHeight / (2.2 * text.labels))) : 12;
    styleLogAxis(chart->GetAxis(vtkAxis::LEFT), words.leftTitle, theme, low, high, leftLabels, text);
}

void drawDepthChart(vtkChartXY* chart, const Pipeline<double>& pipeline, const DepthOptions& options, report::Theme theme,
                    int width, int height, double textScale)
{
    drawDepthChart(chart, pipeline, options, theme, fitChartText(width, height, textScale, depthChartWords(pipeline, options)));
}

void writeDepthPlot(const Pipeline<double>& pipeline, const DepthOptions& options, const std::filesystem::path& file,
                    report::Theme theme, int width, int height, double textScale)
{
    writeChartPng(
        [&](vtkContextView* view) {
            vtkNew<vtkChartXY> chart;
            view->GetScene()->AddItem(chart);
            drawDepthChart(chart, pipeline, options, theme, width, height, textScale);
        },
        width, height, theme, file, "--out");
}

} // namespace viewpipe::gui
